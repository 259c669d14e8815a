#!/usr/bin/env python3
"""Cost of a contact model on 1e5 creepage points from Python against the
same loop in C++ (bench/bench_contact_loop.cpp), issue 18's target: Python
at most 10 % above the C++ loop.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/bench_python_contact.py build/release

Runs build/release/bench/bench_contact_loop (Google Benchmark, JSON output),
then times railsim.contact(model, xi, a=6e-3, b=4e-3, Fz=75e3) on the same
numpy.linspace(0, 0.01, 1e5) creepages (median of several calls against
Google Benchmark's median of 5 repetitions; run it on an idle machine), and
prints both and the ratio per model.
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
cxx = {}
for b in json.loads(p.stdout)["benchmarks"]:
    if b.get("aggregate_name") == "median":
        name = b["run_name"].split("/")[1]
        cxx[name] = b["real_time"] * {"ms": 1e-3, "us": 1e-6, "ns": 1e-9, "s": 1.0}[b["time_unit"]]

xi = np.linspace(0.0, 0.01, 100000)
print(f"{'model':<10} {'C++ loop [ms]':>14} {'Python [ms]':>12} {'ratio':>7}")
worst = 0.0
for model, t_cxx in cxx.items():
    reps = 5 if model == "fastsim" else 25
    times = []
    for _ in range(reps):
        t0 = time.perf_counter()
        railsim.contact(model, xi, a=6e-3, b=4e-3, Fz=75e3, mu=0.3)
        times.append(time.perf_counter() - t0)
    best = float(np.median(times))
    ratio = best / t_cxx
    worst = max(worst, ratio)
    print(f"{model:<10} {t_cxx * 1e3:>14.3f} {best * 1e3:>12.3f} {ratio:>7.3f}")
print(f"largest ratio Python / C++: {worst:.3f} ({'within' if worst <= 1.10 else 'ABOVE'} the 10 % target)")
