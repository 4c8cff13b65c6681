"""dynpos: dynamic positioning of ships — identification, lever arms, control and the virtual
sea trial.

The engine is C++ (the library's application layer); this package calls it in-process, with
numpy arrays in and out. Every analysis takes a log (a path, a :class:`Log` or a pandas
DataFrame) and keyword arguments named like the command line's options (``--min-step`` is
``min_step``, ``--from`` is ``from_``, ``--lambda`` is ``lambda_``), and returns a
:class:`Result` whose ``to_dict()`` is the CLI's ``--json`` document for the same input.
``json=FILE`` and the plot options write the files the CLI writes. Units are SI unless a name
says otherwise. Bad input raises :class:`InputError` (a ``ValueError``) with the message the
CLI prints, and ``file``, ``line``, ``column`` and ``option`` attributes.
"""

from __future__ import annotations

import json as _json
import os
import tempfile
from typing import Any, Mapping, Sequence

from . import _dynpos
from ._dynpos import InputError, Log

__version__: str = _dynpos.__version__

__all__ = [
    "InputError", "Log", "Result", "Estimate", "Simulation", "read_log", "identify_step",
    "identify_thrust_map", "identify_agility", "identify_four_corner",
    "identify_station_keeping", "identify_failure_test", "identify_vessel", "compare_trial",
    "leverarm_gnss", "leverarm_mru",
    "estimate", "consequence", "hybrid_case", "hybrid_vessel", "compare", "capability",
    "capability_loads", "montecarlo", "simulate", "scenarios",
]


class Result:
    """A report: attribute access to its fields (``r.steps[0].K``), ``to_dict()`` (the CLI's
    ``--json`` document) and ``to_frame()`` (its table as a pandas DataFrame)."""

    def __init__(self, data: Mapping[str, Any], table: str | None = None):
        self._data = dict(data)
        self._table = table

    def to_dict(self) -> dict:
        """The document as plain dicts and lists (a deep copy)."""
        return _json.loads(_json.dumps(self._data))

    def to_frame(self, key: str | None = None):
        """The list of records under ``key`` (default: the report's table, e.g. ``steps``) as a
        pandas DataFrame; nested fields become columns such as ``sigma.K``. Needs pandas."""
        import pandas  # optional: only to_frame needs it

        key = key or self._table
        if key is None:
            raise ValueError("this result has no table; name a key holding a list of records")
        return pandas.json_normalize(self._data[key])

    def __getattr__(self, name: str):
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return _wrap(self._data[name])
        except KeyError:
            raise AttributeError(name) from None

    def __getitem__(self, name: str):
        return _wrap(self._data[name])

    def __contains__(self, name: str) -> bool:
        return name in self._data

    def __dir__(self):
        return sorted(set(self._data) | {"to_dict", "to_frame"})

    def __repr__(self) -> str:
        return f"Result({', '.join(sorted(self._data))})"


class Estimate(Result):
    """The result of :func:`estimate`: the summary (``to_dict()`` is the CLI's ``--json``
    document) and ``series``, the observer's time series as a :class:`Log` in SI, named as
    truth.csv names the true motion: ``lf.north``, ``lf.east`` [m], ``lf.heading`` [rad,
    0–2π), ``lf.u``, ``lf.v`` [m/s], ``lf.r`` [rad/s] and the bias b̂ in NED, ``bias.north``,
    ``bias.east`` [N], ``bias.yaw`` [N·m]; one row per observer step. ``to_frame()`` is the
    series as a pandas DataFrame (``time`` [s] first)."""

    def __init__(self, data: Mapping[str, Any], series: Log):
        super().__init__(data)
        self.series = series

    def to_frame(self, key: str | None = None):
        if key is not None:
            return super().to_frame(key)
        import pandas  # optional: only to_frame needs it

        columns = {"time": self.series.time}
        columns.update({name: self.series[name] for name in self.series.channels})
        return pandas.DataFrame(columns)

    def __dir__(self):
        return sorted(set(super().__dir__()) | {"series"})


