#!/usr/bin/env python3
"""Critical speed of the Manchester benchmark coach against the friction
coefficient, through the railsim Python module: the main job's scenario
(scenarios/manchester_coach_critical_speed.yaml) read as a dict, its mu
changed, and railsim.critical_speed run on the down branch for each value.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/friction_sweep.py --mu 0.2,0.3,0.4

Defaults sweep 200..350 km/h in 10 km/h steps (a few minutes on two cores);
the tests run a short version (--v-min 240 --v-max 300 --v-step 30 --mu 0.15,0.4).
Prints a table and writes friction_sweep.csv (and .png unless --no-plot).
"""
import argparse
import copy
import csv
import os

import yaml

import railsim


def scenario_dict(path):
    with open(path) as f:
        return yaml.safe_load(f)


def sweep(spec, base_dir, mus, **settings):
    """Critical speed per friction coefficient: list of (mu, result dict)."""
    out = []
    for mu in mus:
        s = copy.deepcopy(spec)
        s["contact"]["material"]["mu"] = mu
        s["name"] = f"{spec.get('name', 'scenario')}_mu{mu:g}"
        sc = railsim.scenario(s, base_dir=base_dir)
        out.append((mu, railsim.critical_speed(sc, up_branch=False, **settings)))
    return out


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    default = os.path.join(here, "..", "scenarios", "manchester_coach_critical_speed.yaml")
    if not os.path.exists(default):  # installed: the data folder's copy
        default = os.path.join(railsim.data_dir(), "scenarios", "manchester_coach_critical_speed.yaml")
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenario", default=default)
    ap.add_argument("--mu", default="0.2,0.3,0.4", help="comma-separated friction coefficients")
    ap.add_argument("--v-min", type=float, default=200.0)
    ap.add_argument("--v-max", type=float, default=350.0)
    ap.add_argument("--v-step", type=float, default=10.0)
    ap.add_argument("--duration", type=float, default=None, help="simulated time per point [s]")
    ap.add_argument("--out", default="friction_sweep")
    ap.add_argument("--no-plot", action="store_true")
    args = ap.parse_args()
    mus = [float(m) for m in args.mu.split(",") if m]
    spec = scenario_dict(args.scenario)
    os.makedirs(args.out, exist_ok=True)
    res = sweep(spec, os.path.dirname(os.path.abspath(args.scenario)), mus, v_min_kmh=args.v_min,
                v_max_kmh=args.v_max, v_step_kmh=args.v_step, duration=args.duration, continuation=False)
    print(f"{'mu':>6} {'critical speed [km/h]':>24} {'linear [km/h]':>16}")
    with open(os.path.join(args.out, "friction_sweep.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["mu", "critical_speed_kmh", "linear_critical_speed_kmh"])
        for mu, r in res:
            v, vl = r["critical_speed_kmh"], r["linear_critical_speed_kmh"]
            w.writerow([mu, "" if v is None else v, "" if vl is None else vl])
            print(f"{mu:>6.2f} {('none found' if v is None else f'{v:.0f}'):>24} "
                  f"{('none' if vl is None else f'{vl:.1f}'):>16}")
    if not args.no_plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot([m for m, r in res], [r["critical_speed_kmh"] or float("nan") for m, r in res], "o-",
                label="nonlinear (down branch)")
        ax.plot([m for m, r in res], [r["linear_critical_speed_kmh"] or float("nan") for m, r in res], "s--",
                label="linear (eigenvalues)")
        ax.set_xlabel("friction coefficient mu [-]")
        ax.set_ylabel("critical speed [km/h]")
        ax.grid(True, alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, "friction_sweep.png"), dpi=110)


if __name__ == "__main__":
    main()
