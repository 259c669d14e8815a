#!/usr/bin/env bash
# One-step set-up for railsim on Debian 12 (bookworm).
#
#   bash scripts/setup.sh run    install what is missing, build, run the main job
#   bash scripts/setup.sh test   install what is missing, build, run all tests
#   bash scripts/setup.sh build  install what is missing and build only
#   bash scripts/setup.sh check  only check that this system is supported
#
# Supported: Debian 12. Other systems are refused before anything is installed
# (railsim needs SUNDIALS >= 6 and Catch2 v2: Ubuntu 22.04 has SUNDIALS 5.8,
# Ubuntu 24.04 and Debian 13 have Catch2 v3). RAILSIM_SETUP_ANY_SYSTEM=1 tries
# anyway; RAILSIM_OS_RELEASE names another os-release file (for the tests).
#
# Packages come from apt-get (sudo is used only when not root). The build uses
# the CMake preset "release", or "ci" (warnings are errors) when CI=true.
set -euo pipefail

mode="${1:-build}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"

os_release="${RAILSIM_OS_RELEASE:-/etc/os-release}"
os_id="" os_version="" os_name="unknown system"
if [ -r "$os_release" ]; then
  os_id="$(. "$os_release"; echo "${ID:-}")"
  os_version="$(. "$os_release"; echo "${VERSION_ID:-}")"
  os_name="$(. "$os_release"; echo "${PRETTY_NAME:-${ID:-unknown} ${VERSION_ID:-}}")"
fi
if [ "$os_id" != "debian" ] || [ "$os_version" != "12" ]; then
  if [ "${RAILSIM_SETUP_ANY_SYSTEM:-}" != "1" ]; then
    cat >&2 <<MSG
setup: $os_name is not supported. railsim's set-up supports Debian 12 (bookworm):
  it needs SUNDIALS >= 6 and Catch2 v2 from the system's packages
  (Ubuntu 22.04 ships SUNDIALS 5.8; Ubuntu 24.04 and Debian 13 ship Catch2 v3).
  Use a Debian 12 machine or container, or set RAILSIM_SETUP_ANY_SYSTEM=1 to try anyway.
MSG
    exit 1
  fi
  echo "setup: $os_name is not supported; trying anyway (RAILSIM_SETUP_ANY_SYSTEM=1)" >&2
fi
if [ "$mode" = "check" ]; then
  echo "setup: $os_name is supported"
  exit 0
fi

packages=(
  build-essential cmake ccache pkg-config git
  libeigen3-dev libsundials-dev libboost-dev libboost-math-dev
  libyaml-cpp-dev libspdlog-dev catch2 libcli11-dev libfftw3-dev
  libbenchmark-dev libopenmpi-dev openmpi-bin python3 python3-matplotlib
  nlohmann-json3-dev pybind11-dev python3-dev python3-numpy python3-pytest python3-yaml help2man
  binutils dpkg-dev file
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

preset=release
[ "${CI:-}" = "true" ] && preset=ci
cmake --preset "$preset"
cmake --build --preset "$preset"

case "$mode" in
  build) ;;
  run)
    mkdir -p results_out
    "build/$preset/railsim" critical-speed scenarios/manchester_coach_critical_speed.yaml \
      --reduction elastic_fe --out results_out/critical_speed
    ;;
  test)
    ctest --preset "$preset" -j2
    ;;
  *)
    echo "usage: bash scripts/setup.sh run|test|build|check" >&2
    exit 2
    ;;
esac
