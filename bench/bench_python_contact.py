#!/usr/bin/env python3
"""Cost of a contact model on 1e5 creepage points from Python against the
same loop in C++ (bench/bench_contact_loop.cpp), issue 18's target: Python
at most 10 % above the C++ loop.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/bench_python_contact.py build/release

Runs build/release/bench/bench_contact_loop (Google Benchmark, JSON output),
then times railsim.contact(model, xi, a=6e-3, b=4e-3, Fz=75e3) on the same
numpy.linspace(0, 0.01, 1e5) creepages (median of several calls against
Google Benchmark's median of 5 repetitions), and prints both, wall and CPU
time, and their ratios per model. The target is judged on CPU time (the
process's own, steadier on a shared machine); on an idle machine the wall
ratios agree.
"""
import json
import os
import subprocess
import sys
import time

import numpy as np

import railsim

build = sys.argv[1] if len(sys.argv) > 1 else "build/release"
exe = os.path.join(build, "bench", "bench_contact_loop")
p = subprocess.run([exe, "--benchmark_format=json", "--benchmark_repetitions=5",
                    "--benchmark_report_aggregates_only=true"], stdout=subprocess.PIPE, text=True, check=True)
cxx = {}  # model -> (wall, CPU) [s]
for b in json.loads(p.stdout)["benchmarks"]:
    if b.get("aggregate_name") == "median":
        unit = {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1.0}[b["time_unit"]]
        kind, model = b["run_name"].split("/")[:2]
        if kind == "BM_ContactLoop":
            cxx[model] = (b["real_time"] * unit, b["cpu_time"] * unit)
        else:
            print(f"C++ loop allocating its outputs per call, {model}: {b['real_time'] * unit * 1e3:.3f} ms wall, "
                  f"{b['cpu_time'] * unit * 1e3:.3f} ms CPU")

xi = np.linspace(0.0, 0.01, 100000)
print(f"{'model':<10} {'C++ wall [ms]':>14} {'Python wall':>12} {'ratio':>6}   {'C++ CPU [ms]':>13} {'Python CPU':>11} {'ratio':>6}")
worst = 0.0
for model, (w_cxx, c_cxx) in cxx.items():
    reps = 5 if model == "fastsim" else 25
    walls, cpus = [], []
    for _ in range(reps):
        t0, c0 = time.perf_counter(), time.process_time()
        railsim.contact(model, xi, a=6e-3, b=4e-3, Fz=75e3, mu=0.3)
        walls.append(time.perf_counter() - t0)
        cpus.append(time.process_time() - c0)
    w, c = float(np.median(walls)), float(np.median(cpus))
    worst = max(worst, c / c_cxx)
    print(f"{model:<10} {w_cxx * 1e3:>14.3f} {w * 1e3:>12.3f} {w / w_cxx:>6.3f}   {c_cxx * 1e3:>13.3f} {c * 1e3:>11.3f} "
          f"{c / c_cxx:>6.3f}")
print(f"largest CPU-time ratio Python / C++: {worst:.3f} ({'within' if worst <= 1.10 else 'ABOVE'} the 10 % target)")
