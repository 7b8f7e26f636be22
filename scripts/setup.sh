#!/usr/bin/env bash
# One entry point for a fresh Debian machine (run as root):
#   bash scripts/setup.sh run    install what is missing, build into build/, run the main job (vssw summary, then
#                                the validation report of the default suite into report/)
#   bash scripts/setup.sh test   install what is missing, build into build/, run the whole test suite
#   bash scripts/setup.sh build  install and build only
# Only Debian packages; apt-get runs only when one of them is missing.
set -euo pipefail

mode="${1:-run}"
case "$mode" in run|test|build) ;; *) echo "usage: bash scripts/setup.sh run|test|build" >&2; exit 2 ;; esac

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
packages=(
  cmake g++ ninja-build pkg-config   # toolchain
  libfmt-dev nlohmann-json3-dev libcli11-dev   # formatting, JSON output, command line
  libgtest-dev libbenchmark-dev      # tests and benchmarks
  libbullet-dev                      # the Bullet adapter (pkg-config bullet-float64)
  libode-dev                         # the ODE adapter (pkg-config ode, double precision)
  libsimbody-dev                     # the Simbody adapter (CMake config, C++17)
  libtomlplusplus-dev                # bounds files of `vssw check` (TOML)
  libeigen3-dev                      # linear algebra of the two-block roller model (analytic/two_block)
  gnuplot-nox                        # the plots of `vssw report` (SVG; without it the report is written unplotted)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null && sudo_cmd="sudo"
  echo "setup: installing ${missing[*]}" >&2
  $sudo_cmd env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  $sudo_cmd env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$here" -B "$here/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$here/build" -j "$jobs"

case "$mode" in
  run)
    "$here/build/vssw" summary
    echo
    echo "setup: writing the validation report of the default suite (about 40 s on 2 cores) into $here/report" >&2
    "$here/build/vssw" report --suite default --out "$here/report"
    ;;
  test) ctest --test-dir "$here/build" --output-on-failure -j "$jobs" ;;
  build) ;;
esac
