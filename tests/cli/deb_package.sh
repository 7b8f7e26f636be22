#!/usr/bin/env bash
# The Debian package (docs/guide/install.md, "The Debian package"): `cpack -G DEB` from the build folder, its fields,
# and its files run from a folder it is extracted into (dpkg-deb -x), from / and without the VSSW_* variables: the
# program finds the package's data, studies and plugins, and the package's Python module runs an engine. Not checked
# here: `apt install` itself (it would change this machine) and a machine without the source tree.
# Usage: deb_package.sh BUILD_DIR VERSION [PYTHON]   (PYTHON: the interpreter the module was built for; none: no module)
set -euo pipefail
build="$1"
version="$2"
python="${3:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "deb_package.sh: $*" >&2; exit 1; }

cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/pack" >"$work/cpack.log" 2>&1 ||
  fail "cpack failed: $(tail -5 "$work/cpack.log")"
deb="$work/pack/vssw_${version}_$(dpkg --print-architecture).deb"
[ -f "$deb" ] || fail "no $(basename "$deb") made: $(ls "$work/pack")"
for field in Maintainer Description Section; do
  [ -n "$(dpkg-deb -f "$deb" "$field")" ] || fail "the package has no $field field"
done
dpkg-deb -x "$deb" "$work/root"
root="$work/root"
[ -f "$root/usr/share/doc/vssw/copyright" ] || fail "no /usr/share/doc/vssw/copyright (the licence)"

# Depends: every package that owns a shared library the package's binaries load (their DT_NEEDED entries, looked up
# with dpkg -S here, not through dpkg-shlibdeps's tables), plus python3-numpy and the module's python3 when built.
multiarch="$(dpkg-architecture -qDEB_HOST_MULTIARCH)"
sonames=()
while IFS= read -r -d '' binary; do
  file -b "$binary" | grep -q '^ELF' || continue
  mapfile -t -O "${#sonames[@]}" sonames < <(readelf -d "$binary" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
done < <(find "$root/usr" -type f -print0)
mapfile -t sonames < <(printf '%s\n' "${sonames[@]}" | sort -u)
# One dpkg -S for all of them (each call reads dpkg's whole file list): lines "package:arch: /path/soname".
owners="$(dpkg -S "${sonames[@]/#/*/$multiarch/}" 2>/dev/null || true)"
expected=()
for soname in "${sonames[@]}"; do
  owner="$(echo "$owners" | grep -m1 "/$multiarch/$soname\$" | cut -d: -f1)"
  [ -n "$owner" ] || fail "no package owns $soname, which the package's binaries need"
  expected+=("$owner")
done
mapfile -t expected < <(printf '%s\n' "${expected[@]}" | sort -u)
[ -n "$python" ] && expected+=(python3-numpy python3)
# Whether DEPENDS names each expected package (a word of its own: libode8, not libode8-dev).
names_all() {
  local depends=" $(echo "$1" | tr ',|' '  ') " p
  for p in "${expected[@]}"; do
    [[ "$depends" == *" $p "* ]] || { echo "$p"; return 1; }
  done
}
depends="$(dpkg-deb -f "$deb" Depends)"
missing="$(names_all "$depends")" || fail "Depends lacks $missing: $depends"
# The check itself: with the ODE library's package taken out of the field, it must find it missing.
ode_package="$(printf '%s\n' "${expected[@]}" | grep -x 'libode[0-9]*' || true)"
if [ -n "$ode_package" ] && names_all "$(echo "$depends" | sed "s/\b$ode_package\b[^,]*,\?//")" >/dev/null; then
  fail "the Depends check did not notice $ode_package taken out"
fi
if [ -n "$python" ]; then
  minor="$("$python" -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1]}")')"
  [[ "$depends" == *"python3 (>= $minor)"* ]] || fail "Depends does not ask for python3 >= $minor: $depends"
fi

# The program, from / and with none of the VSSW_* variables: data, studies and plugins from the extracted package.
cd /
for v in $(env | sed -n 's/^\(VSSW_[A-Z_]*\)=.*/\1/p'); do unset "$v"; done
vssw="$root/usr/bin/vssw"
"$vssw" --version | grep -q "^vssw $version" || fail "--version does not say $version"
"$vssw" --version | grep -q "$root/usr/lib/vssw/plugins/vssw_engine_ode.so" ||
  fail "--version does not name the package's ODE plugin: $("$vssw" --version)"
"$vssw" summary >/dev/null
"$vssw" compare --engine ode --height 4 --thickness 0.4 --hinge 0.7 >/dev/null
"$vssw" report --suite default --engines ode --cases fig6-vssw --no-plots --out "$work/report" >/dev/null
grep -q '"engine": *"ode"' "$work/report/results.json" || fail "the report has no ODE row"
# Which data and suite it read: with the package's record moved away, and then its suite broken, each run must fail
# naming the package's file (not fall back on the source tree's).
record="$root/usr/share/vssw/data/NGA_no_1063_RRS228.AT2"
mv "$record" "$work/moved.AT2"
if out="$("$vssw" summary 2>&1)"; then fail "summary ran without the package's record"; fi
[[ "$out" == *"$record"* ]] || fail "the program did not read the package's data: $out"
mv "$work/moved.AT2" "$record"
suite="$root/usr/share/vssw/studies/validation-default.toml"
cp "$suite" "$work/suite.toml"
echo 'this line is not TOML' >>"$suite"
if out="$("$vssw" report --suite default --engines ode --cases fig6-vssw --no-plots --out "$work/r2" 2>&1)"; then
  fail "report ran on the package's broken suite (it read another one)"
fi
[[ "$out" == *"$suite"* ]] || fail "the program did not read the package's suite: $out"
cp "$work/suite.toml" "$suite"

# The Python module from Debian's dist-packages folder of the package, run by the Python it was built for.
if [ -n "$python" ]; then
  site="$root/usr/lib/python3/dist-packages"
  [ -f "$site/vssw/_install.py" ] || fail "no Python package in /usr/lib/python3/dist-packages/vssw"
  PYTHONPATH="$site" PYTHONDONTWRITEBYTECODE=1 "$python" -c '
import os, sys, vssw
root = sys.argv[1]
run = vssw.simulate("ode", height=4, thickness=0.4, hinge=0.7, theta0=0.5, t_end=0.3)
assert len(run.t) > 10, len(run.t)
assert vssw.__file__.startswith(root), vssw.__file__
assert str(vssw.data_dir()).startswith(root), vssw.data_dir()
assert os.environ["VSSW_PLUGIN_PATH"].startswith(root), os.environ["VSSW_PLUGIN_PATH"]
' "$root" || fail "the package's Python module did not run ODE on the package's files"
fi
echo "deb_package.sh: $(basename "$deb") ($(du -k "$deb" | cut -f1) kB) holds a vssw that runs from its own files"
