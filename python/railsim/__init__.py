"""railsim: railway vehicle dynamics with pluggable wheel-rail contact.

The Python face of the railsim libraries (the same code as the ``railsim``
program). SI units inside (m, N, Pa, rad, 1/m); speeds in km/h and shifts in
mm where the program's options have them, said in the key names.

Contact models::

    import numpy as np, railsim
    xi = np.linspace(0, 0.01, 101)
    r = railsim.contact("fastsim", xi=xi, a=6e-3, b=4e-3, Fz=75e3, mu=0.3)
    r["Fx"], r["Fy"], r["Mz"], r["valid"]

Every registered model by name (``railsim.tangential_models()``); arrays
broadcast against each other and scalars. ``railsim.mim_fields(...)`` returns
the exact solver's pressure, traction and stick/slip fields.

Geometry: ``railsim.read_profile("S1002", "wheel")``,
``railsim.WheelRailGeometry("S1002", "UIC60", "1/40")`` with ``.solve(y)``,
``.table()`` and ``.conicity()``.

Scenarios: ``railsim.load_scenario(path)`` or ``railsim.scenario(dict)``;
``railsim.run(sc)`` (channels and summary), ``railsim.critical_speed(sc,
...)`` and ``railsim.modes(sc, ...)``.

Errors: ``railsim.InputError`` (a ValueError) for bad input, naming file,
line and key; ``railsim.NumericalError`` (an ArithmeticError) when the
numerics fail.
"""
import json as _json
import math as _math
import os as _os
import tempfile as _tempfile

import numpy as _np

from ._railsim import (InputError, NumericalError, Profile, Scenario, WheelRailGeometry, __version__, data_dir,
                       read_profile, shipped_profile_names, tangential_models)
from . import _railsim

__all__ = ["InputError", "NumericalError", "Profile", "Scenario", "WheelRailGeometry", "__version__", "contact",
           "critical_speed", "data_dir", "hertz_patch", "load_scenario", "mim_fields", "modes", "read_profile", "run",
           "RunResult", "scenario", "shipped_profile_names", "tangential_models"]

def _vector(name, value):
    a = _np.asarray(value, dtype=_np.float64)
    if a.ndim > 1:
        raise InputError(f"{name}: expected a scalar or a 1-D array (got shape {a.shape})")
    return a


def _shape_args(a, b, A, B):
    if (a is None) == (A is None) or (b is None) == (B is None) or (a is None) != (b is None):
        raise InputError("contact patch: give either the semi-axes a, b [m] or the curvatures A, B [1/m]")
    return (False, a, b) if a is not None else (True, A, B)


def _reduction(reduction):
    if reduction is None:
        return (1.0, 1.0, 1.0)
    if isinstance(reduction, str):
        return tuple(_railsim._parse_reduction(reduction))
    if _np.isscalar(reduction):
        return (float(reduction),) * 3
    k = tuple(reduction)
    if len(k) != 3:
        raise InputError("reduction: expected a preset name, one number k or (k11, k22, k23)")
    return k


def contact(model, xi=0.0, eta=0.0, phi=0.0, *, a=None, b=None, A=None, B=None, Fz, E=2.1e11, nu=0.28, mu=0.3,
            V=0.0, reduction=None, grid=0, tolerance=0.0, cache_dir="", extrapolation="default"):
    """Forces of the rail on the wheel of a registered tangential model.

    xi, eta [-], phi [1/m]: creepages; the patch from the semi-axes a, b [m] or
    the curvatures A, B [1/m] and the load Fz [N] (Hertz); material E [Pa],
    nu, mu; rolling speed V [m/s]; reduction: a preset ("elastic_fe", ...), one
    factor k or (k11, k22, k23); extrapolation (model "mim"): "default" or
    "richardson" (from grid N and N/2) or "none" (the grid's own forces, as
    CONTACT). Every argument may be an array; they broadcast.
    Returns a dict of arrays: Fx, Fy [N], Mz [N m], valid (bool), iterations,
    stick_fraction (-1: unknown), the patch a, b [m] and p0 [Pa] (numbers when
    the patch data are scalars, else arrays); reason: per
    point the index of its validity reason in reason_texts (0: valid, "").
    """
    curv, s1, s2 = _shape_args(a, b, A, B)
    k11, k22, k23 = _reduction(reduction)
    names = ["xi", "eta", "phi", "s1", "s2", "Fz", "E", "nu", "mu", "V", "k11", "k22", "k23"]
    values = [xi, eta, phi, s1, s2, Fz, E, nu, mu, V, k11, k22, k23]
    arrays = [_vector(n, v) for n, v in zip(names, values)]
    try:
        shape = _np.broadcast_shapes(*[x.shape for x in arrays])
    except ValueError:
        given = ", ".join(f"{n} {x.shape[0]}" for n, x in zip(names, arrays) if x.ndim == 1 and x.shape[0] != 1)
        raise InputError(f"contact: arrays of different lengths ({given}): give arrays of one length or scalars") \
            from None
    flat = [x.reshape(-1) if x.ndim == 1 else x.reshape(1) for x in arrays]
    r = _railsim._contact_solve(model, curv, *flat, grid=grid, tolerance=tolerance, cache_dir=cache_dir,
                                extrapolation=extrapolation)
    if shape == ():
        for key in ("Fx", "Fy", "Mz", "stick_fraction"):
            r[key] = float(r[key][0])
        r["valid"] = bool(r["valid"][0])
        r["iterations"] = int(r["iterations"][0])
        r["reason"] = r["reason_texts"][int(r["reason"][0])]
    return r


