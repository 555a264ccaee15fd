#!/usr/bin/env python3
"""Checks that both compensations read the table at the machine position (docs/linuxcnc.md §3).

check_machine_position.py WORK VOLCOMP TABLE STEP_MM POWER_ON_MM(X,Y,Z)
WORK/rest.csv (lcnc_run.py, board mode): at every stop LinuxCNC's joint position (cmd_mm_N,
joint.N.pos-cmd), its motor position (motor_cmd_mm_N) and both corrections. The machine was
switched on POWER_ON_MM away from machine zero and homed to switches, so the two positions differ
by the power-on position. At every stop the native correction and the board's (whole steps) must
be the table's value at the machine position (`volcomp lookup`, the PC tool's reading of the same
file) within one step; the table's value at the motor position must differ from it by more than a
step somewhere (else this run could not tell the two apart). Homing must have set the motor
offsets to minus the power-on positions within a step. Exit 1 with every failed check listed.
"""
import csv
import io
import json
import os
import subprocess
import sys

work, volcomp, table, step_mm = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
power_on = [float(v) for v in sys.argv[5].split(",")]
rows = list(csv.DictReader(open(os.path.join(work, "rest.csv"))))
summary = json.load(open(os.path.join(work, "rest.csv.json")))
failures = []


def lookup(columns):
    """The table's correction (steps) at each row's position given by `columns` (mm)."""
    points = "x_mm,y_mm,z_mm\n" + "".join(
        ",".join("%.6f" % float(r[c]) for c in columns) + "\n" for r in rows)
    out = subprocess.run([volcomp, "lookup", table], input=points, capture_output=True, text=True,
                         check=True).stdout
    return [[float(p["d%s_steps" % a]) for a in "xyz"] for p in csv.DictReader(io.StringIO(out))]


at_machine = lookup(["cmd_mm_%d" % j for j in range(3)])
at_motor = lookup(["motor_cmd_mm_%d" % j for j in range(3)])
worst_native = worst_board = worst_motor = 0.0
for r, m, w in zip(rows, at_machine, at_motor):
    for j in range(3):
        native = float(r["native_corr_mm_%d" % j]) / step_mm
        board = float(r["board_corr_%d" % j])
        worst_native = max(worst_native, abs(native - m[j]))
        worst_board = max(worst_board, abs(board - m[j]))
        worst_motor = max(worst_motor, abs(w[j] - m[j]))
        if abs(native - m[j]) > 1 or abs(board - m[j]) > 1:
            failures.append("%s stop %s joint %d at %.4f mm (motor %.4f mm): native %.3f, board "
                            "%d steps; the table there: %.3f steps (at the motor position %.3f)"
                            % (r["program"], r["stop"], j, float(r["cmd_mm_%d" % j]),
                               float(r["motor_cmd_mm_%d" % j]), native, board, m[j], w[j]))
if worst_motor <= 1:
    failures.append("the table differs by at most %.3f steps between the machine and the motor "
                    "positions in this run: it cannot tell them apart (power-on %s mm)"
                    % (worst_motor, power_on))
offsets = summary.get("motor_offset_mm", [0, 0, 0])
homing_error = [abs(o + p) / step_mm for o, p in zip(offsets, power_on)]
if max(homing_error) > 1:
    failures.append("homing set motor offsets %s mm for power-on positions %s mm" %
                    (offsets, power_on))
print("machine position: power-on %s mm, motor offsets after homing %s mm (homing %.2f steps off);"
      " at %d stops the correction at the machine position: native within %.3f, board within %.3f"
      " steps; the table at the motor position would be up to %.2f steps off"
      % (power_on, ["%.4f" % o for o in offsets], max(homing_error), len(rows), worst_native,
         worst_board, worst_motor))
json.dump({"power_on_mm": power_on, "motor_offset_mm": offsets, "native_max_steps": worst_native,
           "board_max_steps": worst_board, "motor_position_max_steps": worst_motor},
          open(os.path.join(work, "machine_position.json"), "w"), indent=1)
if failures:
    print("FAILED:\n  " + "\n  ".join(failures[:20]) +
          ("\n  ... %d more" % (len(failures) - 20) if len(failures) > 20 else ""))
    sys.exit(1)
