"""talus from Python: run any method of a scenario file, step it, look at its
state as numpy arrays between steps, stop it from a callback, and read a run
folder back. The reference is docs/python.md.

    import talus
    with talus.Run("scenarios/dem/collapse_2d.toml", out="/tmp/c", force=True) as run:
        run.run(until=0.1)
        x = run.arrays()["x"]          # particle positions, a view (no copy)
    data = talus.read_run("/tmp/c")    # summary, series (pandas), snapshots

Errors: talus.InputError (bad input, before anything runs; the message names
file, line and key as on the command line) and talus.RunError (a run that went
wrong: its summary.json then says "failed" and why).
"""
import json
import math
import os

from . import _talus
from ._talus import InputError, RunError, __version__

__all__ = ["Run", "RunData", "Scenario", "Wall", "InputError", "RunError", "load_scenario",
           "read_run", "run", "validate"]


def _toml_value(value, key):
    """A Python value as the TOML text of a --set override."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string for any text
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v, key) for v in value) + "]"
    raise InputError(f"overrides: '{key}': {type(value).__name__} is not a TOML value "
                     "(give a number, string, bool or list)")


def _sets(overrides):
    """{"run.duration": 0.5} -> ["run.duration=0.5"] (the command line's --set)."""
    if overrides is None:
        return []
    if not isinstance(overrides, dict):
        raise InputError("overrides: expected a dict of dotted keys, e.g. {'run.duration': 0.5}")
    return [f"{key}={_toml_value(value, key)}" for key, value in overrides.items()]


def _inline(value, key):
    """A Python value as TOML inline text: dicts as inline tables."""
    if isinstance(value, dict):
        return "{" + ", ".join(f"{json.dumps(str(k))} = {_inline(v, f'{key}.{k}')}"
                               for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_inline(v, f"{key}.{i}") for i, v in enumerate(value)) + "]"
    return _toml_value(value, key)


class Scenario:
    """A checked scenario: from a file, or from a dict laid out as the TOML
    file would be ({"method": "dem", "run": {...}, "materials": [{...}]}).
    Built by load_scenario(); give it to Run() or validate()."""

    def __init__(self, path, text, overrides):
        self.path, self.text, self.overrides = path, text, overrides
        self.description = self.validate()

    def validate(self, allow_long_run=False):
        """`talus validate`'s line for this scenario; raises InputError."""
        if self.text is not None:
            return _talus.validate_text(self.text, self.path, self.overrides, allow_long_run)
        return _talus.validate(self.path, self.overrides, allow_long_run)

    def __repr__(self):
        return f"Scenario({self.path!r}: {self.description})"


def load_scenario(source, overrides=None, base=None):
    """A Scenario from a file path or a dict, with --set style overrides,
    checked as `talus validate` checks a file: InputError names the file, line
    and key, or for a dict the dotted path of the key in it
    (".../(dict): materials.0.density: ..."). A dict's relative file names
    (terrain rasters) resolve against `base` (default: the current folder)."""
    sets = _sets(overrides)
    if isinstance(source, dict):
        path = os.path.join(os.path.abspath(base or os.getcwd()), _talus.DICT_SCENARIO)
        # The dict's values go in as overrides of an empty file: without lines,
        # so messages name them by their path in the dict.
        values = [f"{k}={_inline(v, k)}" for k, v in source.items()]
        return Scenario(path, "# a scenario from a Python dict\n", values + sets)
    return Scenario(os.fspath(source), None, sets)


def validate(scenario, overrides=None, allow_long_run=False):
    """Parses and builds a scenario (a path, a dict or a Scenario) without
    running it, as `talus validate` does: returns the one-line description,
    raises InputError."""
    if not isinstance(scenario, Scenario):
        return load_scenario(scenario, overrides).validate(allow_long_run)
    if overrides:
        scenario = Scenario(scenario.path, scenario.text, scenario.overrides + _sets(overrides))
    return scenario.validate(allow_long_run)


class Wall:
    """One wall of a DEM run, read when Run.walls() was called, and the handle
    that changes its motion from the run's current time on.

    Readings (numpy arrays of 3 components, SI; per metre of depth in 2D):
    force (what the particles exert on it, N), torque (about its pivot),
    displacement (of its pivot since t = 0, m), velocity (of its pivot now,
    m/s), pressure (normal force over the servo area, Pa; 0 without a servo),
    servo = (pressure, speed, area) of its servo ((0, ...) when off). They are
    copies: call Run.walls() again after stepping."""

    def __init__(self, run, reading):
        import numpy
        self._run, self.name = run, reading["name"]
        for key in ("force", "torque", "displacement", "velocity"):
            setattr(self, key, numpy.array(reading[key]))
        self.pressure = reading["pressure"]
        self.servo = (reading["servo_pressure"], reading["servo_speed"], reading["servo_area"])

    def set_velocity(self, velocity):
        """From now on the wall translates at `velocity` (2 or 3 numbers, m/s)
        with no end, from where it stands. InputError for a rotating wall or a
        speed the time step was not chosen for (the scenario's rule)."""
        self._run._session.set_wall_velocity(self.name, [float(c) for c in velocity])

    def set_servo(self, pressure, speed=None, area=None):
        """From now on a servo holds `pressure` (Pa) on this plane wall,
        moving along its normal at up to `speed` (m/s), the pressure being the
        normal force over `area` (m^2; m in 2D). speed and area default to the
        servo's present ones. pressure=0 turns the servo off: the wall stays
        where the servo left it."""
        speed = self.servo[1] if speed is None else speed
        area = self.servo[2] if area is None else area
        self._run._session.set_wall_servo(self.name, float(pressure), float(speed), float(area))

    def __repr__(self):
        return f"Wall({self.name!r}, force={self.force.tolist()}, displacement={self.displacement.tolist()})"


def _threads(threads):
    """0 (the run's own, or one) for None; otherwise a positive count."""
    if threads is None:
        return 0
    if int(threads) != threads or threads < 1:
        raise InputError(f"Run: threads must be a whole number of at least 1, got {threads!r}")
    return int(threads)


class Run:
    """One run of a scenario file, driven from Python.

    The constructor checks the scenario (InputError), claims the output folder
    (`out`, default runs/<name> as on the command line; `force=True` empties a
    folder talus wrote before) and builds the method; nothing has stepped yet.
    `resume=DIR` continues the run in DIR from its checkpoint instead, on the
    thread count it last ran on unless `threads` is given (another count ends
    in other bits than the uninterrupted run; a warning then says so).
    The run writes what `talus run` writes (summary.json, series.csv,
    snapshots, log.txt) on the same simulated times however it is stepped.
    """

    def __init__(self, scenario=None, *, out=None, overrides=None, threads=None, force=False,
                 resume=None, allow_long_run=False):
        path, text, sets = "", "", _sets(overrides)
        if isinstance(scenario, dict):
            scenario = load_scenario(scenario)
        if isinstance(scenario, Scenario):
            path, text, sets = scenario.path, scenario.text or "", scenario.overrides + sets
        elif scenario is not None:
            path = os.fspath(scenario)
        self._session = _talus.Session(
            path, text,
            os.fspath(out) if out is not None else "",
            os.fspath(resume) if resume is not None else "",
            sets, _threads(threads), bool(force), bool(allow_long_run))
        self.result = None  # finish()'s dict once finished

    # The clock and where the run writes.
    time = property(lambda self: self._session.time, doc="simulated time, s")
    steps = property(lambda self: self._session.steps, doc="steps taken since t = 0")
    end_time = property(lambda self: self._session.end_time, doc="the run's end time, s")
    time_step = property(lambda self: self._session.time_step, doc="the last time step, s")
    done = property(lambda self: self._session.done,
                    doc="True once the end time is reached or the method stopped (at rest)")
    out = property(lambda self: self._session.out, doc="the run folder")

    def step(self, n=1):
        """Takes up to n steps (fewer at the end); returns how many were taken."""
        if n < 1:
            raise InputError(f"step: n must be at least 1, got {n}")
        return self._session.advance(math.inf, int(n))

    def run(self, until=None, *, every_steps=None, every_time=None, callback=None):
        """Steps to `until` (s; default the end). With a callback, calls
        callback(run) every `every_steps` steps or `every_time` simulated
        seconds (one of them); the run stops there when it returns True.
        Returns the number of steps taken."""
        end = self.end_time if until is None else min(float(until), self.end_time)
        if callback is None:
            return self._session.advance(end, -1)
        if (every_steps is None) == (every_time is None):
            raise InputError("run: with a callback give exactly one of every_steps, every_time")
        if every_steps is not None and every_steps < 1:
            raise InputError(f"run: every_steps must be at least 1, got {every_steps}")
        if every_time is not None and not every_time > 0:
            raise InputError(f"run: every_time must be > 0 s, got {every_time}")
        taken = 0
        tolerance = 1e-9 * max(1.0, self.end_time)
        next_time = self.time + (every_time or 0.0)
        while not self.done and self.time < end - tolerance:
            if every_steps is not None:
                taken += self._session.advance(end, int(every_steps))
            else:
                taken += self._session.advance(min(next_time, end), -1)
                while next_time <= self.time + tolerance:
                    next_time += every_time
            if callback(self) is True:
                break
        return taken

    def arrays(self):
        """The method's state as numpy arrays without copies, by name (see
        units()). DEM: x, v, w, f, r, m, id (v and w writable: a change acts
        on the next step), wall_force, wall_torque (a row per wall, in the
        order of walls()); fv2d: h, hu, hv, elevation; two-phase: hs, hsu,
        hsv, hf, hfu, hfv, elevation (grids as [row from north, column from
        west], like the .npy maps); read-only elsewhere. A view is valid
        until the next step."""
        return self._session.arrays()

    def walls(self):
        """The run's walls by name (DEM; {} for other methods): readings now and
        handles that change their motion (see Wall). A change is a line in
        log.txt and goes into checkpoints, so a resumed run keeps it."""
        return {w["name"]: Wall(self, w) for w in self._session.walls()}

    reorders = property(lambda self: self._session.reorders,
                        doc="times the rows of arrays() were reordered or removed since t = 0 "
                            "(DEM: each neighbour build sorts the particles by cell); while "
                            "it stays the same, row i is the same particle")

    def resolved(self):
        """What the method chose, as summary.json's "resolved" will say: the
        time step, the threads; for grids the transform of arrays() (cells_x,
        cells_y, cell_size_m, x_west, y_north: row 0 is the northern row)."""
        return json.loads(self._session.resolved_json())

    def checkpoint(self):
        """Writes the run's checkpoint now, on a series row: series.csv gets
        a row at this time unless one falls here. InputError once complete.
        talus.Run(resume=run.out) continues from the latest checkpoint."""
        self._session.checkpoint()

    def units(self):
        """The SI unit of each array of arrays()."""
        return self._session.units()

    def finish(self):
        """Writes summary.json ("completed" when done, else "stopped") and
        returns {"out", "headline", "warnings"}."""
        if self.result is None:
            self.result = self._session.finish()
        return self.result

    def __enter__(self):
        return self

    def __exit__(self, kind, value, traceback):
        if self.result is None and not self._session.finished:
            self.finish()
        return False


class RunData:
    """A run folder read back: summary (dict of summary.json), series (a
    pandas DataFrame of series.csv, None without one), snapshots (the
    snapshot files' paths in time order), folder."""

    def __init__(self, folder, summary, series, snapshots):
        self.folder, self.summary, self.series, self.snapshots = folder, summary, series, snapshots

    def __repr__(self):
        return (f"RunData({self.folder!r}, status={self.summary.get('status')!r}, "
                f"{0 if self.series is None else len(self.series)} series rows, "
                f"{len(self.snapshots)} snapshots)")


def read_run(folder):
    """Reads a run folder (summary.json, series.csv, snapshots/) into RunData."""
    folder = os.fspath(folder)
    path = os.path.join(folder, "summary.json")
    if not os.path.isfile(path):
        raise InputError(f"{folder}: no summary.json (not a talus run folder, or still running)")
    with open(path) as f:
        summary = json.load(f)
    series = None
    csv = os.path.join(folder, "series.csv")
    if os.path.isfile(csv):
        import pandas
        series = pandas.read_csv(csv)
    shots = os.path.join(folder, "snapshots")
    snapshots = []
    if os.path.isdir(shots):
        snapshots = sorted(os.path.join(shots, name) for name in os.listdir(shots)
                           if not name.endswith(".pvd"))
    return RunData(folder, summary, series, snapshots)


def run(scenario, **kwargs):
    """Runs a scenario to its end (the keywords of Run) and reads it back."""
    with Run(scenario, **kwargs) as r:
        r.run()
    return read_run(r.out)
