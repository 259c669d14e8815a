# Scenarios from Python: loaded from YAML or built from dicts, run (channels and
# summary as `railsim run` writes them), modes (as `railsim modes`), errors
# naming the scenario file, line and key.
import csv
import json
import re

import numpy as np
import pytest
import yaml

import railsim
from conftest import source

SINGLE = source("scenarios", "single_wheelset.yaml")


def test_run_matches_the_program(cli, tmp_path):
    sc = railsim.load_scenario(SINGLE)
    assert sc.states > 0 and sc.name
    r = railsim.run(sc)
    ch = r.as_dict()
    assert r.summary["status"] == "ok"
    assert r.data.shape == (801, len(r.names))  # 4 s every 5 ms and t = 0
    code, text = cli("run", SINGLE, "--out", tmp_path)
    assert code == 0, text
    with open(tmp_path / "channels.csv") as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0].keys()) == r.names
    for name in ("time", "ws1.y", "ws1.L.Q", "ws1.L.YQ"):
        np.testing.assert_allclose([float(x[name]) for x in rows], ch[name], rtol=1e-9, atol=1e-12, err_msg=name)
    with open(tmp_path / "summary.json") as f:
        s = json.load(f)
    assert list(s.keys()) == list(r.summary.keys())
    assert s["max_lateral_shift"] == pytest.approx(r.summary["max_lateral_shift"], rel=1e-12)
    # Relative to the rails (ws1.y_rel); the absolute shift (ws1.y) is labelled as such.
    assert r.summary["max_lateral_shift"] == pytest.approx(np.max(np.abs(ch["ws1.y_rel"])), rel=1e-9)
    assert r.summary["max_lateral_shift_absolute"] == pytest.approx(np.max(np.abs(ch["ws1.y"])), rel=1e-9)
    assert s["integrator_statistics"] == r.summary["integrator_statistics"]


def test_scenario_from_a_dict_and_pandas(tmp_path):
    with open(SINGLE) as f:
        spec = yaml.safe_load(f)
    spec["duration"] = 1.0
    r = railsim.run(railsim.scenario(spec, base_dir=source("scenarios")), out=tmp_path)
    assert r.data.shape[0] == 201
    assert (tmp_path / "summary.json").exists() and (tmp_path / "channels.csv").exists()
    try:
        import pandas  # noqa: F401
        assert list(r.channels.columns) == r.names
    except ImportError:
        assert isinstance(r.channels, dict) and set(r.channels) == set(r.names)


def test_scenario_errors_name_file_line_and_key(tmp_path):
    with open(SINGLE) as f:
        text = f.read()
    bad = tmp_path / "bad.yaml"
    bad.write_text(text.replace("../vehicles/single_wheelset.yaml", "../vehicles/no_such_vehicle.yaml"))
    line = next(i + 1 for i, l in enumerate(bad.read_text().splitlines()) if "no_such_vehicle" in l)
    with pytest.raises(railsim.InputError, match=rf"bad\.yaml:{line}: key 'vehicle'.*no_such_vehicle.yaml.*not found"):
        railsim.load_scenario(bad)
    with open(SINGLE) as f:
        spec = yaml.safe_load(f)
    spec["speed_kmh"] = -5
    spec.pop("speed", None)
    with pytest.raises(railsim.InputError, match=r"<python dict>:\d+: key 'speed_kmh'"):
        railsim.scenario(spec, base_dir=source("scenarios"))
    # numpy numbers are numbers (np.int64 raised a TypeError); other objects are refused naming the key.
    spec["speed_kmh"] = np.int64(90)
    spec["duration"] = np.array(0.5)
    assert railsim.scenario(spec, base_dir=source("scenarios")).duration == 0.5
    spec["duration"] = object()
    with pytest.raises(railsim.InputError, match=r"scenario: key 'duration': a object is not a scenario value"):
        railsim.scenario(spec, base_dir=source("scenarios"))


