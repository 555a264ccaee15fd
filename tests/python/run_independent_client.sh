#!/usr/bin/env bash
# Starts `volcomp-sim node` serving SLCAN on TCP and on a pty, builds a table image, and runs the
# independent Python SDO client (Debian's /usr/bin/python3 + python3-can) against both.
# usage: run_independent_client.sh VOLCOMP_SIM VOLCOMP SOURCE_DIR
set -euo pipefail
sim=$1 volcomp=$2 src=$3
if ! /usr/bin/python3 -c 'import can' 2>/dev/null; then
  echo "python3-can is not installed (scripts/setup-deps.sh can)" >&2
  exit 1
fi
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
# A 20x20x20 grid (48 KB, about 55 sub-blocks of 127 segments).
/usr/bin/python3 - "$work/grid.csv" <<'PY'
import math, sys
with open(sys.argv[1], "w") as f:
    f.write("x_mm,y_mm,z_mm,dx_um,dy_um,dz_um\n")
    for k in range(20):
        for j in range(20):
            for i in range(20):
                f.write("%d,%d,%d,%.3f,%.3f,%.3f\n" % (i * 25, j * 20, k * 15, 10 * math.sin(i / 3),
                        0.2 * j - 0.1 * k, 5 * math.cos(i / 5 + j / 7)))
PY
"$volcomp" build grid --csv "$work/grid.csv" -o "$work/table.vct" \
  --resolution-nm X=1000,Y=1000,Z=1000 --table-id 5 >/dev/null
for link in tcp pty; do
  rm -f "$work/ready"
  if [[ $link == tcp ]]; then
    "$sim" node --slcan-tcp 0 --ready-file "$work/ready" --duration 60 >"$work/node-$link.log" 2>&1 &
  else
    "$sim" node --slcan-pty "$work/tty" --ready-file "$work/ready" --duration 60 >"$work/node-$link.log" 2>&1 &
  fi
  node_pid=$!
  for _ in $(seq 100); do [[ -s $work/ready ]] && break; sleep 0.05; done
  spec=$(cat "$work/ready")
  case $spec in
    slcan-tcp:*) channel="socket://${spec#slcan-tcp:}" ;;
    slcan:*) channel="${spec#slcan:}" ;;
  esac
  echo "== independent client over $link ($channel)"
  /usr/bin/python3 "$src/tests/python/independent_sdo_client.py" "$channel" "$work/table.vct"
  kill "$node_pid"
  wait "$node_pid" || true
done
