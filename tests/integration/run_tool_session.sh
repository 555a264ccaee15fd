#!/usr/bin/env bash
# The PC tool against `volcomp-sim node` over SLCAN-TCP: upload (progress, --log in candump -L
# format), refusal of activation before referencing, reference, activate, verify --readback,
# status --json, skip of an upload that is already active, and a connection cut in the middle of
# an upload (node stopped), after which a restarted node still has the old table and a new
# upload completes; a node restarted in the middle of an upload on the same port, which the
# upload's retry waits for (heartbeat or boot-up) before it starts again.
# usage: run_tool_session.sh VOLCOMP_SIM VOLCOMP SOURCE_DIR
set -euo pipefail
sim=$1 volcomp=$2 src=$3
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

source "$(dirname "$0")/sim_node_lib.sh"
mkdir -p "$work/flash"

"$volcomp" build grid --csv "$src/samples/grid_example.csv" -o "$work/a.vct" \
  --resolution-nm X=1000,Y=1000,Z=1000 --table-id 1 >/dev/null 2>&1
write_big_grid "$work/big.csv"
"$volcomp" build grid --csv "$work/big.csv" -o "$work/b.vct" \
  --resolution-nm X=1000,Y=1000,Z=1000 --table-id 2 >/dev/null 2>&1

start_node
echo "== upload (not activated: axes not referenced)"
if "$volcomp" upload "$work/a.vct" --can "$can" --activate --log "$work/upload.log" \
     >"$work/out.txt" 2>&1; then
  fail "activation before referencing succeeded"
fi
cat "$work/out.txt"
grep -q "staged and verified" "$work/out.txt" || fail "not staged"
grep -q "0x08000022" "$work/out.txt" || fail "no 0x08000022 in the refusal"
grep -qE '^\([0-9]+\.[0-9]{6}\) slcan0 610#C6002100' "$work/upload.log" || fail "candump log format"
echo "== reference, activate, verify --readback, status"
"$volcomp" reference --can "$can" --axes 1,2,3
sleep 0.3
"$volcomp" activate --can "$can"
"$volcomp" verify "$work/a.vct" --can "$can" --readback
"$volcomp" status --can "$can" --json >"$work/status.json"
grep -q '"present": true' "$work/status.json" || fail "status: no active table"
"$volcomp" upload "$work/a.vct" --can "$can" | tee "$work/out.txt"
grep -q "already has this table active" "$work/out.txt" || fail "no skip of an active table"

echo "== connection cut in the middle of an upload"
"$volcomp" upload "$work/b.vct" --can "$can" --retries 0 --quiet >"$work/cut.txt" 2>&1 &
upload_pid=$!
sleep 0.4
kill "$node_pid"; wait "$node_pid" || true
if wait "$upload_pid"; then fail "upload survived the cut"; fi
cat "$work/cut.txt"
grep -q "upload failed" "$work/cut.txt" || fail "no clear failure message"
start_node
"$volcomp" verify "$work/a.vct" --can "$can" || fail "old table not active after the cut"

echo "== the node restarts in the middle of an upload: the retry waits for it"
"$volcomp" upload "$work/b.vct" --can "$can" --retries 3 --quiet >"$work/restart.txt" 2>&1 &
upload_pid=$!
sleep 0.4
kill "$node_pid"; wait "$node_pid" || true
sleep 1.5
start_node "${can##*:}"  # the same port: the tool reconnects to what it was given
wait "$upload_pid" || { cat "$work/restart.txt"; fail "the upload did not survive a restart"; }
cat "$work/restart.txt"
grep -q "^waiting up to 1 s for node 16 (heartbeat or boot-up)" "$work/restart.txt" ||
  fail "no wait before the retry"
grep -q "^node 16 is there (heartbeat: " "$work/restart.txt" || fail "the node's return not seen"
grep -q "staged and verified" "$work/restart.txt" || fail "not staged after the restart"
"$volcomp" verify "$work/a.vct" --can "$can" || fail "old table not active after the restart"
"$volcomp" upload "$work/b.vct" --can "$can" --quiet --force
"$volcomp" reference --can "$can"
sleep 0.3
"$volcomp" activate --can "$can"
"$volcomp" verify "$work/b.vct" --can "$can"
"$volcomp" deactivate --can "$can"
"$volcomp" status --can "$can" | tee "$work/out.txt"
grep -q "active table: none" "$work/out.txt" || fail "deactivate"

echo "== an upload says which staged table it replaces"
"$volcomp" upload "$work/a.vct" --can "$can" --quiet >/dev/null
"$volcomp" upload "$work/b.vct" --can "$can" --quiet --json >"$work/replace.json" 2>"$work/replace.txt"
cat "$work/replace.txt"
a_crc=$("$volcomp" inspect "$work/a.vct" --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["crc32"])')
grep -q "^replacing the staged table of node 16 (id 1, CRC-32 $a_crc, verified, not active)" \
  "$work/replace.txt" || fail "no word of the staged table replaced"
python3 - "$work/replace.json" "$a_crc" <<'PY' || fail "upload --json: replaced_staged"
import json, sys
r = json.load(open(sys.argv[1]))["replaced_staged"]
assert r == {"table_id": 1, "crc32": sys.argv[2], "state": "verified"}, r
PY
echo "tool session: OK"
