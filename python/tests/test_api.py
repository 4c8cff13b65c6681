"""The Python API against the command line and the library: each result's to_dict() is the
CLI's --json for the same input, logs are numpy views in SI, bad input is a ValueError."""

import json
import math
import os
import subprocess

import numpy as np
import pytest

import dynpos

BIN = os.environ.get("DYNPOS_BIN", "dynpos")
SOURCE = os.environ.get("DYNPOS_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
STEPS = os.path.join(SOURCE, "tests", "cli", "short_steps.csv")


def cli_json(tmp_path, *args):
    out = tmp_path / "cli.json"
    subprocess.run([BIN, *args, "--json", str(out)], check=True, capture_output=True)
    return json.loads(out.read_text())


def step_log(path):
    """A first-order response to two steps: K = 2, T = 3 s, no dead time, at 10 Hz."""
    t = np.arange(0.0, 80.0, 0.1)
    u = np.where(t >= 10.0, 1.0, 0.0) + np.where(t >= 45.0, 1.0, 0.0)
    y = 2.0 * (np.where(t >= 10.0, 1.0 - np.exp(-(t - 10.0) / 3.0), 0.0)
               + np.where(t >= 45.0, 1.0 - np.exp(-(t - 45.0) / 3.0), 0.0))
    with open(path, "w", encoding="utf-8") as f:
        f.write("time [s],cmd [1],response [m]\n")
        for row in zip(t, u, y):
            f.write("{:.1f},{:.0f},{:.9f}\n".format(*row))
    return t, u, y


def test_read_log_gives_numpy_views_in_si(tmp_path):
    (tmp_path / "a.csv").write_text("time [s],heading [deg]\n0,90\n1,180\n")
    log = dynpos.read_log(tmp_path / "a.csv")
    h = log["heading"]
    assert h.dtype == np.float64 and not h.flags.writeable and h.base is not None
    np.testing.assert_allclose(h, [math.pi / 2, math.pi])
    np.testing.assert_array_equal(log.time, [0.0, 1.0])
    assert log.input["files"][0]["format"] == "csv"
    assert "heading" in log and len(log) == 2


def test_identify_step_equals_the_cli_json(tmp_path):
    step_log(tmp_path / "s.csv")
    col = {"input": "cmd", "output": "response"}
    r = dynpos.identify_step(tmp_path / "s.csv", col=col)
    expected = cli_json(tmp_path, "identify", "step", str(tmp_path / "s.csv"), "--col",
                        "input=cmd", "--col", "output=response")
    assert r.to_dict() == expected
    assert len(r.steps) == 2
    assert r.steps[0].K == pytest.approx(2.0, rel=1e-3)
    assert r.steps[0].T == pytest.approx(3.0, rel=1e-2)


def test_a_log_from_arrays_gives_the_same_steps_as_its_file(tmp_path):
    step_log(tmp_path / "s.csv")
    t, u, y = np.loadtxt(tmp_path / "s.csv", delimiter=",", skiprows=1, unpack=True)
    log = dynpos.Log.from_arrays(t, {"input": u, "output": y})  # the file's values exactly
    a = dynpos.identify_step(log).to_dict()["steps"]
    b = dynpos.identify_step(tmp_path / "s.csv", col={"input": "cmd", "output": "response"})
    assert a == b.to_dict()["steps"]


def test_leverarm_gnss_equals_the_cli_json(tmp_path):
    run = dynpos.simulate("turning-circle", seed=2, duration=150, out=tmp_path / "tc")
    assert run.truth["seed"] == 2
    log = tmp_path / "tc" / "log.csv"
    r = dynpos.leverarm_gnss(log, imu_arm=(0.358, 0.804, -4.321))
    expected = cli_json(tmp_path, "leverarm", "gnss", str(log), "--imu-arm",
                        "0.358,0.804,-4.321")
    assert r.to_dict() == expected
    assert r.method == "ins" and r.reference == "co"
    assert [a.name for a in r.arms] == ["gnss1", "gnss2", "gnss3", "mru2"]


def test_simulate_is_deterministic_and_returns_the_truth():
    a = dynpos.simulate("surge-steps-forward", seed=5, duration=60)
    b = dynpos.simulate("surge-steps-forward", seed=5, duration=60)
    np.testing.assert_array_equal(a.log["rpm.port"], b.log["rpm.port"])
    assert a.truth["scenario"]["name"] == "surge-steps-forward"
    assert "u" in a.motion


def test_bad_input_is_an_input_error_with_the_cli_message(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("time [s],cmd [1],response [m]\n0,0,0\n0.1,x,0\n")
    with pytest.raises(dynpos.InputError) as e:
        dynpos.identify_step(bad, col={"input": "cmd", "output": "response"})
    assert isinstance(e.value, ValueError)
    cli = subprocess.run([BIN, "identify", "step", str(bad), "--col", "input=cmd", "--col",
                          "output=response"], capture_output=True, text=True)
    assert cli.returncode == 2
    assert "bad.csv:3:2" in str(e.value)
    assert str(e.value) in cli.stderr
    with pytest.raises(dynpos.InputError, match="unknown option 'min_stepp'"):
        dynpos.identify_step(STEPS, min_stepp=1.0)
    with pytest.raises(dynpos.InputError, match="column 'x'"):
        dynpos.Log.from_arrays(np.arange(3.0), {"x": np.arange(2.0)})


def test_a_dataframe_is_a_log(tmp_path):
    pandas = pytest.importorskip("pandas")
    step_log(tmp_path / "s.csv")
    frame = pandas.read_csv(tmp_path / "s.csv")
    frame.columns = ["time", "input", "output"]
    from_frame = dynpos.identify_step(frame)
    from_file = dynpos.identify_step(tmp_path / "s.csv", col={"input": "cmd",
                                                             "output": "response"})
    assert from_frame.to_dict()["steps"] == from_file.to_dict()["steps"]
    table = from_frame.to_frame()
    assert {"t_step", "K", "T", "delay"} <= set(table.columns) and len(table) == 2
    assert table["sigma.K"].notna().all()
    # A DatetimeIndex is the time axis: seconds from its first stamp, the stamp kept.
    stamps = pandas.date_range("2026-11-26T10:00:00Z", periods=4, freq="250ms")
    log = dynpos.Log.from_frame(pandas.DataFrame({"heading": [0.0, 0.1, None, 0.3]},
                                                 index=stamps), time=None)
    np.testing.assert_allclose(log.time, [0.0, 0.25, 0.5, 0.75])
    assert math.isnan(log["heading"][2]) and log.origin == stamps[0]
    with pytest.raises(dynpos.InputError, match="no column 'stamp'"):
        dynpos.Log.from_frame(frame, time="stamp")


def test_analyses_run_in_threads_with_the_gil_released(tmp_path):
    """Four identifications on two threads give what one after the other gives."""
    from concurrent.futures import ThreadPoolExecutor

    step_log(tmp_path / "s.csv")
    col = {"input": "cmd", "output": "response"}
    alone = [dynpos.identify_step(tmp_path / "s.csv", col=col, method=m).to_dict()
             for m in ("lsq", "smith", "smith2", "rk")]
    with ThreadPoolExecutor(max_workers=2) as pool:
        threaded = list(pool.map(lambda m: dynpos.identify_step(tmp_path / "s.csv", col=col,
                                                                method=m).to_dict(),
                                 ("lsq", "smith", "smith2", "rk")))
    assert threaded == alone


def test_read_log_takes_nmea_captures_and_several_files():
    nmea = dynpos.read_log(os.path.join(SOURCE, "tests", "data", "nmea", "station.nmea"))
    assert nmea.input["files"][0]["format"] == "nmea"
    assert "heading" in nmea and np.all(np.isfinite(nmea.time))
    data = os.path.join(SOURCE, "tests", "data", "multifile")
    nav = os.path.join(data, "nav.csv")
    log = dynpos.read_log(os.path.join(data, "main.csv"),
                          col={"heading": f"HDG@{nav}", "time": f"stamp@{nav}"},
                          clock_offset={nav: -1000})
    assert log.time[0] == 0.0 and log["heading"][0] == pytest.approx(math.radians(358))
    assert len(log.input["files"]) == 2


def test_the_version_is_the_commands():
    cli = subprocess.run([BIN, "--version"], capture_output=True, text=True, check=True)
    assert dynpos.__version__ == cli.stdout.strip()
    assert dynpos.__version__.count(".") == 2


def test_identify_vessel_and_compare_trial_equal_the_cli(tmp_path):
    dynpos.simulate("zig-zag", seed=2, duration=200, out=tmp_path / "zz")
    log = str(tmp_path / "zz" / "log.csv")
    r = dynpos.identify_vessel([log], holdout="none", out=tmp_path / "py.toml", jobs=1)
    expected = cli_json(tmp_path, "identify", "vessel", log, "--holdout", "none", "--out",
                        str(tmp_path / "cli.toml"), "--jobs", "1")
    got = r.to_dict()
    got.pop("run_time_s")
    expected.pop("run_time_s")
    assert got == expected
    assert any(p.determined for p in r.parameters)
    assert (tmp_path / "py.toml").read_text() == (tmp_path / "cli.toml").read_text()
    c = dynpos.compare_trial(log, vessel=tmp_path / "py.toml")
    assert c.nrmse.u < 0.05 and c.nrmse.r < 0.05
    with pytest.raises(dynpos.InputError, match="holdout"):
        dynpos.identify_vessel([log], holdout="other.csv")


def step_db3(path, msgs):
    """The step test as a rosbag2 SQLite bag before Iron (type names only), its custom type
    test_msgs/msg/Feedback as a .msg file under `msgs`; written with Python's sqlite3."""
    import sqlite3
    import struct

    (msgs / "test_msgs" / "msg").mkdir(parents=True)
    (msgs / "test_msgs" / "msg" / "Feedback.msg").write_text("Header header\nfloat64 rpm\n")
    db = sqlite3.connect(path)
    db.execute("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT, type TEXT, "
               "serialization_format TEXT, offered_qos_profiles TEXT)")
    db.execute("CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER, "
               "timestamp INTEGER, data BLOB)")
    db.execute("INSERT INTO topics VALUES (1, '/cmd', 'std_msgs/msg/Float64', 'cdr', '')")
    db.execute("INSERT INTO topics VALUES (2, '/fb', 'test_msgs/msg/Feedback', 'cdr', '')")
    start = 1_714_557_600 * 10**9
    for k in range(800):
        ns = start + k * 100_000_000
        t = 0.1 * k
        u = (1.0 if t >= 10.0 else 0.0) + (1.0 if t >= 45.0 else 0.0)
        y = 2.0 * ((1.0 - math.exp(-(t - 10.0) / 3.0) if t >= 10.0 else 0.0)
                   + (1.0 - math.exp(-(t - 45.0) / 3.0) if t >= 45.0 else 0.0))
        cmd = b"\x00\x01\x00\x00" + struct.pack("<d", u)
        # header (sec, nanosec, frame "" as length 1 and a NUL), padding to 8, then rpm.
        fb = b"\x00\x01\x00\x00" + struct.pack("<iII", ns // 10**9, ns % 10**9, 1) + b"\x00" \
            + b"\x00" * 3 + struct.pack("<d", y)
        db.execute("INSERT INTO messages(topic_id, timestamp, data) VALUES (1, ?, ?)", (ns, cmd))
        db.execute("INSERT INTO messages(topic_id, timestamp, data) VALUES (2, ?, ?)",
                   (ns + 5_000_000, fb))
    db.commit()
    db.close()


def test_a_db3_bag_with_msg_path_equals_the_cli(tmp_path):
    step_db3(tmp_path / "steps.db3", tmp_path / "msgs")
    col = {"input": "/cmd.data", "output": "/fb.rpm"}
    expected = cli_json(tmp_path, "identify", "step", str(tmp_path / "steps.db3"), "--col",
                        "input=/cmd.data", "--col", "output=/fb.rpm", "--msg-path",
                        str(tmp_path / "msgs"))
    for msg_path in (tmp_path / "msgs", str(tmp_path / "msgs"), [tmp_path / "msgs"]):
        r = dynpos.identify_step(tmp_path / "steps.db3", col=col, msg_path=msg_path)
        assert r.to_dict() == expected
    assert len(expected["steps"]) == 2
    assert expected["steps"][0]["K"] == pytest.approx(2.0, rel=1e-3)
    assert {f["format"] for f in expected["input"]["files"]} == {"db3"}
    with pytest.raises(dynpos.InputError, match=r"steps.db3 \(/fb\): no definition of the type "
                       r"test_msgs/msg/Feedback.*--msg-path"):
        dynpos.identify_step(tmp_path / "steps.db3", col=col)
