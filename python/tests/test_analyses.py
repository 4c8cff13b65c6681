"""Every analysis through the Python API against the command line on the same input: to_dict()
equals the CLI's --json document, json= writes the same file, and the plots land where the
CLI puts them. The inputs are short virtual-trial runs (simulated once per test run)."""

import json
import os
import subprocess

import pytest

import dynpos

BIN = os.environ.get("DYNPOS_BIN", "dynpos")
SOURCE = os.environ.get("DYNPOS_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
COMPARE_DATA = os.path.join(SOURCE, "tests", "cli", "data", "compare")


@pytest.fixture(scope="session")
def runs(tmp_path_factory):
    """Short runs of the scenarios the analyses need, seed 3, as the CLI tests use them."""
    root = tmp_path_factory.mktemp("runs")
    plan = {"surge-steps-forward": None, "agility": 300, "four-corner": None, "pure-dp": 900,
            "turning-circle": 120}
    for name, duration in plan.items():
        dynpos.simulate(name, seed=3, duration=duration, out=root / name)
    return root


def cli(tmp_path, *args):
    """The CLI's --json document and file text for `dynpos ARGS --json FILE`."""
    out = tmp_path / "cli.json"
    subprocess.run([BIN, *map(str, args), "--json", str(out)], check=True, capture_output=True)
    return json.loads(out.read_text()), out.read_text()


def same_as_cli(tmp_path, result, written, *args):
    expected, text = cli(tmp_path, *args)
    assert result.to_dict() == expected
    assert written.read_text() == text


def test_identify_step(runs, tmp_path):
    log = runs / "surge-steps-forward" / "log.csv"
    r = dynpos.identify_step(log, col={"input": "command.surge", "output": "rpm.port"},
                             json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "identify", "step", log, "--col",
                "input=command.surge", "--col", "output=rpm.port")
    assert len(r.steps) >= 3 and all(s.status == "ok" for s in r.steps)
    frame = r.to_frame()
    assert list(frame["K"]) == [s.K for s in r.steps]


def test_identify_thrust_map_and_apply(runs, tmp_path):
    log = runs / "surge-steps-forward" / "log.csv"
    r = dynpos.identify_thrust_map(log, min_speed=5, json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "identify", "thrust-map", log,
                "--min-speed", "5")
    assert {t.name for t in r.thrusters} >= {"port", "stb"}
    dynpos.identify_thrust_map(log, col={"time": "time"}, apply=True, out=tmp_path / "py.csv")
    subprocess.run([BIN, "identify", "thrust-map", str(log), "--col", "time=time", "--apply",
                    "--out", str(tmp_path / "cli.csv")], check=True, capture_output=True)
    assert (tmp_path / "py.csv").read_bytes() == (tmp_path / "cli.csv").read_bytes()
    with pytest.raises(dynpos.InputError, match="--apply needs --out"):
        dynpos.identify_thrust_map(log, apply=True)


def test_identify_agility(runs, tmp_path):
    log = runs / "agility" / "log.csv"
    r = dynpos.identify_agility(log, current=(0.2, 318), json=tmp_path / "py.json",
                                plot=tmp_path / "py.svg")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "identify", "agility", log,
                "--current", "0.2,318")
    assert len(r.directions) == 3 and (tmp_path / "py.svg").stat().st_size > 0
    w = dynpos.identify_agility(log, window=[(10, 60, 0)])
    expected, _ = cli(tmp_path, "identify", "agility", log, "--window", "10,60,0")
    assert w.to_dict() == expected


def test_identify_four_corner(runs, tmp_path):
    log = runs / "four-corner" / "log.csv"
    col = {"north": "gnss1.north", "east": "gnss1.east"}
    r = dynpos.identify_four_corner(log, col=col, arm=(-2.0, 0.5), segment="auto",
                                    json=tmp_path / "py.json", plot=tmp_path / "ne.svg")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "identify", "four-corner", log, "--col",
                "north=gnss1.north", "--col", "east=gnss1.east", "--arm", "-2,0.5",
                "--segment", "auto")
    assert len(r.legs) == 4 and (tmp_path / "ne.svg").exists()


