#!/usr/bin/env bash
# cpack -G DEB makes the packages railsim (program, Python module, data, man
# page) and railsim-dev (libraries, headers, CMake package), installed under /usr.
#   test_deb.sh BUILD_DIR CPACK
set -euo pipefail
build="$1" cpack="$2"
work="$(mktemp -d "${TMPDIR:-/tmp}/railsim_deb.XXXXXX")"
trap 'rm -rf "$work"' EXIT
cd "$work"
"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$work" > cpack.log 2>&1 || { cat cpack.log; exit 1; }
run=$(ls "$work"/railsim_*.deb) dev=$(ls "$work"/railsim-dev_*.deb)
dpkg-deb -c "$run" > run.txt
dpkg-deb -c "$dev" > dev.txt
for f in ./usr/bin/railsim ./usr/share/railsim/railsim-data.txt ./usr/share/railsim/profiles/MBench_S1002_v3.prw \
         ./usr/share/man/man1/railsim.1 ./usr/lib/python3/dist-packages/railsim/__init__.py; do
  grep -qF " $f" run.txt || { echo "FAIL: $f not in $run"; exit 1; }
done
for f in ./usr/include/railsim/contact/registry.hpp ./usr/lib/cmake/railsim/railsimConfig.cmake ./usr/lib/librailsim_contact.a; do
  grep -qF " $f" dev.txt || { echo "FAIL: $f not in $dev"; exit 1; }
done
dpkg-deb -f "$run" Depends | tee depends.txt
grep -q "libsundials" depends.txt && grep -q "python3-numpy" depends.txt || { echo "FAIL: Depends"; exit 1; }
dpkg-deb -f "$dev" Depends | grep -q "railsim (= " || { echo "FAIL: railsim-dev Depends"; exit 1; }
echo "deb test passed: $(basename "$run") $(basename "$dev")"
