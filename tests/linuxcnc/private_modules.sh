#!/usr/bin/env bash
# private_modules.sh BUILD_MODULES DIR COMMAND...: runs COMMAND with this build's HAL components in
# LinuxCNC's module directory, in a private mount namespace, without touching the system's
# directory: `loadrt` takes no path, only NAME.so from the directory rtapi_app was built with, so
# DIR/modules gets a link to every system module plus the build's volcomp.so and
# volcomp_board.so (and the modules VOLCOMP_EXTRA_MODULES names: paths, space-separated, e.g. a
# test's stand-in for hardware), and is mounted over the module directory for COMMAND and its
# children only (rtapi_app included). Needs root (unshare, mount). Nothing is left behind when
# COMMAND ends.
set -euo pipefail
if [[ ${1:-} == --inside ]]; then
  shift
  build=$1 dir=$2 sysdir=$3
  shift 3
  # The system's files stay reachable under DIR/system while DIR/modules covers the directory.
  mkdir -p "$dir/system" "$dir/modules"
  mount --bind "$sysdir" "$dir/system"
  for f in "$dir"/system/*; do
    name=$(basename "$f")
    [[ $name == volcomp.so || $name == volcomp_board.so ]] && continue
    ln -sf "$f" "$dir/modules/$name"
  done
  install -m 644 "$build/volcomp.so" "$build/volcomp_board.so" "$dir/modules/"
  for extra in ${VOLCOMP_EXTRA_MODULES:-}; do
    install -m 644 "$extra" "$dir/modules/"
  done
  chmod 755 "$dir" "$dir/modules"
  mount --bind "$dir/modules" "$sysdir"
  exec "$@"
fi
build=$(realpath "$1") dir=$(realpath -m "$2")
shift 2
# LinuxCNC's module directory: RTLIBDIR of its Makefile.modinc, as halcompile installs.
sysdir=/usr/lib/linuxcnc/modules
if modinc=$(halcompile --print-modinc 2>/dev/null) && [[ -f $modinc ]]; then
  sysdir=$(printf 'include %s\nprint-rtlibdir:\n\t@echo $(RTLIBDIR)\n' "$modinc" |
           make -s -f - print-rtlibdir 2>/dev/null || echo "$sysdir")
fi
exec unshare --mount --propagation private "$0" --inside "$build" "$dir" "$sysdir" "$@"
