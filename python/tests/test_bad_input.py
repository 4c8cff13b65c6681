"""Bad input through the Python API: the CLI's bad-input cases (tests/cli), each run both ways.
The CLI exits 2 with "dynpos: error: MESSAGE"; the API raises dynpos.InputError (a ValueError)
whose text is that MESSAGE, with the file, line and option as attributes, and the interpreter
carries on. (Cases the CLI's own argument parser rejects, such as a missing file it checks or an
option the subcommand does not have, are not library errors and are left out.)"""

import os
import subprocess

import pytest

import dynpos

BIN = os.environ.get("DYNPOS_BIN", "dynpos")
SOURCE = os.environ.get("DYNPOS_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
CLI_DIR = os.path.join(SOURCE, "tests", "cli")
STEPS = os.path.join(CLI_DIR, "short_steps.csv")
COMPARE = os.path.join(CLI_DIR, "data", "compare")
NMEA = os.path.join(SOURCE, "tests", "data", "nmea")
MULTI = os.path.join(SOURCE, "tests", "data", "multifile")

FLAGS = {"--strict", "--per-setpoint", "--apply", "--abs-speed", "--rpm", "--no-jumps",
         "--sampled", "--solve-p", "--estimate-time-offset"}
REPEATED = {"--col", "--unit", "--window", "--clock-offset", "--gnss-log", "--nmea",
            "--mru-log", "--init"}
FUNCTIONS = {("identify", "step"): dynpos.identify_step,
             ("identify", "thrust-map"): dynpos.identify_thrust_map,
             ("identify", "agility"): dynpos.identify_agility,
             ("identify", "four-corner"): dynpos.identify_four_corner,
             ("identify", "station-keeping"): dynpos.identify_station_keeping,
             ("identify", "failure-test"): dynpos.identify_failure_test,
             ("leverarm", "gnss"): dynpos.leverarm_gnss,
             ("leverarm", "mru"): dynpos.leverarm_mru}

STEP_COLS = ["--col", "input=cmd", "--col", "output=response"]
SK_COLS = ["--col", "north=response", "--col", "east=response"]
THRUST = ["--col", "thrust.port=response", "--unit", "thrust.port=kN"]
HEADING = ["--col", "heading=flat", "--unit", "heading=rad"]
CASES = [
    ["identify", "step", STEPS, "--col", "input=cmd", "--col", "output=no_such_column"],
    ["identify", "step", os.path.join(CLI_DIR, "bad_steps.csv"), *STEP_COLS],
    ["identify", "step", STEPS, *STEP_COLS, "--segments", os.path.join(CLI_DIR, "bad_segments.csv")],
    ["identify", "step", STEPS, *STEP_COLS, "--method", "fast"],
    ["identify", "step", STEPS, *STEP_COLS, "--min-plateau", "-1"],
    ["identify", "agility", STEPS],
    ["identify", "agility", STEPS, *THRUST],
    ["identify", "agility", STEPS, *THRUST, "--window", "10,5000,90"],
    ["identify", "four-corner", STEPS, "--col", "north=response", "--col", "east=response"],
    ["identify", "four-corner", STEPS, "--col", "north=response", "--col", "east=response",
     "--col", "heading=flat", "--unit", "heading=rad", "--segment", "box"],
    ["identify", "four-corner", STEPS, "--col", "north=response", "--col", "east=response",
     "--col", "heading=flat", "--unit", "heading=rad", "--from", "5000"],
    ["identify", "station-keeping", STEPS],
    ["identify", "station-keeping", STEPS, *SK_COLS, "--from", "100", "--to", "400"],
    ["identify", "station-keeping", STEPS, *SK_COLS, "--from", "50", "--to", "10"],
    ["identify", "station-keeping", STEPS, *SK_COLS, "--from", "50", "--to", "100"],
    ["identify", "four-corner", STEPS, "--col", "north=response", "--col", "east=response",
     "--col", "heading=flat", "--unit", "heading=rad", "--from", "50", "--to", "10"],
    ["identify", "station-keeping", STEPS, *SK_COLS, "--per-setpoint"],
    ["identify", "station-keeping", STEPS, *SK_COLS, "--time-format", "iso"],
    ["identify", "station-keeping", STEPS, *SK_COLS, "--date", "2024-02-30"],
    ["identify", "station-keeping", STEPS, *SK_COLS, "--time-format", "time-of-day"],
    ["identify", "station-keeping", os.path.join(NMEA, "station.nmea"), "--strict"],
    ["identify", "station-keeping", os.path.join(NMEA, "nothing.nmea")],
    ["identify", "station-keeping", os.path.join(NMEA, "station.nmea"), "--format", "xml"],
    ["identify", "station-keeping", os.path.join(NMEA, "station.nmea"), "--col", "heading=HDT"],
    ["identify", "station-keeping", os.path.join(MULTI, "main.csv"), "--col",
     f"heading=HEADING@{MULTI}/nav.csv", "--col", f"time=stamp@{MULTI}/nav.csv"],
    ["identify", "station-keeping", os.path.join(MULTI, "main.csv"), "--col",
     f"heading=HDG@{MULTI}/nav.csv", "--col", f"time=stamp@{MULTI}/nav.csv"],
    ["identify", "thrust-map", STEPS],
    ["identify", "thrust-map", STEPS, "--apply"],
    ["identify", "failure-test", STEPS, *SK_COLS],
    ["identify", "failure-test", STEPS, *THRUST],
    ["identify", "failure-test", STEPS, *THRUST, *SK_COLS, "--arm", "1,0"],
    ["identify", "failure-test", STEPS, *THRUST, "--hold", "-1"],
    ["identify", "failure-test", STEPS, *THRUST, *SK_COLS, "--from", "50", "--to", "10"],
    ["estimate", STEPS, "--observer", "kalman"],
    ["estimate", STEPS, "--tp", "30"],
    ["estimate", STEPS, *SK_COLS],
    ["estimate", STEPS, *SK_COLS, *HEADING],
    ["consequence", STEPS, "--step", "0"],
    ["consequence", STEPS, "--window", "-1"],
    ["consequence", STEPS, *SK_COLS, *HEADING, *THRUST],
    ["leverarm", "mru", STEPS, "--accel", "gravity"],
    ["leverarm", "mru", STEPS],
    ["leverarm", "gnss", STEPS, "--method", "lsq"],
    ["leverarm", "gnss", STEPS, "--imu-arm", "1,2"],
    ["compare", os.path.join(COMPARE, "steps_aug.json"), os.path.join(COMPARE, "legs_after.json")],
    ["compare", os.path.join(COMPARE, "steps_aug.json"), os.path.join(COMPARE, "broken.json")],
    ["compare", os.path.join(COMPARE, "generic_a.json"), os.path.join(COMPARE, "generic_b.json")],
    ["compare", os.path.join(COMPARE, "steps_aug.json"), os.path.join(COMPARE, "steps_nov.json"),
     "--labels", "only one"],
    ["hybrid", "first-order", "--lambda", "-1"],
    ["hybrid", "first-order", "--ki", "30"],
    ["hybrid", "dp", "--sample-period", "0.0305"],
    ["hybrid", "dp", "--no-jumps", "--sampled"],
    ["hybrid", "vessel", "--scenario", "ice2"],
    ["hybrid", "vessel", "--scenario", "ice", "--within", "0"],
    ["capability", "--level", "4"],
    ["capability", "--failure", "bow"],
    ["capability", "--hs", "2"],
    ["capability", "--direction-step", "7"],
    ["simulate", "no-such-test", "--out", "unused"],
    ["simulate", "pure-dp", "--observer", "kalman", "--out", "unused"],
    ["simulate", "surge-steps-forward", "--duration", "-5", "--out", "unused"],
    ["simulate", "surge-steps-forward", "--duration", "5", "--out", "unused", "--vessel",
     os.path.join(CLI_DIR, "bad_sensor_rate.toml")],
    ["simulate", "surge-steps-forward", "--out", "unused", "--vessel",
     os.path.join(CLI_DIR, "bad_vessel.toml")],
]


def number(text: str):
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def options(argv):
    """CLI options as the API's keyword arguments: --min-step 1 → min_step=1."""
    kwargs, i = {}, 0
    while i < len(argv):
        flag = argv[i]
        key = flag[2:].replace("-", "_")
        key = {"from": "from_", "lambda": "lambda_"}.get(key, key)
        if flag in FLAGS:
            kwargs[key] = True
            i += 1
            continue
        value = argv[i + 1]
        if flag == "--window" and "," in value:  # agility's: each window a tuple of numbers
            kwargs.setdefault(key, []).append(tuple(float(v) for v in value.split(",")))
        elif flag in REPEATED and flag != "--window":  # consequence's --window: a number
            kwargs.setdefault(key, []).append(value)
        else:
            kwargs[key] = number(value) if key not in ("labels", "date") else value
        if key in ("imu_arm", "arm"):  # a vector: the API takes the numbers, (1, 2) for "1,2"
            kwargs[key] = tuple(number(v) for v in value.split(","))
        i += 2
    return kwargs


def keyword(key: str) -> str:
    """A request key as the API's message names it: min_step=, from_=, col={'output': COLUMN}."""
    if ":" in key:
        kind, role = key.split(":", 1)
        return f"{kind}={{'{role}': {'COLUMN' if kind == 'col' else 'UNIT'}}}"
    return key + ("_=" if key in ("from", "lambda") else "=")


def flag(key: str) -> str:
    """The same key as the CLI's message names it: --min-step, --col output=COLUMN."""
    if ":" in key:
        kind, role = key.split(":", 1)
        return f"--{kind} {role}={'COLUMN' if kind == 'col' else 'UNIT'}"
    return "--" + key.replace("_", "-")


def as_cli_prints(error) -> str:
    """The API's message with its option spelled as the command line's: the one difference
    between the two front ends' messages."""
    text = str(error)
    if error.option:
        api = "/".join(keyword(k) for k in error.option.split("/"))
        cli = "/".join(flag(k) for k in error.option.split("/"))
        assert f"({api})" in text, text
        text = text.replace(f"({api})", f"({cli})", 1)
    return text


def call_api(argv, tmp_path):
    if argv[0] == "compare":
        return dynpos.compare(argv[1], argv[2], **options(argv[3:]))
    if argv[0] == "hybrid" and argv[1] == "vessel":
        o = options(argv[2:])
        return dynpos.hybrid_vessel(o.pop("scenario"), **o)
    if argv[0] == "hybrid":
        return dynpos.hybrid_case(argv[1], **options(argv[2:]))
    if argv[0] in ("estimate", "consequence"):
        return getattr(dynpos, argv[0])(argv[1], **options(argv[2:]))
    if argv[0] == "capability":
        return dynpos.capability(**options(argv[1:]))
    if argv[0] == "simulate":
        o = options(argv[2:])
        o["out"] = tmp_path / "run"
        return dynpos.simulate(argv[1], **o)
    return FUNCTIONS[(argv[0], argv[1])](argv[2], **options(argv[3:]))


@pytest.mark.parametrize("argv", CASES, ids=[" ".join(os.path.basename(str(a)) for a in c[:4])
                                             for c in CASES])
def test_the_api_raises_what_the_cli_prints(argv, tmp_path):
    argv = [a.replace("unused", str(tmp_path / "run")) for a in argv]
    cli = subprocess.run([BIN, *argv], capture_output=True, text=True)
    assert cli.returncode == 2, cli.stderr
    with pytest.raises(dynpos.InputError) as e:
        call_api(argv, tmp_path)
    assert isinstance(e.value, ValueError)
    assert cli.stderr == f"dynpos: error: {as_cli_prints(e.value)}\n"
    assert not (tmp_path / "run" / "log.csv").exists()


def test_the_error_says_where():
    with pytest.raises(dynpos.InputError) as e:
        dynpos.identify_step(os.path.join(CLI_DIR, "bad_steps.csv"),
                             col={"input": "cmd", "output": "response"})
    assert e.value.file.endswith("bad_steps.csv") and e.value.line == 5
    assert e.value.option is None
    with pytest.raises(dynpos.InputError) as e:
        dynpos.identify_step(STEPS, col={"input": "cmd", "output": "response"}, min_step=-1.0)
    assert e.value.option == "min_step" and "(min_step=)" in str(e.value)


def test_errors_raised_in_python_have_the_same_attributes(tmp_path):
    with pytest.raises(dynpos.InputError) as e:
        dynpos.identify_step(STEPS, min_stepp=1.0)
    assert e.value.option == "min_stepp" and e.value.file is None and e.value.line is None
    not_a_folder = tmp_path / "rose"
    not_a_folder.write_text("")
    with pytest.raises(dynpos.InputError, match=r"\(out=\): '.*rose' exists and is not a folder"):
        dynpos.capability(direction_step=90, out=not_a_folder)


STEP_COL = {"input": "cmd", "output": "response"}


@pytest.mark.parametrize("time", [[0.0, 1.0, 1.0], [0.0, 2.0, 1.0], [0.0, float("nan"), 2.0],
                                  [0.0, float("inf"), 2.0]],
                         ids=["repeated", "backwards", "nan", "inf"])
def test_a_log_from_arrays_needs_finite_increasing_time(time):
    import numpy as np
    with pytest.raises(dynpos.InputError, match=r"^\(time\): row [12] ") as e:
        dynpos.Log.from_arrays(np.array(time), {"x": np.zeros(3)})
    assert e.value.line is None and e.value.file is None


def test_a_log_from_a_frame_needs_finite_increasing_time():
    pandas = pytest.importorskip("pandas")
    frame = pandas.DataFrame({"time": [0.0, 1.0, 1.0], "x": [1.0, 2.0, 3.0]})
    with pytest.raises(dynpos.InputError, match=r"^\(time\): row 2 \(1 s\) is the same time"):
        dynpos.Log.from_frame(frame)


def test_an_infinite_value_is_refused_and_nan_is_missing():
    import numpy as np
    with pytest.raises(dynpos.InputError, match=r"^\(x\): row 2 of column 'x' is -inf"):
        dynpos.Log.from_arrays(np.arange(3.0), {"x": np.array([0.0, 1.0, -np.inf])})
    log = dynpos.Log.from_arrays(np.arange(3.0), {"x": np.array([0.0, np.nan, 1.0])})
    assert np.isnan(log["x"][1])


@pytest.mark.parametrize("call, keyword", [
    (lambda: dynpos.Log.from_arrays([0.0, 1.0], 5), "columns"),
    (lambda: dynpos.Log.from_arrays([0.0, 1.0], {"x": [1.0, 2.0]}, units=["m"]), "units"),
    (lambda: dynpos.Log.from_arrays([0.0, 1.0], {3: [1.0, 2.0]}), "columns"),
    (lambda: dynpos.Log.from_arrays("abc", {}), "time"),
    (lambda: dynpos.identify_step(5, col=STEP_COL), "log"),
    (lambda: dynpos.identify_step(STEPS, col=5), "col"),
    (lambda: dynpos.identify_step(STEPS, col=STEP_COL, json=5), "json"),
    (lambda: dynpos.identify_step(STEPS, col=STEP_COL, min_step="big"), "min_step"),
    (lambda: dynpos.capability(direction_step="ten"), "direction_step"),
    (lambda: dynpos.capability(out=3.5), "out"),
    (lambda: dynpos.simulate("surge-steps-forward", seed="one"), "seed"),
], ids=["columns", "units", "column-name", "time", "log", "col", "json", "min_step",
        "direction_step", "out", "seed"])
def test_a_wrong_type_is_an_input_error_naming_the_keyword(call, keyword):
    with pytest.raises(dynpos.InputError) as e:
        call()
    assert e.value.option == keyword or f"({keyword})" in str(e.value), str(e.value)
    assert "incompatible" not in str(e.value) and "arg0" not in str(e.value), str(e.value)


def test_an_output_in_a_folder_that_takes_no_file_is_an_input_error():
    with pytest.raises(dynpos.InputError, match=r"\(json=\): cannot write in folder '/proc'") as e:
        dynpos.identify_step(STEPS, col=STEP_COL, json="/proc/x.json")
    assert e.value.option == "json"


@pytest.mark.parametrize("tolerance", [1e-300, 0.0, 11.0, float("inf")])
def test_the_wind_tolerance_has_a_range(tolerance):
    with pytest.raises(dynpos.InputError, match=r"\(wind_tolerance=\): the wind tolerance must "
                       r"be from 1e-06 to 10 m/s") as e:
        dynpos.capability(direction_step=90, wind_tolerance=tolerance)
    assert e.value.option == "wind_tolerance"


def test_leverarm_takes_typed_arguments_and_names_a_bad_one():
    """Vectors as tuples or numpy arrays, enums by name; a bad name or a vector of two numbers
    raises InputError naming the keyword."""
    import numpy as np
    q = dynpos._dynpos.LeverarmGnssRequest()
    q.imu_arm = np.array([0.358, 0.804, -4.321])
    assert tuple(q.imu_arm) == (0.358, 0.804, -4.321)
    q.imu_arm = (1, 2, 3)
    q.init = {"gnss1": [0.2, -0.6, -13.9]}
    assert tuple(q.init["gnss1"]) == (0.2, -0.6, -13.9)
    q.method = "Luenberger"
    q.accel = "specific-force"
    assert (q.method, q.accel) == ("luenberger", "specific-force")
    q.utc_at_zero = "10:00:01.5"
    assert q.utc_at_zero == 36001.5
    for function, key, value, text in [
            (dynpos.leverarm_mru, "accel", "gravity", "unknown acceleration convention 'gravity'"),
            (dynpos.leverarm_mru, "method", "kalman", "unknown method 'kalman'"),
            (dynpos.leverarm_gnss, "method", "fast", "unknown method 'fast'"),
            (dynpos.leverarm_gnss, "imu_arm", (1, 2), "'1,2' is not three numbers X,Y,Z"),
            (dynpos.leverarm_gnss, "w1", np.array([1.0, np.nan, 1.0]), "is not three numbers"),
            (dynpos.leverarm_gnss, "utc_at_zero", "25:00", "is not a UTC time")]:
        with pytest.raises(dynpos.InputError) as e:
            function(STEPS, **{key: value})
        assert e.value.option == key, (key, str(e.value))
        assert f"({key}=): " in str(e.value) and text in str(e.value), str(e.value)
    with pytest.raises(dynpos.InputError) as e:
        dynpos.leverarm_gnss(STEPS, init={"gnss1": (1, 2)})
    assert e.value.option == "init"