def hertz_patch(*, a=None, b=None, A=None, B=None, Fz, E=2.1e11, nu=0.28):
    """Hertz solution: A, B [1/m], a, b [m], p0 [Pa], approach [m], Fz [N]."""
    curv, s1, s2 = _shape_args(a, b, A, B)
    return _railsim.hertz_patch(s1, s2, curv, Fz, E, nu)


def mim_fields(xi=0.0, eta=0.0, phi=0.0, *, a=None, b=None, A=None, B=None, Fz, E=2.1e11, nu=0.28, mu=0.3, grid=0,
               tolerance=0.0):
    """The exact solver (MIM) on one Hertzian patch, with its fields.

    Returns x [m] (mx element centres), y [m] (my), pressure, px, py [Pa] as
    (my, mx) arrays, state (0 outside the contact, 1 adhesion, 2 slip), the
    totals Fx, Fy, Fz [N], Mz [N m], counts and converged: the grid's own
    solution (no extrapolation; contact(model="mim", extrapolation="none")).
    """
    curv, s1, s2 = _shape_args(a, b, A, B)
    return _railsim._mim_fields(s1, s2, curv, Fz, xi, eta, phi, E, nu, mu, grid=grid, tolerance=tolerance)


def load_scenario(path):
    """A scenario from a YAML file (scenarios/*.yaml)."""
    return _railsim._load_scenario(_os.fspath(path))


def scenario(spec, base_dir=".", name="<python dict>"):
    """A scenario from a dict with the keys of a scenario file; relative file
    names (vehicle, track, tables) are taken from base_dir. Errors name the
    line of the dict's JSON form (json.dumps(spec, indent=1)). A file name
    (str or path) is read as load_scenario(spec) does."""
    if isinstance(spec, (str, _os.PathLike)):
        return load_scenario(spec)
    text = _json.dumps(_plain(spec, ""), indent=1)
    return _railsim._scenario_from_text(text, name, _os.fspath(base_dir))


def _plain(v, key):
    """The spec with numpy scalars and arrays as Python numbers and lists and
    paths as strings; any other type is refused naming its key."""
    if isinstance(v, dict):
        return {k: _plain(x, f"{key}.{k}" if key else str(k)) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_plain(x, f"{key}[{i}]") for i, x in enumerate(v)]
    if isinstance(v, _np.ndarray):
        return _plain(v.tolist(), key)
    if isinstance(v, _np.generic):
        return v.item()
    if isinstance(v, _os.PathLike):
        return _os.fspath(v)
    if v is None or isinstance(v, (bool, int, float, str)):
        return v
    raise InputError(f"scenario: key '{key}': a {type(v).__name__} is not a scenario value "
                     "(numbers, strings, booleans, lists and dicts)")


def _scenario_of(sc):
    if isinstance(sc, Scenario):
        return sc
    if isinstance(sc, dict):
        return scenario(sc)
    return load_scenario(sc)


class RunResult:
    """Result of run(): channels (DataFrame when pandas is there, else a dict of
    arrays; as_dict() always the dict) and summary (the summary.json dict)."""

    def __init__(self, names, data, summary):
        self.names = list(names)
        self.data = data
        self.summary = summary
        self._dict = {n: data[:, i] for i, n in enumerate(self.names)}
        try:
            import pandas
            self.channels = pandas.DataFrame(data, columns=self.names)
        except ImportError:
            self.channels = self._dict

    def as_dict(self):
        return self._dict

    def __repr__(self):
        return f"<railsim.RunResult {self.data.shape[0]} rows x {len(self.names)} channels, status {self.summary.get('status')}>"


