#!/usr/bin/env bash
# The PC tool and `volcomp-sim node` never do less than asked without saying so, and say why they
# refuse. Sections (all by default, or those named after the three paths):
#   values     `sdo write` refuses an out-of-range value before sending (exit 2), nothing stored
#   axes       `reference --axes 4` on a 3-axis board is refused (exit 1)
#   readback   `verify --readback` reads the table it names (active, or staged with --staged);
#              exit 1 for a different table, 3 without a board
#   reasons    a refused store names the rule and the axis; a refused verification the board's
#              reason; an empty staging bank shows no old id and CRC-32
#   monitor    `monitor --duration` ends on time with a longer interval
#   clamp      a table the board would clamp is refused by upload and activate (exit 1, naming
#              axis, value and limit) unless --allow-clamp; then `status` shows it clamped
#   powerloss  SIGKILL in the middle of an upload (the flash directory is written through): the
#              restarted node has the active table intact and takes a new upload
# usage: run_safety_session.sh VOLCOMP_SIM VOLCOMP SOURCE_DIR [SECTION...]
set -euo pipefail
sim=$1 volcomp=$2 src=$3
shift 3
sections=${*:-values axes readback reasons monitor clamp powerloss json}
work=$(mktemp -d)
trap 'kill -9 $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
node_pid=
source "$(dirname "$0")/sim_node_lib.sh"
power_cycle() {  # SIGKILL: nothing is saved at exit, only what the flash operations wrote
  kill -9 "$node_pid"; wait "$node_pid" 2>/dev/null || true
  start_node
}
# json_is FILE KEY VALUE: stdout FILE is one JSON object whose KEY (a.b for nesting) is VALUE.
json_is() {
  python3 - "$@" <<'PY' || fail "JSON $2 != $3 in $(cat "$1")"
import json, sys
path, key, want = sys.argv[1:4]
v = json.load(open(path))
for k in key.split("."):
    v = v[k]
sys.exit(0 if str(v) == want else 1)
PY
}
# run EXPECTED_EXIT OUTFILE COMMAND...: runs the command, checks its exit code.
run() {
  local want=$1 out=$2; shift 2
  set +e; "$@" >"$out" 2>&1; local got=$?; set -e
  cat "$out"
  [[ $got == "$want" ]] || fail "exit $got, expected $want: $*"
}
grid() {  # grid CSV FILE with constant corrections DX DY DZ (um) on a 0..400 x 0..280 x 0..200 mm box
  python3 - "$@" <<'PY'
import sys
path, dx, dy, dz = sys.argv[1], *map(float, sys.argv[2:5])
with open(path, "w") as f:
    f.write("x_mm,y_mm,z_mm,dx_um,dy_um,dz_um\n")
    for z in (0, 100, 200):
        for y in (0, 140, 280):
            for x in (0, 200, 400):
                f.write("%d,%d,%d,%.3f,%.3f,%.3f\n" % (x, y, z, dx + 0.01 * x, dy, dz))
PY
}
build() {  # build IMAGE CSV ID
  "$volcomp" build grid --csv "$2" -o "$1" --resolution-nm X=1000,Y=1000,Z=1000 --table-id "$3" \
    >/dev/null
}
unlock() { "$volcomp" sdo write 2110:0 0x6B6C6E75 --can "$can" >/dev/null; }
referenced_and_at_rest() { "$volcomp" reference --can "$can" >/dev/null; sleep 0.3; }

mkdir -p "$work/flash"
build "$work/a.vct" "$src/samples/grid_example.csv" 1
grid "$work/b.csv" 5 -3 2
build "$work/b.vct" "$work/b.csv" 2
start_node
o=$work/out.txt

