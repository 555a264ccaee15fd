#!/usr/bin/env bash
# check_install.sh BUILD_DIR WORK: `cmake --install` of the LinuxCNC component into a private
# DESTDIR puts volcomp.so and volcomp_board.so into LinuxCNC's module directory (the RTLIBDIR of
# halcompile --print-modinc's Makefile.modinc) and volcomp.9 into <prefix>/share/man/man9, the
# page renders without warnings, and the uninstall-linuxcnc target removes exactly those files.
# Nothing outside WORK is written but the build's install manifest, which the uninstall removes
# (no root needed).
set -euo pipefail
build=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
stage=$work/stage
# `cmake --install` records what it installed in the build's install manifest, which the
# uninstall target reads: keep a manifest of a real install made from this build as it was.
manifest=$build/install_manifest_linuxcnc.txt
if [[ -f $manifest ]]; then
  cp -p "$manifest" "$work/manifest.saved"
  trap 'mv -f "$work/manifest.saved" "$manifest"' EXIT
fi
modinc=$(halcompile --print-modinc)
moddir=$(printf 'include %s\nprint-rtlibdir:\n\t@echo $(RTLIBDIR)\n' "$modinc" | make -s -f - print-rtlibdir)
[[ -n $moddir ]] || { echo "check_install: no RTLIBDIR in $modinc" >&2; exit 1; }
DESTDIR=$stage cmake --install "$build" --component linuxcnc --prefix /opt/volcomp-test \
  >"$work/install.log"
fail=0
for f in "$moddir/volcomp.so" "$moddir/volcomp_board.so" /opt/volcomp-test/share/man/man9/volcomp.9; do
  if [[ ! -f $stage$f ]]; then
    echo "check_install: $f not installed (DESTDIR $stage)" >&2
    fail=1
  fi
done
installed=$(cd "$stage" && find . -type f | sort)
echo "check_install: installed under DESTDIR: $(echo $installed)"
if [[ $(echo "$installed" | wc -l) -ne 3 ]]; then
  echo "check_install: expected exactly 3 files" >&2
  fail=1
fi
# The installed module is the build's.
cmp "$stage$moddir/volcomp.so" "$build/linuxcnc/modules/volcomp.so" || fail=1
# The man page renders (man -l), without groff warnings.
warnings=$(groff -man -ww -z "$stage/opt/volcomp-test/share/man/man9/volcomp.9" 2>&1 || true)
if [[ -n $warnings ]]; then
  echo "check_install: volcomp.9: $warnings" >&2
  fail=1
fi
MANWIDTH=80 man -l "$stage/opt/volcomp-test/share/man/man9/volcomp.9" 2>/dev/null | grep "joint-pos-cmd" >/dev/null ||
  { echo "check_install: man -l volcomp.9 does not show the pins" >&2; fail=1; }
# What the build's uninstall-linuxcnc target runs, with the same DESTDIR: it removes the files the
# install recorded (--prefix included).
DESTDIR=$stage cmake -D "MANIFEST=$manifest" -D "FILES=" \
  -P "$(dirname "$0")/../../linuxcnc/uninstall.cmake" >"$work/uninstall.log"
left=$(cd "$stage" && find . -type f)
if [[ -n $left ]]; then
  echo "check_install: left after uninstall: $left" >&2
  fail=1
fi
[[ $fail -eq 0 ]] && echo "check_install: install and uninstall into $moddir and man9: ok"
exit $fail
