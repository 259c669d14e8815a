#!/usr/bin/env python3
"""Creep-force curves of every registered contact model against the exact
solver (MIM), through the railsim Python module: the notebook-style way of
doing what `railsim contact CASES.yaml --model M --out r.csv` does through files.

One Hertzian patch (a = 6 mm, b = 4 mm, Fz = 75 kN, steel, mu = 0.3); three
curves: longitudinal creepage xi, lateral creepage eta, and eta with spin
phi = 0.5 1/m. Each model is one vectorised call per curve (the loop runs in
C++). Prints the largest deviation of |F| from MIM's over each curve, in
per cent of mu Fz, and draws creep_force_curves.png (matplotlib).

    PYTHONPATH=build/release/python /usr/bin/python3 examples/creep_force_curves.py --out results_out/creep

Models built from cached tables (mim_table) are included only with --tabulated
(the first use builds the table: about 40 s on two cores).
"""
import argparse
import os

import numpy as np

import railsim

PATCH = {"a": 6.0e-3, "b": 4.0e-3, "Fz": 75.0e3}
MATERIAL = {"E": 2.1e11, "nu": 0.28, "mu": 0.3}


def curve_cases(points=41):
    """The three curves as arrays: name -> (xi, eta, phi)."""
    s = np.linspace(0.0, 0.006, points)
    z = np.zeros_like(s)
    return {"longitudinal": (s, z, z), "lateral": (z, s, z), "lateral_with_spin": (z, s, np.full_like(s, 0.5))}


def creep_curve(model, xi, eta, phi, **options):
    """Fx, Fy, Mz and validity of one model on one curve (railsim.contact)."""
    return railsim.contact(model, xi, eta, phi, **PATCH, **MATERIAL, **options)


def write_cases_yaml(path, xi, eta, phi):
    """The same points as a case file of `railsim contact` (numbers written
    with repr: the file holds the doubles exactly)."""
    with open(path, "w") as f:
        f.write("material: {E: %r, nu: %r, mu: %r}\ncases:\n" % (MATERIAL["E"], MATERIAL["nu"], MATERIAL["mu"]))
        for i, (x, e, p) in enumerate(zip(xi, eta, phi)):
            f.write("  - {id: p%d, a: %r, b: %r, Fz: %r, xi: %r, eta: %r, phi: %r}\n"
                    % (i, PATCH["a"], PATCH["b"], PATCH["Fz"], float(x), float(e), float(p)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="creep_force_curves", help="output folder")
    ap.add_argument("--points", type=int, default=41, help="points per curve")
    ap.add_argument("--mim-grid", type=int, default=30, help="MIM elements across the minor axis")
    ap.add_argument("--tabulated", action="store_true", help="also the models built from cached tables")
    ap.add_argument("--no-plot", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    models = [m["name"] for m in railsim.tangential_models()
              if m["name"] != "mim" and (m["compared_by_default"] or (args.tabulated and m["tabulated"]))]
    muN = MATERIAL["mu"] * PATCH["Fz"]
    results = {}
    print(f"{'model':<14}" + "".join(f"{c:>20}" for c in curve_cases(args.points)))
    for curve, (xi, eta, phi) in curve_cases(args.points).items():
        ref = creep_curve("mim", xi, eta, phi, grid=args.mim_grid)
        results[(curve, "mim")] = ref
        for m in models:
            results[(curve, m)] = r = creep_curve(m, xi, eta, phi)
            r["dev_pct"] = 100.0 * np.max(np.hypot(r["Fx"] - ref["Fx"], r["Fy"] - ref["Fy"])) / muN
    for m in models:
        print(f"{m:<14}" + "".join(f"{results[(c, m)]['dev_pct']:>19.2f}%" for c in curve_cases(args.points)))
    if not args.no_plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
        for ax, (curve, (xi, eta, phi)) in zip(axes, curve_cases(args.points).items()):
            x = xi if curve == "longitudinal" else eta
            comp = "Fx" if curve == "longitudinal" else "Fy"
            for m in models + ["mim"]:
                r = results[(curve, m)]
                ax.plot(x * 1e3, -r[comp] / muN, "k-" if m == "mim" else "-", lw=2.5 if m == "mim" else 1,
                        label="MIM (exact)" if m == "mim" else m)
            ax.set_title(curve.replace("_", " "))
            ax.set_xlabel("creepage [1e-3]")
            ax.set_ylabel(f"-{comp} / (mu Fz)")
            ax.grid(True, alpha=0.3)
        axes[0].legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, "creep_force_curves.png"), dpi=110)
        print("wrote", os.path.join(args.out, "creep_force_curves.png"))


if __name__ == "__main__":
    main()