def _wrap(value):
    if isinstance(value, dict):
        return Result(value)
    if isinstance(value, list):
        return [_wrap(v) for v in value]
    return value


def _log_from_frame(frame, time: str | None = "time", units: Mapping[str, str] | None = None):
    """A log from a pandas DataFrame: the ``time`` column [s] (or, with ``time=None``, the
    index: seconds, or a DatetimeIndex as seconds from its first stamp, kept in ``log.origin``)
    and every other numeric column as a channel named by the column (copied once; NaN stays
    missing). ``units`` gives SI units by column."""
    import numpy
    import pandas

    origin = None
    if time is None:
        index = frame.index
        if isinstance(index, pandas.DatetimeIndex):
            origin = index[0]
            t = (index - origin).total_seconds().to_numpy(dtype=float)
        else:
            t = index.to_numpy(dtype=float)
        columns = frame
    else:
        if time not in frame.columns:
            raise _input_error(f"(time): the DataFrame has no column '{time}'; name the time "
                               "column with time=..., or time=None for the index", "time")
        t = frame[time].to_numpy(dtype=float)
        columns = frame.drop(columns=[time])
    data = {str(name): numpy.asarray(columns[name], dtype=float) for name in columns.columns
            if numpy.issubdtype(columns[name].dtype, numpy.number)}
    log = Log.from_arrays(t, data, dict(units or {}))
    log.origin = origin
    return log


Log.from_frame = staticmethod(_log_from_frame)


def _pairs(mapping: Mapping[str, Any] | Sequence[str] | None, key: str = "col") -> list[str]:
    """{"role": "column"} or ["role=column"] as the CLI's ROLE=VALUE strings."""
    if mapping is None:
        return []
    if isinstance(mapping, Mapping):
        return [f"{k}={v}" for k, v in mapping.items()]
    if isinstance(mapping, str):
        return [mapping]
    if isinstance(mapping, (list, tuple)) and all(isinstance(v, str) for v in mapping):
        return list(mapping)
    raise _input_error(f"({_option_name(key)}): {_type_name(mapping)} is not a dict or a list of "
                       "NAME=VALUE strings; give e.g. {\"input\": \"cmd\"}", key)


def _by_name(value, key: str) -> dict:
    """{"gnss1": VALUE} as it is, or ["gnss1=VALUE"] as that dict; paths as text."""
    if isinstance(value, str):
        value = [value]
    if isinstance(value, (list, tuple)) and all(isinstance(v, str) for v in value):
        pairs = [v.split("=", 1) for v in value]
        if any(len(p) != 2 or not p[0] or not p[1] for p in pairs):
            raise _input_error(f"({_option_name(key)}): expected NAME=VALUE strings or a dict, "
                               f"e.g. {{\"gnss1\": ...}}", key)
        value = dict(pairs)
    if not isinstance(value, Mapping):
        raise _input_error(f"({_option_name(key)}): {_type_name(value)} is not a dict; give e.g. "
                           "{\"gnss1\": ...}", key)
    return {k: os.fspath(v) if isinstance(v, os.PathLike) else v for k, v in value.items()}


def _type_name(value) -> str:
    """"a float", "an int": what a value is, for a message."""
    name = type(value).__name__
    return ("an " if name[:1] in "aeiou" else "a ") + name


# What a request's field takes, from the C++ type pybind11 names in its TypeError.
_TAKES = {"float": "a number", "int": "a whole number", "str": "text", "bool": "True or False",
          "os.PathLike": "a path", "List[str]": "a list of text", "list[str]": "a list of text",
          "List[float]": "a list of numbers", "list[float]": "a list of numbers"}


def _takes(error: TypeError) -> str:
    import re
    m = re.search(r"arg0: ([^)]+)\) -> None", str(error))
    if not m:
        return "another type"
    kind = m.group(1).strip()
    optional = re.fullmatch(r"(?:Optional\[(.*)\]|(.*) \| None)", kind)
    if optional:
        kind = optional.group(1) or optional.group(2)
        return _TAKES.get(kind, kind) + " or None"
    return _TAKES.get(kind, kind)


