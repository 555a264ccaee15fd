#!/usr/bin/env bash
# `volcomp config` and `volcomp nmt` against `volcomp-sim node` over SLCAN-TCP: a board's
# configuration saved, edited and applied (written, stored, reset node, read back), saved again
# and applied to a fresh board, which then saves the identical file; the values checked with
# `sdo read`; files with an unknown key or an out-of-range value refused with their line before
# anything is sent (the frame log stays empty); a new units per step refused while a table is
# active (the home position in mm before and after), applied with --force; the NMT commands;
# status and monitor in machine units.
# usage: run_config_session.sh VOLCOMP_SIM VOLCOMP
set -euo pipefail
sim=$(realpath "$1") volcomp=$(realpath "$2")
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# start_node NAME: a fresh simulated board with its own flash; its CAN spec in $can.
start_node() {
  mkdir -p "$work/$1"
  "$sim" node --slcan-tcp 0 --flash-dir "$work/$1" --ready-file "$work/$1.ready" --duration 120 \
    >>"$work/$1.log" 2>&1 &
  for _ in $(seq 100); do [[ -s $work/$1.ready ]] && break; sleep 0.05; done
  [[ -s $work/$1.ready ]] || fail "node $1 did not start"
  can=$(cat "$work/$1.ready")
}
cd "$work"

echo "== save, edit, apply"
start_node a
"$volcomp" config save factory.ini --can "$can"
grep -q '^\[axis Z\]$' factory.ini || fail "no [axis Z] section"
"$volcomp" config save factory.ini --can "$can" 2>err.txt && fail "an existing file was replaced"
grep -q "exists; give --force" err.txt || fail "no --force hint"
sed -e 's/^axes = X Y Z /axes = X Y Z C /' \
    -e '0,/^home_position = 0 /s//home_position = -5000 /' \
    -e '0,/^max_correction = 1000 /s//max_correction = 800 /' factory.ini >machine.ini
printf '\n[axis C]\nkind = rotary        # a rotary table\nunits_per_step = 0.0001\n' >>machine.ini
"$volcomp" config apply machine.ini --can "$can" --log apply.log | tee out.txt
grep -q "2018:1 home_position (axis X) 0 -> -5000" out.txt || fail "change not listed"
grep -q "read back: all 156 objects as in machine.ini, in force" out.txt || fail "not read back"
grep -qE 'slcan0 610#2310100173617665 T$' apply.log || fail "no store (1010:1 = \"save\")"
grep -qE 'slcan0 000#8110 T$' apply.log || fail "no NMT reset node (000#8110) in the log"
[[ $("$volcomp" sdo read 2018:1 --can "$can") == "-5000 (0xFFFFEC78)" ]] || fail "2018:1"
[[ $("$volcomp" sdo read 2010:4 --can "$can") == "67 (0x43)" ]] || fail "2010:4 is not 'C'"
"$volcomp" config show --can "$can" | tee show.txt
grep -q "settings in force" show.txt || fail "show: not in force"
grep -qE '^2015:1  X    max_correction +800 +800 +1000 +\* steps' show.txt || fail "show: 2015:1"
"$volcomp" config apply machine.ini --can "$can" | grep -q "in force already; nothing written" \
  || fail "a second apply wrote something"

echo "== round trip through a fresh board"
"$volcomp" config save first.ini --can "$can"
start_node b
"$volcomp" config apply first.ini --can "$can"
"$volcomp" config save second.ini --can "$can"
cmp first.ini second.ini || { diff first.ini second.ini; fail "save -> apply -> save differs"; }
[[ $("$volcomp" sdo read 2012:4 --can "$can") == "100000 (0x186A0)" ]] || fail "2012:4"

echo "== refused files: the line, nothing sent"
sed 's/^max_rate = 2000 /max_rte = 2000 /' first.ini >typo.ini
line=$(grep -n '^max_rte' typo.ini | cut -d: -f1)
set +e
"$volcomp" config apply typo.ini --can "$can" --log typo.log 2>err.txt; code=$?
set -e
[[ $code == 1 ]] || fail "typo: exit $code"
grep -q "typo.ini:$line: unknown key 'max_rte' in \[axis X\]" err.txt || { cat err.txt; fail "typo"; }
[[ ! -s typo.log ]] || fail "frames were sent for a refused file"
sed '0,/^max_correction = 800 /s//max_correction = 70000 /' first.ini >range.ini
line=$(grep -n '^max_correction = 70000' range.ini | cut -d: -f1)
set +e
"$volcomp" config apply range.ini --can "$can" --log range.log 2>err.txt; code=$?
set -e
[[ $code == 1 ]] || fail "range: exit $code"
grep -q "range.ini:$line: max_correction = 70000: above the highest value 65536" err.txt \
  || { cat err.txt; fail "range"; }
[[ ! -s range.log ]] || fail "frames were sent for a refused file"
"$volcomp" config save third.ini --can "$can"
cmp second.ini third.ini || fail "the board changed after refused files"

echo "== a new units per step: the home position in mm, refused while a table is active"
printf 'x_mm,y_mm,z_mm,dx_um,dy_um,dz_um\n' >grid.csv
for x in 0 100; do for y in 0 100; do for z in 0 100; do
  printf '%s,%s,%s,5,-3,2\n' $x $y $z >>grid.csv
done; done; done
"$volcomp" build grid --csv grid.csv -o t.vct --resolution-nm X=1000,Y=1000,Z=1000 --table-id 7 \
  >/dev/null