def test_four_corner_typed_arguments(runs):
    """The arm as a tuple, a list or a numpy array, the segmentation by name; a bad one of
    either is an InputError naming the keyword."""
    import numpy

    log = runs / "four-corner" / "log.csv"
    col = {"north": "gnss1.north", "east": "gnss1.east"}
    by_tuple = dynpos.identify_four_corner(log, col=col, arm=(-2.0, 0.5), segment="track")
    for arm in ([-2.0, 0.5], numpy.array([-2.0, 0.5])):
        assert dynpos.identify_four_corner(log, col=col, arm=arm,
                                           segment="track").to_dict() == by_tuple.to_dict()
    assert by_tuple.segmentation == "track" and by_tuple.arm_m == [-2.0, 0.5]
    q = dynpos._dynpos.FourCornerRequest()
    q.segment = "setpoints"
    assert q.segment == "setpoints"
    with pytest.raises(dynpos.InputError, match=r"\(segment=\): unknown segmentation 'box'") as e:
        dynpos.identify_four_corner(log, col=col, segment="box")
    assert e.value.option == "segment"
    with pytest.raises(dynpos.InputError, match=r"\(arm=\)") as e:
        dynpos.identify_four_corner(log, col=col, arm=(1.0, 2.0, 3.0))
    assert e.value.option == "arm"
    with pytest.raises(dynpos.InputError, match=r"\(arm=\): the antenna lever arm is not finite"):
        dynpos.identify_four_corner(log, col=col, arm=(float("nan"), 0.0))


@pytest.mark.parametrize("window", [(5000, 6000), (50, 10)])
def test_window_errors_are_the_same_in_every_windowed_analysis(runs, window):
    """One window rule (LogSource): the same bad window, the same message, naming from_=/to=."""
    log = runs / "pure-dp" / "log.csv"
    col = {"north": "gnss1.north", "east": "gnss1.east"}
    messages = []
    for analysis in (dynpos.identify_four_corner, dynpos.identify_station_keeping):
        with pytest.raises(dynpos.InputError) as e:
            analysis(log, col=col, from_=window[0], to=window[1])
        assert e.value.option == "from/to" and e.value.file == str(log)
        messages.append(str(e.value))
    assert messages[0] == messages[1]
    assert f"(from_=/to=): the window {window[0]} … {window[1]} s " in messages[0]


def test_identify_station_keeping(runs, tmp_path):
    log = runs / "pure-dp" / "log.csv"
    col = {"north": "gnss1.north", "east": "gnss1.east"}
    r = dynpos.identify_station_keeping(log, col=col, per_setpoint=True, duration=200,
                                        waves="Hs 2 m", json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "identify", "station-keeping", log, "--col",
                "north=gnss1.north", "--col", "east=gnss1.east", "--per-setpoint",
                "--duration", "200", "--waves", "Hs 2 m")
    assert len(r.windows) >= 2
    assert len(r.to_frame()) == len(r.windows)


def test_leverarm_mru(runs, tmp_path):
    truth = runs / "turning-circle" / "truth.csv"
    log = runs / "turning-circle" / "log.csv"
    r = dynpos.leverarm_mru(truth, mru_log={"mru1": log}, json=tmp_path / "py.json",
                            plots=tmp_path / "plots")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "leverarm", "mru", truth, "--mru-log",
                f"mru1={log}")
    assert any(p.suffix == ".svg" for p in (tmp_path / "plots").iterdir())


def test_leverarm_gnss_thesis_method(runs, tmp_path):
    truth = runs / "turning-circle" / "truth.csv"
    log = runs / "turning-circle" / "log.csv"
    r = dynpos.leverarm_gnss(truth, gnss_log={"gnss1": log, "gnss2": log}, method="lsq", lag=5,
                             json=tmp_path / "py.json", plots=tmp_path / "plots")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "leverarm", "gnss", truth, "--gnss-log",
                f"gnss1={log}", "--gnss-log", f"gnss2={log}", "--method", "lsq", "--lag", "5")
    assert r.method == "lsq" and len(r.arms) == 2
    assert (tmp_path / "plots" / "excitation.svg").exists()


def test_compare(runs, tmp_path):
    a = os.path.join(COMPARE_DATA, "steps_aug.json")
    b = os.path.join(COMPARE_DATA, "steps_nov.json")
    r = dynpos.compare(a, b, labels="Aug 2014,Nov 2014", json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "compare", a, b, "--labels",
                "Aug 2014,Nov 2014")
    assert r.labels == ["Aug 2014", "Nov 2014"] and len(r.to_frame()) == len(r.rows)
    # Results in memory compare like their files.
    log = runs / "surge-steps-forward" / "log.csv"
    col = {"input": "command.surge", "output": "rpm.port"}
    lsq = dynpos.identify_step(log, col=col)
    smith = dynpos.identify_step(log, col=col, method="smith")
    c = dynpos.compare(lsq, smith, labels=("lsq", "smith"))
    assert c.labels == ["lsq", "smith"] and c.kind == "step"


def test_hybrid_case(tmp_path):
    r = dynpos.hybrid_case("dp", sampled=True, seed=4, end_time=20, json=tmp_path / "py.json",
                           out=tmp_path / "out")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "hybrid", "dp", "--sampled", "--seed", "4",
                "--end-time", "20", "--out", tmp_path / "out")
    assert r.case == "dp" and len(r.plots) == 4
    f = dynpos.hybrid_case("first-order", lambda_=2.0, no_jumps=True)
    expected, _ = cli(tmp_path, "hybrid", "first-order", "--lambda", "2", "--no-jumps")
    assert f.to_dict() == expected


