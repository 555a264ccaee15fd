#!/usr/bin/env bash
# check_configure.sh SOURCE_DIR WORK: what configuring says about LinuxCNC's headers
# (docs/linuxcnc.md §1), on a configure of its own whose header directory is WORK/inc/linuxcnc
# (no tests, no benchmarks: about a second):
# - headers missing: the configure names the missing files and the package to install, and the
#   targets volcomp_native and volcomp_board fail with that text instead of being unknown;
# - VOLCOMP_LINUXCNC=ON with the headers missing: the configure fails with that text;
# - the headers installed after the configure: the next build configures again by itself and
#   builds the components (checked on the build files' regeneration, stand-in headers).
set -euo pipefail
src=$1 work=$2
if ! command -v ninja >/dev/null; then
  echo "check_configure: ninja is missing" >&2
  exit 77
fi
rm -rf "$work"
mkdir -p "$work/inc"
inc=$work/inc/linuxcnc
fail=0
expect() {  # WHAT FILE TEXT (CMake wraps its messages: compared with white space collapsed)
  if ! tr -s ' \n' '  ' <"$2" | grep -F -- "$3" >/dev/null; then
    echo "check_configure: $1: no \"$3\" in:" >&2
    sed 's/^/  /' "$2" >&2
    fail=1
  fi
}
configure() {  # BUILD_DIR EXTRA_ARGS...
  local b=$1
  shift
  cmake -S "$src" -B "$b" -G Ninja -DVOLCOMP_LINUXCNC_INCLUDE_DIR="$inc" \
    -DVOLCOMP_BUILD_TESTS=OFF -DVOLCOMP_BUILD_BENCHMARKS=OFF "$@"
}

# Headers missing (AUTO).
configure "$work/b" >"$work/configure.log" 2>&1
missing="LinuxCNC's development headers are not installed ($inc/hal.h, $inc/rtapi.h, $inc/rtapi_app.h missing)"
expect "configure without headers" "$work/configure.log" "$missing"
expect "configure without headers" "$work/configure.log" "sudo apt install linuxcnc-uspace-dev"
for t in volcomp_native volcomp_board; do
  if cmake --build "$work/b" --target $t >"$work/$t.log" 2>&1; then
    echo "check_configure: target $t succeeded without LinuxCNC's headers" >&2
    fail=1
  fi
  expect "target $t without headers" "$work/$t.log" "$t: $missing"
done

# VOLCOMP_LINUXCNC=ON: an error.
if configure "$work/b-on" -DVOLCOMP_LINUXCNC=ON >"$work/configure-on.log" 2>&1; then
  echo "check_configure: VOLCOMP_LINUXCNC=ON configured without the headers" >&2
  fail=1
fi
expect "VOLCOMP_LINUXCNC=ON without headers" "$work/configure-on.log" "VOLCOMP_LINUXCNC=ON: $missing"

# The headers appear (as installing linuxcnc-uspace-dev makes /usr/include/linuxcnc): the next
# build regenerates its files with the components (stand-in headers: the build files are what is
# checked, nothing is compiled).
mkdir -p "$inc"
touch "$inc/hal.h" "$inc/rtapi.h" "$inc/rtapi_app.h"
ninja -C "$work/b" build.ninja >"$work/reconfigure.log" 2>&1
expect "the build after installing the headers" "$work/reconfigure.log" "Re-running CMake"
expect "the build after installing the headers" "$work/reconfigure.log" \
  ": building the HAL components volcomp and volcomp_board"
ninja -C "$work/b" -t targets all >"$work/targets.txt" 2>&1 || true
if ! grep -q '^linuxcnc/modules/volcomp.so:' "$work/targets.txt"; then
  echo "check_configure: after the headers appeared the build has no linuxcnc/modules/volcomp.so" >&2
  fail=1
fi
[[ $fail -eq 0 ]] && echo "check_configure: missing headers named with the package to install;" \
  "targets fail with that text; VOLCOMP_LINUXCNC=ON refuses; headers installed later are" \
  "picked up by the next build"
exit $fail
