#!/usr/bin/env bash
# The picture of the report's top in README.md and docs/index.md (docs/img/report-top.png), from a report folder,
# with headless Chromium (Debian chromium; scripts/setup.sh installs it for `test`):
#   build/vssw report --out report && bash scripts/report_screenshot.sh report
set -euo pipefail
report="$(cd "${1:-report}" && pwd)"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
chromium --headless=new --no-sandbox --disable-gpu --hide-scrollbars --force-device-scale-factor=1 \
  --window-size=1200,1000 --screenshot="$here/docs/img/report-top.png" "file://$report/report.html" 2>/dev/null
echo "wrote $here/docs/img/report-top.png"
