"""The identification analyses' typed arguments: methods by name, windows and currents as
tuples, and bad values raised as InputError naming the keyword."""

import os
import subprocess

import pytest

import dynpos

BIN = os.environ.get("DYNPOS_BIN", "dynpos")
SOURCE = os.environ.get("DYNPOS_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
STEPS = os.path.join(SOURCE, "tests", "cli", "short_steps.csv")
STEP_COL = {"input": "cmd", "output": "response"}
THRUST_COL = {"thrust.port": "response"}


def test_step_methods_by_name_any_case():
    lsq = dynpos.identify_step(STEPS, col=STEP_COL, method="lsq")
    rk = dynpos.identify_step(STEPS, col=STEP_COL, method="RK")
    assert lsq.method == "lsq" and rk.method == "rk"
    assert len(rk.steps) == 2 and rk.steps[0].T2 is not None


def test_a_bad_method_or_derived_output_names_the_keyword():
    with pytest.raises(dynpos.InputError, match=r"\(method=\): unknown method 'fast'") as e:
        dynpos.identify_step(STEPS, col=STEP_COL, method="fast")
    assert e.value.option == "method"
    assert "lsq, smith, smith2, rk" in str(e.value)
    with pytest.raises(dynpos.InputError, match=r"\(derive=\): unknown derive 'speed'") as e:
        dynpos.identify_step(STEPS, col=STEP_COL, derive="speed")
    assert e.value.option == "derive"


def test_a_step_window_error_names_the_keywords():
    with pytest.raises(dynpos.InputError, match=r"\(from_=/to=\): the window 500 … 600 s starts "
                                                r"after the log's last row at 70 s") as e:
        dynpos.identify_step(STEPS, col=STEP_COL, from_=500, to=600)
    assert e.value.option == "from/to" and e.value.file.endswith("short_steps.csv")
    cli = subprocess.run([BIN, "identify", "step", STEPS, "--col", "input=cmd", "--col",
                          "output=response", "--from", "500", "--to", "600"],
                         capture_output=True, text=True)
    assert cli.returncode == 2
    assert cli.stderr == "dynpos: error: " + str(e.value).replace("(from_=/to=)",
                                                                 "(--from/--to)") + "\n"


def test_agility_windows_and_current_as_tuples(tmp_path):
    json = tmp_path / "py.json"
    r = dynpos.identify_agility(STEPS, col=THRUST_COL, unit={"thrust.port": "kN"},
                                window=[(10, 40, 90), (40, 69, 270, 50, 20)],
                                current=(0.2, 318), json=json)
    cli = tmp_path / "cli.json"
    subprocess.run([BIN, "identify", "agility", STEPS, "--col", "thrust.port=response",
                    "--unit", "thrust.port=kN", "--window", "10,40,90", "--window",
                    "40,69,270,50,20", "--current", "0.2,318", "--json", str(cli)],
                   check=True, capture_output=True)
    assert json.read_text() == cli.read_text()
    assert [d.magnitude_pct for d in r.directions] == [100, 50]
    assert r.directions[1].yaw_pct == 20 and r.current.to_deg == 318


def test_agility_bad_window_or_current_names_the_keyword():
    with pytest.raises(dynpos.InputError, match=r"\(window=\): a window needs 3 to 5 numbers, "
                                                r"has 2") as e:
        dynpos.identify_agility(STEPS, col=THRUST_COL, window=[(10, 20)])
    assert e.value.option == "window"
    with pytest.raises(dynpos.InputError, match=r"\(window=\)"):
        dynpos.identify_agility(STEPS, col=THRUST_COL, window=["10,20,90"])
    with pytest.raises(dynpos.InputError, match=r"\(current=\)") as e:
        dynpos.identify_agility(STEPS, col=THRUST_COL, window=[(10, 40, 90)], current=(-1, 0))
    assert e.value.option == "current"
    with pytest.raises(dynpos.InputError, match=r"\(window=\): window at t = 10 s: window "
                                                r"\[10, 5000\] s is not inside the log"):
        dynpos.identify_agility(STEPS, col=THRUST_COL, unit={"thrust.port": "kN"},
                                window=[(10, 5000, 90)])


def test_thrust_map_out_is_checked_before_the_run(tmp_path):
    with pytest.raises(dynpos.InputError, match=r"\(out=\): folder '.*no' does not exist"):
        dynpos.identify_thrust_map(STEPS, col={"rpm.port": "cmd"}, unit={"rpm.port": "rpm"},
                                   apply=True, out=tmp_path / "no" / "x.csv")


def test_a_unit_or_clock_offset_found_unused_later_names_the_keyword():
    """Checked once the whole map is known (a unit without its column, an offset for a file no
    role reads): the error is still the option's, spelled as Python spells it."""
    with pytest.raises(dynpos.InputError, match=r"\(unit=\): 'u=kn': role 'u' has a unit") as e:
        dynpos.identify_step(STEPS, col=STEP_COL, unit={"u": "kn"})
    assert e.value.option == "unit"
    with pytest.raises(dynpos.InputError,
                       match=r"\(clock_offset=\): 'nva.csv=1(\.0)?': no role is read from") as e:
        dynpos.identify_step(STEPS, col=STEP_COL, clock_offset={"nva.csv": 1.0})
    assert e.value.option == "clock_offset"
