# Contact models from Python: every registered model on arrays (signs, mirror
# symmetry, saturation at mu Fz), the same numbers as `railsim contact`
# through files (1e-12), the MIM fields (equilibrium, Coulomb bound, stick and
# slip), and errors as Python exceptions with railsim's message.
import csv
import math

import numpy as np
import pytest

import railsim
from conftest import source
import creep_force_curves as ex

PATCH = dict(a=6e-3, b=4e-3, Fz=75e3, E=2.1e11, nu=0.28, mu=0.3)
MODELS = [m["name"] for m in railsim.tangential_models() if m["compared_by_default"]]


def test_every_model_is_callable_on_arrays():
    assert {"linear", "fastsim", "mim", "chopaya", "polach"} <= set(MODELS)
    xi = np.linspace(-2e-3, 2e-3, 9)
    for m in MODELS:
        r = railsim.contact(m, xi, 0.0, 0.0, **PATCH)
        for key in ("Fx", "Fy", "Mz", "stick_fraction"):
            assert r[key].shape == xi.shape, (m, key)
        assert r["a"] == pytest.approx(6e-3) and r["b"] == pytest.approx(4e-3)  # one patch: numbers
        per_point = railsim.contact(m, xi[:2], a=[6e-3, 5e-3], b=4e-3, Fz=75e3)
        assert per_point["a"].tolist() == pytest.approx([6e-3, 5e-3])
        assert r["valid"].dtype == bool and r["valid"].shape == xi.shape
        assert r["model"] == m


@pytest.mark.parametrize("model", MODELS)
def test_signs_and_mirror_symmetry(model):
    # Kalker's convention (contact/types.hpp): a positive creepage gives a
    # negative force; pure xi gives no Fy, pure eta no Fx; mirroring a
    # creepage mirrors its force (every sign combination of xi and eta).
    s = np.array([1e-4, 1e-3, 4e-3])
    for sx in (-1, 1):
        for se in (-1, 1):
            r = railsim.contact(model, sx * s, se * s, 0.0, **PATCH)
            m = railsim.contact(model, -sx * s, -se * s, 0.0, **PATCH)
            assert np.all(np.sign(r["Fx"]) == -sx), model
            assert np.all(np.sign(r["Fy"]) == -se), model
            np.testing.assert_allclose(m["Fx"], -r["Fx"], rtol=1e-6, atol=1e-6 * PATCH["Fz"])
            np.testing.assert_allclose(m["Fy"], -r["Fy"], rtol=1e-6, atol=1e-6 * PATCH["Fz"])
            np.testing.assert_allclose(m["Mz"], -r["Mz"], rtol=1e-5, atol=1e-7 * PATCH["Fz"])
    px = railsim.contact(model, s, 0.0, 0.0, **PATCH)
    np.testing.assert_allclose(px["Fy"], 0.0, atol=1e-9 * PATCH["Fz"])


@pytest.mark.parametrize("model", [m for m in MODELS if m != "linear"])
def test_saturation_at_mu_fz(model):
    # Far into full slip the tangential force reaches mu Fz (Coulomb) and never exceeds it.
    r = railsim.contact(model, np.array([0.05, 0.0, 0.035]), np.array([0.0, 0.05, 0.035]), 0.0, **PATCH)
    F = np.hypot(r["Fx"], r["Fy"])
    muN = PATCH["mu"] * PATCH["Fz"]
    assert np.all(F <= muN * (1 + 1e-6)), model
    assert np.all(F >= 0.9 * muN), model


def test_scalars_broadcast_and_reduction():
    lin = railsim.contact("linear", 1e-3, **PATCH)
    assert isinstance(lin["Fx"], float) and isinstance(lin["valid"], bool) and isinstance(lin["reason"], str)
    assert lin["valid"] == (lin["reason"] == "")
    red = railsim.contact("linear", 1e-3, **PATCH, reduction="elastic_fe")
    assert red["Fx"] == pytest.approx(0.72 * lin["Fx"], rel=1e-12)  # k11 = 0.72 scales C11
    arr = railsim.contact("linear", [1e-3, 2e-3], Fz=[75e3, 75e3], a=6e-3, b=4e-3)
    assert arr["Fx"][1] == pytest.approx(2 * arr["Fx"][0], rel=1e-12)  # linear theory is linear


def _cli_curve(cli, tmp_path, model, xi, eta, phi):
    cases = tmp_path / f"{model}_cases.yaml"
    ex.write_cases_yaml(cases, xi, eta, phi)
    out = tmp_path / f"{model}.csv"
    code, text = cli("contact", cases, "--model", model, "--out", out)
    assert code == 0, text
    with open(out) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in ("Fx", "Fy", "Mz")}, [r["valid"] for r in rows]


