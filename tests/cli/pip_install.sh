#!/usr/bin/env bash
# `pip install --no-build-isolation --no-index .` into a fresh virtual environment with the system's site-packages
# (docs/guide/install.md, "pip"), reusing the build folder (VSSW_PIP_BUILD_DIR) instead of building the project again;
# then, from / and with no VSSW_* variables, the environment's `import vssw` and `vssw` run the analytic model and an
# engine on the environment's own plugins and data.
# Usage: pip_install.sh SOURCE_DIR BUILD_DIR PYTHON
set -euo pipefail
source_dir="$1"
build="$2"
python="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "pip_install.sh: $*" >&2; exit 1; }
for v in $(env | sed -n 's/^\(VSSW_[A-Z_]*\)=.*/\1/p'); do unset "$v"; done
export PYTHONDONTWRITEBYTECODE=1 PIP_DISABLE_PIP_VERSION_CHECK=1

"$python" -m venv --system-site-packages "$work/venv"
venv="$work/venv"
pip=("$venv/bin/python" -m pip install --no-build-isolation --no-index --no-cache-dir -q)
# A build folder that is not one: refused by name, nothing installed.
if out="$(VSSW_PIP_BUILD_DIR="$work/nowhere" VSSW_PIP_WORK_DIR="$work/pip" "${pip[@]}" "$source_dir" 2>&1)"; then
  fail "pip installed from a build folder that does not exist"
fi
[[ "$out" == *"vssw: error: VSSW_PIP_BUILD_DIR=$work/nowhere is not a CMake build folder"* ]] ||
  fail "a wrong VSSW_PIP_BUILD_DIR was not named: $out"
VSSW_PIP_BUILD_DIR="$build" VSSW_PIP_WORK_DIR="$work/pip" "${pip[@]}" "$source_dir" >"$work/pip.log" 2>&1 ||
  fail "pip install failed: $(tail -20 "$work/pip.log")"

cd /
"$venv/bin/vssw" --version | grep -q "$venv/lib/vssw/plugins/vssw_engine_ode.so" ||
  fail "the environment's vssw does not name its own ODE plugin: $("$venv/bin/vssw" --version)"
"$venv/bin/vssw" compare --engine ode --height 4 --thickness 0.4 --hinge 0.7 >/dev/null
script='
import os, sys, vssw
venv = sys.argv[1]
assert vssw.__file__.startswith(venv + "/lib/"), vssw.__file__
assert str(vssw.data_dir()).startswith(venv + "/share/vssw/"), vssw.data_dir()
assert os.environ["VSSW_PLUGIN_PATH"] == venv + "/lib/vssw/plugins", os.environ["VSSW_PLUGIN_PATH"]
wall = dict(height=4, thickness=0.4, hinge=0.7, theta0=0.5, t_end=0.3)
assert all(len(vssw.simulate(e, **wall).t) > 10 for e in ["analytic", "ode"])
shaken = vssw.simulate("analytic", height=4, thickness=0.4, hinge=0.7, record="records/kern1952-taft-021.at2", pga=0.3)
assert len(shaken.t) > 10
'
"$venv/bin/python" -c "$script" "$venv" || fail "the environment's vssw did not run on its own files"
# Which plugins it opened: with the environment's ODE plugin moved away, the run must fail naming that folder.
mv "$venv/lib/vssw/plugins/vssw_engine_ode.so" "$work/"
if out="$("$venv/bin/python" -c "$script" "$venv" 2>&1)"; then fail "ODE ran without the environment's plugin"; fi
[[ "$out" == *"$venv/lib/vssw/plugins"* ]] || fail "a missing plugin was not named in the environment: $out"
echo "pip_install.sh: the virtual environment's vssw runs on its own plugins and data"