def run(sc, out=None):
    """Run a scenario (a Scenario, a dict or a YAML path). With out, also write
    out/channels.csv, out/summary.json and out/yq.png as `railsim run`."""
    r = _railsim._run(_scenario_of(sc), "" if out is None else _os.fspath(out))
    return RunResult(r["names"], r["data"], _json.loads(r["summary_json"]))


def _given(what, name, v):
    """A number given by the caller, or NaN (the C++ side's "not given") for None;
    a non-finite number is refused (NaN would read as "not given")."""
    if v is None:
        return float("nan")
    f = float(v)
    if not _math.isfinite(f):
        raise InputError(f"{what}: {name} = {v}: expected a finite number (omit it for the scenario's setting)")
    return f


def _whole(what, name, v):
    """An integer argument; 1.5 is refused rather than truncated."""
    f = float(v)
    if not (_math.isfinite(f) and f == int(f)):
        raise InputError(f"{what}: {name} = {v}: expected a whole number")
    return int(f)


def critical_speed(sc, method="bifurcation", *, model="", reduction="", v_min_kmh=None, v_max_kmh=None,
                   v_step_kmh=None, duration=None, disturbance_mm=None, small_disturbance_mm=None, threshold_mm=None,
                   deceleration=None, up_branch=True, continuation=None, threads=0, out=None):
    """Critical speed as `railsim critical-speed` (one run, no baseline):
    settings default to the scenario's critical_speed section. Returns a dict:
    critical_speed_kmh, linear_critical_speed_kmh (None when none found),
    points (bifurcation: arrays per sweep point, with each point's state:
    settled, growing, decaying, centred, stopped, failed, too_short) or
    ramping (the record), the settings. No critical speed is not always "no
    hunting": bifurcation's `undetermined` says why when a numerical failure
    or runs too short left no verdict (None otherwise; the program exits 3 or
    2 there), ramping's `derailment` when the ramp derailed. The sweep keeps its points in out/bifurcation.csv (resumable);
    without out a temporary folder is used."""
    sweep_only = dict(v_step_kmh=v_step_kmh, duration=duration, small_disturbance_mm=small_disturbance_mm,
                      continuation=continuation, up_branch=None if up_branch is True else up_branch)
    if method == "ramping":
        for name, value in sweep_only.items():
            if value is not None:
                raise InputError(f"critical_speed: {name} applies to the bifurcation sweep, not to ramping (which "
                                 "takes v_min_kmh, v_max_kmh, disturbance_mm, threshold_mm and deceleration)")
    elif deceleration is not None:
        raise InputError("critical_speed: deceleration applies to ramping (method=\"ramping\"), not to the "
                         "bifurcation sweep")
    s = _scenario_of(sc)
    cont = -1 if continuation is None else int(bool(continuation))
    args = (s, method, model, reduction if isinstance(reduction, str) else ",".join(map(str, _reduction(reduction))),
            *(_given("critical_speed", n, v) for n, v in (
                ("v_min_kmh", v_min_kmh), ("v_max_kmh", v_max_kmh), ("v_step_kmh", v_step_kmh),
                ("duration", duration), ("disturbance_mm", disturbance_mm),
                ("small_disturbance_mm", small_disturbance_mm), ("threshold_mm", threshold_mm),
                ("deceleration", deceleration))),
            bool(up_branch), cont, _whole("critical_speed", "threads", threads))
    if out is not None:
        return _railsim._critical_speed(*args, _os.fspath(out))
    with _tempfile.TemporaryDirectory(prefix="railsim_cs_") as tmp:
        return _railsim._critical_speed(*args, tmp)


def modes(sc, v_min_kmh=20.0, v_max_kmh=400.0, v_step_kmh=10.0, count=6):
    """Least damped oscillatory modes versus speed, as `railsim modes`: arrays
    speed_kmh, rank, frequency_hz, damping_ratio, real_1_s, imag_rad_s and the
    linear critical speed (None when stable throughout, or when already unstable at
    v_min_kmh: then unstable_at_v_min is True and the critical speed lies at or
    below v_min_kmh)."""
    return _railsim._modes(_scenario_of(sc), float(v_min_kmh), float(v_max_kmh), float(v_step_kmh),
                           _whole("modes", "count", count))
