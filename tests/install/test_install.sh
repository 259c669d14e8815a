#!/usr/bin/env bash
# Install into a temporary prefix and use the installation as a user would,
# from another folder, with RAILSIM_DATA_DIR, RAILSIM_PROFILE_DIR and
# RAILSIM_CACHE_DIR unset: the program finds its data relative to itself (no
# source or build path in the installed binaries), runs the main job (a short
# sweep of the same scenario, charts included), the Python module imports from
# the prefix, and a consumer project builds with find_package(railsim).
#   test_install.sh BUILD_DIR SOURCE_DIR CMAKE PYTHON
set -euo pipefail
build="$1" src="$2" cmake="$3" python="$4"
work="$(mktemp -d "${TMPDIR:-/tmp}/railsim_install.XXXXXX")"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
fail() { echo "FAIL: $*" >&2; exit 1; }

"$cmake" --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }

for f in bin/railsim lib/librailsim_contact.a lib/librailsim_analysis.a lib/librailsim_core.a \
         include/railsim/contact/registry.hpp include/railsim/core/version.hpp include/railsim/core/errors.hpp \
         lib/cmake/railsim/railsimConfig.cmake lib/cmake/railsim/railsimTargets.cmake \
         lib/python3/dist-packages/railsim/__init__.py \
         share/railsim/railsim-data.txt share/railsim/profiles/MBench_S1002_v3.prw share/railsim/profiles/NOTICE.md \
         share/railsim/plots/render_chart.py share/railsim/vehicles/manchester_coach.yaml \
         share/railsim/vehicles/contact_tables/RSGEO_S1002_UIC60_1in40.dat share/railsim/vehicles/contact_tables/NOTICE.md \
         share/railsim/tracks/curve_R300.yaml share/railsim/scenarios/manchester_coach_critical_speed.yaml \
         share/man/man1/railsim.1 share/doc/railsim/LICENSE; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
ls "$prefix"/lib/python3/dist-packages/railsim/_railsim*.so > /dev/null || fail "Python module not installed"
grep -q '^\.SH ENVIRONMENT' "$prefix/share/man/man1/railsim.1" || fail "man page without ENVIRONMENT section"
# Installed headers include each other as <railsim/...> only.
if grep -rnE '#include "(core|config|results|contact|track|engine)/' "$prefix/include/railsim" | head -3 | grep .; then
  fail "installed headers include project headers without the railsim/ prefix"
fi
# No source or build path compiled into the installed binaries. Debug
# information is left out of the check: a RelWithDebInfo build (the asan
# preset) names its compile folders there (DW_AT_comp_dir), which the program
# never reads; the code and data it runs with must name none.
for b in "$prefix/bin/railsim" "$prefix"/lib/python3/dist-packages/railsim/_railsim*.so; do
  strip --strip-debug -o "$work/no_debug" "$b" || fail "strip --strip-debug $b"
  if strings "$work/no_debug" | grep -F -e "$src/" -e "$build/" | head -3 | grep .; then fail "$b names a source or build path"; fi
done

run() { env -u RAILSIM_DATA_DIR -u RAILSIM_PROFILE_DIR -u RAILSIM_CACHE_DIR XDG_CACHE_HOME="$work/cache" \
            PATH="$prefix/bin:/usr/bin:/bin" "$@"; }
mkdir -p "$work/elsewhere" && cd "$work/elsewhere"
[ "$(run railsim --version)" = "railsim $(sed -n 's/^railsim \([0-9.]*\) .*/\1/p' "$prefix/share/railsim/railsim-data.txt")" ] \
  || fail "railsim --version: $(run railsim --version)"
run railsim version | grep -qF "data folder   $prefix/share/railsim" || { run railsim version; fail "data folder"; }

# The main job (critical speed of the coach with and without the reduction), on a short sweep whose
# lowest speed does not hunt (a sweep hunting at its lowest speed has no critical speed, exit 2).
data="$prefix/share/railsim"
run railsim critical-speed "$data/scenarios/manchester_coach_critical_speed.yaml" --reduction elastic_fe \
    --v-min 200 --v-max 300 --v-step 100 --no-up-branch --no-continuation --duration 2 --out cs > cs.log 2>&1 || { cat cs.log; fail "main job"; }
for f in cs/summary.json cs/bifurcation.csv cs/bifurcation.png cs/bifurcation_reduction.png cs/unreduced/bifurcation.csv; do
  [ -s "$f" ] || { cat cs.log; fail "main job did not write $f"; }
done
if grep -q "not found" cs.log; then cat cs.log; fail "main job could not find a data file"; fi
"$python" -c "import json,sys; s=json.load(open('cs/summary.json')); sys.exit(0 if s['linear_critical_speed_kmh'] and s['unreduced'] else 1)" \
  || fail "summary.json of the main job"
# Shipped profiles by name, and a run with its chart.
run railsim conicity --wheel S1002 --rail UIC60 --inclination 1/40 > con.log 2>&1 || { cat con.log; fail "conicity"; }
grep -q '^3,0\.' con.log || { cat con.log; fail "conicity output"; }
run railsim run "$data/scenarios/single_wheelset.yaml" --out run > run.log 2>&1 || { cat run.log; fail "run"; }
[ -s run/yq.png ] || { cat run.log; fail "run: no yq.png (chart script not found?)"; }
# A missing data folder is a clear error, not a crash.
if env RAILSIM_DATA_DIR="$work/nothing" XDG_CACHE_HOME="$work/cache" "$prefix/bin/railsim" conicity --wheel S1002 \
     --rail UIC60 > bad.log 2>&1; then fail "bad RAILSIM_DATA_DIR accepted"; fi
[ "$(env RAILSIM_DATA_DIR="$work/nothing" "$prefix/bin/railsim" conicity --wheel S1002 > /dev/null 2>&1; echo $?)" = 2 ] \
  || fail "bad RAILSIM_DATA_DIR: exit code is not 2"
grep -q "RAILSIM_DATA_DIR" bad.log || { cat bad.log; fail "bad RAILSIM_DATA_DIR message"; }

# The installed Python module.
run env PYTHONPATH="$prefix/lib/python3/dist-packages" "$python" - "$prefix" <<'PY' || fail "installed Python module"
import sys, railsim
prefix = sys.argv[1]
assert railsim.__file__.startswith(prefix), railsim.__file__
assert railsim.data_dir() == prefix + "/share/railsim", railsim.data_dir()
assert railsim.read_profile("S1002", "wheel").y.size > 100
r = railsim.contact("fastsim", [1e-3, 2e-3], a=6e-3, b=4e-3, Fz=75e3)
assert (r["Fx"] < 0).all()
print("python ok", railsim.__version__)
PY

# A consumer project: find_package(railsim), railsim::railsim. It is compiled
# and linked with the build's own flags, so a sanitizer build's (instrumented)
# static libraries link into an instrumented consumer.
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
"$cmake" -S "$src/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$(cache_value CMAKE_CXX_FLAGS)" -DCMAKE_EXE_LINKER_FLAGS="$(cache_value CMAKE_EXE_LINKER_FLAGS)" \
  > "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; fail "consumer configure"; }
"$cmake" --build "$work/consumer" -j2 >> "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; fail "consumer build"; }
grep -q -- "-I$src" "$work/consumer/compile_commands.json" && fail "consumer compiled against the source tree"
out="$(run "$work/consumer/railsim_consumer")" || fail "consumer run: $out"
echo "$out"
echo "$out" | grep -q "railsim $(run railsim --version | cut -d' ' -f2)" || fail "consumer output"
echo "install test passed: $prefix"
