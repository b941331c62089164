"""The Python examples (examples/python/) in shortened forms: each runs, writes
what it says, and its numbers are those of the runs it made."""
import importlib.util
import json
import math
import os

import pytest

ROOT = os.environ.get("TALUS_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))


def example(name):
    path = os.path.join(ROOT, "examples", "python", name + ".py")
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_calibration_with_scipy_fits_two_parameters(tmp_path):
    cal = example("calibrate_dam_break")
    # Coarse grains, two 5 cm segments, three evaluations (as tests/app/test_calibrate.sh).
    report = cal.main(["--out", str(tmp_path), "--evaluations", "3",
                       "--set", "dam_break.release.radius_min=4e-3",
                       "--set", "dam_break.release.radius_max=8e-3",
                       "--set", "dam_break.release.porosity=0.2", "--set", "run.duration=1.0",
                       "--set", "dam_break.segment_length=0.05", "--set", "dam_break.segments=2",
                       "--target", "gamma_1=20", "--target", "gamma_2=25"])
    with open(tmp_path / "calibration.json") as f:
        saved = json.load(f)
    assert saved == json.loads(json.dumps(report))
    evaluations = saved["evaluations"]
    assert len(evaluations) == 3
    for e in evaluations:
        with open(os.path.join(e["folder"], "summary.json")) as f:
            s = json.load(f)
        angle, rolling = e["parameters"]
        # The trial values reached the run (friction is stored as tan(angle)).
        assert s["scenario"]["materials"][0]["friction"] == pytest.approx(
            math.tan(math.radians(angle)), rel=1e-12)
        assert s["scenario"]["contact"]["kuen_particle_factor"] == pytest.approx(rolling)
        # The misfit is that of the run's own angles.
        assert e["misfit"] == pytest.approx(cal.misfit(s, saved["targets"]), rel=1e-12)
    assert saved["best"] == min(range(3), key=lambda k: evaluations[k]["misfit"])
    # Two parameters moved: the first simplex varies each.
    assert {tuple(e["parameters"]) for e in evaluations} == {(15.5, 0.5), (25.0, 0.5), (15.5, 0.9)}


def test_friction_study_gives_shorter_runout_for_more_friction(tmp_path):
    study = example("runout_friction_study")
    rows = study.main(["--out", str(tmp_path), "--mu", "0.1", "0.4", "--duration", "40"])
    low, high = rows
    # More basal friction: the flow stops sooner and shorter (Voellmy, the same release).
    assert high["runout_x_m"] < low["runout_x_m"]
    assert high["max_speed_m_s"] < low["max_speed_m_s"]
    assert os.path.getsize(tmp_path / "study.png") > 10000
    with open(tmp_path / "study.csv") as f:
        assert len(f.read().strip().split("\n")) == 3


def test_triaxial_two_stage_changes_the_walls_between_the_stages(tmp_path):
    tri = example("triaxial_two_stage")
    r = tri.main(["--out", str(tmp_path), "--strain", "0.03"])
    # Stage 1: the six servos set from Python settle at p0 (measured: 19999.6 to
    # 20000.1 Pa; the bound leaves room for another packing).
    assert len(r["consolidated_pressures"]) == 6
    for p in r["consolidated_pressures"].values():
        assert p == pytest.approx(2e4, rel=1e-3)
    # Stage 2: the top wall moves at the speed the script set, exactly.
    assert r["top_speed_in_shear"] == pytest.approx(0.01, rel=1e-9)
    assert 0.03 <= r["axial_strain"] < 0.031  # the callback ended the run there
    # The side servos hold p0 up to a proportional controller's lag behind the
    # dilating sample (measured +0.6 % to +3.8 %).
    low, high = r["lateral_stress_in_shear"]
    assert 0.99 * 2e4 < low and high < 1.06 * 2e4
    # A plausibility band, not a validation: the mobilised friction of spheres
    # with mu = 0.5 after 3 % axial strain (measured sin(phi) = 0.51, 31 deg).
    assert 0.3 < r["final_sin_phi"] < 0.7
    with open(tmp_path / "triaxial.csv") as f:
        lines = f.read().strip().split("\n")
    assert lines[0].startswith("time,stage,side_x") and len(lines) > 50
    assert os.path.getsize(tmp_path / "triaxial.png") > 10000
    with open(os.path.join(r["folder"], "log.txt")) as f:
        log = f.read()
    assert log.count("servo holds 20000 Pa") == 6 and "wall 'top' translates at" in log
    with open(os.path.join(r["folder"], "summary.json")) as f:
        assert json.load(f)["status"] == "stopped"
