#!/usr/bin/env python3
"""Writes cases.yaml: the contact states of railsim's own exact reference set
for the tangential models with spin (README.md in this folder).

Patches: CONTACT's Hertzian cases of tests/data/reference/contact/
hertz_normal_analytic.csv with a/b = 0.2, 1, 1.33 (thesis_Rw460_Rr300) and 5,
Fz = 75 kN, steel (E 210 GPa, nu 0.28), mu = 0.3. Families per patch:
  lat_spin   eta x phi, all four sign combinations
  long_spin  xi x phi, all four sign combinations
  spin       pure spin, both signs, up to 5 1/m
  creep      pure longitudinal / lateral / combined creepage, both signs
  combined   xi, eta and phi together
Run:  python3 make_cases.py > cases.yaml
"""
import csv
import os

HERE = os.path.dirname(os.path.abspath(__file__))
HERTZ = os.path.join(HERE, "..", "..", "reference", "contact", "hertz_normal_analytic.csv")
PATCHES = [("aob0.2", "ellipse_aob0.2"), ("aob1", "ellipse_aob1"),
           ("aob1.33", "thesis_Rw460_Rr300"), ("aob5", "ellipse_aob5")]
CREEP = [0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01]
SPIN_COMB = [0.5, 1.0, 2.0]
SPIN_PURE = [0.1, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0]
PURE = [0.0005, 0.001, 0.002, 0.005]
COMBINED = [(0.001, 0.001, 1.0), (0.001, -0.001, 1.0), (-0.002, 0.0005, -0.5),
            (0.0005, -0.002, 2.0), (0.002, 0.002, -2.0), (-0.001, -0.001, 1.0),
            (0.0003, 0.0003, 0.3), (0.0003, -0.0003, 0.3)]


def signed(values):
    return [-v for v in reversed(values)] + list(values)


def main():
    rows = {r["case_id"]: r for r in csv.DictReader(open(HERTZ))}
    print("# railsim's exact reference set for tangential models with spin; written by make_cases.py")
    print("# (patches from tests/data/reference/contact/hertz_normal_analytic.csv). Solve with")
    print("#   railsim contact cases.yaml --model mim --grid 120 --tolerance 1e-8 --no-timing --out mim_grid120.csv")
    print("material: {E: 2.1e11, nu: 0.28, mu: 0.3}")
    print("cases:")
    for name, case in PATCHES:
        a = float(rows[case]["a_mm"]) * 1e-3
        b = float(rows[case]["b_mm"]) * 1e-3

        def emit(family, xi, eta, phi):
            print(f"  - {{id: {name}/{family}/{xi:g}/{eta:g}/{phi:g}, a: {a:.9g}, b: {b:.9g}, Fz: 75000, "
                  f"xi: {xi:g}, eta: {eta:g}, phi: {phi:g}}}")

        for phi in signed(SPIN_COMB):
            for eta in signed(CREEP):
                emit("lat_spin", 0.0, eta, phi)
        for phi in signed(SPIN_COMB):
            for xi in signed(CREEP):
                emit("long_spin", xi, 0.0, phi)
        for phi in signed(SPIN_PURE):
            emit("spin", 0.0, 0.0, phi)
        for v in signed(PURE):
            emit("creep", v, 0.0, 0.0)
            emit("creep", 0.0, v, 0.0)
        for xi, eta in [(0.001, 0.001), (0.002, -0.001), (-0.0005, 0.002)]:
            emit("creep", xi, eta, 0.0)
        for xi, eta, phi in COMBINED:
            emit("combined", xi, eta, phi)


if __name__ == "__main__":
    main()