def _fspath(value, key: str) -> str:
    """A path given as text or an os.PathLike, else an InputError naming the keyword."""
    try:
        return os.fspath(value)
    except TypeError:
        raise _input_error(f"({_option_name(key)}): {_type_name(value)} is not a path; give a "
                           "file name", key) from None


def _is_frame(value) -> bool:
    return type(value).__name__ == "DataFrame" and hasattr(value, "columns")


_LOG_OPTIONS = ("clock_offset", "max_gap", "format", "bag_time", "msg_path", "strict",
                "time_format", "date", "time_order", "jobs")
# Options that take a list of paths, or one path.
_PATH_LIST_OPTIONS = ("msg_path",)
# Options given as ROLE=VALUE (or NAME=FILE) pairs: a dict or a list of strings.
_PAIR_OPTIONS = ("clock_offset",)
# Options taken as a dict by name (gnssK, mruK); a list of "NAME=VALUE" strings is read as one.
_DICT_OPTIONS = ("gnss_log", "nmea", "init", "mru_log")


def _option_name(key: str) -> str:
    """A keyword argument as messages spell it: "min_step=", "from_="."""
    return key + "="


def _input_error(message: str, option: str | None = None) -> InputError:
    """An InputError raised on the Python side, with the attributes the engine's errors have."""
    e = InputError(message)
    e.file, e.line, e.column, e.option = None, None, None, option
    return e


def _set(request, key: str, value) -> None:
    if key.startswith("_") or not hasattr(request, key):
        raise _input_error(f"({_option_name(key)}): unknown option '{key}'", key)
    if key in _PAIR_OPTIONS:
        value = _pairs(value, key)
    elif key in _DICT_OPTIONS:
        value = _by_name(value, key)
    elif key in _PATH_LIST_OPTIONS and isinstance(value, (str, os.PathLike)):
        value = [os.fspath(value)]
    elif isinstance(value, os.PathLike):
        value = os.fspath(value)
    elif isinstance(value, (list, tuple)) and value and isinstance(value[0], os.PathLike):
        value = [os.fspath(v) for v in value]
    try:
        setattr(request, key, value)
    except TypeError as e:
        raise _input_error(f"({_option_name(key)}): {_type_name(value)} is not what it takes: "
                           f"give {_takes(e)}", key) from None


def _source(log, col=None, unit=None, map=None, **log_options) -> _dynpos.LogSource:
    s = _dynpos.LogSource()
    if _is_frame(log):
        log = _log_from_frame(log)
    if isinstance(log, Log):
        s.memory = log
    else:
        try:
            s.log = os.fspath(log)
        except TypeError:
            raise _input_error(f"(log): {_type_name(log)} is not a log; give a path, a Log or a "
                               "pandas DataFrame", "log") from None
    s.col = _pairs(col, "col")
    s.unit = _pairs(unit, "unit")
    if map is not None:
        s.map = _fspath(map, "map")
    for key, value in log_options.items():
        _set(s, key, value)
    return s


def _request(cls, log, col, unit, map, options: Mapping[str, Any]):
    q = cls()
    q.source = _source(log, col, unit, map,
                       **{k: v for k, v in options.items() if k in _LOG_OPTIONS})
    for key, value in options.items():
        if key not in _LOG_OPTIONS:
            _set(q, key, value)
    return q


def _options(cls, options: Mapping[str, Any]):
    q = cls()
    for key, value in options.items():
        _set(q, key, value)
    return q


def _path(value, key: str = "json") -> str:
    return "" if value is None else _fspath(value, key)


def read_log(path, col=None, unit=None, map=None, roles: Sequence[str] | None = None,
             **log_options) -> Log:
    """Reads a log (CSV with a column map, an NMEA 0183 capture, or several files with
    ``col={"role": "column@file"}``) into a :class:`Log` whose channels are numpy float64
    arrays in SI, without copying: ``log["heading"]`` [rad], ``log.time`` [s]. ``log.input``
    describes what was read (files, time stamps, skipped lines). ``roles`` limits it to those
    roles."""
    log, input_json = _dynpos.read_log(_source(path, col, unit, map, **log_options), roles)
    log.input = _json.loads(input_json)
    return log