for section in $sections; do
  echo "== $section"
  case $section in
    values)
      unlock
      run 2 "$o" "$volcomp" sdo write 2010:1 300 --can "$can"
      grep -q "0..255" "$o" || fail "the refusal does not name the range"
      run 2 "$o" "$volcomp" sdo write 2010:1 -1 --can "$can"
      run 0 "$o" "$volcomp" sdo read 2010:1 --can "$can"
      grep -q "^88 " "$o" || fail "axis 1 name changed: $(cat "$o")"
      run 0 "$o" "$volcomp" sdo write 2018:1 -5000 --can "$can"
      run 0 "$o" "$volcomp" sdo read 2018:1 --can "$can"
      grep -q "^-5000 " "$o" || fail "home position not -5000"
      "$volcomp" sdo write 2018:1 0 --can "$can" >/dev/null
      ;;
    axes)
      run 1 "$o" "$volcomp" reference --axes 4 --can "$can"
      grep -q "has 3 axes" "$o" || fail "the refusal does not name the axis count"
      run 0 "$o" "$volcomp" reference --axes 1,2,3 --can "$can"
      ;;
    readback)
      "$volcomp" upload "$work/a.vct" --can "$can" --quiet >/dev/null
      referenced_and_at_rest
      "$volcomp" activate --can "$can" >/dev/null
      "$volcomp" upload "$work/b.vct" --can "$can" --quiet >/dev/null  # staged, not active
      run 0 "$o" "$volcomp" verify "$work/a.vct" --readback --can "$can"
      grep -q "identical" "$o" || fail "active table not read back"
      run 0 "$o" "$volcomp" verify "$work/b.vct" --readback --staged --can "$can"
      run 1 "$o" "$volcomp" verify "$work/b.vct" --readback --can "$can"
      grep -q "DIFFERENT" "$o" || fail "no DIFFERENT"
      run 1 "$o" "$volcomp" verify "$work/a.vct" --readback --staged --can "$can"
      run 3 "$o" "$volcomp" verify "$work/a.vct" --readback --can slcan-tcp:127.0.0.1:1
      run 3 "$o" "$volcomp" verify "$work/a.vct" --readback --can "$can" --node 99 --timeout-ms 200
      ;;
    reasons)
      unlock
      "$volcomp" sdo write 201D:2 1000 --can "$can" >/dev/null  # drive slower than the input
      run 1 "$o" "$volcomp" sdo write 1010:1 0x65766173 --can "$can"
      grep -q "axis 2: max input rate (0x201E) + max correction rate (0x2016) must not exceed" \
        "$o" || fail "the store refusal does not name the rule and the axis"
      "$volcomp" sdo write 201D:2 2000000 --can "$can" >/dev/null
      # A table for 2 um/step on X while the board runs 1 um/step, 0x2012:1 edited to 2 um but not
      # in force: the tool checks against the settings in force (0x2124), refuses and names them.
      unlock
      "$volcomp" sdo write 2012:1 2000000 --can "$can" >/dev/null  # edited, not in force
      "$volcomp" build grid --csv "$work/b.csv" -o "$work/x2.vct" --table-id 5 \
        --resolution-nm X=2000,Y=1000,Z=1000 >/dev/null
      run 1 "$o" "$volcomp" upload "$work/x2.vct" --can "$can" --quiet
      grep -q "not yet in force" "$o" || fail "no warning about settings not in force"
      grep -q "the board runs 1000 steps/mm (1000 nm/step) (0x2012:1)" "$o" ||
        fail "the refusal does not name the resolution in force"
      unlock
      "$volcomp" sdo write 2101:0 3 --can "$can" >/dev/null  # clear: then nothing is staged
      run 1 "$o" "$volcomp" sdo write 2101:0 4 --can "$can"
      grep -q "the board says: nothing is staged" "$o" || fail "verify refusal without reason"
      "$volcomp" sdo write 2012:1 1000000 --can "$can" >/dev/null
      run 1 "$o" "$volcomp" upload "$work/x2.vct" --can "$can" --quiet
      grep -q "0x2012:1" "$o" || fail "the upload refusal does not name 0x2012"
      unlock
      "$volcomp" sdo write 2101:0 3 --can "$can" >/dev/null  # clear the staging bank
      run 0 "$o" "$volcomp" status --can "$can"
      grep -q "^staged table: empty" "$o" || fail "no empty staging line"
      ! grep "^staged table" "$o" | grep -q "CRC-32" || fail "an empty bank shows a CRC-32"
      ;;
    monitor)
      start_s=$(date +%s.%N)
      run 0 "$o" "$volcomp" monitor --interval-ms 5000 --duration 1 --can "$can"
      python3 -c "import sys; t = float(sys.argv[2]) - float(sys.argv[1]); print('%.2f s' % t);
