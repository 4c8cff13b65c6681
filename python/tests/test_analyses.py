"""Every analysis through the Python API against the command line on the same input: to_dict()
equals the CLI's --json document, json= writes the same file, and the plots land where the
CLI puts them. The inputs are short virtual-trial runs (simulated once per test run)."""

import json
import os
import subprocess

import numpy as np
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


def test_capability_transient(tmp_path):
    options = dict(level=3, transient=True, failure="tunnel", direction_step=90, rows=[3],
                   settle=60, after=60)
    r = dynpos.capability(json=tmp_path / "py.json", out=tmp_path / "fp", **options)
    same_as_cli(tmp_path, r, tmp_path / "py.json", "capability", "--level", "3", "--transient",
                "--failure", "tunnel", "--direction-step", "90", "--rows", "3", "--settle", "60",
                "--after", "60")
    assert r.analysis == "capability-transient" and (tmp_path / "fp" / "footprint.svg").exists()
    assert [p.direction_deg for p in r.points] == [0.0, 90.0, 180.0, 270.0]
    assert all(p.peak_excursion_m > 0.0 for p in r.points)
    with pytest.raises(dynpos.InputError, match=r"--rows is an option of --transient"):
        dynpos.capability(rows=[3])
    with pytest.raises(dynpos.InputError, match=r"--wind-tolerance is not an option"):
        dynpos.capability(wind_tolerance=1.0, **options)


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


# The virtual trial's GNSS antenna 1 moved to the control origin with the MRU's roll and pitch.
DP_COL = {"north": "gnss1.north", "east": "gnss1.east", "roll": "mru1.roll", "pitch": "mru1.pitch"}
DP_CLI_COL = ["--col", "north=gnss1.north", "--col", "east=gnss1.east", "--col",
              "roll=mru1.roll", "--col", "pitch=mru1.pitch"]


def arm_text(arm):
    return ",".join(repr(float(v)) for v in arm)


@pytest.fixture(scope="session")
def trip(tmp_path_factory):
    """The annual DP trial's thruster trip (the bow tunnel at 600 s of 1200 s), seed 1."""
    return dynpos.simulate("dp-thruster-trip", seed=1, out=tmp_path_factory.mktemp("trip"))


@pytest.fixture(scope="session")
def dp_run(tmp_path_factory):
    """400 s of pure DP at heading 0 (weather from the bow) with the EKF in the loop, seed 3."""
    return dynpos.simulate("pure-dp", seed=3, duration=400, observer="ekf",
                           out=tmp_path_factory.mktemp("dp"))


def test_identify_failure_test_against_the_truth(trip, tmp_path):
    """The trip found in the logger's files (thrust feedback, GNSS antenna 1 at 1 Hz moved to
    the control origin by its surveyed arm) against truth.json's failure, which the simulator
    measures on the control origin's true motion with the same meanings: the instant within
    0.5 s, the peak excursion within max(5 %, 0.1 m), the recovery within 2 s (or both never),
    the peak heading change within 0.25°."""
    log = os.path.join(trip.out, "log.csv")
    arm = trip.truth["lever_arms"]["gnss1"]
    r = dynpos.identify_failure_test(log, col=DP_COL, arm=arm, json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "identify", "failure-test", log, *DP_CLI_COL,
                "--arm", arm_text(arm))
    truth = trip.truth["failure"]
    assert truth["time_s"] == 600 and truth["units"] == ["tunnel"]
    assert r.arm_m == arm and r.arm_with_attitude and len(r.events) == 1
    e = r.events[0]
    assert e.unit == truth["unit"] and e.units == truth["units"]
    assert abs(e.time_s - truth["time_s"]) <= 0.5
    assert abs(e.peak_excursion_m - truth["peak_excursion_m"]) <= max(
        0.05 * truth["peak_excursion_m"], 0.1)
    if truth["recovery_s"] is None:
        assert e.recovery_s is None
    else:
        assert e.recovery_s is not None and abs(e.recovery_s - truth["recovery_s"]) <= 2.0
    assert abs(e.peak_heading_deg - truth["peak_heading_deg"]) <= 0.25
    assert list(r.to_frame()["unit"]) == ["tunnel"]


