"""The Python API (docs/python.md) against the command line: the same bits
however a run is driven, views of the state, errors, callbacks, resume and
the GIL. Run by ctest with PYTHONPATH=build/python and TALUS=build/talus."""
import filecmp
import json
import os
import subprocess
import threading

import numpy as np
import pytest

import talus

ROOT = os.environ.get("TALUS_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("TALUS", "talus")
COLLAPSE = os.path.join(ROOT, "scenarios", "dem", "collapse_2d.toml")
TERRAIN = os.path.join(ROOT, "scenarios", "runout", "runout_terrain_2d.toml")
SHORT = {"run.duration": 0.03, "output.series_interval": 0.005}


def physics(folder):
    """summary.json without what depends on the wall clock or the folder."""
    with open(os.path.join(folder, "summary.json")) as f:
        s = json.load(f)
    for key in ("run", "timings", "scenario_file"):
        s.pop(key, None)
    return s


def cli_run(tmp_path, name, overrides, threads=1):
    out = tmp_path / name
    sets = [a for k, v in overrides.items() for a in ("--set", f"{k}={v}")]
    subprocess.run([BINARY, "run", COLLAPSE, "--out", str(out), "--quiet", "--threads",
                    str(threads), *sets], check=True)
    return out


@pytest.mark.parametrize("threads", [1, 2])
def test_stepping_from_python_gives_the_command_lines_bits(tmp_path, threads):
    reference = cli_run(tmp_path, "cli", SHORT, threads)
    with talus.Run(COLLAPSE, out=tmp_path / "py", overrides=SHORT, threads=threads) as run:
        # Irregular pieces: single steps, a step count, a time, then the end.
        for n in (1, 1, 7, 250):
            assert run.step(n) == n
        run.run(until=0.0123)
        assert run.time == pytest.approx(0.0123, abs=run.time_step)
        run.run()
        assert run.done
    assert filecmp.cmp(reference / "series.csv", tmp_path / "py" / "series.csv", shallow=False)
    assert physics(reference) == physics(tmp_path / "py")


def test_arrays_are_views_and_velocities_act_on_the_next_step(tmp_path):
    def one_step(kick):
        with talus.Run(COLLAPSE, out=tmp_path / f"kick{kick}", overrides=SHORT) as run:
            a = run.arrays()
            address = a["x"].__array_interface__["data"][0]
            a["v"][:, 0] += kick  # every grain 1 m/s faster along x
            run.step(1)
            b = run.arrays()
            # Same memory after a step (no re-sort this early): the old view sees the new state.
            assert b["x"].__array_interface__["data"][0] == address
            assert np.array_equal(a["x"], b["x"])
            return b["x"].copy(), run.time_step

    x0, dt = one_step(0.0)
    x1, _ = one_step(1.0)
    # x += v dt with the kicked v. The same kick for every grain leaves the
    # grains' relative velocities, so the pair forces (elastic and damping) are
    # unchanged, and a grain off the walls shifts by dt exactly (to round-off);
    # the grains touching the floor, back wall or gate (4.5 % here) feel the
    # walls' damping of the changed velocity (measured: 95.5 % shift by dt to
    # 1e-9, the others by 0.91-1 dt; the bounds leave room for another packing).
    shift = (x1[:, 0] - x0[:, 0]) / dt
    assert np.mean(np.abs(shift - 1.0) < 1e-9) > 0.9
    assert np.all(np.abs(shift - 1.0) < 0.2)


def test_read_only_arrays_refuse_writes(tmp_path):
    with talus.Run(COLLAPSE, out=tmp_path / "ro", overrides=SHORT) as run:
        a = run.arrays()
        assert run.units()["x"] == "m" and run.units()["v"] == "m/s"
        with pytest.raises(ValueError):
            a["x"][0, 0] = 1.0
        assert a["id"].dtype == np.int64 and a["x"].shape == (a["r"].shape[0], 2)


def test_bad_input_raises_input_error_with_the_key(tmp_path):
    with pytest.raises(talus.InputError, match="duraton"):
        talus.Run(COLLAPSE, out=tmp_path / "bad", overrides={"run.duraton": 1})
    with pytest.raises(talus.InputError, match="duraton"):
        talus.validate(COLLAPSE, {"run.duraton": 1})
    with pytest.raises(talus.InputError, match="not a TOML value"):
        talus.validate(COLLAPSE, {"run.duration": object()})
    assert not (tmp_path / "bad").exists()  # refused before the folder was made


def test_a_callback_stops_the_run_and_the_summary_says_so(tmp_path):
    seen = []

    def stop_after_10ms(run):
        seen.append(run.time)
        return run.time >= 0.01

    with talus.Run(COLLAPSE, out=tmp_path / "cb", overrides=SHORT) as run:
        run.run(every_time=0.004, callback=stop_after_10ms)
        assert not run.done
    assert seen == pytest.approx([0.004, 0.008, 0.012], abs=2e-5)
    data = talus.read_run(tmp_path / "cb")
    assert data.summary["status"] == "stopped"
    assert data.series["time"].iloc[-1] <= 0.012 + 1e-9


def test_resume_from_python_continues_bit_for_bit(tmp_path):
    sets = dict(SHORT, **{"output.checkpoint_interval": 0.01})
    reference = cli_run(tmp_path, "whole", sets)
    with talus.Run(COLLAPSE, out=tmp_path / "parts", overrides=sets) as run:
        run.run(until=0.015)  # past the checkpoint at 0.01 s, then stopped
    with talus.Run(resume=tmp_path / "parts") as run:
        assert run.time == pytest.approx(0.01, abs=run.time_step)
        run.run()
    assert filecmp.cmp(reference / "series.csv", tmp_path / "parts" / "series.csv", shallow=False)
    assert physics(reference)["metrics"] == physics(tmp_path / "parts")["metrics"]


def test_resume_takes_the_runs_thread_count_and_warns_on_another(tmp_path):
    sets = dict(SHORT, **{"output.checkpoint_interval": 0.01})
    for name in ("same", "other"):
        with talus.Run(COLLAPSE, out=tmp_path / name, overrides=sets, threads=2) as run:
            run.run(until=0.015)
    with talus.Run(resume=tmp_path / "same") as run:
        assert run.resolved()["threads"] == 2
        run.run()
    assert "warnings" not in run.result or not run.result["warnings"]
    with talus.Run(resume=tmp_path / "other", threads=1) as run:
        run.run()
    assert any("resumed on 1 thread where the run ran on 2" in w for w in run.result["warnings"])
    assert "resumed on 1 thread" in " ".join(
        talus.read_run(tmp_path / "other").summary["warnings"])
    with pytest.raises(talus.InputError, match="threads"):
        talus.Run(COLLAPSE, out=tmp_path / "bad", threads=0)


@pytest.mark.parametrize("scenario, sets", [
    (os.path.join("mpm", "mpm_column_collapse.toml"),
     {"run.duration": 0.02, "output.series_interval": 0.002,
      "output.checkpoint_interval": 0.008}),
    (os.path.join("runout", "runout_terrain_2d.toml"),
     {"run.duration": 6.0, "output.checkpoint_interval": 2.0}),
])
def test_mpm_and_fv2d_resume_from_python_bit_for_bit(tmp_path, scenario, sets):
    path = os.path.join(ROOT, "scenarios", scenario)
    whole = tmp_path / "whole"
    args = [a for k, v in sets.items() for a in ("--set", f"{k}={v}")]
    subprocess.run([BINARY, "run", path, "--out", str(whole), "--quiet", *args], check=True)
    end = sets["run.duration"]
    with talus.Run(path, out=tmp_path / "parts", overrides=sets) as run:
        run.run(until=0.6 * end)  # past a checkpoint, then stopped
    with talus.Run(resume=tmp_path / "parts") as run:
        assert run.time < 0.6 * end
        run.run()
    assert filecmp.cmp(whole / "series.csv", tmp_path / "parts" / "series.csv", shallow=False)
    assert physics(whole)["metrics"] == physics(tmp_path / "parts")["metrics"]


def test_the_gil_is_released_while_a_run_steps(tmp_path):
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            stop.wait(0.001)

    with talus.Run(COLLAPSE, out=tmp_path / "gil", overrides={"run.duration": 0.05}) as run:
        worker = threading.Thread(target=count)
        worker.start()
        before = len(ticks)
        run.run()
        during = len(ticks) - before
        stop.set()
        worker.join()
    assert during > 10  # the other thread ran while run() stepped


def test_grid_arrays_hold_the_flow(tmp_path):
    with talus.Run(TERRAIN, out=tmp_path / "fv2d", overrides={"run.duration": 2.0}) as run:
        run.run()
        a = run.arrays()
        assert set(a) == {"h", "hu", "hv", "elevation"}
        h = a["h"].copy()
        elevation = a["elevation"].copy()
    data = talus.read_run(tmp_path / "fv2d")
    # The grid as the maps the run wrote: row 0 north (the .npy files).
    assert np.array_equal(elevation, np.load(tmp_path / "fv2d" / "elevation.npy"))
    dx, dy = data.summary["resolved"]["cell_size_m"]
    assert h.shape == (data.summary["resolved"]["cells_y"], data.summary["resolved"]["cells_x"])
    assert h.sum() * dx * dy == pytest.approx(data.series["volume"].iloc[-1], rel=1e-12)


def test_mpm_arrays_hold_the_points_and_their_stresses(tmp_path):
    column = os.path.join(ROOT, "scenarios", "mpm", "mpm_column_collapse.toml")
    with talus.Run(column, out=tmp_path / "mpm", overrides={"run.duration": 0.01}) as run:
        run.run()
        a = run.arrays()
        n = a["x"].shape[0]
        assert a["v"].flags.writeable and not a["stress"].flags.writeable
        assert a["stress"].shape == (n, 3, 3) and a["mass"].shape == (n,)
        s = a["stress"].copy()
        y = a["x"][:, 1].copy()
    data = talus.read_run(tmp_path / "mpm")
    assert n == data.series["points"].iloc[-1]
    # The stride of the stress (a field of each point's material state) read
    # right: Cauchy stresses are symmetric, and the column's weight compresses
    # (tension positive) its lower half, while after 0.01 s the loading from
    # the base has not yet reached the upper half (no tension there).
    assert np.abs(s - s.transpose(0, 2, 1)).max() <= 1e-9 * np.abs(s).max()
    lower = y < np.median(y)
    assert s[lower, 1, 1].mean() < 0.0 <= -s[~lower, 1, 1].mean()


def test_ctrl_c_interrupts_a_run_that_can_then_be_finished(tmp_path):
    import _thread

    with talus.Run(COLLAPSE, out=tmp_path / "int", overrides={"run.duration": 5.0}) as run:
        timer = threading.Timer(0.3, _thread.interrupt_main)  # as if Ctrl-C were pressed
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            run.run()
        timer.join()
        assert 0.0 < run.time < 5.0 and not run.done
    assert talus.read_run(tmp_path / "int").summary["status"] == "stopped"


def test_a_dict_scenario_runs_as_its_file_and_errors_name_the_dict_path(tmp_path):
    import tomllib

    with open(COLLAPSE, "rb") as f:
        as_dict = tomllib.load(f)
    as_dict["run"]["duration"] = 0.01
    scenario = talus.load_scenario(as_dict, base=os.path.dirname(COLLAPSE))
    assert scenario.description.startswith("valid (2D DEM, 1160 particles")
    talus.run(scenario, out=tmp_path / "dict")
    reference = cli_run(tmp_path, "file", {"run.duration": 0.01})
    assert filecmp.cmp(reference / "series.csv", tmp_path / "dict" / "series.csv", shallow=False)
    as_dict["materials"][0]["density"] = -5
    with pytest.raises(talus.InputError) as bad:
        talus.load_scenario(as_dict)
    message = str(bad.value)
    assert "(dict): materials.0.density: expected a positive number" in message
    assert "--set" not in message


def test_dan_arrays_hold_the_blocks(tmp_path):
    flume = os.path.join(ROOT, "scenarios", "runout", "runout_flume_A.toml")
    with talus.Run(flume, out=tmp_path / "dan", overrides={"run.duration": 0.5}) as run:
        run.run()
        a = run.arrays()
        s, volume = a["s"].copy(), a["volume"].copy()
        assert a["v"].shape == s.shape and a["k"].shape == volume.shape == (s.size - 1,)
    data = talus.read_run(tmp_path / "dan")
    assert np.all(np.diff(s) > 0)  # boundary blocks in order along the path
    assert volume.sum() == pytest.approx(data.summary["metrics"]["volume_m3"], rel=1e-12)