def identify_step(log, col=None, unit=None, map=None, *, json=None, **options) -> Result:
    """Step identification (thesis 3.2): every step of the input and a first-order-plus-dead-
    time fit (``method="lsq"``, ``"smith"``, ``"smith2"``, ``"rk"``) of the output's response;
    K in output unit per input unit, T and delay [s]. Options as ``dynpos identify step``:
    ``from_``, ``to``, ``step_at`` [s], ``derive`` (``"total-speed"``), ``min_step`` (input's
    SI unit), ``min_plateau`` [s], ``segments`` (file). A method or derived output it does not
    know raises InputError naming the keyword. Table: ``steps``."""
    q = _request(_dynpos.StepRequest, log, col, unit, map, options)
    return Result(_json.loads(_dynpos.run_step(q, _path(json))), "steps")


def identify_thrust_map(log, col=None, unit=None, map=None, *, json=None, out=None,
                        **options) -> Result:
    """Thrust map (3.17): c₊ and c₋ of T = c·n|n| [N/rps²] per thruster from shaft speed and
    thrust, or with ``apply=True`` the vessel file's maps applied to the shaft speeds, written
    to ``out`` (CSV). Options as ``dynpos identify thrust-map``: ``min_speed`` [rpm],
    ``apply``, ``abs_speed``, ``vessel``. Table: ``thrusters``."""
    q = _request(_dynpos.ThrustMapRequest, log, col, unit, map, options)
    doc = _dynpos.run_thrust_map(q, _path(json), _path(out, "out"))
    return Result(_json.loads(doc), "thrusters")


def identify_agility(log, col=None, unit=None, map=None, *, json=None, plot=None,
                     **options) -> Result:
    """Thrust agility (thesis 3.5.1): the time to 63.2 % [s] of every thruster's (and the
    speed's) response after each joystick step. Options as ``dynpos identify agility``:
    ``window`` (a list of (T_STEP, T_END, DIR_DEG[, THRUST_PCT[, YAW_PCT]]) tuples), ``current``
    ((SPEED_MPS, TO_DEG)), ``rpm``, ``min_response`` [%], ``min_demand`` [%]; ``plot`` (SVG).
    Table: ``directions``."""
    q = _request(_dynpos.AgilityRequest, log, col, unit, map, options)
    doc = _dynpos.run_agility(q, _path(json), _path(plot, "plot"))
    return Result(_json.loads(doc), "directions")


def identify_four_corner(log, col=None, unit=None, map=None, *, json=None, plot=None,
                         **options) -> Result:
    """DP 4-corner test (thesis 3.5.2): the legs, their durations [s], accumulated thrust
    [kNs] and energy [kJ]. Options as ``dynpos identify four-corner``: ``radius`` [m],
    ``heading_tol`` [deg], ``segment`` ("auto", "setpoints", "track"), ``arm`` ((X, Y) [m]: a
    tuple, list or numpy array), ``from_``, ``to`` [s]; ``plot`` (SVG). Table: ``legs``."""
    if "arm" in options and isinstance(options["arm"], str):
        options["arm"] = [float(v) for v in options["arm"].split(",")]
    q = _request(_dynpos.FourCornerRequest, log, col, unit, map, options)
    return Result(_json.loads(_dynpos.run_four_corner(q, _path(json), _path(plot, "plot"))), "legs")


