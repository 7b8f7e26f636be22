#!/usr/bin/env bash
# The Debian package on a fresh Debian 12 system (docs/guide/install.md, "The Debian package"): a minimal bookworm
# made by debootstrap in a temporary folder, the package installed there by apt with what it depends on, then, in a
# chroot (no source tree, no build folder, nothing of this machine's), `vssw --version`, the default validation
# report and `import vssw` running ODE. Not part of the test suite: it downloads about 300 MB and takes 5 to 10 minutes.
# Usage (as root): bash scripts/deb_fresh_machine.sh PACKAGE.deb [MIRROR]
set -euo pipefail
fail() { echo "deb_fresh_machine.sh: $*" >&2; exit 1; }
[ $# -ge 1 ] || fail "usage: bash scripts/deb_fresh_machine.sh PACKAGE.deb [MIRROR]"
deb="$1"
mirror="${2:-http://deb.debian.org/debian}"
[ "$(id -u)" -eq 0 ] || fail "run it as root (debootstrap and chroot need it)"
[ -f "$deb" ] || fail "no package file $deb (make one with: cd build && cpack -G DEB)"
command -v debootstrap >/dev/null || fail "debootstrap is missing (apt-get install debootstrap)"

root="$(mktemp -d /var/tmp/vssw-fresh.XXXXXX)"
chmod 755 "$root"  # a system's root folder: apt's unprivileged user reads its lists there
cleanup() {
  umount "$root/proc" 2>/dev/null || true
  rm -rf --one-file-system "$root"
  rm -f "$root.debootstrap.log"
}
trap cleanup EXIT
echo "deb_fresh_machine.sh: a minimal Debian 12 in $root" >&2
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
  fail "debootstrap failed: $(tail -3 "$root.debootstrap.log")"
rm -f "$root.debootstrap.log"
cp /etc/resolv.conf "$root/etc/resolv.conf"
# A fixed name inside the chroot: the path given reaches no shell.
cp -- "$deb" "$root/tmp/vssw.deb"
mount -t proc proc "$root/proc"

echo "deb_fresh_machine.sh: apt-get install ./vssw.deb" >&2
chroot "$root" /usr/bin/env DEBIAN_FRONTEND=noninteractive /bin/bash -c '
  set -eo pipefail
  apt-get update -qq
  apt-get install -y -qq /tmp/vssw.deb >/tmp/apt.log 2>&1 || { tail -20 /tmp/apt.log; exit 1; }
  echo "installed: $(grep -c "^Setting up" /tmp/apt.log) packages"
  cd /root
  vssw --version >/tmp/version.out
  head -1 /tmp/version.out
  vssw report --suite default --out /root/report >/tmp/report.out
  head -1 /tmp/report.out
  test -s /root/report/report.html
  python3 -c "
import vssw
run = vssw.simulate(\"ode\", height=4, thickness=0.4, hinge=0.7, theta0=0.5, t_end=1)
print(\"import vssw:\", vssw.__version__, vssw.__file__, \"ODE samples:\", len(run.t))
"' || fail "the installed package did not run (output above)"
echo "deb_fresh_machine.sh: $(basename "$deb") installs and runs on a fresh Debian 12"
