"""Walls driven from Python (docs/python.md#walls), checkpoints on demand and
the re-sort counter: a wall's new velocity acts from the current time on
without a jump, the changes survive a checkpoint and resume bit for bit, bad
changes raise InputError before anything moves."""
import json
import os

import numpy as np
import pytest

import talus

ROOT = os.environ.get("TALUS_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
COLLAPSE = os.path.join(ROOT, "scenarios", "dem", "collapse_2d.toml")
SHORT = {"run.duration": 0.03, "output.series_interval": 0.005}


def test_a_new_wall_velocity_acts_from_now_on_without_a_jump(tmp_path):
    with talus.Run(COLLAPSE, out=tmp_path / "w", overrides=SHORT) as run:
        run.run(until=0.004)
        back = run.walls()["back"]
        assert np.array_equal(back.displacement, [0, 0, 0])
        back.set_velocity([-0.05, 0.0])
        t0 = run.time
        # Set, not yet stepped: the wall stands where it stood.
        assert np.array_equal(run.walls()["back"].displacement, [0, 0, 0])
        run.run(until=0.008)
        moved = run.walls()["back"]
        assert moved.displacement[0] == pytest.approx(-0.05 * (run.time - t0), rel=1e-12)
        assert moved.velocity[0] == -0.05
        # Stopped again: it stays where it got to, exactly.
        moved.set_velocity([0.0, 0.0])
        where = run.walls()["back"].displacement.copy()
        run.step(50)
        assert np.array_equal(run.walls()["back"].displacement, where)
        with open(os.path.join(run.out, "log.txt")) as f:
            log = f.read()
        assert "wall 'back' translates at (-0.05, 0, 0) m/s (set by the caller)" in log


def test_wall_force_array_is_a_view_of_the_walls(tmp_path):
    with talus.Run(COLLAPSE, out=tmp_path / "w", overrides=SHORT) as run:
        run.step(20)
        a = run.arrays()
        names = list(run.walls())
        assert a["wall_force"].shape == (len(names), 2)
        assert not a["wall_force"].flags.writeable
        run.step(20)
        walls = run.walls()
        # The view taken before the steps reads the forces of now.
        for k, name in enumerate(names):
            assert np.array_equal(a["wall_force"][k], walls[name].force[:2])
            assert a["wall_torque"][k] == walls[name].torque[2]
        floor = names.index("floor")
        assert a["wall_force"][floor, 1] < 0  # the grains push the floor down
        assert run.units()["wall_force"] == "N/m" and run.units()["m"] == "kg/m"


def test_bad_wall_changes_raise_input_error(tmp_path):
    with talus.Run(COLLAPSE, out=tmp_path / "w", overrides=SHORT) as run:
        walls = run.walls()
        with pytest.raises(talus.InputError, match="no wall 'roof'.*'floor'"):
            run._session.set_wall_velocity("roof", [0.0, 0.0])
        # The builder's rule: a wall this fast would press a grain deeper than its radius.
        with pytest.raises(talus.InputError, match="faster than the impact speed|pressed"):
            walls["back"].set_velocity([-50.0, 0.0])
        with pytest.raises(talus.InputError, match="xy plane"):
            walls["back"].set_velocity([0.0, 0.0, 1.0])
        with pytest.raises(talus.InputError, match="needs a plane wall"):
            walls["floor"].set_servo(1e3, 0.01, 0.5)
        with pytest.raises(talus.InputError, match="expected 2 or 3 numbers"):
            walls["back"].set_velocity([1.0])
        run.step(5)  # nothing was changed: the run goes on
        assert np.array_equal(run.walls()["back"].displacement, [0, 0, 0])


def test_fv2d_has_no_walls(tmp_path):
    path = os.path.join(ROOT, "scenarios", "runout", "runout_terrain_2d.toml")
    with talus.Run(path, out=tmp_path / "g", overrides={"run.duration": 1.0}) as run:
        assert run.walls() == {}
        with pytest.raises(talus.InputError, match="no walls"):
            run._session.set_wall_velocity("x", [0.0, 0.0])


def drive(run, until):
    """The same script for the whole run and its parts: the back wall pulled
    away at 5 ms, stopped at 15 ms."""
    for t, v in ((0.005, -0.2), (0.015, 0.0)):
        if run.time < t - 1e-12 <= until:
            run.run(until=t)
            run.walls()["back"].set_velocity([v, 0.0])
    run.run(until=until)


def final_state(run):
    a = run.arrays()
    order = np.argsort(a["id"])
    return a["x"][order].copy(), a["v"][order].copy()


# On two threads the checkpoint falls between neighbour builds: the resume must
# reuse the threads' chunk cut of the last build (it is in the checkpoint).
@pytest.mark.parametrize("threads", [1, 2])
def test_checkpoint_now_and_resume_keep_the_changed_walls_bit_for_bit(tmp_path, threads):
    with talus.Run(COLLAPSE, out=tmp_path / "whole", overrides=SHORT, threads=threads) as run:
        drive(run, run.end_time)
        whole = final_state(run)
    whole_headline = run.result["headline"]
    with talus.Run(COLLAPSE, out=tmp_path / "parts", overrides=SHORT, threads=threads) as run:
        drive(run, 0.0123)  # between series rows: the checkpoint adds one
        t_checkpoint = run.time
        run.checkpoint()
        drive(run, 0.02)  # then stopped: the resume goes back to 0.0123
    with talus.Run(resume=tmp_path / "parts", threads=threads) as run:
        assert run.time == t_checkpoint
        # The velocity set at 5 ms came back from the checkpoint, not the scenario.
        assert run.walls()["back"].velocity[0] == -0.2
        drive(run, run.end_time)
        parts = final_state(run)
    # What the command line prints at the end (largest wall force and where).
    assert run.result["headline"] == whole_headline
    assert np.array_equal(whole[0], parts[0]) and np.array_equal(whole[1], parts[1])
    with open(tmp_path / "whole" / "summary.json") as f:
        a = json.load(f)
    with open(tmp_path / "parts" / "summary.json") as f:
        b = json.load(f)
    # The metrics hold the walls' forces, peaks, impulses and work.
    assert a["metrics"] == b["metrics"]
    # The series: the same rows, and the checkpoint's own row.
    whole_rows = talus.read_run(tmp_path / "whole").series
    part_rows = talus.read_run(tmp_path / "parts").series
    extra = np.abs(part_rows["time"] - t_checkpoint) < 1e-12
    assert extra.sum() == 1
    assert part_rows[~extra].reset_index(drop=True).equals(whole_rows)


def test_checkpoint_now_for_dan_and_refused_once_complete(tmp_path):
    dan = os.path.join(ROOT, "scenarios", "runout", "runout_flume_A.toml")
    whole = talus.run(dan, out=tmp_path / "whole")
    with talus.Run(dan, out=tmp_path / "parts") as run:
        run.run(until=0.3 * run.end_time)
        run.checkpoint()
        run.run(until=0.6 * run.end_time)
    with talus.Run(resume=tmp_path / "parts") as run:
        assert run.time < 0.31 * run.end_time
        run.run()
    assert talus.read_run(tmp_path / "parts").summary["metrics"] == whole.summary["metrics"]
    with talus.Run(COLLAPSE, out=tmp_path / "c", overrides={"run.duration": 0.002}) as run:
        run.run()
        with pytest.raises(talus.InputError, match="complete"):
            run.checkpoint()


def test_reorders_counts_the_resorts_and_rows_keep_their_particle_between(tmp_path):
    with talus.Run(COLLAPSE, out=tmp_path / "r", overrides=SHORT) as run:
        first = run.reorders
        assert first >= 1  # the build before the first step sorts once
        ids = run.arrays()["id"].copy()
        seen_same, seen_new = 0, 0
        while not run.done and (seen_same < 3 or seen_new < 1):
            before = run.reorders
            run.step(10)
            now = run.arrays()["id"]
            if run.reorders == before:
                assert np.array_equal(now, ids)  # no re-sort: the same rows
                seen_same += 1
            else:
                seen_new += 1
            ids = now.copy()
        assert seen_same >= 3 and seen_new >= 1


def test_resolved_gives_the_grid_transform_before_the_first_step(tmp_path):
    path = os.path.join(ROOT, "scenarios", "runout", "runout_terrain_2d.toml")
    with talus.Run(path, out=tmp_path / "g", overrides={"run.duration": 1.0}) as run:
        grid = run.resolved()
        assert run.arrays()["h"].shape == (grid["cells_y"], grid["cells_x"])
        run.run()
    assert talus.read_run(tmp_path / "g").summary["resolved"] == grid


def test_a_second_thread_cannot_change_or_step_a_run_while_it_steps(tmp_path):
    import threading
    run = talus.Run(COLLAPSE, out=tmp_path / "t", overrides={"run.duration": 0.3})
    worker = threading.Thread(target=run.run)
    worker.start()
    while not run._session.stepping and worker.is_alive():
        pass  # the GIL is free while the run steps
    try:
        # Refused, not raced: the other thread holds the run.
        with pytest.raises(talus.InputError, match="stepping"):
            run.walls()["back"].set_velocity([-0.05, 0.0])
        with pytest.raises(talus.InputError, match="stepping"):
            run.step(1)
        with pytest.raises(talus.InputError, match="stepping"):
            run.checkpoint()
    finally:
        worker.join()
    assert run.done
    run.finish()
    assert talus.read_run(tmp_path / "t").summary["status"] == "completed"