def identify_vessel(logs, col=None, unit=None, map=None, *, out=None, json=None, report=None,
                    **options) -> Result:
    """The hull model of a vessel file fitted to logged tests (``dynpos identify vessel``): an
    output-error fit of the simulator's own model driven by each log's thrust and rudder
    feedback to the logged u, v, r. ``logs``: one log per test (paths, Logs or DataFrames; the
    log options apply to each). Options: ``vessel`` (the starting vessel file), ``holdout``
    (the LOG held out and scored, ``"none"``), ``max_rel_sigma``, ``max_rel_sigma_fitted``,
    ``step``, ``sample``, ``stretch`` [s], ``jobs``; ``out`` (the identified vessel file), ``report`` (folder). Table:
    ``parameters`` (``key``, ``value``, ``sigma``, ``determined``; the hull's, the wind's and
    the model's units' dead times and thrust maps); ``units``: each unit's step fits and
    thrust map."""
    if isinstance(logs, (str, os.PathLike, Log)) or _is_frame(logs):
        logs = [logs]
    log_options = {k: v for k, v in options.items() if k in _LOG_OPTIONS}
    q = _dynpos.VesselIdRequest()
    q.logs = [_source(log, col, unit, map, **log_options) for log in logs]
    for key, value in options.items():
        if key not in _LOG_OPTIONS or key == "jobs":
            _set(q, key, value)
    doc = _dynpos.run_vessel_id(q, _path(out, "out"), _path(json), _path(report, "report"))
    return Result(_json.loads(doc), "parameters")


def compare_trial(log, col=None, unit=None, map=None, *, json=None, plot=None,
                  **options) -> Result:
    """One logged test re-simulated with its logged feedback and a vessel file
    (``dynpos compare-trial``): NRMSE of u, v, r and of the track. Options: ``vessel``,
    ``step``, ``sample``, ``stretch`` [s]; ``plot`` (SVG)."""
    q = _request(_dynpos.CompareTrialRequest, log, col, unit, map, options)
    return Result(_json.loads(_dynpos.run_compare_trial(q, _path(json), _path(plot, "plot"))))


def identify_station_keeping(log, col=None, unit=None, map=None, *, json=None,
                             **options) -> Result:
    """Stationkeeping (thesis 3.5.3): position and heading deviations [m, deg], thrust and power
    over a window, or per setpoint hold. Options as ``dynpos identify station-keeping``:
    ``from_``, ``to``, ``duration`` [s], ``per_setpoint``, ``waves``, ``current`` (as observed).
    Table: ``windows``."""
    q = _request(_dynpos.StationKeepingRequest, log, col, unit, map, options)
    return Result(_json.loads(_dynpos.run_station_keeping(q, _path(json))), "windows")


def identify_failure_test(log, col=None, unit=None, map=None, *, json=None,
                          **options) -> Result:
    """Thruster failure test (DP annual trials, IMCA M 190; FMEA proving trials): each trip
    found in the units' feedback (``thrust.NAME``, else ``rpm.NAME``) with the control origin's
    peak excursion from its pre-failure mean [m], time to peak [s], recovery [s] (back within
    the pre-failure footprint for ``hold``; None if never), peak heading change [deg] and the
    other units' redistribution. Roles: time; north, east [m] or lat, lon; heading; roll, pitch
    (with an arm's Z). Options as ``dynpos identify failure-test``: ``arm`` ((X, Y) or (X, Y, Z)
    [m], BODY, of the antenna whose position is logged: a tuple, list, numpy array or "X,Y,Z"),
    ``rpm``, ``from_``, ``to``, ``pre_window``, ``redistribution_window``, ``hold``,
    ``response_window``, ``max_fall``, ``min_off`` [s]. Table: ``events``."""
    q = _request(_dynpos.FailureTestRequest, log, col, unit, map, options)
    return Result(_json.loads(_dynpos.run_failure_test(q, _path(json))), "events")


def leverarm_gnss(log, col=None, unit=None, map=None, *, json=None, plots=None,
                  **options) -> Result:
    """GNSS antenna (and further MRU) lever arms [m, BODY]: from the logger alone by GNSS/INS
    fusion (``method="ins"``, the default with an MRU in the log) or the thesis' estimators
    (``"lsq"``, ``"luenberger"``, ``"adaptive"``). Options as ``dynpos leverarm gnss``:
    ``imu``, ``imu_arm`` ((X, Y, Z) [m]: a tuple, list or numpy array), ``accel``
    ("kinematic", "specific-force"), ``antennas``, ``nmea``/``gnss_log`` ({"gnssK": FILE}),
    ``utc_at_zero`` ("HH:MM:SS" or seconds of the UTC day), ``init`` ({"gnssK": (X, Y, Z)}),
    ``w1``, ``w2``, ``gamma``, ``L``, ``init_p0`` ((X, Y, Z)), ``time_offset`` [s],
    ``max_time_offset`` [s], ``gnss_std`` [m], ...; ``plots`` (folder). Table: ``arms``."""
    q = _request(_dynpos.LeverarmGnssRequest, log, col, unit, map, options)
    doc = _dynpos.run_leverarm_gnss(q, _path(json), _path(plots, "plots"))
    return Result(_json.loads(doc), "arms")


