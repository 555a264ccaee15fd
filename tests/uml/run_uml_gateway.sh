#!/usr/bin/env bash
# The CAN gateway on real SocketCAN: boots Debian's user-mode-linux kernel with the host filesystem
# as root, loads can, can-raw, can-dev and vcan, creates vcan0 (controller side) and vcan1 (drive
# side), runs volcomp-fw-linux between them, and tests/gateway/csp_session.py as the CNC master
# (vcan0) and three CiA 402 CSP drives (vcan1): corrected targets and corrected feedback frame by
# frame, pass-through of SYNC/NMT/SDO/EMCY, a table upload with `volcomp upload --can
# socketcan:vcan0` while the gateway runs, activation refused before referencing and while moving,
# then allowed at rest. Then SIGTERM must stop the firmware cleanly.
# Artifacts (ARTIFACT_DIR): uml-gateway-candump.log (candump -L of both buses),
# uml-gateway-stats.json (the firmware's own counters and latency), uml-gateway-latency.json
# (per-frame forwarding latency from the candump kernel timestamps).
# usage: run_uml_gateway.sh VOLCOMP_FW_LINUX VOLCOMP SOURCE_DIR ARTIFACT_DIR
# VOLCOMP_UML_SESSION_ARGS: more options for csp_session.py (e.g. --stall-first-attempt-s 0.5)
set -euo pipefail
fw=$(realpath "$1") volcomp=$(realpath "$2") src=$(realpath "$3") artifacts=$4
source "$(dirname "$0")/uml_lib.sh"
uml_require
for tool in candump; do
  command -v $tool >/dev/null || { echo "$tool is not installed (can-utils)" >&2; exit 1; }
done
if ! /usr/bin/python3 -c 'import can' 2>/dev/null; then
  echo "python3-can is not installed (scripts/setup-deps.sh can)" >&2
  exit 1
fi
mkdir -p "$artifacts"
work=$(mktemp -d /tmp/volcomp-uml-gw.XXXXXX)
trap 'rm -rf "$work"' EXIT
session=$src/tests/gateway/csp_session.py

# The table: corrections on a 5x5x5 grid (0..400 mm), 100 nm per drive increment.
/usr/bin/python3 "$session" --volcomp "$volcomp" --table "$work/table.vct" \
  --grid-csv "$work/grid.csv" --write-grid-only
"$volcomp" build grid --csv "$work/grid.csv" -o "$work/table.vct" \
  --resolution-nm X=100,Y=100,Z=100 --table-id 21 >/dev/null

cat >"$work/board.conf" <<CONF
[board]
node_id = 16
heartbeat_ms = 500
tick_hz = 1000
axes = X Y Z
[can]
controller = vcan0
drives = vcan1
[gateway]
feedback = sync
[axis X]
units_per_step = 0.0001
target_pdo = 0x201:2
actual_pdo = 0x181:2
max_correction = 2000
max_rate = 20000
max_accel = 500000
home_position = 1000000
[axis Y]
units_per_step = 0.0001
target_pdo = 0x202:2
actual_pdo = 0x182:2
max_correction = 2000
max_rate = 20000
max_accel = 500000
home_position = 500000
[axis Z]
units_per_step = 0.0001
target_pdo = 0x203:2
actual_pdo = 0x183:2
max_correction = 2000
max_rate = 20000
max_accel = 500000
home_position = 200000
[gpio]
backend = fake:$work/gpio
[flash]
tables = $work/tables.bin
settings = $work/settings.bin
sync = true
[process]
realtime_priority = 50
lock_memory = true
CONF
printf 'enable=1\n' >"$work/gpio"
"$fw" --config "$work/board.conf" --check-config >/dev/null

{
uml_init_prologue vcan0 vcan1
cat <<INIT
rc=1
(
  set -e
  cd $work
  # candump above the firmware's real-time priority, with a large socket buffer: it must not drop
  # frames, or the latency pairing below would be wrong (-d reports any drop on stderr).
  chrt -f 60 candump -L -d -r 8388608 vcan0 vcan1 > candump.log 2> candump.err &
  dump=\$!
  $fw --config board.conf --ready-file ready --stats stats.json > fw.log 2>&1 &
  board=\$!
  for i in \$(seq 100); do [ -s ready ] && break; sleep 0.05; done
  /usr/bin/python3 $session --volcomp $volcomp --table table.vct --grid-csv grid-check.csv --timeout-ms $uml_sdo_timeout_ms ${VOLCOMP_UML_SESSION_ARGS:-}
  kill -TERM \$board
  wait \$board
  echo "firmware exit code \$?"
  sleep 0.1
  kill \$dump
) > $work/session.log 2>&1 && rc=0
INIT
uml_init_epilogue "$work"
} >"$work/init.sh"
uml_boot 240 "$work"
cp -f "$work/candump.log" "$artifacts/uml-gateway-candump.log" 2>/dev/null || true
cp -f "$work/stats.json" "$artifacts/uml-gateway-stats.json" 2>/dev/null || true
if grep -qi drop "$work/candump.err" 2>/dev/null; then
  echo "--- candump reported dropped frames:"; cat "$work/candump.err"
fi
cat "$work/session.log" 2>/dev/null || true
echo "--- firmware log"
cat "$work/fw.log" 2>/dev/null || true
echo "user-mode-linux run: $uml_ms ms; candump log:" \
  "$artifacts/uml-gateway-candump.log ($(wc -l < "$artifacts/uml-gateway-candump.log" 2>/dev/null || echo 0) frames)"
uml_session_ok "$work" || exit 1
grep -q "CSP gateway session: OK" "$work/session.log"
grep -q "firmware exit code 0" "$work/session.log"
grep -q "stopped by signal" "$work/fw.log"
/usr/bin/python3 "$src/tests/gateway/candump_latency.py" "$artifacts/uml-gateway-candump.log" \
  --json "$artifacts/uml-gateway-latency.json"
# The board's own SDO traffic stays on the controller bus; the upload went through it.
grep -qE '^\([0-9]+\.[0-9]{6}\) vcan0 610#C6002100' "$artifacts/uml-gateway-candump.log"
if grep -qE '^\([0-9]+\.[0-9]{6}\) vcan1 (610|590|710)#' "$artifacts/uml-gateway-candump.log"; then
  echo "the board's own frames reached the drive bus" >&2
  exit 1
fi
echo "CAN gateway in user-mode-linux: OK"
