#!/usr/bin/env bash
# The recipes of docs/linuxcnc.md §3.2, executed as written on copies of LinuxCNC's own sample
# configurations (part of the LinuxCNC integration test, run_linuxcnc_test.sh, inside its lock):
#   run_recipes.sh VOLCOMP MODULE_DIR SOURCE_DIR WORK ARTIFACT_DIR
# stepgen: sim/axis/corexy/corexy_by_kins.ini (3joint_xyz.hal: stepgen, simulated home switches,
#          corexykins, inch) + the block "# volcomp-stepgen.hal" of the docs
# servo:   sim/tklinuxcnc/servo_sim.ini (servo_sim.hal: pid + encoder, home switch on X,
#          COMP_FILE on X, inch) + the block "# volcomp-servo.hal"; then the reload checks
# hm2-stepper, hm2-servo: by_interface/mesa/hm2-stepper and hm2-servo (5i20.ini: a Mesa card's
#          stepgens in position mode; pid on its pwmgens and encoders, a shared home switch, an
#          index on Y; inch) + the blocks "# volcomp-hm2-stepper.hal", "# volcomp-hm2-servo.hal";
#          the card is hm2_standin.comp (built here with halcompile), loaded in place of the
#          driver under the card's name
# Each copy changes only what running headless needs (DISPLAY, no APP) and what the docs tell a
# user to add to the INI file ([HAL]HALFILE after the machine's, [VOLCOMP]TABLE). The tables come
# from the S500 model over each machine's joint range. Checks: check_recipe.py.
set -euo pipefail
volcomp=$(realpath "$1") modules=$(realpath "$2") src=$(realpath "$3")
work=$(realpath -m "$4") artifacts=$(realpath -m "$5")
here=$(cd "$(dirname "$0")" && pwd)
samples=${VOLCOMP_LINUXCNC_SAMPLES:-/usr/share/doc/linuxcnc/examples/sample-configs}
mesa=$samples/by_interface/mesa
if [[ ! -f $samples/sim/axis/corexy/corexy_by_kins.ini || ! -f $samples/sim/tklinuxcnc/servo_sim.ini ||
      ! -f $mesa/hm2-stepper/5i20.ini || ! -f $mesa/hm2-servo/5i20.ini ]]; then
  echo "run_recipes: LinuxCNC's sample configurations are not in $samples" >&2
  exit 1
fi
run_uid=$(id -u nobody)
mkdir -p "$work"

# The block of docs/linuxcnc.md whose first line is "# NAME" (fenced code), as a file.
doc_block() {  # NAME OUT
  python3 - "$src/docs/linuxcnc.md" "$1" "$2" <<'EOF'
import re, sys
text = open(sys.argv[1]).read()
blocks = [b for b in re.findall(r"^```[^\n]*\n(.*?)^```", text, re.S | re.M)
          if b.startswith("# " + sys.argv[2])]
if len(blocks) != 1:
    sys.exit("run_recipes: docs/linuxcnc.md has %d blocks starting \"# %s\"" % (len(blocks), sys.argv[2]))
open(sys.argv[3], "w").write(blocks[0])
EOF
}

# What the docs tell a user to add to the INI file: the HAL file after the machine's HALFILE
# lines, a [VOLCOMP] section with the table; and the headless display.
edit_ini() {  # INI HALFILE TABLE
  python3 - "$@" <<'EOF'
import sys
ini, halfile, table = sys.argv[1:4]
lines = open(ini).read().split("\n")
section, last_halfile = None, None
for i, l in enumerate(lines):
    s = l.strip()
    if s.startswith("[") and s.endswith("]"):
        section = s
    elif section == "[HAL]" and s.replace(" ", "").startswith("HALFILE="):
        last_halfile = i
if last_halfile is None:
    sys.exit("run_recipes: %s has no [HAL]HALFILE" % ini)
lines.insert(last_halfile + 1, "HALFILE = " + halfile)
lines += ["", "[VOLCOMP]", "TABLE = " + table, ""]
open(ini, "w").write("\n".join(lines))
EOF
}

