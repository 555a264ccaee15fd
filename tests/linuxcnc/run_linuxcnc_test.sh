#!/usr/bin/env bash
# The volcomp integration test with a real LinuxCNC (docs/linuxcnc.md §4; ctest label external).
#   run_linuxcnc_test.sh VOLCOMP LCNC_EVALUATE MODULE_DIR SOURCE_DIR ARTIFACT_DIR
# Builds the S500 table with the PC tool, writes the GOST 27843 (X, Y, Z) and ISO 230-6 (four body
# diagonals) programs with `volcomp program`, runs `linuxcnc -r` headless with lcnc_run.py as its
# display and this build's two HAL components in a private module directory (loadrt accepts no
# paths: private_modules.sh mounts one over LinuxCNC's for the run only; needs root), on a machine
# switched on at a different place every run (VOLCOMP_LCNC_SEED repeats one) that homes to
# switches, evaluates the recorded rest points (lcnc_evaluate, then `volcomp evaluate`) and checks
# the figures (check_figures.py) and the machine position the corrections were read at
# (check_machine_position.py); then runs the recipes of docs/linuxcnc.md on LinuxCNC's own sample
# configurations (run_recipes.sh). Exit 77 (skipped) without root or without LinuxCNC.
set -euo pipefail
trap 'echo "run_linuxcnc_test: failed at line $LINENO: $BASH_COMMAND" >&2' ERR
volcomp=$1 evaluate=$2 modules=$3 src=$4 artifacts=$5
here=$(cd "$(dirname "$0")" && pwd)
if [[ $(id -u) -ne 0 ]]; then
  echo "run_linuxcnc_test: needs root (a private module directory, rtapi_app's RTAPI_UID)" >&2
  exit 77
fi
if ! command -v linuxcnc >/dev/null || ! command -v halcompile >/dev/null; then
  echo "run_linuxcnc_test: LinuxCNC not installed (scripts/setup-deps.sh linuxcnc)" >&2
  exit 77
fi

# One LinuxCNC on the machine at a time: the module directory, HAL's shared memory and the
# real-time priorities belong to the machine, and a second LinuxCNC (another checkout's test)
# disturbs or breaks this one. The lock serialises this test between checkouts; the wait for
# rtapi_app also covers a LinuxCNC started otherwise.
wait_for_no_linuxcnc() {  # seconds
  local waited=0
  while pgrep -x rtapi_app >/dev/null; do
    if ((waited == 0)); then echo "run_linuxcnc_test: waiting for the running LinuxCNC" >&2; fi
    if ((waited >= $1 * 2)); then
      echo "run_linuxcnc_test: another LinuxCNC (rtapi_app) is still running after $1 s" >&2
      exit 1
    fi
    sleep 0.5
    waited=$((waited + 1))
  done
}
exec 9>/tmp/volcomp-linuxcnc-test.lock
if ! flock -w 540 9; then
  echo "run_linuxcnc_test: another checkout's LinuxCNC test held the lock for 540 s" >&2
  exit 1
fi

# rtapi_app refuses to run as root: it drops to RTAPI_UID and keeps its FIFO in RTAPI_FIFO_PATH.
run_uid=$(id -u nobody)
work=$(mktemp -d /tmp/volcomp-linuxcnc.XXXXXX)
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"
mkdir "$work/fifo"
chown nobody "$work/fifo"

