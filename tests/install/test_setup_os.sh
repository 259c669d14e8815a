#!/usr/bin/env bash
# scripts/setup.sh refuses the systems it does not support, with a clear
# message and before installing anything, and accepts Debian 12.
#   test_setup_os.sh SOURCE_DIR
set -euo pipefail
src="$1"
work="$(mktemp -d "${TMPDIR:-/tmp}/railsim_setup.XXXXXX")"
trap 'rm -rf "$work"' EXIT
check() {  # id version pretty expected-exit
  printf 'ID=%s\nVERSION_ID="%s"\nPRETTY_NAME="%s"\n' "$1" "$2" "$3" > "$work/os-release"
  set +e
  out="$(env -u RAILSIM_SETUP_ANY_SYSTEM RAILSIM_OS_RELEASE="$work/os-release" bash "$src/scripts/setup.sh" check 2>&1)"
  code=$?
  set -e
  [ "$code" = "$4" ] || { echo "FAIL: $3: exit $code, expected $4: $out"; exit 1; }
  echo "$3 -> exit $code: $(echo "$out" | head -1)"
  if [ "$4" != 0 ]; then
    echo "$out" | grep -q "supports Debian 12" || { echo "FAIL: $3: message: $out"; exit 1; }
    echo "$out" | grep -q "SUNDIALS >= 6" || { echo "FAIL: $3: message names no reason: $out"; exit 1; }
    echo "$out" | grep -q "installing" && { echo "FAIL: $3: installed before refusing"; exit 1; }
  fi
  return 0
}
check ubuntu 22.04 "Ubuntu 22.04.4 LTS" 1
check ubuntu 24.04 "Ubuntu 24.04 LTS" 1
check debian 13 "Debian GNU/Linux 13 (trixie)" 1
check fedora 40 "Fedora Linux 40" 1
check debian 12 "Debian GNU/Linux 12 (bookworm)" 0
rm "$work/os-release"
set +e
out="$(env -u RAILSIM_SETUP_ANY_SYSTEM RAILSIM_OS_RELEASE="$work/os-release" bash "$src/scripts/setup.sh" check 2>&1)"
code=$?
set -e
[ "$code" = 1 ] || { echo "FAIL: no os-release accepted"; exit 1; }
echo "setup test passed"
