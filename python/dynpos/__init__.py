"""dynpos: dynamic positioning of ships — identification, lever arms and the virtual sea trial.

The engine is C++ (the library's application layer); this package calls it in-process, with
numpy arrays in and out. Every analysis takes a log (a path, or a :class:`Log`) and keyword
arguments named like the command line's options (``--min-step`` is ``min_step``, ``--from``
is ``from_``), and returns a :class:`Result` whose ``to_dict()`` is the CLI's ``--json``.
Units are SI unless a name says otherwise. Bad input raises :class:`InputError` (a
``ValueError``) with the message the library gives.
"""

from __future__ import annotations

import json
import os
import tempfile
from typing import Any, Mapping, Sequence

from . import _dynpos
from ._dynpos import InputError, Log

__all__ = ["InputError", "Log", "Result", "Simulation", "read_log", "identify_step",
           "leverarm_gnss", "simulate"]


class Result:
    """A report: attribute access to its fields (``r.steps[0].gain``), ``to_dict()`` (the CLI's
    ``--json`` document) and ``to_frame(key)`` (a list of records as a pandas DataFrame)."""

    def __init__(self, data: Mapping[str, Any]):
        self._data = dict(data)

    def to_dict(self) -> dict:
        return json.loads(json.dumps(self._data))

    def to_frame(self, key: str):
        import pandas  # optional: only to_frame needs it

        return pandas.DataFrame(self._data[key])

    def __getattr__(self, name: str):
        try:
            return _wrap(self._data[name])
        except KeyError:
            raise AttributeError(name) from None

    def __getitem__(self, name: str):
        return _wrap(self._data[name])

    def __dir__(self):
        return sorted(set(self._data) | {"to_dict", "to_frame"})

    def __repr__(self) -> str:
        return f"Result({', '.join(sorted(self._data))})"


def _wrap(value):
    if isinstance(value, dict):
        return Result(value)
    if isinstance(value, list):
        return [_wrap(v) for v in value]
    return value


def _pairs(mapping: Mapping[str, Any] | Sequence[str] | None) -> list[str]:
    """{"role": "column"} or ["role=column"] as the CLI's ROLE=VALUE strings."""
    if mapping is None:
        return []
    if isinstance(mapping, Mapping):
        return [f"{k}={v}" for k, v in mapping.items()]
    return list(mapping)


def _source(log, col=None, unit=None, map=None, **log_options) -> _dynpos.LogSource:
    s = _dynpos.LogSource()
    if isinstance(log, Log):
        s.memory = log
    else:
        s.log = os.fspath(log)
    s.col = _pairs(col)
    s.unit = _pairs(unit)
    if map is not None:
        s.map = os.fspath(map)
    for key, value in log_options.items():
        if key == "clock_offset":
            value = _pairs(value)
        _set(s, key, value)
    return s


_LOG_OPTIONS = ("clock_offset", "max_gap", "format", "strict", "time_format", "date",
                "time_order")


def _set(request, key: str, value) -> None:
    if key.startswith("_") or not hasattr(request, key):
        raise InputError(f"(--{key.rstrip('_').replace('_', '-')}): unknown option '{key}'")
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    try:
        setattr(request, key, value)
    except TypeError as e:
        raise InputError(f"(--{key.rstrip('_').replace('_', '-')}): {e}") from None


def _request(cls, log, col, unit, map, options: Mapping[str, Any]):
    log_options = {k: v for k, v in options.items() if k in _LOG_OPTIONS}
    q = cls()
    q.source = _source(log, col, unit, map, **log_options)
    for key, value in options.items():
        if key not in _LOG_OPTIONS:
            _set(q, key, value)
    return q


def read_log(path, col=None, unit=None, map=None, roles: Sequence[str] | None = None,
             **log_options) -> Log:
    """Reads a log (CSV with a column map, an NMEA 0183 capture, or several files with
    ``col={"role": "column@file"}``) into a :class:`Log` whose channels are numpy float64
    arrays in SI, without copying: ``log["heading"]``, ``log.time``. ``log.input`` describes
    what was read (files, time stamps, skipped lines). ``roles`` limits it to those roles."""
    log, input_json = _dynpos.read_log(_source(path, col, unit, map, **log_options), roles)
    log.input = json.loads(input_json)
    return log


def identify_step(log, col=None, unit=None, map=None, **options) -> Result:
    """Step identification (thesis 3.2): every step of the input and a first-order-plus-dead-
    time fit (``method="lsq"``, ``"smith"``, ``"smith2"``, ``"rk"``) of the output's response.
    Options as ``dynpos identify step``: ``from_``, ``to``, ``step_at`` [s], ``derive``,
    ``min_step`` (input's SI unit), ``min_plateau`` [s], ``segments`` (file)."""
    q = _request(_dynpos.StepRequest, log, col, unit, map, options)
    return Result(json.loads(_dynpos.run_step(q)))


def leverarm_gnss(log, col=None, unit=None, map=None, **options) -> Result:
    """GNSS antenna (and further MRU) lever arms [m, BODY]: from the logger alone by GNSS/INS
    fusion (``method="ins"``, the default with an MRU in the log) or the thesis' estimators
    (``"lsq"``, ``"luenberger"``, ``"adaptive"``). Options as ``dynpos leverarm gnss``:
    ``imu``, ``imu_arm`` ("X,Y,Z" [m]), ``accel``, ``antennas``, ``nmea``/``gnss_log``
    (["gnssK=FILE"]), ``time_offset`` [s], ``max_time_offset`` [s], ``gnss_std`` [m], ..."""
    q = _request(_dynpos.LeverarmGnssRequest, log, col, unit, map, options)
    return Result(json.loads(_dynpos.run_leverarm_gnss(q)))


class Simulation:
    """A virtual sea-trial run: ``log`` (the trial logger, SI), ``truth`` (truth.json as a
    dict), ``motion`` (the true motion and actuator states, truth.csv) and ``out`` (its folder)."""

    def __init__(self, out: str):
        self.out = out
        self.log = read_log(os.path.join(out, "log.csv"))
        truth_csv = os.path.join(out, "truth.csv")
        with open(truth_csv, encoding="utf-8") as f:
            names = [c.split(" [")[0] for c in f.readline().strip().split(",")]
        # The true commands are fractions in truth.csv, percent as a logger's role: left out.
        self.motion = read_log(truth_csv, roles=[n for n in names if not n.startswith("command.")])
        with open(os.path.join(out, "truth.json"), encoding="utf-8") as f:
            self.truth = json.load(f)


def simulate(scenario: str, seed: int = 1, out=None, duration: float | None = None,
             vessel=None, log_rate: float | None = None) -> Simulation:
    """Runs a scenario of the virtual R/V Gunnerus (a built-in name such as
    ``"turning-circle"`` or a .toml file) with a master seed: the same seed gives the same
    log, bit for bit. The files go to ``out`` as ``dynpos simulate --out`` writes them (a
    temporary folder, removed after reading, when not given)."""
    q = _dynpos.SimulateRequest()
    q.scenario = os.fspath(scenario)
    q.seed = seed
    q.duration = duration
    q.log_rate = log_rate
    if vessel is not None:
        q.vessel = os.fspath(vessel)
    if out is not None:
        q.out = os.fspath(out)
        _dynpos.run_simulate(q)
        return Simulation(q.out)
    with tempfile.TemporaryDirectory(prefix="dynpos-") as tmp:
        q.out = tmp
        _dynpos.run_simulate(q)
        return Simulation(tmp)