@pytest.mark.parametrize("model", MODELS)
def test_notebook_curve_equals_railsim_contact_through_files(cli, tmp_path, model):
    # The example's creep-force curve (lateral creepage with spin) through Python
    # and through a case file and `railsim contact`: the same doubles.
    xi, eta, phi = ex.curve_cases(15)["lateral_with_spin"]
    xi = xi + 2e-4  # every component non-zero
    py = ex.creep_curve(model, xi, eta, phi)
    ref, valid = _cli_curve(cli, tmp_path, model, xi, eta, phi)
    for k in ("Fx", "Fy", "Mz"):
        scale = np.max(np.abs(ref[k]))
        assert scale > 0
        np.testing.assert_allclose(py[k], ref[k], rtol=1e-12, atol=1e-12 * scale, err_msg=f"{model} {k}")
    assert [("1" if v else "0") for v in py["valid"]] == valid or [str(bool(v)).lower() for v in py["valid"]] == valid


def test_mim_fields_balance_the_totals_and_obey_coulomb():
    r = railsim.mim_fields(1e-3, 5e-4, 0.3, **PATCH, grid=24)
    assert r["converged"]
    dA = (r["x"][1] - r["x"][0]) * (r["y"][1] - r["y"][0])
    assert r["pressure"].shape == (r["y"].size, r["x"].size) == r["state"].shape
    assert np.sum(r["pressure"]) * dA == pytest.approx(PATCH["Fz"], rel=1e-9)
    assert np.sum(r["px"]) * dA == pytest.approx(r["Fx"], rel=1e-9)
    assert np.sum(r["py"]) * dA == pytest.approx(r["Fy"], rel=1e-9)
    X, Y = np.meshgrid(r["x"], r["y"])
    assert np.sum(X * r["py"] - Y * r["px"]) * dA == pytest.approx(r["Mz"], rel=1e-9, abs=1e-9 * PATCH["Fz"] * 6e-3)
    t = np.hypot(r["px"], r["py"])
    assert np.all(t <= PATCH["mu"] * r["pressure"] * (1 + 1e-6) + 1e-6)
    slip = r["state"] == 2
    np.testing.assert_allclose(t[slip], PATCH["mu"] * r["pressure"][slip], rtol=1e-6)
    assert r["n_adhesion"] > 0 and r["n_slip"] > 0  # partial slip at these creepages
    # Hertz: the largest pressure near p0 = 3 Fz / (2 pi a b).
    assert r["pressure"].max() == pytest.approx(1.5 * PATCH["Fz"] / (math.pi * r["a"] * r["b"]), rel=0.05)
    # Pure rolling sticks everywhere; a large creepage slides everywhere.
    assert railsim.mim_fields(0.0, 0.0, 0.0, **PATCH, grid=16)["n_slip"] == 0
    full = railsim.mim_fields(0.05, 0.0, 0.0, **PATCH, grid=16)
    # (to the solver's tolerance: measured 1e-5 of mu Fz)
    assert full["n_adhesion"] == 0 and full["Fx"] == pytest.approx(-PATCH["mu"] * PATCH["Fz"], rel=1e-4)
    # The model "mim" without extrapolation on the same point gives the same totals.
    m = railsim.contact("mim", 1e-3, 5e-4, 0.3, **PATCH, grid=24, extrapolation="none")
    assert m["Fx"] == pytest.approx(r["Fx"], rel=1e-9) and m["Mz"] == pytest.approx(r["Mz"], rel=1e-9)


def test_mim_extrapolation_choices():
    # Default = Richardson from grid N and N/2 = 2 F_N - F_N/2 of the plain grids.
    d = railsim.contact("mim", 1e-3, 5e-4, 0.3, **PATCH, grid=24)
    r = railsim.contact("mim", 1e-3, 5e-4, 0.3, **PATCH, grid=24, extrapolation="richardson")
    f = railsim.contact("mim", 1e-3, 5e-4, 0.3, **PATCH, grid=24, extrapolation="none")
    h = railsim.contact("mim", 1e-3, 5e-4, 0.3, **PATCH, grid=12, extrapolation="none")
    assert d["Fx"] == r["Fx"] and d["Fy"] == r["Fy"]
    assert d["Fx"] == pytest.approx(2 * f["Fx"] - h["Fx"], rel=1e-6)
    assert d["Fy"] == pytest.approx(2 * f["Fy"] - h["Fy"], rel=1e-6)
    with pytest.raises(railsim.InputError, match="extrapolation must be"):
        railsim.contact("mim", 1e-3, **PATCH, extrapolation="linear")