def leverarm_mru(log, col=None, unit=None, map=None, *, json=None, plots=None,
                 **options) -> Result:
    """MRU lever arms [m, BODY] from the MRUs' accelerations (thesis 4.3): least squares or the
    observer. Options as ``dynpos leverarm mru``: ``mru_log`` ({"mruK": FILE}), ``reference``
    ("mruK": the other MRUs' arms from it, no velocity needed), ``accel``,
    ``method`` ("lsq", "observer"), ``window_s``, ``tau_s`` [s], ``w1`` [1/s]; ``plots``
    (folder). Table: ``arms``."""
    q = _request(_dynpos.LeverarmMruRequest, log, col, unit, map, options)
    doc = _dynpos.run_leverarm_mru(q, _path(json), _path(plots, "plots"))
    return Result(_json.loads(doc), "arms")


def estimate(log, col=None, unit=None, map=None, *, json=None, out=None,
             **options) -> Estimate:
    """The DP observer run over a logged DP run, as the DP system's own would have run: the
    low-frequency motion and the bias b̂ (the environmental load the thrusters held against,
    NED) as a time series (:class:`Estimate` ``series``, SI), and b̂'s mean and spread after
    ``settle``. Roles: time; north, east [m] or lat, lon; heading; roll, pitch (with an arm's
    Z); per unit of the vessel ``thrust.NAME`` and its ``rudder.NAME`` or ``azimuth.NAME``.
    Options as ``dynpos estimate``: ``vessel`` (file), ``arm`` ((X, Y) or (X, Y, Z) [m]),
    ``observer`` ("ekf", "passive"), ``tp`` [s] (the wave peak period the wave model is set
    for), ``rate`` [Hz], ``max_hold``, ``settle``, ``from_``, ``to`` [s], ``mru`` (the MRU a
    GNSS gap is bridged on: "auto", "none" or its name); ``out`` (the series'
    CSV as the CLI writes it: deg, kN)."""
    q = _request(_dynpos.EstimateRequest, log, col, unit, map, options)
    doc, series = _dynpos.run_estimate(q, _path(json), _path(out, "out"))
    return Estimate(_json.loads(doc), series)


def consequence(log, col=None, unit=None, map=None, *, json=None, out=None,
                **options) -> Result:
    """Consequence analysis (DNV-RU-SHIP Pt.6 Ch.3) along a logged DP run: every ``step`` the
    observer's b̂ (as :func:`estimate`), averaged over ``window`` and taken into BODY at the
    estimated heading, is the load; for each single failure of the vessel the largest factor λ
    of it the remaining thrusters hold, and the margin λ − 1 of the worst case (negative:
    position would have been lost). Options: those of :func:`estimate`, and ``step``,
    ``window`` [s]; ``out`` (the points' CSV). Table: ``per_case``."""
    q = _request(_dynpos.ConsequenceRequest, log, col, unit, map, options)
    doc = _dynpos.run_consequence(q, _path(json), _path(out, "out"))
    return Result(_json.loads(doc), "per_case")


def hybrid_case(case: str = "first-order", *, json=None, out=None, **options) -> Result:
    """A hybrid integral action case study (thesis 5.3): ``"first-order"`` (5.3.1) or
    ``"dp"`` (5.3.2), the hybrid run against the conventional one. Options as ``dynpos hybrid
    CASE``: ``no_jumps``, ``sampled``, ``seed``, ``lambda_``, ``dwell`` [s], ``sample_period``
    [s], ``noise_power``, ``end_time`` [s], ``heading`` [deg] (dp), ``ki`` [1/s²] and
    ``solve_p`` (first-order); ``out`` (folder for the plots)."""
    q = _options(_dynpos.HybridCaseRequest, {"case": case, **options})
    return Result(_json.loads(_dynpos.run_hybrid_case(q, _path(json), _path(out, "out"))))


