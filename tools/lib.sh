# Shared by tools/setup, tools/dev, tools/run and tools/test: where the build
# environment lives and how a command enters it. Sourced, never run.
#
# Two modes:
#   native  Debian 13 or newer: the packages are installed on the host itself.
#   root    an older Debian/Ubuntu host: a Debian 13 root made by debootstrap in
#           the user's cache, entered with bubblewrap.
# Either way a command runs under bubblewrap, so tests get a private network
# namespace (loopback only) and a private PID namespace (nothing outlives them).

set -euo pipefail

NQ_CHECKOUT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
NQ_SHARED=$(cd "$NQ_CHECKOUT/.." && pwd)/shared
NQ_PACKAGES_FILE=$NQ_CHECKOUT/tools/packages.txt
NQ_CACHE=${XDG_CACHE_HOME:-$HOME/.cache}/neptus-qt
NQ_CCACHE_DIR=${NEPTUS_CCACHE_DIR:-$NQ_CACHE/ccache}
NQ_MIRROR=${NEPTUS_DEBIAN_MIRROR:-http://deb.debian.org/debian}
NQ_SUITE=trixie
# Bump when the way the root is made changes, so that old roots are replaced.
NQ_ROOT_RECIPE=1
NQ_BUILD_PRESET=${NEPTUS_PRESET:-dev}
NQ_BUILD_DIR=$NQ_CHECKOUT/build/$NQ_BUILD_PRESET
NQ_BINDS=()

if [ -t 2 ]; then NQ_BOLD=$'\033[1m' NQ_RED=$'\033[1;31m' NQ_PLAIN=$'\033[0m'; else NQ_BOLD= NQ_RED= NQ_PLAIN=; fi
nq_say() { printf '%sneptus-qt:%s %s\n' "$NQ_BOLD" "$NQ_PLAIN" "$*" >&2; }
nq_die() { printf '%sneptus-qt: error:%s %s\n' "$NQ_RED" "$NQ_PLAIN" "$*" >&2; exit 1; }

nq_packages() { sed -e 's/#.*//' -e 's/[[:space:]]//g' "$NQ_PACKAGES_FILE" | grep -v '^$'; }

# The Python test peers (tools/python-packages.txt), pinned, in a venv: its
# folder as seen inside the environment, and on the host.
nq_python_packages() { sed -e 's/#.*//' -e 's/[[:space:]]//g' "$NQ_CHECKOUT/tools/python-packages.txt" | grep -v '^$'; }
nq_python_hash() { { nq_python_packages; echo "$NQ_SUITE"; } | sha256sum | cut -c1-12; }
nq_python_dir() {
  if [ "$(nq_mode)" = native ]; then echo "$NQ_CACHE/python"; else echo /opt/neptus-python; fi
}
nq_python_host_dir() {
  if [ "$(nq_mode)" = native ]; then echo "$NQ_CACHE/python"; else echo "$(nq_root_dir)/opt/neptus-python"; fi
}

nq_root_dir() {
  local hash
  hash=$({ nq_packages; echo "$NQ_SUITE recipe $NQ_ROOT_RECIPE"; } | sha256sum | cut -c1-12)
  echo "$NQ_CACHE/root-$hash"
}

# The clean Debian 13 root the install test installs the .deb into: the
# run-time packages only (tools/runtime-packages.txt, tools/install-test-packages.txt).
nq_install_root_packages() {
  sed -e 's/#.*//' -e 's/[[:space:]]//g' "$NQ_CHECKOUT/tools/runtime-packages.txt" \
    "$NQ_CHECKOUT/tools/install-test-packages.txt" | grep -v '^$' | sort -u
}
nq_install_root_dir() {
  local hash
  hash=$({ nq_install_root_packages; echo "$NQ_SUITE recipe $NQ_ROOT_RECIPE"; } | sha256sum | cut -c1-12)
  echo "$NQ_CACHE/install-root-$hash"
}

# native or root; NEPTUS_ENV=native|root overrides the guess.
nq_mode() {
  if [ -n "${NEPTUS_ENV:-}" ]; then echo "$NEPTUS_ENV"; return; fi
  local id="" version="" like=""
  if [ -r /etc/os-release ]; then
    id=$(. /etc/os-release; echo "${ID:-}")
    version=$(. /etc/os-release; echo "${VERSION_ID:-}")
    like=$(. /etc/os-release; echo "${ID_LIKE:-}")
  fi
  if [ "$id" = debian ]; then
    # testing/unstable have no VERSION_ID: they are newer than 13.
    if [ -z "$version" ] || [ "${version%%.*}" -ge 13 ]; then echo native; else echo root; fi
    return
  fi
  # Another apt-based distribution: native when its Qt is 6.8 or newer.
  if command -v apt-cache >/dev/null; then
    local qt
    qt=$(apt-cache policy qt6-base-dev 2>/dev/null | awk '/Candidate:/ {print $2}')
    if [ -n "$qt" ] && [ "$qt" != "(none)" ] && dpkg --compare-versions "$qt" ge 6.8; then
      echo native
    else
      echo root
    fi
    return
  fi
  nq_die "unsupported host '${id:-unknown} ${like}': tools/setup needs an apt-based system (Debian 12+ or Ubuntu)."
}

# Runs a command as root on the host: directly when we are root, else via sudo.
nq_as_root() {
  if [ "$(id -u)" = 0 ]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else nq_die "this step needs root and sudo is missing: run 'tools/setup' once as root."
  fi
}

nq_ready() {
  [ -f "$(nq_install_root_dir)/.neptus-ready" ] || return 1
  [ "$(cat "$(nq_python_host_dir)/.neptus-ready" 2>/dev/null)" = "$(nq_python_hash)" ] || return 1
  if [ "$(nq_mode)" = native ]; then
    [ -f "$NQ_CACHE/native-ready" ] && [ "$(cat "$NQ_CACHE/native-ready")" = "$(nq_packages | sha256sum)" ] \
      && command -v bwrap >/dev/null
  else
    [ -f "$(nq_root_dir)/.neptus-ready" ] && command -v bwrap >/dev/null
  fi
}

nq_ensure_setup() {
  nq_ready || "$NQ_CHECKOUT/tools/setup"
}

# nq_enter [--net] [--gui] [--] CMD ARGS...
# Runs CMD inside the build environment. Without --net it has only loopback.
nq_enter() {
  local net=0 gui=0
  while [ $# -gt 0 ]; do
    case "$1" in
      --net) net=1; shift ;;
      --gui) gui=1; shift ;;
      --) shift; break ;;
      *) break ;;
    esac
  done
  local args=()
  if [ "$(nq_mode)" = native ]; then
    args+=(--bind / /)
  else
    args+=(--bind "$(nq_root_dir)" /)
  fi
  mkdir -p "$NQ_CCACHE_DIR" "$NQ_CACHE/home"
  args+=(--dev /dev --proc /proc --tmpfs /tmp
         --bind "$NQ_CHECKOUT" "$NQ_CHECKOUT"
         --bind "$NQ_CCACHE_DIR" "$NQ_CCACHE_DIR"
         --unshare-pid --unshare-ipc --unshare-uts --die-with-parent
         --clearenv
         --setenv PATH "$NQ_BUILD_DIR/bin:$(nq_python_dir)/bin:/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin"
         --setenv HOME "$HOME"
         --setenv USER "$(id -un)"
         --setenv LANG C.UTF-8
         --setenv TERM "${TERM:-dumb}"
         --setenv CCACHE_DIR "$NQ_CCACHE_DIR"
         --setenv CCACHE_BASEDIR "$NQ_CHECKOUT"
         --setenv CCACHE_NOHASHDIR 1
         --setenv CCACHE_COMPILERCHECK content
         --setenv NEPTUS_CHECKOUT "$NQ_CHECKOUT"
         --setenv NEPTUS_BUILD_DIR "$NQ_BUILD_DIR")
  # Small filesystems of their own (2 MiB tmpfs each) for the tests of a full disk (ENOSPC): one
  # per test, so that tests running side by side do not fill each other's. (bubblewrap 0.7 and
  # newer, not setuid; without --size the tests say they are skipped.)
  if bwrap --help 2>&1 | grep -q -- '--size'; then
    local disk
    for disk in recorder spool mission-saves layout-saves; do args+=(--size 2097152 --tmpfs "/tmp/small-disks/$disk"); done
    args+=(--setenv NEPTUS_SMALL_DISKS /tmp/small-disks)
  fi
  [ -d "$NQ_SHARED" ] && args+=(--ro-bind "$NQ_SHARED" "$NQ_SHARED")
  # The install test's clean root, read only (it installs into an overlay).
  local install_root
  install_root=$(nq_install_root_dir)
  [ -f "$install_root/.neptus-ready" ] \
    && args+=(--ro-bind "$install_root" "$install_root" --setenv NEPTUS_INSTALL_ROOT "$install_root")
  # Folders a caller needs inside, e.g. where a screenshot is to be written.
  local bind
  for bind in "${NQ_BINDS[@]}"; do args+=(--bind "$bind" "$bind"); done
  # The user's own Neptus-Qt settings, components and consoles survive the sandbox.
  local dir
  for dir in "${XDG_CONFIG_HOME:-$HOME/.config}/neptus-qt" "${XDG_DATA_HOME:-$HOME/.local/share}/neptus-qt"; do
    mkdir -p "$dir" && args+=(--bind "$dir" "$dir")
  done
  local var
  for var in CI NEPTUS_ENV QT_QPA_PLATFORM QT_LOGGING_RULES QT_SCALE_FACTOR QT_FONT_DPI CTEST_PARALLEL_LEVEL CTEST_OUTPUT_ON_FAILURE; do
    [ -n "${!var:-}" ] && args+=(--setenv "$var" "${!var}")
  done
  if [ "$net" = 1 ]; then
    [ -e /etc/resolv.conf ] && args+=(--ro-bind /etc/resolv.conf /etc/resolv.conf)
  else
    args+=(--unshare-net)
  fi
  if [ "$gui" = 1 ]; then
    [ -d /tmp/.X11-unix ] && args+=(--bind /tmp/.X11-unix /tmp/.X11-unix)
    [ -n "${DISPLAY:-}" ] && args+=(--setenv DISPLAY "$DISPLAY")
    if [ -n "${XAUTHORITY:-}" ] && [ -f "$XAUTHORITY" ]; then
      args+=(--ro-bind "$XAUTHORITY" "$XAUTHORITY" --setenv XAUTHORITY "$XAUTHORITY")
    elif [ -f "$HOME/.Xauthority" ]; then
      args+=(--ro-bind "$HOME/.Xauthority" "$HOME/.Xauthority" --setenv XAUTHORITY "$HOME/.Xauthority")
    fi
    if [ -n "${XDG_RUNTIME_DIR:-}" ] && [ -d "$XDG_RUNTIME_DIR" ]; then
      args+=(--bind "$XDG_RUNTIME_DIR" "$XDG_RUNTIME_DIR" --setenv XDG_RUNTIME_DIR "$XDG_RUNTIME_DIR")
      [ -n "${WAYLAND_DISPLAY:-}" ] && args+=(--setenv WAYLAND_DISPLAY "$WAYLAND_DISPLAY")
    fi
    [ -d /dev/dri ] && args+=(--dev-bind /dev/dri /dev/dri)
  fi
  local cwd=$PWD
  case "$cwd" in "$NQ_CHECKOUT"*) ;; *) cwd=$NQ_CHECKOUT ;; esac
  args+=(--chdir "$cwd")
  exec bwrap "${args[@]}" -- "$@"
}

# Configures (once) and builds incrementally, inside the environment.
# nq_build [TARGET...]: everything, or only those targets.
nq_build() {
  (nq_enter -- "$NQ_CHECKOUT/tools/inner/build" "$NQ_BUILD_PRESET" "$@")
}
