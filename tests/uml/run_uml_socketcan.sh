#!/usr/bin/env bash
# Real SocketCAN: boots Debian's user-mode-linux kernel with the host filesystem as root, loads
# can, can-raw, can-dev and vcan, creates vcan0, runs the simulated node (the real firmware) on
# vcan0 through the SocketCAN backend, and uploads + activates a table with the PC tool's SocketCAN
# transport. candump -L records the bus; the log is kept as a test artifact.
# usage: run_uml_socketcan.sh VOLCOMP_SIM VOLCOMP SOURCE_DIR ARTIFACT_DIR
set -euo pipefail
sim=$1 volcomp=$2 src=$3 artifacts=$4
uml=$(command -v linux.uml || true)
if [[ -z $uml ]]; then
  echo "user-mode-linux is not installed (scripts/setup-deps.sh can)" >&2
  exit 1
fi
mods=$(ls -d /usr/lib/uml/modules/*/kernel | head -n1)
mkdir -p "$artifacts"
work=$(mktemp -d /tmp/volcomp-uml.XXXXXX)
trap 'rm -rf "$work"' EXIT
"$volcomp" build grid --csv "$src/samples/grid_example.csv" -o "$work/table.vct" \
  --resolution-nm X=1000,Y=1000,Z=1000 --table-id 9 >/dev/null 2>&1

cat >"$work/init.sh" <<INIT
#!/bin/sh
export PATH=/usr/sbin:/usr/bin:/sbin:/bin
mount -t proc proc /proc; mount -t sysfs sys /sys
for m in net/can/can.ko net/can/can-raw.ko drivers/net/can/dev/can-dev.ko drivers/net/can/vcan.ko; do
  insmod $mods/\$m || echo "insmod \$m failed"
done
ip link add dev vcan0 type vcan && ip link set vcan0 txqueuelen 1000 && ip link set up vcan0
rc=1
(
  set -e
  candump -L vcan0 > $work/candump.log &
  dump=\$!
  $sim node --socketcan vcan0 --ready-file $work/ready --duration 50 > $work/node.log 2>&1 &
  node=\$!
  for i in \$(seq 100); do [ -s $work/ready ] && break; sleep 0.05; done
  $volcomp upload $work/table.vct --can socketcan:vcan0 --quiet
  $volcomp reference --can socketcan:vcan0 --axes 1,2,3
  sleep 0.3
  $volcomp activate --can socketcan:vcan0
  $volcomp verify $work/table.vct --can socketcan:vcan0 --readback
  $volcomp status --can socketcan:vcan0
  kill \$node; kill \$dump
) > $work/session.log 2>&1 && rc=0
echo \$rc > $work/rc
/sbin/poweroff -f
INIT
chmod +x "$work/init.sh"
start=$(date +%s%N)
timeout 60 "$uml" mem=384M root=/dev/root rootfstype=hostfs rootflags=/ rw init="$work/init.sh" \
  con=null con0=null,fd:2 </dev/null >"$work/uml.log" 2>&1 || true
end=$(date +%s%N)
cp -f "$work/candump.log" "$artifacts/uml-candump.log" 2>/dev/null || true
cat "$work/session.log" 2>/dev/null || true
echo "user-mode-linux run: $(( (end - start) / 1000000 )) ms; candump log: $artifacts/uml-candump.log ($(wc -l < "$artifacts/uml-candump.log" 2>/dev/null || echo 0) frames)"
if [[ "$(cat "$work/rc" 2>/dev/null)" != 0 ]]; then
  echo "--- uml console" >&2; tail -30 "$work/uml.log" >&2
  echo "--- node log" >&2; cat "$work/node.log" >&2 2>/dev/null || true
  exit 1
fi
grep -q "verified: the image is the active table" "$work/session.log"
grep -qE '^\([0-9]+\.[0-9]{6}\) vcan0 610#C6002100' "$artifacts/uml-candump.log"
echo "SocketCAN in user-mode-linux: OK"