headless() {  # FILE (the INI or include file with [DISPLAY]): our display, no X applications
  sed -i "s|^DISPLAY *=.*|DISPLAY = $here/lcnc_recipe_run.py|; s|^APP *=|#APP =|" "$1"
}

run_recipe() {  # NAME DIR INI
  local name=$1 dir=$2 ini=$3 status=0
  shift 3
  mkdir -p "$dir/fifo"
  chown nobody "$dir/fifo"
  chmod -R a+rX "$dir"
  (cd "$dir" && VOLCOMP_RECIPE_OUT="$dir/recipe.csv" RTAPI_UID=$run_uid \
    RTAPI_FIFO_PATH="$dir/fifo/rtapi_fifo" "$@" \
    timeout 300 "$here/private_modules.sh" "$modules" "$dir/rtlib" linuxcnc -r "$ini" \
    >"$dir/linuxcnc.log" 2>&1) || status=$?
  mkdir -p "$artifacts/recipe-$name"
  cp "$dir"/*.hal "$dir"/*.ini "$dir/linuxcnc.log" "$dir"/recipe.csv* "$artifacts/recipe-$name/" \
    2>/dev/null || true
  grep "^lcnc_recipe_run: \|^volcomp" "$dir/linuxcnc.log" >&2 || true
  if [[ ! -f "$dir/recipe.csv.json" ]]; then
    echo "run_recipes: LinuxCNC ($name) ended (status $status) without results" >&2
    tail -n 30 "$dir/linuxcnc.log" >&2
    return 1
  fi
}

build_table() {  # OUT RANGE [SPACING_MM] (mm, over the machine's joint range)
  "$volcomp" build model --model "$src/samples/model/s500.conf" --resolution-nm X=1000,Y=1000,Z=1000 \
    --range "$2" --spacing-mm "${3:-20}" -o "$1" >/dev/null
}

# A copy of a Mesa sample with the stand-in in place of the card's driver (the only change to its
# HAL file).
mesa_sample() {  # SAMPLE DIR
  cp -rL "$mesa/$1" "$2"
  sed -i '/^loadrt hostmot2/d; s|^loadrt \[HOSTMOT2\](DRIVER) .*|loadrt hm2_standin names=hm2_[HOSTMOT2](BOARD).0|' \
    "$2/$1.hal"
  grep -q '^loadrt hm2_standin' "$2/$1.hal" || { echo "run_recipes: $1.hal: no driver line" >&2; return 1; }
  cp "$2/5i20.ini" "$2/machine.ini"
  headless "$2/machine.ini"
}

# VOLCOMP_RECIPES="NAME ...": only those runs (when working on one; the test runs all).
# fail: the recipe being run failed (named again at the end).
want() { [[ -z ${VOLCOMP_RECIPES:-} || " $VOLCOMP_RECIPES " == *" $1 "* ]] && current=$1; }
current="" failed=()
fail() { [[ " ${failed[*]} " == *" $current "* ]] || failed+=("$current"); }
if want stepgen; then
# --- stepgen: corexy (corexykins: joint 0 = X+Y, joint 1 = X-Y; the table is in joint space) ---
d=$work/stepgen
cp -rL "$samples/sim/axis/corexy" "$d"
doc_block volcomp-stepgen.hal "$d/volcomp-stepgen.hal"
build_table "$d/table.vct" X=-100:600,Y=-300:300,Z=-140:20
headless "$d/corexy_base.inc"
cp "$d/corexy_by_kins.ini" "$d/machine.ini"
edit_ini "$d/machine.ini" volcomp-stepgen.hal "$d/table.vct"
# The sample's 250 us base thread lets stepgen make 2 kHz: 0.25 in/s, at most 0.125 in/s per axis
# on a diagonal of corexy. Three stops around home.
echo "== LinuxCNC run 3: docs recipe on LinuxCNC's sample sim/axis/corexy (stepgen, inch)" >&2
run_recipe stepgen "$d" machine.ini env VOLCOMP_RECIPE_FEED=6 \
  VOLCOMP_RECIPE_POINTS="0.4,0.2,-0.3;0.6,0.1,-0.5;0.3,0.4,-0.2" || fail
python3 "$here/check_recipe.py" stepgen "$d" "$volcomp" "$d/table.vct" 0.000125 25.4 || fail

fi
if want servo; then
# --- servo: tklinuxcnc/servo_sim (pid + encoder; X homes to a switch; COMP_FILE on X) ---
d=$work/servo
cp -rL "$samples/sim/tklinuxcnc" "$d"
doc_block volcomp-servo.hal "$d/volcomp-servo.hal"
build_table "$d/table.vct" X=-270:270,Y=-270:270,Z=-60:110
cp "$d/servo_sim.ini" "$d/machine.ini"
headless "$d/machine.ini"
edit_ini "$d/machine.ini" volcomp-servo.hal "$d/table.vct"
echo "== LinuxCNC run 4: docs recipe on LinuxCNC's sample sim/tklinuxcnc/servo_sim (pid + encoder, inch), reloads" >&2
run_recipe servo "$d" machine.ini env VOLCOMP_RECIPE_FEED=100 \
  VOLCOMP_RECIPE_POINTS="3,2,-1;-2,3,1.5;4,-1,0.5" VOLCOMP_RECIPE_RELOAD=1 \
  VOLCOMP_RECIPE_TABLE="$d/table.vct" || fail
# One encoder count (6000 per inch).
python3 "$here/check_recipe.py" servo "$d" "$volcomp" "$d/table.vct" 0.000166667 25.4 servo || fail

fi
# --- Mesa cards: the stand-in, built like any third-party component ---
mkdir -p "$work/hm2_standin"
(cd "$work/hm2_standin" && halcompile --compile "$here/hm2_standin.comp" >halcompile.log 2>&1) || {
  echo "run_recipes: halcompile of hm2_standin.comp failed:" >&2
  cat "$work/hm2_standin/halcompile.log" >&2
  exit 1
}
standin=$work/hm2_standin/hm2_standin.so

if want hm2-stepper; then
d=$work/hm2-stepper
mesa_sample hm2-stepper "$d"
doc_block volcomp-hm2-stepper.hal "$d/volcomp-hm2-stepper.hal"
build_table "$d/table.vct" X=-260:260,Y=-260:260,Z=-260:260 40
edit_ini "$d/machine.ini" volcomp-hm2-stepper.hal "$d/table.vct"
echo "== LinuxCNC run 5: docs recipe on LinuxCNC's sample by_interface/mesa/hm2-stepper (card's stepgens, inch)" >&2
run_recipe hm2-stepper "$d" machine.ini env VOLCOMP_EXTRA_MODULES="$standin" \
  VOLCOMP_RECIPE_FEED=120 VOLCOMP_RECIPE_POINTS="2,1,-1;-3,4,2;5,-2,0.5" || fail
# One step (SCALE 1000 per inch).
python3 "$here/check_recipe.py" hm2-stepper "$d" "$volcomp" "$d/table.vct" 0.001 25.4 || fail

fi
if want hm2-servo; then
d=$work/hm2-servo
mesa_sample hm2-servo "$d"
doc_block volcomp-hm2-servo.hal "$d/volcomp-hm2-servo.hal"
build_table "$d/table.vct" X=-80:260,Y=-80:260,Z=-80:80
edit_ini "$d/machine.ini" volcomp-hm2-servo.hal "$d/table.vct"
echo "== LinuxCNC run 6: docs recipe on LinuxCNC's sample by_interface/mesa/hm2-servo (pid on the card's pwmgens and encoders, inch)" >&2
run_recipe hm2-servo "$d" machine.ini env VOLCOMP_EXTRA_MODULES="$standin" \
  VOLCOMP_RECIPE_FEED=50 VOLCOMP_RECIPE_POINTS="2,1,-1;-1,3,1;4,-2,0.5" || fail
# One encoder count (81920 per inch); command-deriv unconnected: pid differentiates the command.
python3 "$here/check_recipe.py" hm2-servo "$d" "$volcomp" "$d/table.vct" 0.0000122070 25.4 pid || fail
fi
((${#failed[@]} == 0)) && exit 0
echo "run_recipes: FAILED: ${failed[*]}" >&2
exit 1
