#!/usr/bin/env bash
# One entry point for a fresh Debian machine (run as root):
#   bash scripts/setup.sh run    install what is missing, build into build/, run the main job (vssw summary, then
#                                the validation report of the default suite into report/)
#   bash scripts/setup.sh test   install what is missing, build into build/, run the whole test suite; then the three
#                                parsers' fuzz harnesses built with libFuzzer, ASan and UBSan (clang) into
#                                build-asan/ and fuzzed (what CI runs: .ci/run)
#   bash scripts/setup.sh build  install and build only
#   bash scripts/setup.sh asan   install, then the whole suite built with ASan + UBSan (clang) into build-asan/ and
#                                run, the fuzz tests with libFuzzer (about 10 minutes on 2 cores: not in CI, run it
#                                before landing a change; docs/contributing/fuzzing-and-sanitizers.md "Sanitizers")
#   bash scripts/setup.sh profile  install and build, with the profilers the speed notes quote (callgrind, perf)
# Only Debian packages; apt-get runs only when one of them is missing.
set -euo pipefail

mode="${1:-run}"
case "$mode" in run|test|build|asan|profile) ;; *) echo "usage: bash scripts/setup.sh run|test|build|asan|profile" >&2; exit 2 ;; esac

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
packages=(
  cmake g++ ninja-build pkg-config   # toolchain
  git                                # the build's commit stamp, and the tests of the commit hook and the release
  libfmt-dev nlohmann-json3-dev libcli11-dev   # formatting, JSON output, command line
  libgtest-dev libbenchmark-dev      # tests and benchmarks
  libtomlplusplus-dev                # bounds files of `vssw check` (TOML)
  libeigen3-dev                      # linear algebra of the two-block roller model (analytic/two_block)
  hyperfine                          # timing whole commands side by side (medians; docs/measurements/speed.md)
  gnuplot-nox                        # the plots of `vssw report` and `vssw study` (SVG; without it: no plots)
  libopenmpi-dev openmpi-bin         # `mpirun -n P vssw study` (optional at build time; the MPI test needs it)
  parallel                           # GNU parallel: scripts/study_parallel.sh runs a study's shards (and its test)
  pybind11-dev python3-dev           # the Python module (python/, `import vssw`), built for Debian's /usr/bin/python3
  python3-numpy python3-pandas       # its traces (NumPy arrays) and study() as a DataFrame (pandas: optional at run time)
  python3-pytest                     # its tests (the CTest vssw_python)
  python3-venv python3-pip python3-setuptools python3-wheel  # `pip install --no-build-isolation .` into a
                                     # virtual environment (pyproject.toml, setup.py; the CTest vssw_pip_install)
  dpkg-dev file                      # `cpack -G DEB`: dpkg-shlibdeps computes the package's Depends, finding the
                                     # binaries with file (cmake/debian_package.cmake; the CTest vssw_deb_package)
  python3-markdown                   # tests/markdown_scan.py: report.md and study.md rendered as MkDocs does
  python3-matplotlib python3-pil     # Simulation.plot / animate (optional at run time), GIFs through Pillow, the wall sketch
  python3-nbclient python3-nbformat python3-ipykernel  # docs/notebooks/first-steps.ipynb run by its test (nbclient)
  mkdocs mkdocs-material             # the documentation site (mkdocs.yml; the CTest vssw_docs builds it with --strict)
  python3-pymdownx                   # its equations, marked by pymdownx.arithmatex (mkdocs-material depends on it too)
  libjs-mathjax                      # rendered by MathJax 2.7, copied into the site (scripts/mkdocs_mathjax.py)
)
# Each engine's packages, from the DEBIAN lines of its folder's multibody/<engine>/engine.cmake.
engine_packages="$(bash "$here/scripts/engine_packages.sh" "$here")"
mapfile -t -O "${#packages[@]}" packages <<< "$engine_packages"
# The sanitizer build (test and asan only, so `run` installs none of it): clang, its sanitizer and libFuzzer runtimes
# (libclang-rt-dev), and llvm for llvm-symbolizer, without which ASan and UBSan print stacks as bare addresses.
# About 65 MB to download, 300 MB installed.
case "$mode" in test|asan) packages+=(clang libclang-rt-dev llvm) ;; esac
# The test that renders report.html in a real browser (tests/cli/report_browser.sh, skipped without it): headless
# Chromium, test only (/usr/lib/chromium is 350 MB installed; `run` and `build` do not need it).
case "$mode" in test) packages+=(chromium) ;; esac
# The code-shape check (tests/code_shape.py) finds each function's extent with Universal Ctags; test only.
# The profilers behind the "where the time goes" figures of docs/ (instruction counts: valgrind's callgrind; samples:
# perf record); profile only. Whole commands are timed with hyperfine, above.
case "$mode" in profile) packages+=(valgrind linux-perf) ;; esac
case "$mode" in test) packages+=(universal-ctags) ;; esac
# The type checker the Python module's tests run over the package and a script typed against it
# (python/tests/test_types.py: its annotations and py.typed); test only, about 35 MB installed.
case "$mode" in test) packages+=(python3-mypy) ;; esac

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

