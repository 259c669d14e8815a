# Profiles, wheel-rail geometry and conicity from Python: the same numbers as
# `railsim geometry` and `railsim conicity`, and the geometry's symmetry.
import csv

import numpy as np
import pytest

import railsim


def test_shipped_profiles_and_errors():
    w = railsim.read_profile("S1002", "wheel")
    assert w.kind == "wheel" and w.y.size == w.z.size > 100
    assert np.all(np.diff(w.y) > 0)
    # The flange (largest z, profile z down) lies at negative y (field side +).
    assert w.y[np.argmax(w.z)] < 0
    r = railsim.read_profile("UIC60", "rail")
    assert r.kind == "rail"
    with pytest.raises(railsim.InputError, match="wheel profile, not a rail"):
        railsim.read_profile("S1002", "rail")
    with pytest.raises(railsim.InputError, match="cannot open"):
        railsim.read_profile("/no/such/profile.prw", "wheel")
    # The unit option: 0 (from the file) or metres per file unit in [1e-6, 1].
    for unit in (-1.0, float("nan"), 2.0):
        with pytest.raises(railsim.InputError, match=r"unit option = .*expected 0 .* in \[1e-6, 1\]"):
            railsim.read_profile("S1002", "wheel", unit=unit)
    assert railsim.read_profile("S1002", "wheel", unit=1e-3).y.size == w.y.size


def test_geometry_is_mirror_symmetric_and_matches_the_program(cli, tmp_path):
    g = railsim.WheelRailGeometry("S1002", "UIC60", "1/40")
    c0 = g.solve(0.0)
    assert c0["left"][0]["radius"] == pytest.approx(c0["right"][0]["radius"], rel=1e-9)
    a, b = g.solve(4e-3), g.solve(-4e-3)
    # Mirror: the left wheel at +y is the right wheel at -y.
    assert a["left"][0]["radius"] == pytest.approx(b["right"][0]["radius"], rel=1e-9)
    assert a["roll"] == pytest.approx(-b["roll"], rel=1e-6, abs=1e-12)
    assert a["left"][0]["radius"] > a["right"][0]["radius"]  # shifted left: the left wheel rolls on a larger radius
    t = g.table(-0.01, 0.01, 5e-4, cache_dir=str(tmp_path / "cache"))
    out = tmp_path / "table.csv"
    code, text = cli("geometry", "--wheel", "S1002", "--rail", "UIC60", "--inclination", "1/40", "--y-min", "-0.01",
                     "--y-max", "0.01", "--y-step", "5e-4", "--cache-dir", tmp_path / "cache2", "--out", out)
    assert code == 0, text
    with open(out) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == t["y"].size == 41
    for col in ("y", "roll", "left_radius", "right_angle", "left_A"):
        np.testing.assert_allclose([float(r[col]) for r in rows], t[col], rtol=1e-9, err_msg=col)


def test_conicity_matches_the_program(cli, tmp_path):
    g = railsim.WheelRailGeometry("S1002", "UIC60", "1/40")
    c = g.conicity(cache_dir=str(tmp_path))
    code, text = cli("conicity", "--wheel", "S1002", "--rail", "UIC60", "--inclination", "1/40", "--cache-dir", tmp_path)
    assert code == 0, text
    lines = [l for l in text.splitlines() if l and l[0].isdigit() and "," in l]
    prog = [float(l.split(",")[1]) for l in lines]
    assert len(prog) == 6
    np.testing.assert_allclose(c["equivalent_conicity"], prog, atol=1e-5)  # printed with 5 decimals
    assert np.all((c["equivalent_conicity"] > 0.05) & (c["equivalent_conicity"] < 0.5))
    # delta r is odd in y, to the contact search's precision (measured 8e-9 m).
    np.testing.assert_allclose(c["delta_r"], -c["delta_r"][::-1], rtol=0, atol=5e-8)
    # Amplitudes: positive and within the table; the message names the list element and the range.
    for bad in ([0.0], [3e-3, -1e-3], [0.02]):
        with pytest.raises(railsim.InputError, match=r"amplitudes\[\d\]: .*expected a value in \(0, 0.012\] m"):
            g.conicity(amplitudes=bad, cache_dir=str(tmp_path))
    # A shift step too coarse for the regression (0.024 m gave 15.85 at 1 mm).
    with pytest.raises(railsim.InputError, match=r"amplitudes\[0\]: .*y step 24 mm is too coarse"):
        g.conicity(y_step=0.024, cache_dir=str(tmp_path))