def test_failure_test_takes_the_arm_typed_and_names_a_bad_one(trip):
    import numpy

    log = os.path.join(trip.out, "log.csv")
    arm = trip.truth["lever_arms"]["gnss1"]
    expected = dynpos.identify_failure_test(log, col=DP_COL, arm=tuple(arm)).to_dict()
    for given in (numpy.array(arm), arm_text(arm)):
        assert dynpos.identify_failure_test(log, col=DP_COL, arm=given).to_dict() == expected
    # Two numbers: Z is 0 (no attitude needed); without an arm, the antenna's own track.
    flat = dynpos.identify_failure_test(log, col=DP_COL, arm=arm[:2])
    assert flat.arm_m == [arm[0], arm[1], 0.0]
    assert dynpos.identify_failure_test(log, col=DP_COL).arm_m is None
    with pytest.raises(dynpos.InputError, match=r"\(arm=\): '1,2,3,4' is not a lever arm") as e:
        dynpos.identify_failure_test(log, col=DP_COL, arm=(1, 2, 3, 4))
    assert e.value.option == "arm"
    with pytest.raises(dynpos.InputError, match=r"\(arm=\): the antenna lever arm is not finite"):
        dynpos.identify_failure_test(log, col=DP_COL, arm=(float("nan"), 0.0))


def test_simulate_observer_and_the_dp_truth_columns(dp_run, tmp_path):
    """observer= as --observer (the same files, byte for byte), and truth.csv's DP columns in
    Simulation.motion: lf, env_load and demand in every DP run, observer only with one."""
    subprocess.run([BIN, "simulate", "pure-dp", "--seed", "3", "--duration", "400", "--observer",
                    "ekf", "--out", str(tmp_path / "cli")], check=True, capture_output=True)
    for name in ("log.csv", "truth.csv", "truth.json"):
        assert (tmp_path / "cli" / name).read_bytes() == open(
            os.path.join(dp_run.out, name), "rb").read(), name
    assert dp_run.truth["observer"] == "ekf"
    dp_columns = {f"{g}.{k}" for g, ks in (("lf", ("north", "east", "heading")),
                                          ("env_load", ("north", "east", "yaw")),
                                          ("demand", ("surge", "sway", "yaw"))) for k in ks}
    observer_columns = {"observer.north", "observer.east", "observer.heading",
                        "observer.bias.north", "observer.bias.east", "observer.bias.yaw"}
    assert dp_columns | observer_columns <= set(dp_run.motion.channels)
    ideal = dynpos.simulate("pure-dp", seed=3, duration=20)
    assert "observer" not in ideal.truth and dp_columns <= set(ideal.motion.channels)
    assert not observer_columns & set(ideal.motion.channels)
    # The EKF in the loop follows the true low-frequency position within decimetres.
    m = dp_run.motion
    settled = m.time >= 120
    for k in ("north", "east"):
        error = m[f"observer.{k}"][settled] - m[f"lf.{k}"][settled]
        assert float(np.sqrt(np.mean(error ** 2))) < 0.3, k
    with pytest.raises(dynpos.InputError, match=r"\(observer=\): unknown observer 'kalman'"):
        dynpos.simulate("pure-dp", duration=5, observer="kalman")


