#!/usr/bin/env bash
# Real SocketCAN: boots Debian's user-mode-linux kernel with the host filesystem as root, loads
# can, can-raw, can-dev and vcan, creates vcan0, runs the simulated node (the real firmware) on
# vcan0 through the SocketCAN backend, and uploads + activates a table with the PC tool's SocketCAN
# transport. candump -L records the bus; the log is kept as a test artifact. First, on vcan1, the
# kernel-level checks of the socket (KERNEL_TEST: filter, dropped-frame count, receive buffer).
# usage: run_uml_socketcan.sh VOLCOMP_SIM VOLCOMP SOURCE_DIR ARTIFACT_DIR [KERNEL_TEST]
set -euo pipefail
sim=$1 volcomp=$2 src=$3 artifacts=$4 kernel_test=${5:-}
source "$(dirname "$0")/uml_lib.sh"
uml_require
mkdir -p "$artifacts"
work=$(mktemp -d /tmp/volcomp-uml.XXXXXX)
trap 'rm -rf "$work"' EXIT
"$volcomp" build grid --csv "$src/samples/grid_example.csv" -o "$work/table.vct" \
  --resolution-nm X=1000,Y=1000,Z=1000 --table-id 9 >/dev/null 2>&1

{
uml_init_prologue vcan0 vcan1
cat <<INIT
rc=1
(
  set -e
  # (set -e does not act inside a subshell whose status && tests: each check exits by itself.)
  if [ -n "$kernel_test" ]; then VOLCOMP_VCAN=vcan1 $kernel_test || exit 1; fi
  candump -L vcan0 > $work/candump.log &
  dump=\$!
  $sim node --socketcan vcan0 --ready-file $work/ready --duration 50 > $work/node.log 2>&1 &
  node=\$!
  for i in \$(seq 100); do [ -s $work/ready ] && break; sleep 0.05; done
  $volcomp upload $work/table.vct --can socketcan:vcan0 --timeout-ms $uml_sdo_timeout_ms --quiet
  $volcomp reference --can socketcan:vcan0 --timeout-ms $uml_sdo_timeout_ms --axes 1,2,3
  sleep 0.3
  $volcomp activate --can socketcan:vcan0 --timeout-ms $uml_sdo_timeout_ms
  $volcomp verify $work/table.vct --can socketcan:vcan0 --timeout-ms $uml_sdo_timeout_ms --readback
  $volcomp status --can socketcan:vcan0 --timeout-ms $uml_sdo_timeout_ms
  kill \$node; kill \$dump
) > $work/session.log 2>&1 && rc=0
INIT
uml_init_epilogue "$work"
} >"$work/init.sh"
uml_boot 150 "$work"
cp -f "$work/candump.log" "$artifacts/uml-candump.log" 2>/dev/null || true
cat "$work/session.log" 2>/dev/null || true
echo "user-mode-linux run: $uml_ms ms; candump log: $artifacts/uml-candump.log ($(wc -l < "$artifacts/uml-candump.log" 2>/dev/null || echo 0) frames)"
if ! uml_session_ok "$work"; then
  echo "--- node log" >&2; cat "$work/node.log" >&2 2>/dev/null || true
  exit 1
fi
grep -q "verified: the image is the active table" "$work/session.log"
grep -qE '^\([0-9]+\.[0-9]{6}\) vcan0 610#C6002100' "$artifacts/uml-candump.log"
echo "SocketCAN in user-mode-linux: OK"