def hybrid_vessel(scenario: str, *, json=None, out=None, **options) -> Result:
    """Hybrid against conventional integral action on the virtual Gunnerus under a sudden load
    (``"ice"`` or ``"mooring"``): peak offset [m], time back within ``within`` [m], IAE,
    energy and jumps. Options as ``dynpos hybrid vessel``: ``seed``, ``within`` [m]; ``out``
    (folder for the plots)."""
    q = _options(_dynpos.HybridVesselRequest, {"scenario": scenario, **options})
    return Result(_json.loads(_dynpos.run_hybrid_vessel(q, _path(json), _path(out, "out"))))


def compare(a, b, *, json=None, **options) -> Result:
    """Two results of the same analysis side by side (e.g. before and after a retrofit): each
    figure of A and B with its change. ``a`` and ``b`` are JSON files written by an analysis,
    or :class:`Result` objects / dicts (written to a temporary file first). Options as
    ``dynpos compare``: ``format`` ("text", "markdown"), ``labels`` ("LABEL_A,LABEL_B" or
    (LABEL_A, LABEL_B)), ``step_tolerance`` [s].
    Table: ``rows``."""
    with tempfile.TemporaryDirectory(prefix="dynpos-") as tmp:
        paths = []
        for name, value in (("A", a), ("B", b)):
            if isinstance(value, (Result, dict)):
                path = os.path.join(tmp, f"{name}.json")
                data = value.to_dict() if isinstance(value, Result) else value
                with open(path, "w", encoding="utf-8") as f:
                    _json.dump(data, f)
                value = path
            paths.append(_fspath(value, name.lower()))
        q = _options(_dynpos.CompareRequest, {"a": paths[0], "b": paths[1], **options})
        return Result(_json.loads(_dynpos.run_compare(q, _path(json))), "rows")


def capability(*, json=None, out=None, **options) -> Result:
    """DP capability after DNV-ST-0111: per direction of the weather (off the bow, clockwise)
    the DP capability number and the strongest wind held [m/s], intact and after single
    failures. Options as ``dynpos capability``: ``level`` (1 the standard's table at rated
    thrust, 2 the model's thrust losses and a ``site`` table or fixed ``hs`` [m], ``tp`` [s],
    ``current`` [m/s], 3 time-domain runs), ``vessel`` (file), ``failure`` ("worst", "none", an
    actuator of the model, or a unit or "group:NAME" of a ``[[thruster]]`` layout), ``direction_step`` [deg], ``wind_tolerance`` [m/s]; level 3: ``duration``,
    ``settle`` [s], ``footprint`` [m], ``footprint_deg`` [deg], ``seed``, ``jobs``; ``out``
    (folder for rose.svg). ``transient=True`` (level 3, a named ``failure``): the failure as it
    happens, as ``dynpos capability --transient``, with ``rows`` (weather rows, DP numbers),
    ``after`` [s], ``seeds`` and ``observer`` ("ideal", "passive", "ekf" or "raw"); per direction
    and row the largest excursion after the failure and the time to it (``out``: footprint.svg).
    Table: ``points``."""
    q = _options(_dynpos.CapabilityRequest, options)
    given = [name.replace("_", "-") for name in options]
    doc = _dynpos.run_capability(q, given, _path(json), _path(out, "out"))
    return Result(_json.loads(doc), "points")


def capability_loads(loads, *, json=None, **options) -> Result:
    """For each environmental load of a table (CSV: direction_deg, X_N, Y_N, N_Nm in BODY), the
    largest factor held by the vessel's thruster layout and the limiting units, as ``dynpos
    capability --loads``. Options: ``vessel`` (file; its [[thruster]] units, else the model's),
    ``failure`` ("worst", "none", a unit's name or "group:NAME"). Table: ``points``."""
    q = _options(_dynpos.FeasibilityRequest, {"loads": _fspath(loads, "loads"), **options})
    return Result(_json.loads(_dynpos.run_feasibility(q, _path(json))), "points")