# In a git work tree: the commit-msg hook (subjects of at most 72 characters; a hook of the clone's own is kept).
bash "$here/scripts/install_hooks.sh" "$here"

jobs="$(nproc 2>/dev/null || echo 2)"

# The whole suite built with AddressSanitizer and UndefinedBehaviorSanitizer by clang (docs/contributing/fuzzing-and-sanitizers.md "Sanitizers"), in its
# own folder. RelWithDebInfo with -gline-tables-only: -O2 keeps the engine suites fast enough, line tables give
# file:line in the reports at a fraction of full -g's compile and link time (CI's time is bounded). The
# benchmarks are not tests and are left out. The fuzz CTests (label fuzz) run there with libFuzzer.
sanitizer_configure() {
  CXX=clang++ cmake -S "$here" -B "$here/build-asan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVSSW_SANITIZE=ON \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -gline-tables-only -DNDEBUG" \
    -DVSSW_BUILD_BENCH=OFF >/dev/null
}
sanitizer_options() {
  # detect_leaks stays on (the default). strict_string_checks and detect_stack_use_after_return: more checks at
  # little cost. halt_on_error (UBSan): with -fno-sanitize-recover already fatal; print_stacktrace gives the stack.
  export ASAN_OPTIONS="strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
}
sanitizer_build_and_test() {
  sanitizer_configure
  cmake --build "$here/build-asan" -j "$jobs"
  sanitizer_options
  ctest --test-dir "$here/build-asan" --output-on-failure -j "$jobs" -E "$asan_excluded"
}
# In CI: only the three fuzz harnesses (the parsers compiled into them with libFuzzer's coverage, ASan and UBSan; a
# few files) and their tests. The whole suite under the sanitizers doubles the build and takes CI past its budget
# (measured: 16 min for `test` with it, docs/contributing/fuzzing-and-sanitizers.md "Sanitizers"); it is the `asan` mode.
sanitizer_fuzz() {
  sanitizer_configure
  cmake --build "$here/build-asan" -j "$jobs" --target fuzz_ground_motion fuzz_bounds_file fuzz_study_file
  sanitizer_options
  ctest --test-dir "$here/build-asan" --output-on-failure -j "$jobs" -L fuzz
}
# Left out of the sanitizer run (they run in the normal build): the two threshold bisections of Simbody's rigid
# contact (ThresholdMatchesTheAnalyticModel, OverburdenRaisesTheThresholdAsEq12Says). Each bisects on dozens of
# whole simulations, nearly all of it inside the uninstrumented Simbody library, where ASan finds little to check:
# 86 s and 187 s under ASan (32 s and 65 s without), three quarters of the sanitizer run's test time, for adapter
# code that the other simbody_rigid tests (period, restitutions, moving supports) run under ASan as well. CTest's
# names of these tests end in '  # GetParam() = ...', hence the ( |$).
asan_excluded='^Engines/CrossEngine\.(ThresholdMatchesTheAnalyticModel|OverburdenRaisesTheThresholdAsEq12Says)/simbody_rigid( |$)'

if [ "$mode" = asan ]; then
  sanitizer_build_and_test
  exit 0
fi

# The test run (CI) fails on a warning in the project's own code; the others only print it.
werror=OFF
[ "$mode" = test ] && werror=ON
cmake -S "$here" -B "$here/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DVSSW_WERROR="$werror" >/dev/null
cmake --build "$here/build" -j "$jobs"

case "$mode" in
  run)
    "$here/build/vssw" summary
    echo
    echo "setup: writing the validation report of the default suite (about 40 s on 2 cores) into $here/report" >&2
    "$here/build/vssw" report --suite default --out "$here/report"
    ;;
  test)
    ctest --test-dir "$here/build" --output-on-failure -j "$jobs"
    sanitizer_fuzz
    ;;
  build|profile) ;;
esac
