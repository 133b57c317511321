#!/usr/bin/env bash
# The .deb on a clean Debian 13: packs the build with CPack, installs the
# package into an overlay over the clean root tools/setup made (the run-time
# packages only, no source tree, no build tree), lets apt remove every
# package the .deb does not depend on, and runs the installed programs there:
# `neptus --self-test` (every QML type and console, rendered), `neptus-msg
# list`, `neptus-sim --help`. A library or QML module the package forgets to
# depend on is gone by then, and the programs fail.
#
# Usage: check-deb.sh BUILD_DIR. Exit 77 (skipped, with the reason) without
# the clean root or the rights to mount an overlay and chroot into it.
set -uo pipefail
build=$1
root=${NEPTUS_INSTALL_ROOT:-}
if [ -z "$root" ] || [ ! -f "$root/.neptus-ready" ]; then
  echo "SKIPPED: no clean install root (tools/setup makes it; NEPTUS_INSTALL_ROOT is unset)"
  exit 77
fi
work=$(mktemp -d /tmp/neptus-deb-XXXXXX)
merged=$work/merged
mkdir -p "$work"/{upper,work,merged,pkg}
cleanup() {
  for m in "$merged/tmp/.X11-unix" "$merged/tmp" "$merged/proc" "$merged/dev" "$merged"; do
    mountpoint -q "$m" && umount -l "$m"
  done
  rm -rf "$work"
}
trap cleanup EXIT
if ! mount -t overlay overlay -o "lowerdir=$root,upperdir=$work/upper,workdir=$work/work" "$merged" 2>"$work/mount.err"; then
  echo "SKIPPED: cannot mount an overlay over the clean root here ($(cat "$work/mount.err")): the test needs root in its sandbox"
  exit 77
fi
mount --rbind /dev "$merged/dev" && mount -t proc proc "$merged/proc" && mount -t tmpfs tmpfs "$merged/tmp" || {
  echo "FAIL: cannot mount /dev, /proc and /tmp into the clean root"; exit 1; }
if [ -n "${DISPLAY:-}" ] && [ -d /tmp/.X11-unix ]; then
  mkdir -p "$merged/tmp/.X11-unix" && mount --bind /tmp/.X11-unix "$merged/tmp/.X11-unix"
fi
# A sanitizer build's programs run with the suite's sanitizer options; its
# leak suppressions are copied in (the source tree is not there).
lsan=${LSAN_OPTIONS:-}
if [[ $lsan =~ suppressions=([^:]+) ]]; then
  cp "${BASH_REMATCH[1]}" "$merged/tmp/lsan.supp" && lsan=${lsan/"${BASH_REMATCH[1]}"/\/tmp\/lsan.supp}
fi
in_root() { chroot "$merged" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
  DEBIAN_FRONTEND=noninteractive DISPLAY="${DISPLAY:-}" LIBGL_ALWAYS_SOFTWARE=1 QT_QPA_PLATFORM=xcb \
  ASAN_OPTIONS="${ASAN_OPTIONS:-}" UBSAN_OPTIONS="${UBSAN_OPTIONS:-}" LSAN_OPTIONS="$lsan" "$@"; }
failures=0
check() { if [ "$2" = 0 ]; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }

# Pack.
(cd "$work/pkg" && cpack -G DEB -B "$work/pkg" --config "$build/CPackConfig.cmake" >"$work/cpack.log" 2>&1)
deb=$(ls "$work"/pkg/neptus-qt_*.deb 2>/dev/null | head -1)
[ -n "$deb" ]; status=$? # taken before the description's $(…), which sets $? again
check "cpack made $(basename "${deb:-no .deb}")" $status
[ -n "$deb" ] || { tail -20 "$work/cpack.log"; exit 1; }
echo "Depends: $(dpkg-deb -f "$deb" Depends)"
contents=$(dpkg-deb -c "$deb")
grep -q "./usr/share/neptus-qt/msgdefs/imc.xml" <<<"$contents"; check "the package holds the message definitions" $?

# Install: every dependency must already be in the clean root (it has no network).
cp "$deb" "$merged/tmp/neptus-qt.deb"
in_root dpkg -i /tmp/neptus-qt.deb >"$work/dpkg.log" 2>&1; status=$?
check "dpkg -i in a clean Debian 13 root" $status
if [ $status != 0 ]; then
  grep -E "depends on|dependency" "$work/dpkg.log" | sed 's/^/  /'
  echo "  (a library dpkg-shlibdeps added belongs in tools/install-test-packages.txt)"
  exit 1
fi
# Only what the package depends on stays (and a desktop's OpenGL driver and font).
in_root sh -c 'apt-mark showmanual | xargs -r apt-mark auto >/dev/null &&
               apt-mark manual neptus-qt libgl1-mesa-dri fonts-dejavu-core >/dev/null &&
               apt-get -y -o APT::AutoRemove::RecommendsImportant=false -o APT::AutoRemove::SuggestsImportant=false autoremove --purge' >"$work/autoremove.log" 2>&1
status=$?
removed=$(grep '^Removing' "$work/autoremove.log" | awk '{print $2}' | tr '\n' ' ')
check "apt removed what the package does not depend on: ${removed:-nothing}" $status
[ $status = 0 ] || tail -5 "$work/autoremove.log" | sed 's/^/  /'

# Run the installed programs where nothing else is.
in_root test ! -e "$(cd "$(dirname "$0")/../.." && pwd)"; check "the source tree is not there" $?
in_root neptus-msg list >"$work/list.txt" 2>&1
grep -q "EstimatedState" "$work/list.txt"; status=$?
check "neptus-msg list reads the installed definitions ($(wc -l <"$work/list.txt") lines)" $status
in_root neptus-sim --help >/dev/null 2>&1; check "neptus-sim --help" $?
in_root neptus-mission targets --vehicle x8-02 >"$work/targets.txt" 2>&1
grep -q "^qgc-plan" "$work/targets.txt" && ! grep -q "missing" "$work/targets.txt"
check "neptus-mission targets finds the installed vehicles and stylesheets" $?
if [ -n "${DISPLAY:-}" ]; then
  in_root neptus --self-test >"$work/selftest.log" 2>&1; status=$?
  check "neptus --self-test from the package: $(grep -c ' ok$' "$work/selftest.log") types and consoles" $status
  [ $status = 0 ] || { grep "FAILED" "$work/selftest.log" || tail -15 "$work/selftest.log"; } | head -15 | sed 's/^/  /'
else
  echo "FAIL: no display for neptus --self-test (run through tools/test)"; failures=$((failures + 1))
fi
[ "$failures" = 0 ] && echo "the .deb installs and runs on a clean Debian 13" || exit 1
