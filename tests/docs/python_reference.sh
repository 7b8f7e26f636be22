#!/usr/bin/env bash
# The Python API reference (docs/reference/python.md) is what scripts/gen_python_reference.py writes from the built
# module today: its --check passes on the committed page, and fails, naming the page, on a copy with one line changed.
#   tests/docs/python_reference.sh PYTHON BUILD_PYTHON_DIR SOURCE_DIR
set -euo pipefail
python="$1"
package="$2"
src="$3"
export PYTHONDONTWRITEBYTECODE=1
"$python" "$src/scripts/gen_python_reference.py" --python-path "$package" --check
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
sed '0,/^### vssw.simulate$/s//### vssw.simulate_renamed/' "$src/docs/reference/python.md" >"$out/python.md"
if "$python" "$src/scripts/gen_python_reference.py" --python-path "$package" --check --out "$out/python.md" \
     >"$out/check.txt" 2>&1; then
  echo "FAIL: --check passed a page that differs from the module"; exit 1
fi
if ! grep -q "$out/python.md is out of date" "$out/check.txt"; then
  echo "FAIL: the stale page was not named:"; cat "$out/check.txt"; exit 1
fi
echo "python reference: docs/reference/python.md is what the module gives"
