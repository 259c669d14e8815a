#!/usr/bin/env python3
"""Walk the README's quick examples: every line of every fenced block marked
```sh is run with bash from the source root, with the build folder's program
first on PATH (build/release in the README stands for this build's folder,
e.g. build/ci under the ci preset), and every ```python block with this
Python and the build's module on PYTHONPATH. Each must exit 0; the files a
command names after --out must exist afterwards. Long jobs (the main job) and
the set-up commands are in indented blocks, which are not walked.

    walk_readme.py SOURCE_DIR BUILD_DIR
"""
import os
import re
import shlex
import subprocess
import sys
import time

src, build = sys.argv[1], sys.argv[2]
text = open(os.path.join(src, "README.md")).read()
blocks = re.findall(r"^```sh\n(.*?)^```", text, flags=re.S | re.M)
commands = [l.strip() for b in blocks for l in b.splitlines() if l.strip() and not l.strip().startswith("#")]
if len(commands) < 5:
    sys.exit(f"README: expected at least 5 example commands in ```sh blocks, found {len(commands)}")
rel_build = os.path.relpath(build, src)
env = os.environ.copy()
env["PATH"] = os.path.abspath(build) + os.pathsep + env.get("PATH", "")
env["PYTHONPATH"] = os.path.join(os.path.abspath(build), "python")
failed = 0
for code in re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M):
    t0 = time.monotonic()
    p = subprocess.run([sys.executable, "-c", code], cwd=src, env=env, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    ok = p.returncode == 0
    print(f"{'ok  ' if ok else 'FAIL'} {time.monotonic() - t0:6.1f} s  python block: {code.splitlines()[0]} ...")
    if not ok:
        failed += 1
        print(p.stdout[-3000:])
for cmd in commands:
    run = cmd.replace("build/release", rel_build)
    t0 = time.monotonic()
    p = subprocess.run(["bash", "-c", run], cwd=src, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True)
    dt = time.monotonic() - t0
    ok = p.returncode == 0
    args = shlex.split(run)
    for i, a in enumerate(args[:-1]):
        if a == "--out" and not os.path.exists(os.path.join(src, args[i + 1])):
            ok = False
            p.stdout += f"\n--out {args[i + 1]} was not written"
    print(f"{'ok  ' if ok else 'FAIL'} {dt:6.1f} s  {cmd}")
    if not ok:
        failed += 1
        print(p.stdout[-3000:])
total = len(commands) + len(re.findall(r"^```python\n", text, flags=re.M))
print(f"{total - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