sys.exit(0 if t < 3.5 else 1)" "$start_s" "$(date +%s.%N)" || fail "--duration 1 not honoured"
      ;;
    clamp)
      unlock
      for a in 1 2 3; do "$volcomp" sdo write 2015:$a 100 --can "$can" >/dev/null; done
      "$volcomp" sdo write 1010:1 0x65766173 --can "$can" >/dev/null
      power_cycle
      grid "$work/c.csv" 400 0 0  # X asks 400..404 steps
      build "$work/c.vct" "$work/c.csv" 3
      run 1 "$o" "$volcomp" upload "$work/c.vct" --can "$can" --quiet
      grep -q "axis 1 (X): the table asks for up to 404.0 steps of correction, the board's max \
correction (0x2015:1) is 100 steps" "$o" || fail "the clamp refusal does not name axis, value, limit"
      run 0 "$o" "$volcomp" upload "$work/c.vct" --can "$can" --quiet --allow-clamp
      grep -q "warning: axis 1 (X)" "$o" || fail "no warning with --allow-clamp"
      referenced_and_at_rest
      run 1 "$o" "$volcomp" activate --can "$can"
      grep -q "(0x2015:1) is 100 steps" "$o" || fail "activate does not refuse the clamp"
      run 0 "$o" "$volcomp" activate --can "$can" --allow-clamp
      sleep 0.5
      run 0 "$o" "$volcomp" status --can "$can"
      grep -q "^axis 1 X: .*CLAMPED (0x2015)" "$o" || fail "status: not clamped"
      grep "^axis 2 Y: " "$o" | grep -q "CLAMPED\|RATE LIMITED" && fail "status: axis 2 limited"
      grep -q "^axis 1 X: input 0 steps,.*(+100.000 steps, max 100 = " "$o" || fail "not clamped to 100"
      ;;
    powerloss)
      "$volcomp" upload "$work/a.vct" --can "$can" --quiet >/dev/null
      referenced_and_at_rest
      "$volcomp" activate --can "$can" >/dev/null
      write_big_grid "$work/big.csv"
      build "$work/big.vct" "$work/big.csv" 4
      "$volcomp" upload "$work/big.vct" --can "$can" --retries 0 --quiet >"$o" 2>&1 &
      upload_pid=$!
      sleep 0.4
      kill -9 "$node_pid"; wait "$node_pid" 2>/dev/null || true
      if wait "$upload_pid"; then fail "the upload survived the power loss"; fi
      start_node
      run 0 "$o" "$volcomp" verify "$work/a.vct" --readback --can "$can"
      run 0 "$o" "$volcomp" upload "$work/big.vct" --can "$can" --quiet
      run 0 "$o" "$volcomp" verify "$work/big.vct" --readback --staged --can "$can"
      ;;
    json)  # --json: one object on stdout whatever happened (messages on stderr)
      j=$work/json.txt
      set +e; "$volcomp" upload "$work/b.vct" --can "$can" --force --json >"$j" 2>/dev/null; e=$?
      set -e; [[ $e == 0 ]] || fail "upload --json exit $e"
      json_is "$j" result staged; json_is "$j" image.table_id 2; json_is "$j" exit_code 0
      set +e; "$volcomp" verify "$work/b.vct" --staged --readback --can "$can" --json >"$j"; e=$?
      set -e; [[ $e == 0 ]] || fail "verify --json exit $e"
      json_is "$j" verdict staged; json_is "$j" readback.identical True
      set +e; "$volcomp" verify "$work/b.vct" --can "$can" --json >"$j"; e=$?; set -e
      [[ $e == 1 ]] || fail "verify of a table not active: exit $e"
      json_is "$j" verdict "staged, not active"
      referenced_and_at_rest
      "$volcomp" activate --can "$can" --json >"$j"
      json_is "$j" active_table_id 2
      set +e; "$volcomp" activate --can "$can" --json >"$j"; e=$?; set -e
      [[ $e == 1 ]] || fail "activate with nothing staged: exit $e"
      json_is "$j" exit_code 1; grep -q "nothing is staged" "$j" || fail "no reason in the JSON"
      set +e; "$volcomp" verify "$work/b.vct" --can slcan-tcp:127.0.0.1:1 --json >"$j"; e=$?; set -e
      [[ $e == 3 ]] || fail "verify without a board: exit $e"
      json_is "$j" exit_code 3
      "$volcomp" monitor --can "$can" --json --interval-ms 100 --duration 0.35 >"$j"
      python3 - "$j" <<'PY' || fail "monitor --json: $(cat "$j")"
import json, sys
rows = [json.loads(l) for l in open(sys.argv[1])]
assert len(rows) >= 3, rows
assert [a["name"] for a in rows[-1]["axes"]] == ["X", "Y", "Z"], rows[-1]
assert "machine_mm" in rows[-1]["axes"][0] and "clamped" in rows[-1]["axes"][0], rows[-1]
PY
      ;;
    *) fail "unknown section $section" ;;
  esac
done
echo "safety session: OK"
