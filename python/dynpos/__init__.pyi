# Type stubs of the package dynpos: every keyword argument of every analysis, with its type, so
# that editors complete the names. Units are in the docstrings of dynpos/__init__.py; the
# keyword names are the command line's options (--min-step is min_step). A test checks that
# these names are exactly what each analysis accepts.

import os
from typing import Any, Literal, Mapping, Sequence

import numpy
import numpy.typing

_Path = str | os.PathLike[str]
_Pairs = Mapping[str, Any] | Sequence[str] | str | None
_LogLike = _Path | Log | Any  # a path, a Log or a pandas DataFrame
_Vec3 = tuple[float, float, float] | Sequence[float] | numpy.typing.ArrayLike | str  # X,Y,Z
_Arm = (tuple[float, float] | tuple[float, float, float] | Sequence[float]
        | numpy.typing.ArrayLike | str)  # X,Y[,Z]

__version__: str  # the command's --version

class InputError(ValueError):
    """Bad input: the CLI's message; where it was found, None where not known."""

    file: str | None
    line: int | None
    column: int | None
    option: str | None  # the request key, e.g. "min_step"

class Log:
    """A log: one time axis [s], channels in SI as read-only numpy views (no copy)."""

    input: dict[str, Any]
    origin: Any
    @staticmethod
    def from_arrays(time: numpy.typing.ArrayLike, columns: Mapping[str, numpy.typing.ArrayLike],
                    units: Mapping[str, str] = ...) -> Log: ...
    @staticmethod
    def from_frame(frame: Any, time: str | None = "time",
                   units: Mapping[str, str] | None = None) -> Log: ...
    @property
    def time(self) -> numpy.ndarray: ...
    @property
    def channels(self) -> list[str]: ...
    def __getitem__(self, name: str) -> numpy.ndarray: ...
    def __contains__(self, name: str) -> bool: ...
    def __len__(self) -> int: ...
    def unit(self, name: str) -> str: ...

class Result:
    """A report: attribute access to its fields, to_dict() (the CLI's --json), to_frame()."""

    def __init__(self, data: Mapping[str, Any], table: str | None = None) -> None: ...
    def to_dict(self) -> dict[str, Any]: ...
    def to_frame(self, key: str | None = None) -> Any: ...
    def __getattr__(self, name: str) -> Any: ...
    def __getitem__(self, name: str) -> Any: ...
    def __contains__(self, name: str) -> bool: ...

class Estimate(Result):
    """estimate()'s result: the summary, and the observer's time series in SI."""

    series: Log
    def __init__(self, data: Mapping[str, Any], series: Log) -> None: ...

class Simulation:
    out: str | None
    log: Log
    motion: Log
    truth: dict[str, Any]

def read_log(path: _Path, col: _Pairs = None, unit: _Pairs = None, map: _Path | None = None,
             roles: Sequence[str] | None = None, *, clock_offset: _Pairs = ...,
             max_gap: float = ..., format: Literal["auto", "csv", "nmea", "mcap", "db3"] = ...,
             bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ..., time_format: str = ..., date: str = ...,
             time_order: str = ..., jobs: int = ...) -> Log: ...
def identify_step(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                  map: _Path | None = None, *, json: _Path | None = None,
                  method: Literal["lsq", "smith", "smith2", "rk"] = ...,
                  from_: float | None = ..., to: float | None = ...,
                  step_at: float | None = ..., derive: Literal["", "total-speed"] = ...,
                  min_step: float = ...,
                  min_plateau: float = ..., segments: _Path = ..., clock_offset: _Pairs = ...,
                  max_gap: float = ..., format: str = ..., bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ...,
                  time_format: str = ..., date: str = ..., time_order: str = ..., jobs: int = ...) -> Result: ...
def identify_thrust_map(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                        map: _Path | None = None, *, json: _Path | None = None,
                        out: _Path | None = None, min_speed: float = ..., apply: bool = ...,
                        abs_speed: bool = ..., vessel: _Path = ..., clock_offset: _Pairs = ...,
                        max_gap: float = ..., format: str = ..., bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ...,
                        time_format: str = ..., date: str = ...,
                        time_order: str = ..., jobs: int = ...) -> Result: ...