"$volcomp" reference --axes 1,2,3,4 --can "$can" >/dev/null
"$volcomp" upload t.vct --can "$can" --activate --quiet >/dev/null || fail "upload --activate"
# X: 0.001 -> 0.0025 mm per step with home_position -5000 steps (-5 mm -> -12.5 mm).
sed '0,/^units_per_step = 0.001 /s//units_per_step = 0.0025 /' third.ini >coarse.ini
set +e
"$volcomp" config apply coarse.ini --can "$can" --log coarse.log >out.txt 2>err.txt; code=$?
set -e
[[ $code == 1 ]] || { cat out.txt err.txt; fail "resolution change with a table active: exit $code"; }
grep -q "while table id 7 (CRC-32 0x[0-9A-F]*) is active" err.txt || { cat err.txt; fail "no table named"; }
grep -q "axis 1 X: resolution 1000 steps/mm (1000 nm/step) -> 400 steps/mm (2500 nm/step); home position -5000 steps = -5.0000 mm -> -5000 steps = -12.5000 mm" \
  err.txt || { cat err.txt; fail "no home position in mm"; }
grep -q -- "--force; nothing written" err.txt || fail "no --force hint"
! grep -qE ' 610#2[0-9A-F]' coarse.log || fail "frames written for a refused change"
"$volcomp" config apply coarse.ini --can "$can" --force --json >coarse.json 2>/dev/null ||
  fail "apply --force"
python3 - <<'PY' || fail "apply --force: resolution_changes"
import json
r = json.load(open("coarse.json"))
x = r["resolution_changes"][0]
assert (x["name"], x["units_per_step_before"], x["units_per_step"]) == ("X", 0.001, 0.0025), x
assert (x["steps_per_unit_before"], x["steps_per_unit"]) == (1000, 400), x  # 1/0.001, 1/0.0025
assert abs(x["home_position_before"] + 5) < 1e-9 and abs(x["home_position"] + 12.5) < 1e-9, x
assert r["outcome"] == "in force", r["outcome"]
PY
"$volcomp" status --can "$can" | grep -q "active table: none" || fail "the table was not dropped"

echo "== nmt"
"$volcomp" nmt stop --can "$can" | grep -q "heartbeat reports stopped" || fail "nmt stop"
"$volcomp" nmt start --can "$can" | grep -q "heartbeat reports operational" || fail "nmt start"
"$volcomp" nmt pre-op --can "$can" | grep -q "heartbeat reports pre-operational" || fail "pre-op"
"$volcomp" nmt reset-comm --can "$can" | grep -q "boot-up seen" || fail "nmt reset-comm"
"$volcomp" nmt reset --can "$can" | grep -q "boot-up seen" || fail "nmt reset"
set +e
"$volcomp" nmt restart --can "$can" 2>/dev/null; code=$?
set -e
[[ $code == 2 ]] || fail "nmt restart: exit $code"

echo "== status and monitor in machine units"
"$volcomp" status --can "$can" | tee status.txt
grep -q "^axis 4 C: input 0 steps, machine not referenced, correction +0.000 arcsec" status.txt || fail "status axis C"
# X has 0.0025 mm per step since coarse.ini: 800 steps = 2000 µm
grep -q "max 800 = 2000.000 µm)" status.txt || fail "status: max correction of X"
"$volcomp" status --can "$can" --json >status.json
grep -q '"name": "C"' status.json || fail "status --json: names"
grep -q '"commanded_mm": 0' status.json || fail "status --json: mm"
# Rows at most every 100 ms; each reads a snapshot over the simulated bus (longer on a busy
# machine), so the count is checked loosely.
"$volcomp" monitor --can "$can" --csv --interval-ms 100 --duration 1 >monitor.csv 2>/dev/null
head -1 monitor.csv |
  grep -q '^time_s,state,X_commanded_mm,X_machine_mm,X_correction_um,X_correction_steps,' \
  || fail "monitor --csv header"
fields=$(head -1 monitor.csv | awk -F, '{print NF}')
rows=$(tail -n +2 monitor.csv | awk -F, -v n="$fields" 'NF == n' | wc -l)
[[ $rows -ge 2 ]] || { cat monitor.csv; fail "monitor --csv: $rows rows of $fields fields"; }
# Not referenced: no machine position yet (an empty cell, not a made-up 0).
[[ $(sed -n 2p monitor.csv | cut -d, -f4) == "" ]] || fail "monitor --csv: machine position before referencing"
"$volcomp" monitor --can "$can" --interval-ms 100 --duration 0.25 >monitor.txt 2>/dev/null
grep -q '| X input 0.0000 mm, correction +0.00 um (+0.00 steps) |.* C input 0.0000 deg, correction +0.00 arcsec (+0.00 steps) |' \
  monitor.txt || { cat monitor.txt; fail "monitor: axis names and units"; }
# Referenced: the machine position of status, in the CSV and the text.
"$volcomp" reference --axes 1,2,3,4 --can "$can" >/dev/null || fail "reference"
"$volcomp" status --can "$can" --json >status.json
x_machine=$(python3 -c 'import json,sys; print("%.6f" % json.load(open("status.json"))["axes"][0]["machine_mm"])')
"$volcomp" monitor --can "$can" --csv --interval-ms 100 --duration 0.25 >monitor.csv 2>/dev/null
[[ $(sed -n 2p monitor.csv | cut -d, -f4) == "$x_machine" ]] ||
  { cat monitor.csv; fail "monitor --csv: X machine position, status says $x_machine"; }
"$volcomp" monitor --can "$can" --interval-ms 100 --duration 0.25 >monitor.txt 2>/dev/null
grep -q "| X machine $(printf '%.4f' "$x_machine") mm, correction" monitor.txt ||
  { cat monitor.txt; fail "monitor: X machine position"; }
echo "PASS"
