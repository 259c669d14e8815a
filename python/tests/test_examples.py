# The example scripts under examples/ run (short settings) and say what they should.
import csv
import os
import subprocess
import sys

from conftest import source


def _run(script, *args, cwd):
    p = subprocess.run([sys.executable, source("examples", script), *args], cwd=cwd, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True, env=os.environ.copy())
    assert p.returncode == 0, p.stdout
    return p.stdout


def test_creep_force_curves_example(tmp_path):
    out = _run("creep_force_curves.py", "--out", str(tmp_path), "--points", "13", "--mim-grid", "20", cwd=tmp_path)
    assert (tmp_path / "creep_force_curves.png").stat().st_size > 10000
    rows = {l.split()[0]: l for l in out.splitlines() if l.strip()}
    for m in ("linear", "fastsim", "chopaya", "polach"):
        assert m in rows, out
    # FASTSIM stays within 10 % of mu Fz of the exact solver on these curves.
    fastsim = [float(x.rstrip("%")) for x in rows["fastsim"].split()[1:]]
    assert max(fastsim) < 10.0, out


def test_friction_sweep_example(tmp_path):
    out = _run("friction_sweep.py", "--mu", "0.15,0.4", "--v-min", "240", "--v-max", "300", "--v-step", "30",
               "--duration", "3", "--out", str(tmp_path), cwd=tmp_path)
    with open(tmp_path / "friction_sweep.csv") as f:
        rows = list(csv.DictReader(f))
    assert [float(r["mu"]) for r in rows] == [0.15, 0.4]
    for r in rows:
        # The coach's Hopf bifurcation is subcritical: the limit cycle survives
        # below the linear critical speed, so the nonlinear one (the lowest
        # hunting speed of the down branch) is found and lies below it.
        assert r["critical_speed_kmh"] and r["linear_critical_speed_kmh"], out
        assert 270.0 <= float(r["critical_speed_kmh"]) <= 300.0, out
        assert float(r["critical_speed_kmh"]) < float(r["linear_critical_speed_kmh"]), out
    assert (tmp_path / "friction_sweep.png").exists()