def identify_agility(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                     map: _Path | None = None, *, json: _Path | None = None,
                     plot: _Path | None = None,
                     window: Sequence[tuple[float, float, float]
                                      | tuple[float, float, float, float]
                                      | tuple[float, float, float, float, float]] = ...,
                     current: tuple[float, float] | None = ...,
                     rpm: bool = ..., min_response: float = ..., min_demand: float = ...,
                     clock_offset: _Pairs = ..., max_gap: float = ..., format: str = ...,
                     bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ..., time_format: str = ..., date: str = ...,
                     time_order: str = ..., jobs: int = ...) -> Result: ...
def identify_four_corner(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                         map: _Path | None = None, *, json: _Path | None = None,
                         plot: _Path | None = None, radius: float = ...,
                         heading_tol: float = ...,
                         segment: Literal["auto", "setpoints", "track"] = ...,
                         arm: Sequence[float] | numpy.ndarray | str | None = ...,
                         from_: float | None = ...,
                         to: float | None = ..., clock_offset: _Pairs = ...,
                         max_gap: float = ..., format: str = ..., bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ...,
                         time_format: str = ..., date: str = ...,
                         time_order: str = ..., jobs: int = ...) -> Result: ...
def identify_vessel(logs: _LogLike | Sequence[_LogLike], col: _Pairs = None,
                    unit: _Pairs = None, map: _Path | None = None, *,
                    out: _Path | None = None, json: _Path | None = None,
                    report: _Path | None = None, vessel: _Path = ..., holdout: str = ...,
                    max_rel_sigma: float = ..., max_rel_sigma_fitted: float = ...,
                    step: float = ..., sample: float = ..., stretch: float = ...,
                    clock_offset: _Pairs = ..., max_gap: float = ..., format: str = ...,
                    bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ..., time_format: str = ..., date: str = ...,
                    time_order: str = ..., jobs: int = ...) -> Result: ...
def compare_trial(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                  map: _Path | None = None, *, json: _Path | None = None,
                  plot: _Path | None = None, vessel: _Path = ..., step: float = ...,
                  sample: float = ..., stretch: float = ..., clock_offset: _Pairs = ...,
                  max_gap: float = ...,
                  format: str = ..., bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ..., time_format: str = ...,
                  date: str = ..., time_order: str = ..., jobs: int = ...) -> Result: ...
def identify_station_keeping(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                             map: _Path | None = None, *, json: _Path | None = None,
                             from_: float | None = ..., to: float | None = ...,
                             duration: float = ..., per_setpoint: bool = ..., waves: str = ...,
                             current: str = ..., clock_offset: _Pairs = ...,
                             max_gap: float = ..., format: str = ..., bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ...,
                             time_format: str = ..., date: str = ...,
                             time_order: str = ..., jobs: int = ...) -> Result: ...
def identify_failure_test(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                          map: _Path | None = None, *, json: _Path | None = None,
                          arm: _Arm | None = ..., rpm: bool = ...,
                          from_: float | None = ..., to: float | None = ...,
                          pre_window: float = ..., redistribution_window: float = ...,
                          hold: float = ..., response_window: float = ...,
                          max_fall: float = ..., min_off: float = ...,
                          clock_offset: _Pairs = ..., max_gap: float = ..., format: str = ...,
                          bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ..., time_format: str = ..., date: str = ...,
                          time_order: str = ..., jobs: int = ...) -> Result: ...
def leverarm_gnss(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                  map: _Path | None = None, *, json: _Path | None = None,
                  plots: _Path | None = None,
                  method: Literal["auto", "ins", "luenberger", "adaptive", "lsq"] = ...,
                  imu: str = ..., imu_arm: _Vec3 | None = ...,
                  accel: Literal["kinematic", "specific-force"] = ...,
                  antennas: Sequence[str] = ..., gnss_log: Mapping[str, _Path] = ...,
                  nmea: Mapping[str, _Path] = ..., utc_at_zero: str | float | None = ...,
                  init: Mapping[str, _Vec3] = ..., w1: _Vec3 | None = ...,
                  w2: _Vec3 | None = ..., gamma: _Vec3 | None = ..., L: _Vec3 | None = ...,
                  init_p0: _Vec3 | None = ..., adaptive_rate: float = ...,
                  lag: int = ..., time_offset: float | None = ...,
                  estimate_time_offset: bool = ..., max_time_offset: float = ...,
                  converged_from: float = ..., pe_window: float = ..., gnss_std: float = ...,
                  clock_offset: _Pairs = ..., max_gap: float = ..., format: str = ...,
                  bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ..., time_format: str = ..., date: str = ...,
                  time_order: str = ..., jobs: int = ...) -> Result: ...