def test_options_the_model_does_not_read_are_refused():
    # They were ignored silently: chopaya has no grid, fastsim no tolerance, mim no table cache.
    with pytest.raises(railsim.InputError, match="grid: model 'chopaya' does not use it .*fastsim.*mim"):
        railsim.contact("chopaya", 1e-3, **PATCH, grid=30)
    with pytest.raises(railsim.InputError, match="tolerance: model 'fastsim' does not use it .*mim, mim_table"):
        railsim.contact("fastsim", 1e-3, **PATCH, tolerance=1e-6)
    with pytest.raises(railsim.InputError, match="cache_dir: model 'mim' does not use it .*mim_table"):
        railsim.contact("mim", 1e-3, **PATCH, cache_dir="/tmp")
    with pytest.raises(railsim.InputError, match="extrapolation: model 'fastrip' does not use it .*: mim\\)"):
        railsim.contact("fastrip", 1e-3, **PATCH, extrapolation="none")
    # The options a model reads still pass.
    assert railsim.contact("fastsim", 1e-3, **PATCH, grid=10)["Fx"] < 0


def test_errors_are_python_exceptions_with_railsims_message():
    with pytest.raises(railsim.InputError, match="unknown.*(fastsim|known)"):
        railsim.contact("no_such_model", 1e-3, **PATCH)
    with pytest.raises(railsim.InputError, match="different lengths \\(xi 2, eta 3\\)"):
        railsim.contact("linear", [1e-3, 2e-3], [0.0, 0.0, 0.0], **PATCH)
    with pytest.raises(railsim.InputError, match="semi-axes"):
        railsim.contact("linear", 1e-3, a=6e-3, A=1.0, b=4e-3, Fz=75e3)
    with pytest.raises(railsim.InputError):
        railsim.contact("linear", 1e-3, a=-6e-3, b=4e-3, Fz=75e3)
    assert issubclass(railsim.NumericalError, ArithmeticError)


@pytest.mark.parametrize("arg, value, expect", [
    ("V", -1.0, r"V = -1: expected a value in \[0, 200\] m/s"),
    ("V", float("nan"), r"V = nan"),
    ("mu", 0.0, r"mu = 0: expected a value in \(0, 2\]"),
    ("nu", 0.5, r"nu = 0.5: expected a value in \[0, 0.5\)"),
    ("E", 1e20, r"E = 1e\+20"),
    ("Fz", float("inf"), r"Fz = inf"),
    ("xi", float("nan"), r"xi = nan: expected a finite number"),
    ("phi", [0.0, float("inf")], r"phi\[1\] = inf"),
])
def test_out_of_range_inputs_name_the_argument_and_the_range(arg, value, expect):
    args = dict(a=6e-3, b=4e-3, Fz=75e3)
    args[arg] = value
    for model in ("linear", "fastsim"):
        with pytest.raises(railsim.InputError, match=expect):
            railsim.contact(model, **args)
    if arg != "V":
        with pytest.raises(railsim.InputError, match=expect.split(":")[0].replace(r"\[1\]", "")):
            railsim.mim_fields(**{k: (v[1] if isinstance(v, list) else v) for k, v in args.items()}, grid=8)
    # The range's edge is accepted: V = 0 (no rolling speed given) and 200 m/s.
    for V in (0.0, 200.0):
        r = railsim.contact("fastsim", 1e-3, a=6e-3, b=4e-3, Fz=75e3, V=V)
        assert r["valid"] and r["Fx"] < 0.0


def test_hertz_patch_checks_the_ranges_of_contact():
    p = railsim.hertz_patch(A=2.0, B=10.0, Fz=75e3)
    assert 1e-3 < p["a"] < 1e-2 and p["Fz"] == 75e3
    for kwargs, expect in [
        (dict(A=1.0, B=1.0, Fz=1e300), r"Fz = 1e\+300: expected a value in \(0, 1e\+07\] N"),
        (dict(A=1.0, B=1.0, Fz=1e4, E=1.0), r"E = 1: expected a value in \[1e\+09, 1e\+13\] Pa"),
        (dict(a=1e100, b=1e100, Fz=1e4), r"a = 1e\+100: expected a value in \[1e-06, 1\] m"),
        (dict(A=1e-12, B=1e-12, Fz=1e4), r"semi-axis a \(from A, B and Fz\)"),
    ]:
        with pytest.raises(railsim.InputError, match=expect):
            railsim.hertz_patch(**kwargs)
    # contact() and mim_fields() take the same patches.
    with pytest.raises(railsim.InputError, match=r"point 0: the patch of A, B and Fz has semi-axes"):
        railsim.contact("linear", 1e-3, A=1e-12, B=1e-12, Fz=1e4)
    with pytest.raises(railsim.InputError, match=r"semi-axis a \(from A, B and Fz\)"):
        railsim.mim_fields(1e-3, A=1e-12, B=1e-12, Fz=1e4, grid=8)
