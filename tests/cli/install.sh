#!/usr/bin/env bash
# `cmake --install` staged into a temporary folder (DESTDIR), then the installed program run from there: it must find
# the installed data, not the source tree's (README "Install"). Usage: install.sh BUILD_DIR
set -euo pipefail
build="$1"
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
DESTDIR="$stage" cmake --install "$build" --prefix /opt/vssw >/dev/null
prefix="$stage/opt/vssw"
vssw="$prefix/bin/vssw"
for f in bin/vssw share/vssw/data/table1.csv share/vssw/data/NGA_no_1063_RRS228.AT2 share/vssw/bounds/ci.toml \
         share/vssw/studies/validation-default.toml share/doc/vssw/LICENSE share/doc/vssw/CITATION.cff; do
  [ -e "$prefix/$f" ] || { echo "install.sh: $f was not installed" >&2; exit 1; }
done
cd /  # nothing relative to the source tree
unset VSSW_DATA_DIR
"$vssw" --version | grep -q '^vssw ' || { echo "install.sh: --version printed no version" >&2; exit 1; }
"$vssw" summary >/dev/null
# Which data it read: with the installed record removed, the summary must fail naming the installed path.
mv "$prefix/share/vssw/data/NGA_no_1063_RRS228.AT2" "$stage/moved.AT2"
if out="$("$vssw" summary 2>&1)"; then echo "install.sh: summary ran without the installed record" >&2; exit 1; fi
echo "$out" | grep -q "$prefix/share/vssw/data/NGA_no_1063_RRS228.AT2" ||
  { echo "install.sh: the installed vssw did not read the installed data: $out" >&2; exit 1; }
mv "$stage/moved.AT2" "$prefix/share/vssw/data/NGA_no_1063_RRS228.AT2"
# The environment variable comes first.
if out="$(VSSW_DATA_DIR="$stage/nowhere" "$vssw" summary 2>&1)"; then
  echo "install.sh: VSSW_DATA_DIR was not used" >&2; exit 1
fi
echo "$out" | grep -q "$stage/nowhere" || { echo "install.sh: VSSW_DATA_DIR was not used: $out" >&2; exit 1; }
"$vssw" check --bounds "$prefix/share/vssw/bounds/ci.toml" >/dev/null
# Which suite it read: with the installed default suite broken, the check must fail naming the installed file.
suite="$prefix/share/vssw/studies/validation-default.toml"
echo 'this line is not TOML' >>"$suite"
if out="$("$vssw" check --bounds "$prefix/share/vssw/bounds/ci.toml" 2>&1)"; then
  echo "install.sh: check ran on a broken installed suite (it read another one)" >&2; exit 1
fi
echo "$out" | grep -q "$suite" || { echo "install.sh: the installed vssw did not read the installed suite: $out" >&2; exit 1; }
echo "install.sh: installed vssw ran on its installed data"