def leverarm_mru(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                 map: _Path | None = None, *, json: _Path | None = None,
                 plots: _Path | None = None, mru_log: Mapping[str, _Path] = ...,
                 reference: str = ..., accel: Literal["kinematic", "specific-force"] = ...,
                 method: Literal["lsq", "observer"] = ..., window_s: float = ...,
                 tau_s: float = ..., w1: float = ..., clock_offset: _Pairs = ...,
                 max_gap: float = ..., format: str = ..., bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ...,
                 time_format: str = ..., date: str = ..., time_order: str = ..., jobs: int = ...) -> Result: ...
def estimate(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
             map: _Path | None = None, *, json: _Path | None = None, out: _Path | None = None,
             vessel: _Path = ..., arm: _Arm | None = ...,
             observer: Literal["ekf", "passive"] = ..., tp: float = ..., rate: float = ...,
             max_hold: float = ..., settle: float = ..., from_: float | None = ...,
             to: float | None = ..., mru: str = ..., clock_offset: _Pairs = ..., max_gap: float = ...,
             format: str = ..., bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ..., time_format: str = ..., date: str = ...,
             time_order: str = ..., jobs: int = ...) -> Estimate: ...
def consequence(log: _LogLike, col: _Pairs = None, unit: _Pairs = None,
                map: _Path | None = None, *, json: _Path | None = None,
                out: _Path | None = None, vessel: _Path = ..., arm: _Arm | None = ...,
                observer: Literal["ekf", "passive"] = ..., tp: float = ..., rate: float = ...,
                max_hold: float = ..., settle: float = ..., from_: float | None = ...,
                to: float | None = ..., mru: str = ..., step: float = ..., window: float = ...,
                clock_offset: _Pairs = ..., max_gap: float = ..., format: str = ...,
                bag_time: Literal["auto", "header", "receive"] = ...,
             msg_path: _Path | Sequence[_Path] = ..., strict: bool = ..., time_format: str = ..., date: str = ...,
                time_order: str = ..., jobs: int = ...) -> Result: ...
def hybrid_case(case: Literal["first-order", "dp"] = "first-order", *,
                json: _Path | None = None, out: _Path | None = None, no_jumps: bool = ...,
                sampled: bool = ..., seed: int = ..., lambda_: float | None = ...,
                dwell: float | None = ..., sample_period: float | None = ...,
                noise_power: float | None = ..., end_time: float | None = ...,
                heading: float | None = ..., ki: float | None = ...,
                solve_p: bool = ...) -> Result: ...
def hybrid_vessel(scenario: Literal["ice", "mooring"], *, json: _Path | None = None,
                  out: _Path | None = None, seed: int = ..., within: float = ...) -> Result: ...
def compare(a: _Path | Result | Mapping[str, Any], b: _Path | Result | Mapping[str, Any], *,
            json: _Path | None = None, format: Literal["text", "markdown"] = ...,
            labels: str | tuple[str, str] | None = ..., step_tolerance: float = ...) -> Result: ...
def capability(*, json: _Path | None = None, out: _Path | None = None,
               level: Literal[1, 2, 3] = ..., vessel: _Path = ...,
               failure: str = ..., site: _Path = ..., hs: float | None = ...,
               tp: float | None = ..., current: float | None = ...,
               direction_step: float = ..., wind_tolerance: float | None = ...,
               duration: float = ..., settle: float = ..., footprint: float = ...,
               footprint_deg: float = ..., seed: int = ..., jobs: int = ...,
               transient: bool = ..., rows: list[int] = ..., after: float = ...,
               seeds: int = ..., observer: Literal["ideal", "passive", "ekf", "raw"] = ...
               ) -> Result: ...
def capability_loads(loads: _Path, *, json: _Path | None = None, vessel: _Path = ...,
                     failure: str = ...) -> Result: ...
def montecarlo(scenario: str, seeds: str | tuple[int, int] = ..., *, json: _Path | None = None,
               jobs: int = ..., measure: Literal["auto", "steps", "station-keeping",
                                                 "lever-arms"] = ...,
               duration: float | None = ..., vessel: _Path = ...,
               shard: str | tuple[int, int] = ...,
               work_dir: _Path = ...) -> Result: ...
def simulate(scenario: str, seed: int = 1, out: _Path | None = None,
             duration: float | None = None, vessel: _Path | None = None,
             log_rate: float | None = None, jobs: int = 0,
             observer: Literal["ideal", "passive", "ekf", "raw"] | None = None
             ) -> Simulation | dict[str, Simulation]: ...
def scenarios() -> dict[str, str]: ...