def test_estimate_against_the_truth(dp_run, tmp_path):
    """The observer over the logged run: the --json document and the CSV as the CLI's, the
    series in SI the CSV's, and against truth.csv: b̂'s mean after the settling time within
    10 % of the true load's horizontal magnitude in north and east and 15 % in yaw (as the CLI
    test), the LF position within 0.3 m RMS and the heading within 0.5° RMS of the true LF
    motion."""
    log = os.path.join(dp_run.out, "log.csv")
    arm = dp_run.truth["lever_arms"]["gnss1"]
    r = dynpos.estimate(log, col=DP_COL, arm=arm, tp=7, json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "estimate", log, *DP_CLI_COL, "--arm",
                arm_text(arm), "--tp", "7")
    assert r.observer == "ekf" and r.steps == 4000 and r.bias.from_s == 120
    s = r.series
    assert len(s) == r.steps and s.unit("bias.yaw") == "N*m" and s.unit("lf.heading") == "rad"
    # The summary is the series' own mean.
    after = s.time >= r.bias.from_s
    assert np.count_nonzero(after) == r.bias.samples
    for k, key in (("north", "north_N"), ("east", "east_N"), ("yaw", "yaw_Nm")):
        assert np.mean(s[f"bias.{k}"][after]) == pytest.approx(r.bias.mean[key], rel=1e-9)
    # The series against the truth.
    m = dp_run.motion
    load = {k: np.interp(s.time, m.time, m[f"env_load.{k}"])[after].mean()
            for k in ("north", "east", "yaw")}
    horizontal = np.hypot(load["north"], load["east"])
    for k in ("north", "east"):
        assert abs(r.bias.mean[f"{k}_N"] - load[k]) < 0.10 * horizontal, k
    assert abs(r.bias.mean.yaw_Nm - load["yaw"]) < 0.15 * abs(load["yaw"])
    for k in ("north", "east"):
        error = s[f"lf.{k}"][after] - np.interp(s.time, m.time, m[f"lf.{k}"])[after]
        assert float(np.sqrt(np.mean(error ** 2))) < 0.3, k
    heading = np.interp(s.time, m.time, np.unwrap(m["lf.heading"]))
    dpsi = np.angle(np.exp(1j * (s["lf.heading"] - heading)))[after]
    assert np.degrees(np.sqrt(np.mean(dpsi ** 2))) < 0.5
    # out= writes the CLI's CSV (deg, kN), the series' values.
    dynpos.estimate(log, col=DP_COL, arm=arm, tp=7, out=tmp_path / "py.csv")
    subprocess.run([BIN, "estimate", log, *DP_CLI_COL, "--arm", arm_text(arm), "--tp", "7",
                    "--out", str(tmp_path / "cli.csv")], check=True, capture_output=True)
    assert (tmp_path / "py.csv").read_bytes() == (tmp_path / "cli.csv").read_bytes()
    csv = np.genfromtxt(tmp_path / "py.csv", delimiter=",", skip_header=1)
    assert np.allclose(csv[:, 0], s.time)
    assert np.allclose(csv[:, 3], np.degrees(s["lf.heading"]), atol=1e-6)
    assert np.allclose(csv[:, 7], s["bias.north"] / 1e3, atol=1e-6)
    # The fixes' age: 1 Hz GNSS, so at most 1 s, as the JSON's longest.
    assert np.allclose(csv[:, 10], s["position.age"], atol=1e-6)
    assert abs(s["position.age"].max() - r.longest_without_position_s) < 1e-9
    # The logged MRU stands by for a GNSS gap (none in this log); mru="none" leaves it out.
    assert r.bridge["mru"] == "mru1" and r.bridge["rows"] == 0
    assert dynpos.estimate(log, col=DP_COL, arm=arm, tp=7, mru="none").bridge is None
    frame = r.to_frame()
    assert list(frame.columns[:2]) == ["time", "lf.north"] and len(frame) == r.steps
    # The passive observer runs on the held fix: it never coasts.
    passive = dynpos.estimate(log, col=DP_COL, arm=arm, tp=7, observer="passive")
    assert passive.measurement == "held" and passive.coasting_steps == 0


def test_consequence(dp_run, tmp_path):
    """Heading 0, the weather from the bow: the tunnel's loss is the worst case with a wide
    margin at every point (λ > 3, as the CLI test), none negative; out= the CLI's CSV."""
    log = os.path.join(dp_run.out, "log.csv")
    arm = dp_run.truth["lever_arms"]["gnss1"]
    r = dynpos.consequence(log, col=DP_COL, arm=arm, tp=7, json=tmp_path / "py.json")
    same_as_cli(tmp_path, r, tmp_path / "py.json", "consequence", log, *DP_CLI_COL, "--arm",
                arm_text(arm), "--tp", "7")
    assert r.layout == "model" and r.cases == ["port", "stb", "rudder.port", "rudder.stb",
                                               "tunnel"]
    assert r.points == 23 and r.from_s == 180 and r.to_s == 400 and r.estimate.observer == "ekf"
    assert r.smallest_margin.failure == "tunnel" and r.smallest_margin.margin > 2.0
    assert r.fraction_negative == 0 and r.intact.min_load_factor > r.smallest_margin.load_factor
    assert list(r.to_frame()["failure"]) == r.cases
    dynpos.consequence(log, col=DP_COL, arm=arm, tp=7, step=20, window=30,
                       out=tmp_path / "py.csv")
    subprocess.run([BIN, "consequence", log, *DP_CLI_COL, "--arm", arm_text(arm), "--tp", "7",
                    "--step", "20", "--window", "30", "--out", str(tmp_path / "cli.csv")],
                   check=True, capture_output=True)
    text = (tmp_path / "py.csv").read_text()
    # A point every 20 s from the settling time and the window on, 150 … 390 s.
    assert text == (tmp_path / "cli.csv").read_text() and len(text.splitlines()) == 1 + 13