res_nm=2500
step_mm=0.0025
# Where the simulated machine is switched on, drawn anew each run (mm from machine zero, whole
# steps; the home switches are 0.5 mm below zero): homing then sets LinuxCNC's motor offsets to
# minus these, and the compensation must still read the table at the machine position.
seed=${VOLCOMP_LCNC_SEED:-$(($(od -An -N4 -tu4 /dev/urandom | tr -d ' ') % 1000000000))}
# 20..80 mm on X and Y, 20..60 mm on Z: the S500 table differs by more than 10 steps between
# points 20 mm apart somewhere on the test's stops, and homing at 15 mm/s takes under 6 s.
power_on() {  # RUN: "x,y,z" mm
  awk -v s="$seed" -v run="$1" -v st=$step_mm 'BEGIN { srand(s); for (i = 0; i < 3 * run; ++i) rand();
    printf "%.4f,%.4f,%.4f", int((20 + 60 * rand()) / st) * st,
    int((20 + 60 * rand()) / st) * st, int((20 + 40 * rand()) / st) * st }'
}
power_on_1=$(power_on 0)
power_on_2=$(power_on 1)
echo "run_linuxcnc_test: seed $seed (VOLCOMP_LCNC_SEED): power-on positions run 1 $power_on_1 mm, run 2 $power_on_2 mm" >&2
# set_power_on INI "x,y,z": the [SIM] values of volcomp-sim.ini for that power-on position.
set_power_on() {
  local ini=$1 j=0 p home_offset
  home_offset=$(awk -F' *= *' '/^HOME_OFFSET/ {print $2; exit}' "$ini")
  for p in ${2//,/ }; do
    sed -i "s|^POWER_ON_$j = .*|POWER_ON_$j = $p|" "$ini"
    # The switch in motor coordinates, half a step below it (it closes at and below).
    sed -i "s|^HOME_SWITCH_$j = .*|HOME_SWITCH_$j = $(awk -v o="$home_offset" -v p="$p" \
      -v st=$step_mm 'BEGIN { printf "%.6f", o - p - st / 2 }')|" "$ini"
    j=$((j + 1))
  done
}
# The programs' feed (mm/min): LinuxCNC's MAX_LINEAR_VELOCITY (mm/s) in volcomp-sim.ini.
feed=$(awk -F' *= *' '/^MAX_LINEAR_VELOCITY/ {print $2 * 60}' "$src/linuxcnc/config/volcomp-sim.ini")
# 0.5 s: the recorder waits for 100 ms of still values; on a loaded machine values were seen to
# settle only after 0.2 s, and a snapshot still waiting when its 0.3 s dwell ended missed the next
# stop (docs/linuxcnc.md §4).
dwell=0.5
"$volcomp" build model --model "$src/samples/model/s500.conf" \
  --resolution-nm X=$res_nm,Y=$res_nm,Z=$res_nm --spacing-mm 10 -o "$work/table.vct" >"$work/build.txt"
programs=() eval_args=()
pos() {  # axis end pitch
  "$volcomp" program positioning --axis "$1" --start 10 --end "$2" --pitch "$3" --count 6 \
    --runs 2 --feed $feed --dwell-s $dwell -o "$work/gost_$1.ngc" --targets-csv "$work/gost_$1.csv"
  programs+=("$work/gost_$1.ngc")
  eval_args+=(--positioning "gost_$1.ngc=$work/gost_$1.csv")
}
pos X 390 60
pos Y 270 40
pos Z 190 30
diag() {  # name p1 p2 file
  "$volcomp" program diagonal --name "$1" --p1 "$2" --p2 "$3" --increment-mm 123.59 --runs 2 \
    --feed $feed --dwell-s $dwell -o "$work/$4.ngc" --targets-csv "$work/$4.csv"
  programs+=("$work/$4.ngc")
  eval_args+=(--diagonal "$4.ngc=$work/$4.csv")
}
# The four body diagonals of the box 10 mm inside the S500's travel (as in volcomp-sim demo),
# 5 targets each (the fewest ISO 230-6 §5.2 allows on 494 mm: the run time of the test counts).
# Each is named by its start corner (ISO 230-6).
diag -X-Y-Z 10,10,10 390,270,190 diag_nnn
diag +X-Y-Z 390,10,10 10,270,190 diag_pnn
diag -X+Y-Z 10,270,10 390,10,190 diag_npn
diag -X-Y+Z 10,10,190 390,270,10 diag_nnp

# run_lcnc DIR MODE PROGRAM...: LinuxCNC headless in DIR (volcomp-sim.ini there), lcnc_run.py as
# its display; the rest points go to DIR/rest.csv, the summary to DIR/rest.csv.json.
run_lcnc() {
  local dir=$1 mode=$2 status=0
  shift 2
  # LinuxCNC's realtime process of the run before may still be exiting: it would compete with the
  # new one (its threads keep their SCHED_FIFO priority) and share its HAL.
  wait_for_no_linuxcnc 540
  # Real-time threads already running (they compete with the base thread): listed in the log.
  ps -eLo pid,tid,cls,rtprio,pcpu,comm | awk 'NR == 1 || ($3 == "FF" || $3 == "RR") && $4 < 99' \
    >"$dir/rt_threads_before.txt" || true
  cp "$here/lcnc_run.py" "$here/rtapi_priority.py" "$dir/"
  sed -i "s|^DISPLAY = .*|DISPLAY = $dir/lcnc_run.py|" "$dir/volcomp-sim.ini"
  mkdir -p "$dir/fifo"
  chown nobody "$dir/fifo"
  chmod -R a+rX "$dir"
  (cd "$dir" && IFS=: && VOLCOMP_LCNC_MODE=$mode VOLCOMP_LCNC_FIFO_PRIORITY=60 \
    VOLCOMP_LCNC_OUT="$dir/rest.csv" VOLCOMP_LCNC_PROGRAMS="$*" \
    RTAPI_UID=$run_uid RTAPI_FIFO_PATH="$dir/fifo/rtapi_fifo" \
    timeout 900 "$here/private_modules.sh" "$modules" "$dir/rtlib" linuxcnc -r volcomp-sim.ini \
    >"$dir/linuxcnc.log" 2>&1) || status=$?
  mkdir -p "$artifacts/$mode"
  cp "$dir/linuxcnc.log" "$dir/rest.csv" "$dir/rest.csv.json" "$dir/rt_threads_before.txt" \
     "$artifacts/$mode/" 2>/dev/null || true
  grep "^lcnc_run: " "$dir/linuxcnc.log" | grep -v "^lcnc_run: threads" >&2 || true
  grep -v "Running with fallback_uid\|main loop took\|^lcnc_run: " "$dir/linuxcnc.log" |
    tail -n 25 >&2 || true
  if [[ ! -f "$dir/rest.csv.json" ]]; then
    echo "run_linuxcnc_test: LinuxCNC ($mode) ended (status $status) without results" >&2
    exit 1
  fi
}

# 0. The native component in a bare rtapi_app: loadrt's refusals, instances, gantry, rotary, inch,
#    run-time parameters (a few seconds).
# step NAME COMMAND...: runs a part whose failure does not stop the others; its output also goes
# to $work/steps/NAME.log, and a failed part is named, with its failure lines, at the very end (CI
# shows the head and the tail of a long log: the verdict must be in the tail).
failed=()
mkdir -p "$work/steps"
step() {
  local name=$1
  shift
  "$@" 2>&1 | tee "$work/steps/$name.log" >&2 || failed+=("$name")
}
wait_for_no_linuxcnc 540
step hal_component "$here/run_hal_component_test.sh" "$volcomp" "$modules" "$src" "$work/hal"
cp "$work/hal/halrun.log" "$artifacts/" 2>/dev/null || mkdir -p "$artifacts"

# 1. The board behind stepgen and the native component in the position loop, in one run.
cp "$src/linuxcnc/config/volcomp-sim.ini" "$src/linuxcnc/config/volcomp-sim.hal" "$work/"
sed -i "s|^TABLE = .*|TABLE = $work/table.vct|" "$work/volcomp-sim.ini"
set_power_on "$work/volcomp-sim.ini" "$power_on_1"
echo "== LinuxCNC run 1: board and native component (${#programs[@]} programs)" >&2
start=$(date +%s)
run_lcnc "$work" board "${programs[@]}"
"$evaluate" --rest "$work/rest.csv" --step-mm $step_mm --out "$work/eval" "${eval_args[@]}"
for c in before board native; do
  for a in X Y Z; do
    "$volcomp" evaluate positioning "$work/eval/$c/gost_$a.csv" --standard gost27843 \
      --allow-few-runs --json >"$work/eval/$c/gost_$a.json" 2>>"$work/evaluate.log"
  done
  "$volcomp" evaluate diagonal "$work/eval/$c/diagonals.csv" --allow-few-runs --json \
    >"$work/eval/$c/diagonals.json" 2>>"$work/evaluate.log"
done

# 2. LinuxCNC's own 1-D joint compensation, from the uncompensated X and Y positioning results of
#    run 1: X as COMP_FILE_TYPE 1, Y as type 0; the same X and Y programs again.
comp=$work/comp
mkdir -p "$comp"
cp "$src/linuxcnc/config/volcomp-comp.hal" "$work/volcomp-sim.ini" "$comp/"
sed -i "s|^HALFILE = .*|HALFILE = volcomp-comp.hal|" "$comp/volcomp-sim.ini"
set_power_on "$comp/volcomp-sim.ini" "$power_on_2"
# As a user would: the export merges its lines into the machine's [JOINT_n] sections (--ini).
"$volcomp" export linuxcnc --x "$work/eval/before/gost_X.csv" --type 1 --allow-few-runs \
  -o "$comp/type1" --ini "$comp/volcomp-sim.ini" >&2
"$volcomp" export linuxcnc --y "$work/eval/before/gost_Y.csv" --type 0 --allow-few-runs \
  -o "$comp/type0" --ini "$comp/volcomp-sim.ini" >&2
for j in 0 1; do
  if [[ $(grep -c "^\[JOINT_$j\]" "$comp/volcomp-sim.ini") -ne 1 ]]; then
    echo "run_linuxcnc_test: export linuxcnc --ini left [JOINT_$j] other than once" >&2
    exit 1
  fi
done
echo "== LinuxCNC run 2: joint compensation files (gost_X, gost_Y)" >&2
run_lcnc "$comp" comp "$work/gost_X.ngc" "$work/gost_Y.ngc"
"$evaluate" --rest "$comp/rest.csv" --step-mm $step_mm --out "$comp/eval" \
  --positioning "gost_X.ngc=$work/gost_X.csv" --positioning "gost_Y.ngc=$work/gost_Y.csv"
for a in X Y; do
  "$volcomp" evaluate positioning "$comp/eval/comp1d/gost_$a.csv" --standard gost27843 \
    --allow-few-runs --json >"$comp/eval/comp1d/gost_$a.json" 2>>"$work/evaluate.log"
done
wall12=$(($(date +%s) - start))

# 3, 4. The recipes of docs/linuxcnc.md on LinuxCNC's own sample configurations.
wait_for_no_linuxcnc 540
step recipes "$here/run_recipes.sh" "$volcomp" "$modules" "$src" "$work/recipes" "$artifacts"
wall=$(($(date +%s) - start))

mkdir -p "$artifacts"
cp -r "$work/eval" "$work/rest.csv" "$work/rest.csv.json" "$work/table.vct" "$work"/*.ngc \
   "$artifacts/"
cp -r "$comp/eval" "$artifacts/comp/"
cp -r "$comp/type0" "$comp/type1" "$comp/volcomp-sim.ini" "$artifacts/comp/"
step check_comp python3 "$here/check_comp.py" "$comp" \
  "0:1:$comp/type1/x.comp:$work/gost_X.csv:gost_X.ngc" "1:0:$comp/type0/y.comp:$work/gost_Y.csv:gost_Y.ngc"
step check_machine_position python3 "$here/check_machine_position.py" "$work" "$volcomp" \
  "$work/table.vct" $step_mm "$power_on_1"
cp "$work/machine_position.json" "$artifacts/" 2>/dev/null || true
step check_figures python3 "$here/check_figures.py" "$work" "$wall"
cp -r "$work/steps" "$artifacts/"
echo "LinuxCNC runs 1 and 2: $wall12 s; with the recipes (runs 3 and 4): $wall s; seed $seed" >&2
((${#failed[@]} == 0)) && exit 0
echo "run_linuxcnc_test: FAILED: ${failed[*]} (seed $seed; logs in $artifacts/steps)" >&2
for name in "${failed[@]}"; do
  grep -i -A 12 "failed\|without results\|error:" "$work/steps/$name.log" | head -n 40 |
    sed "s|^|  $name: |" >&2 || true
done
exit 1