def test_modes_match_the_program(cli, tmp_path):
    sc = railsim.load_scenario(SINGLE)
    m = railsim.modes(sc, 50, 150, 50, count=3)
    code, text = cli("modes", SINGLE, "--v-min", 50, "--v-max", 150, "--v-step", 50, "--count", 3, "--out", tmp_path)
    assert code == 0, text
    with open(tmp_path / "modes.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == m["speed_kmh"].size
    np.testing.assert_allclose([float(r["damping_ratio"]) for r in rows], m["damping_ratio"], rtol=1e-8, atol=1e-12)
    np.testing.assert_allclose([float(r["frequency_hz"]) for r in rows], m["frequency_hz"], rtol=1e-8)
    if m["linear_critical_speed_kmh"] is not None:
        assert f"{m['linear_critical_speed_kmh']:.1f} km/h" in text
    assert m["unstable_at_v_min"] is False
    # Already unstable at v_min (the shipped wheelset's linear critical speed, 176.5 km/h, lies below 180):
    # no critical speed, a flag, as the program says "at or below".
    a = railsim.modes(sc, 180, 200, 10, count=1)
    assert a["linear_critical_speed_kmh"] is None and a["unstable_at_v_min"] is True


def test_critical_speed_matches_the_program(cli, tmp_path):
    # The same library call as `railsim critical-speed`, with the settings resolved the same way:
    # the sweep points, the nonlinear and the linear critical speed agree with the program's files.
    sc = railsim.load_scenario(SINGLE)
    for method in ("bifurcation", "ramping"):
        out = tmp_path / method
        # 6 s per point: the last 30 % (1.8 s) holds the cycles a verdict needs (1 s runs have none: exit 2).
        # (The sweep's step and duration do not apply to ramping: both refuse them there.)
        sweep = dict(v_step_kmh=60, duration=6.0) if method == "bifurcation" else {}
        r = railsim.critical_speed(sc, method=method, v_min_kmh=60, v_max_kmh=180, **sweep)
        args = ["--v-step", 60, "--duration", 6.0] if method == "bifurcation" else []
        code, text = cli("critical-speed", SINGLE, "--method", method, "--v-min", 60, "--v-max", 180, *args,
                         "--out", out)
        assert code == 0, text
        with open(out / "summary.json") as f:
            s = json.load(f)
        for key in ("critical_speed_kmh", "linear_critical_speed_kmh"):
            if s.get(key) is None:
                assert r[key] is None, key
            else:
                assert r[key] == pytest.approx(s[key], rel=1e-9), key
        if method == "bifurcation":
            with open(out / "bifurcation.csv") as f:
                rows = list(csv.DictReader(f))
            assert len(rows) == r["points"]["speed_kmh"].size
            np.testing.assert_allclose(sorted(1e3 * float(x["amplitude_m"]) for x in rows),  # m in the file
                                       sorted(r["points"]["amplitude_mm"]), rtol=1e-9, atol=1e-12)
        else:
            assert r["settings"]["start_speed_kmh"] == pytest.approx(180.0)


def test_critical_speed_below_the_range_is_no_verdict():
    # Hunting already at the lowest speed swept (linear critical speed 176.5 km/h): a bound, not a critical speed.
    sc = railsim.load_scenario(SINGLE)
    r = railsim.critical_speed(sc, v_min_kmh=190, v_max_kmh=200, v_step_kmh=10, duration=3.0)
    assert r["critical_speed_kmh"] is None
    assert "still hunts at the lowest speed of the sweep, 190.0 km/h" in r["undetermined"]


def test_critical_speed_says_when_there_is_no_verdict(cli, tmp_path):
    # 1 s per point: the last 30 % hold no cycle. The library says why there is no critical speed
    # (undetermined, each point's state too_short), the program exits 2 with the same reason.
    sc = railsim.load_scenario(SINGLE)
    r = railsim.critical_speed(sc, v_min_kmh=60, v_max_kmh=180, v_step_kmh=60, duration=1.0, up_branch=False)
    assert r["critical_speed_kmh"] is None
    assert "too short" in r["undetermined"]
    assert "too_short" in r["points"]["state"]
    code, text = cli("critical-speed", SINGLE, "--v-min", 60, "--v-max", 180, "--v-step", 60, "--duration", 1.0,
                     "--no-up-branch", "--out", tmp_path)
    assert code == 2, text
    assert "too short" in text
    # With enough time the verdict stands and says so.
    r = railsim.critical_speed(sc, v_min_kmh=60, v_max_kmh=180, v_step_kmh=60, duration=6.0, up_branch=False)
    assert r["undetermined"] is None


@pytest.mark.parametrize("kwargs, names", [
    (dict(duration=1e-3), "duration: expected a number in [0.5, 600] s"),
    (dict(duration=-1.0), "duration: expected a number in [0.5, 600] s"),
    (dict(v_step_kmh=1e-6), "v_step_kmh 1e-06: 80..300 km/h would take"),
    (dict(v_max_kmh=5000.0), "v_min_kmh/v_max_kmh: need 0 < v_min_kmh < v_max_kmh <= 720 km/h"),
    (dict(disturbance_mm=-50.0), "disturbance_mm: expected a number in [0.01, 20] mm"),
    (dict(small_disturbance_mm=0.0), "small_disturbance_mm: expected a number in [0.001, 20] mm"),
    (dict(threshold_mm=-1.0), "threshold_mm: expected a number in [0.001, 20] mm"),
    (dict(method="ramping", deceleration=50.0), "deceleration: expected a number in [0.001, 10] m/s^2"),
    (dict(threads=-3), "threads: expected a whole number in [0, 256]"),
    # NaN is the binding's "not given": given by the caller it is refused, not replaced by the default.
    (dict(v_min_kmh=float("nan"), v_max_kmh=100.0), "critical_speed: v_min_kmh = nan: expected a finite number"),
    (dict(duration=float("nan")), "critical_speed: duration = nan: expected a finite number"),
    (dict(threshold_mm=float("inf")), "critical_speed: threshold_mm = inf: expected a finite number"),
    (dict(threads=1.5), "critical_speed: threads = 1.5: expected a whole number"),
    # What does not apply to the method is refused, as on the command line.
    (dict(method="ramping", duration=3.0), "critical_speed: duration applies to the bifurcation sweep, not to ramping"),
    (dict(method="ramping", up_branch=False), "critical_speed: up_branch applies to the bifurcation sweep"),
    (dict(deceleration=1.0), "critical_speed: deceleration applies to ramping"),
])
def test_critical_speed_refuses_what_the_program_refuses(kwargs, names):
    # The command line's ranges, naming the Python argument (before: a 1 ms duration gave no critical speed and
    # no reason, which read as stable; a 1e-6 km/h step grew without bound; a negative duration raised
    # "vector::reserve").
    sc = railsim.load_scenario(SINGLE)
    with pytest.raises(railsim.InputError, match=re.escape(names)):
        railsim.critical_speed(sc, **kwargs)


@pytest.mark.parametrize("args, count, names", [
    ((50.0, 200.0, 1e-9), 6, "v_step_kmh 1e-09: 50..200 km/h would take"),
    ((50.0, 800.0, 10.0), 6, "need 0 < v_min_kmh < v_max_kmh <= 720 km/h"),
    ((50.0, 100.0, 10.0), 0, "count: expected a whole number in [1, 50]"),
    ((50.0, 100.0, 10.0), 1.5, "modes: count = 1.5: expected a whole number"),
])
def test_modes_refuses_what_the_program_refuses(args, count, names):
    # Before: a 1e-9 km/h step overflowed the speed count (empty arrays, no error), 1e-6 grew past 1.4 GB.
    sc = railsim.load_scenario(SINGLE)
    with pytest.raises(railsim.InputError, match=re.escape(names)):
        railsim.modes(sc, *args, count=count)


def test_output_folder_lock_is_the_programs(tmp_path):
    # A folder another writer holds (as a running `railsim` holds its --out: flock on DIR/.railsim.lock with its
    # pid inside) is refused by run and critical_speed, naming the holder (Python wrote into it before).
    import fcntl
    out = tmp_path / "held"
    out.mkdir()
    with open(out / ".railsim.lock", "w") as held:
        fcntl.flock(held, fcntl.LOCK_EX | fcntl.LOCK_NB)
        held.write("4242")
        held.flush()
        sc = railsim.load_scenario(SINGLE)
        with pytest.raises(railsim.InputError, match=r"another railsim process \(pid 4242\)"):
            railsim.run(sc, out=out)
        with pytest.raises(railsim.InputError, match=r"another railsim process \(pid 4242\)"):
            railsim.critical_speed(sc, v_min_kmh=150, v_max_kmh=200, out=out)
        assert not (out / "summary.json").exists()
    # Released: the folder is free again.
    spec = dict(duration=0.2)
    with open(SINGLE) as f:
        spec = {**yaml.safe_load(f), **spec}
    railsim.run(railsim.scenario(spec, base_dir=source("scenarios")), out=out)
    assert (out / "summary.json").exists()


@pytest.fixture
def ctrl_c():
    """Python's own Ctrl-C handler for the test (a process started in the
    background of a shell inherits SIGINT ignored, and Python then leaves it
    so), and a function sending SIGINT to this process after some seconds."""
    import os
    import signal
    import threading
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    timers = []

    def after(seconds):
        t = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
        timers.append(t)
        t.start()

    yield after
    for t in timers:
        t.cancel()
    signal.signal(signal.SIGINT, before)


def test_ctrl_c_stops_a_run_and_keeps_its_rows(tmp_path, ctrl_c):
    # Ctrl-C during run(): KeyboardInterrupt soon after (not at the run's
    # end), channels.csv whole up to the time summary.json names.
    import time
    with open(source("scenarios/manchester_coach_curve_R300.yaml")) as f:
        spec = yaml.safe_load(f)
    spec["duration"] = 240.0  # minutes of work: the stop must come from Ctrl-C
    sc = railsim.scenario(spec, base_dir=source("scenarios"))
    full = sc.duration
    t0 = time.monotonic()
    ctrl_c(1.5)
    with pytest.raises(KeyboardInterrupt):
        railsim.run(sc, out=tmp_path)
    waited = time.monotonic() - t0
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["status"] == "interrupted"
    assert isinstance(summary["running_safety"], str)
    t_said = float(re.search(r"t = ([0-9.e+-]+) s", summary["interrupted"]).group(1))
    assert 0.0 < t_said < full
    with open(tmp_path / "channels.csv") as f:
        rows = list(csv.reader(f))
    assert all(len(r) == len(rows[0]) for r in rows)
    assert float(rows[-1][0]) == pytest.approx(t_said, abs=1e-5)
    assert waited < 30.0  # stopped within the poll period, not after the whole run


def test_ctrl_c_stops_a_sweep_which_then_resumes(tmp_path, ctrl_c):
    sc = railsim.scenario(source("tests/data/scenarios/single_wheelset_flange.yaml"))  # a file name: read
    # 8 runs of 400 s simulated, four above the critical speed (hunting: no early
    # end, about 1.6 s each here): stopped in the first of those.
    kw = dict(v_min_kmh=150, v_max_kmh=180, v_step_kmh=10, duration=400, threads=1)
    ctrl_c(1.5)
    with pytest.raises(KeyboardInterrupt):
        railsim.critical_speed(sc, out=tmp_path / "stopped", **kw)
    resumed = railsim.critical_speed(sc, out=tmp_path / "stopped", **kw)
    clean = railsim.critical_speed(sc, out=tmp_path / "clean", **kw)
    assert resumed["critical_speed_kmh"] == clean["critical_speed_kmh"]
    assert (tmp_path / "stopped" / "bifurcation.csv").read_text() == (tmp_path / "clean" / "bifurcation.csv").read_text()


def test_speeds_in_km_h_are_the_numbers_given(tmp_path):
    # 240 km/h -> 66.666... m/s -> 240.00000000000003 km/h: echoed as given.
    sc = railsim.load_scenario(source("scenarios/single_wheelset.yaml"))
    r = railsim.critical_speed(sc, v_min_kmh=100, v_max_kmh=240, v_step_kmh=20, duration=0.5, threads=1,
                               out=tmp_path)
    assert set(r["points"]["speed_kmh"]) == {100.0, 120.0, 140.0, 160.0, 180.0, 200.0, 220.0, 240.0}
    assert r["settings"]["v_max_kmh"] == 240.0
    assert r["settings"]["v_step_kmh"] == 20.0
    assert "240.00000000000003" not in (tmp_path / "bifurcation.csv").read_text() + str(r)