def test_hybrid_cases_are_named():
    q = dynpos._dynpos.HybridCaseRequest()
    assert q.case == "first-order"
    q.case = "dp"
    assert q.case == "dp"
    for call, key in ((lambda: dynpos.hybrid_case("second-order"), "case"),
                      (lambda: dynpos.hybrid_vessel("ice2"), "scenario")):
        with pytest.raises(dynpos.InputError) as e:
            call()
        assert e.value.option == key and f"({key}=): unknown" in str(e.value)


def test_hybrid_vessel(tmp_path):
    r = dynpos.hybrid_vessel("mooring", seed=2, within=2.0, json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "hybrid", "vessel", "--scenario", "mooring",
                "--seed", "2", "--within", "2")
    assert r.within_m == 2.0


def test_simulate_campaign_and_scenarios(tmp_path):
    names = dynpos.scenarios()
    assert set(names) >= {"pure-dp", "four-corner", "agility", "turning-circle"}
    assert all(description for description in names.values())
    runs = dynpos.simulate("campaign", seed=3, duration=20, out=tmp_path / "all")
    assert set(runs) == set(names)
    one = runs["yaw-steps"]
    assert one.out == os.fspath(tmp_path / "all" / "yaw-steps")
    assert one.truth["scenario"]["name"] == "yaw-steps" and one.log.time[-1] <= 20.0


def test_capability(tmp_path):
    r = dynpos.capability(direction_step=30, json=tmp_path / "py.json", out=tmp_path / "rose")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "capability", "--direction-step", "30")
    assert r.level == 1 and len(r.points) == 12 and (tmp_path / "rose" / "rose.svg").exists()
    frame = r.to_frame()
    assert list(frame["direction_deg"]) == [30.0 * i for i in range(12)]
    assert all(w <= i.max_wind_mps for w, i in zip(frame["max_wind_mps"], r.intact))


def test_capability_loads(tmp_path):
    data = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "cli", "data")
    loads, vessel = os.path.join(data, "loads_osv.csv"), os.path.join(data, "osv_layout.toml")
    r = dynpos.capability_loads(loads, vessel=vessel, json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "capability", "--loads", loads, "--vessel",
                vessel)
    assert r.layout == "[[thruster]]" and len(r.points) == 5
    assert all(0.0 < p.load_factor < 100.0 and p.failure != "none" for p in r.points[:2])
    with pytest.raises(dynpos.InputError, match="group:bus B"):
        dynpos.capability_loads(loads, vessel=vessel, failure="stern")


def test_capability_of_a_layout(tmp_path):
    data = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "cli", "data")
    vessel = os.path.join(data, "azimuth_layout.toml")
    r = dynpos.capability(vessel=vessel, direction_step=90, json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "capability", "--vessel", vessel,
                "--direction-step", "90")
    assert r.layout == "[[thruster]]" and [p.failure for p in r.points][:2] == ["az_port", "az_stb"]
    with pytest.raises(dynpos.InputError, match=r"\(failure=\): no unit or group 'port'"):
        dynpos.capability(vessel=vessel, failure="port")


def test_montecarlo(tmp_path):
    r = dynpos.montecarlo("turning-circle", (1, 2), jobs=2, json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "montecarlo", "turning-circle", "--seeds",
                "1..2", "--jobs", "2")
    doc = r.to_dict()
    assert [s["seed"] for s in doc["samples"]] == [1, 2]
    assert doc["summary"] and all(stats["n"] == 2 for stats in doc["summary"].values())
    # A shard of the range, as for `dynpos montecarlo merge`.
    second = dynpos.montecarlo("turning-circle", "1..2", shard="2/2", jobs=1)
    assert second.to_dict()["samples"] == doc["samples"][1:]
    with pytest.raises(dynpos.InputError, match=r"\(seeds=\): the range 5\.\.4 is empty"):
        dynpos.montecarlo("turning-circle", "5..4")


def test_montecarlo_takes_typed_seeds_shards_and_measures():
    q = dynpos._dynpos.MonteCarloRequest()
    q.seeds, q.shard, q.measure = (3, 9), (2, 4), "lever-arms"
    assert (q.seeds, q.shard, q.measure) == ((3, 9), (2, 4), "lever-arms")
    q.seeds, q.shard = "7", "1/3"
    assert (q.seeds, q.shard) == ((7, 7), (1, 3))
    for options, key in (({"measure": "everything"}, "measure"), ({"shard": "2-4"}, "shard"),
                         ({"seeds": "a..b"}, "seeds")):
        with pytest.raises(dynpos.InputError) as e:
            dynpos.montecarlo("turning-circle", **{"seeds": (1, 2), **options})
        assert e.value.option == key and f"({key}=)" in str(e.value)
