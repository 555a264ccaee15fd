#!/usr/bin/env bash
# The native component as HAL sees it, in a real rtapi_app without motion (halrun, a few seconds;
# part of the LinuxCNC integration test, run_linuxcnc_test.sh, inside its lock):
#   run_hal_component_test.sh VOLCOMP MODULE_DIR SOURCE_DIR WORK
# - loadrt refuses a missing, a damaged and an unreadable table with the reason (errno text, the
#   text of `volcomp inspect`, the uid rtapi_app reads as) and loads after each refusal;
# - two instances by names= with their own tables, units and joint maps: vc-mm (the S500 grid,
#   mm) and vc-in (an XYZA table of AXIS1D tables with a wrapping rotary A, built by `volcomp build
#   axis`; inch; axes=XYYZA: a gantry's joints 1 and 2 share Y): each joint's correction is the
#   table's value (`volcomp lookup`) at the joint position, joint 2 follows joint 1's position,
#   A wraps (405 degrees reads 45), inch positions and corrections are converted;
# - per-instance pins; run-time parameters: a smaller max-correction clamps at once (clamped),
#   a limit the limiter cannot hold is refused with a message and the parameter set back.
set -euo pipefail
volcomp=$(realpath "$1") modules=$(realpath "$2") src=$(realpath "$3") work=$(realpath -m "$4")
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"
mkdir -p "$work/fifo"
chown nobody "$work/fifo"
cd "$work"
"$volcomp" build model --model "$src/samples/model/s500.conf" --resolution-nm X=2500,Y=2500,Z=2500 \
  --spacing-mm 20 -o grid.vct >/dev/null
printf 'position_mm,dev_forward_um\n0,0\n100,10\n200,30\n300,20\n400,0\n' >x.csv
printf 'position_mm,dev_forward_um\n0,0\n100,-5\n200,-15\n300,0\n400,8\n' >y.csv
printf 'position_mm,dev_forward_um\n0,2\n100,4\n200,0\n300,-4\n400,-2\n' >z.csv
printf 'position_deg,dev_forward_arcsec\n0,0\n90,20\n180,0\n270,-20\n360,0\n' >a.csv
"$volcomp" build axis --x x.csv --y y.csv --z z.csv --a a.csv --wrap \
  --resolution-nm X=1000,Y=1000,Z=1000,A=1000 -o xyza.vct >/dev/null
cp grid.vct damaged.vct
printf '\x55' | dd of=damaged.vct bs=1 seek=300 conv=notrunc 2>/dev/null
cp grid.vct private.vct
chmod 600 private.vct  # root's: rtapi_app (RTAPI_UID nobody) may not read it
chmod 755 "$work"
chmod 644 grid.vct xyza.vct damaged.vct

# Joint positions: vc-mm in mm; vc-in in inch (X 150 mm, Y 50 mm, Y's second joint elsewhere,
# Z 20 mm, A 405 degrees).
cat >test.hal <<EOF
loadrt volcomp table=$work/nonexistent.vct
loadrt volcomp table=$work/damaged.vct
loadrt volcomp table=$work/private.vct
loadrt threads name1=servo period1=1000000
loadrt volcomp names=vc-mm,vc-in table=$work/grid.vct,$work/xyza.vct units=mm,inch axes=XYZ,XYYZA
addf vc-mm.feedback servo
addf vc-in.feedback servo
addf vc-mm.update servo
addf vc-in.update servo
setp vc-mm.enable 1
setp vc-mm.referenced 1
setp vc-in.enable 1
setp vc-in.referenced 1
setp vc-mm.joint.0.joint-pos-cmd 123.4
setp vc-mm.joint.1.joint-pos-cmd 56.7
setp vc-mm.joint.2.joint-pos-cmd 89.0
setp vc-mm.joint.0.pos-cmd-in 10
setp vc-mm.joint.0.pos-fb-in 10
setp vc-mm.joint.0.vel-cmd-in 2
setp vc-in.joint.0.joint-pos-cmd 5.905511811
setp vc-in.joint.1.joint-pos-cmd 1.968503937
setp vc-in.joint.2.joint-pos-cmd 9.0
setp vc-in.joint.3.joint-pos-cmd 0.787401575
setp vc-in.joint.4.joint-pos-cmd 405
start
loadusr -w sleep 1.5
show pin vc-
show param vc-
setp vc-in.axis.x.max-correction 0.0001
setp vc-mm.axis.y.max-correction-accel 1e12
loadusr -w sleep 0.5
show pin vc-in.joint.0.correction
show pin vc-in.clamped
show param vc-mm.axis.y.max-correction-accel
EOF
status=0
RTAPI_UID=$(id -u nobody) RTAPI_FIFO_PATH="$work/fifo/rtapi_fifo" \
  timeout 60 "$here/private_modules.sh" "$modules" "$work/rtlib" halrun -k -f test.hal \
  >halrun.log 2>&1 || status=$?
