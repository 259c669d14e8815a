#!/usr/bin/env python3
"""Writes cases.yaml: deep-slip contact states with spin (issue 15).

Small patches (545 N, the load of a flange-root patch in the main job's
contact audit) with creepage 1, 3 and 10 times (xi, eta) = (0.00504, 0.00346)
and spin 0.633 1/m, every sign combination of (xi, eta, phi), on a/b 0.25, 1,
2.7 and 5. Solve with
  railsim contact cases.yaml --model mim --grid 60 --tolerance 1e-8 --no-timing --out mim_grid60.csv
"""
patches = {"aob0.25": (0.0005, 0.002), "aob1": (0.00092, 0.00092), "aob2.7": (0.001515613111, 0.0005599518435),
           "aob5": (0.002, 0.0004)}
with open("cases.yaml", "w") as out:
    out.write("# Deep-slip states with spin; written by make_cases.py (command there).\n")
    out.write("material: {E: 2.1e11, nu: 0.28, mu: 0.3}\ncases:\n")
    for name, (a, b) in patches.items():
        for scale in (1, 3, 10):
            for sx in (1, -1):
                for se in (1, -1):
                    for sp in (1, -1):
                        out.write("  - {id: %s/x%d/%+d%+d%+d, a: %g, b: %g, Fz: 545.27, xi: %g, eta: %g, phi: %g}\n"
                                  % (name, scale, sx, se, sp, a, b, sx * 0.00504 * scale, se * 0.00346 * scale,
                                     sp * 0.633))
