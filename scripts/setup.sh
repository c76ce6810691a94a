#!/usr/bin/env bash
# One-step set-up on Debian 12: install what is missing from Debian's
# packages, configure and build, then
#   setup.sh run   build in Release (build-release/) and run the default
#                  benchmark (B1b) in ./output
#   setup.sh test  build in Debug (build-debug/) and run the whole test suite
set -euo pipefail

mode=${1:-run}
case "$mode" in
  run | test) ;;
  *)
    echo "usage: $0 run|test" >&2
    exit 2
    ;;
esac
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

packages=(libdeal.ii-dev cmake g++ make numdiff ccache perl openmpi-bin procps)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" ||
    missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing from Debian's packages: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

jobs=$(nproc)
if [ "$mode" = run ]; then
  build="$root/build-release"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$build" -j "$jobs" --target mpm-otm
  "$build/mpm-otm" --overwrite
  echo "Output is in $(pwd)/output; open output/particles.pvd in ParaView."
else
  build="$root/build-debug"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Debug
  cmake --build "$build" -j "$jobs"
  # Open MPI refuses to start as root unless told otherwise.
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  cd "$build"
  ctest -j "$jobs" --output-on-failure
fi