python3 - "$work" "$volcomp" <<'EOF' || exit 1
import csv, io, re, subprocess, sys
work, volcomp = sys.argv[1:3]
log = open(work + "/halrun.log", errors="replace").read()
failures = []
def check(ok, what):
    if not ok:
        failures.append(what)
for want in ['cannot read table "%s/nonexistent.vct": No such file or directory' % work,
             'table "%s/damaged.vct" refused: invalid table image: image CRC-32 does not match '
             '(kImageBadCrc)' % work,
             'cannot read table "%s/private.vct": Permission denied (rtapi_app reads as uid' % work]:
    check(want in log, "loadrt's message missing: " + want)
values = {}
for m in re.finditer(r"^\s*\d+\s+(?:float|bit|s32|u32)\s+(?:IN|OUT|I/O|RW|RO)\s+(\S+)\s+(\S+)", log, re.M):
    values.setdefault(m.group(2), []).append(m.group(1))
def v(name, i=0):
    if name not in values or len(values[name]) <= i:
        return float("nan")
    text = values[name][i]
    return {"TRUE": 1.0, "FALSE": 0.0}.get(text, None) if text in ("TRUE", "FALSE") else float(text)
def lookup(table, header, row):
    out = subprocess.run([volcomp, "lookup", table], input=header + "\n" + row + "\n",
                         capture_output=True, text=True, check=True).stdout
    return next(csv.DictReader(io.StringIO(out)))
step = 0.0025
g = lookup(work + "/grid.vct", "x_mm,y_mm,z_mm", "123.4,56.7,89.0")
for j, a in enumerate("xyz"):
    got, want = v("vc-mm.joint.%d.correction" % j), float(g["d%s_um" % a]) / 1000
    check(abs(got - want) <= step, "vc-mm joint %d: correction %.6f mm, the table %.6f mm" % (j, got, want))
check(abs(v("vc-mm.joint.0.pos-cmd-out") - (10 + v("vc-mm.joint.0.correction"))) < 1e-5 and
      abs(v("vc-mm.joint.0.pos-fb-out") - (10 - v("vc-mm.joint.0.correction"))) < 1e-5,
      "vc-mm joint 0: pos-cmd-out / pos-fb-out are not the input plus / minus the correction")
check(abs(v("vc-mm.joint.0.vel-cmd-out") - 2) < 1e-6, "vc-mm: vel-cmd-out at rest is not vel-cmd-in")
t = lookup(work + "/xyza.vct", "x_mm,y_mm,z_mm,a_deg", "150,50,20,45")
inch = 25.4
want = [float(t["dx_um"]) / 1000 / inch, float(t["dy_um"]) / 1000 / inch,
        float(t["dy_um"]) / 1000 / inch, float(t["dz_um"]) / 1000 / inch,
        float(t["da_arcsec"]) / 3600]
for j in range(5):
    got = v("vc-in.joint.%d.correction" % j)
    tol = 0.001 / 3600 * 1000 if j == 4 else 0.001 / inch  # a table step
    check(abs(got - want[j]) <= tol, "vc-in joint %d: correction %.8f, the table %.8f" % (j, got, want[j]))
check(v("vc-in.active") == 1 and v("vc-mm.active") == 1, "an instance is not active")
check(v("vc-in.table-error") == 0 and v("vc-in.clamped") == 0, "vc-in: table-error or clamped set")
# After `setp vc-in.axis.x.max-correction 0.0001`: clamped at once; the refused acceleration
# is set back to its default (200000 steps/s^2 of 2.5 um) with a message.
check(abs(v("vc-in.joint.0.correction", 1)) <= 0.0001 + 1e-12, "vc-in: max-correction did not clamp")
check(v("vc-in.clamped", 1) == 1, "vc-in: clamped not set")
check(abs(v("vc-mm.axis.y.max-correction-accel", 1) - 500.0) < 1e-6,
      "vc-mm: the refused acceleration was not set back: %s" % values.get("vc-mm.axis.y.max-correction-accel"))
check("vc-mm: axis Y: limits refused" in log, "no message for the refused limit")
print("HAL component: loadrt refusals with their reasons; two instances (names=, units=mm,inch, "
      "axes=XYZ,XYYZA); gantry joint 2 follows joint 1 (%.6f = %.6f in); A at 405 deg reads the "
      "table at 45 deg (%.6f deg); run-time max-correction clamps, a refused limit is set back"
      % (v("vc-in.joint.2.correction"), v("vc-in.joint.1.correction"), v("vc-in.joint.4.correction")))
if failures:
    print("FAILED (HAL component):\n  " + "\n  ".join(failures))
    sys.exit(1)
EOF
exit 0