def montecarlo(scenario: str, seeds: str | tuple[int, int] = (1, 10), *, json=None,
               **options) -> Result:
    """A scenario of the virtual sea trial run for many seeds, each seed's logger files
    analysed as a user's, and the spread of every identified quantity against truth: how far a
    sea-trial result can be trusted. ``seeds``: "A..B" or (A, B), inclusive. Options as
    ``dynpos montecarlo``: ``jobs`` (seeds at once, 0 = every core; the result does not depend
    on it), ``measure`` ("auto", "steps", "station-keeping" or "lever-arms"), ``duration`` [s],
    ``vessel`` (file), ``shard`` ((i, N) or "i/N": this part of the seeds, for ``dynpos
    montecarlo merge``), ``work_dir`` (where each seed's files go; default temporary). Table:
    ``summary`` (quantity: n, mean, std, min, max, truth, bias, rms_error); ``samples`` per
    seed."""
    q = _options(_dynpos.MonteCarloRequest, {"seeds": seeds, **options})
    q.scenario = _fspath(scenario, "scenario")
    return Result(_json.loads(_dynpos.run_montecarlo(q, _path(json))), "summary")


class Simulation:
    """A virtual sea-trial run: ``log`` (the trial logger, SI), ``truth`` (truth.json as a
    dict), ``motion`` (every column of truth.csv, SI: the true motion and actuator states, and
    in DP runs ``lf.*``, ``env_load.*``, ``demand.*`` and with an observer ``observer.*``;
    commands and levers as fractions) and ``out`` (its folder, None when it was temporary)."""

    def __init__(self, folder: str, out: str | None):
        self.out = out
        self.log = read_log(os.path.join(folder, "log.csv"))
        self.motion = _dynpos.read_csv_all(os.path.join(folder, "truth.csv"))
        with open(os.path.join(folder, "truth.json"), encoding="utf-8") as f:
            self.truth = _json.load(f)


def simulate(scenario: str, seed: int = 1, out=None, duration: float | None = None,
             vessel=None, log_rate: float | None = None, jobs: int = 0,
             observer: str | None = None):
    """Runs a scenario of the virtual R/V Gunnerus (a built-in name such as
    ``"turning-circle"``, see :func:`scenarios`, or a .toml file) with a master seed: the same
    seed gives the same log, bit for bit (``jobs``: campaign runs at once, 0 = every core). The files go to ``out`` as ``dynpos simulate --out``
    writes them (a temporary folder, removed after reading, when not given). ``observer``
    (DP scenarios): what the DP controller runs on, ``"ideal"`` (the true low-frequency
    motion), ``"passive"``, ``"ekf"`` or ``"raw"``; None: the scenario's. Returns a
    :class:`Simulation`; for ``"campaign"`` a dict of them by scenario name."""
    q = _dynpos.SimulateRequest()
    q.scenario = _fspath(scenario, "scenario")
    for key, value in (("seed", seed), ("duration", duration), ("log_rate", log_rate),
                       ("jobs", jobs), ("observer", observer)):
        _set(q, key, value)
    if vessel is not None:
        q.vessel = _fspath(vessel, "vessel")

    def run(folder: str, keep: bool):
        q.out = folder
        runs = {name: Simulation(os.fspath(path), os.fspath(path) if keep else None)
                for name, path in _dynpos.run_simulate(q)}
        return runs if q.scenario == "campaign" else next(iter(runs.values()))

    if out is not None:
        return run(_fspath(out, "out"), True)
    with tempfile.TemporaryDirectory(prefix="dynpos-") as tmp:
        return run(tmp, False)


def scenarios() -> dict[str, str]:
    """The built-in scenarios of the virtual sea trial: {name: description}."""
    return dict(_dynpos.scenarios())
