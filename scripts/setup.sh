#!/usr/bin/env bash
# One-step set-up for railsim on Debian/Ubuntu.
#
#   bash scripts/setup.sh run    install what is missing, build, run the main job
#   bash scripts/setup.sh test   install what is missing, build, run all tests
#   bash scripts/setup.sh build  install what is missing and build only
#
# Packages come from apt-get (sudo is used only when not root). The build uses
# the CMake preset "release", or "ci" (warnings are errors) when CI=true.
set -euo pipefail

mode="${1:-build}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"

packages=(
  build-essential cmake ccache pkg-config git
  libeigen3-dev libsundials-dev libboost-dev libboost-math-dev
  libyaml-cpp-dev libspdlog-dev catch2 libcli11-dev libfftw3-dev
  libbenchmark-dev libopenmpi-dev openmpi-bin python3 python3-matplotlib
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
    echo "usage: bash scripts/setup.sh run|test|build" >&2
    exit 2
    ;;
esac
