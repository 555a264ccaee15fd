#!/usr/bin/env python3
"""Checks LinuxCNC's joint compensation from `volcomp export linuxcnc` (docs/linuxcnc.md §5).

check_comp.py COMP_WORK JOINT:TYPE:FILE:TARGETS.csv:PROGRAM ...
At every recorded stop of PROGRAM (rest.csv of lcnc_run.py in comp mode) the compensated command
LinuxCNC sent to the joint (motor-pos-cmd) minus the motor offset homing set (motor-offset) minus
the nominal (pos-cmd) must equal the trim the file asks for, computed here from the file text by LinuxCNC's documented rule: the triplets
"nominal forward reverse" (COMP_FILE_TYPE 1: trims; 0: positions, trim = nominal - position),
linear between nominals, the forward trim after a move up, the reverse trim after a move down
(the approach direction of the stop, from the program's targets CSV).
"""
import csv
import json
import os
import sys

TOL_MM = 1e-6
work = sys.argv[1]
rest = list(csv.DictReader(open(os.path.join(work, "rest.csv"))))
failures, worst, checked = [], 0.0, 0


def trims(path, ftype):
    rows = [tuple(map(float, line.split())) for line in open(path) if line.strip()]
    if ftype == 0:
        rows = [(n, n - f, n - r) for n, f, r in rows]
    return rows


def trim_at(rows, p, up):
    col = 1 if up else 2
    if p <= rows[0][0]:
        return rows[0][col]
    if p >= rows[-1][0]:
        return rows[-1][col]
    for a, b in zip(rows, rows[1:]):
        if a[0] <= p < b[0]:
            return a[col] + (b[col] - a[col]) * (p - a[0]) / (b[0] - a[0])
    raise AssertionError("unreachable")


for spec in sys.argv[2:]:
    joint, ftype, path, targets, program = spec.split(":")
    joint, ftype = int(joint), int(ftype)
    rows = trims(path, ftype)
    stops = [r for r in rest if r["program"] == program]
    dirs = [t["direction"] for t in csv.DictReader(
        line for line in open(targets) if not line.startswith("#"))]
    if len(stops) != len(dirs):
        failures.append("%s: %d stops recorded, %d in %s" % (program, len(stops), len(dirs),
                                                              targets))
        continue
    for s, d in zip(stops, dirs):
        nominal = float(s["pos_cmd_mm_%d" % joint])
        applied = (float(s["motor_cmd_mm_%d" % joint]) - float(s["motor_offset_mm_%d" % joint]) -
                   nominal)
        want = trim_at(rows, nominal, d == "up")
        worst = max(worst, abs(applied - want))
        checked += 1
        if abs(applied - want) > TOL_MM:
            failures.append("%s joint %d at %.4f mm (%s): LinuxCNC applied %.6f mm, the file "
                            "asks %.6f mm" % (program, joint, nominal, d, applied, want))
# At rest LinuxCNC's command and its feedback (the step generators, its own compensation taken
# out) agree within a step.
rest_ferror = json.load(open(os.path.join(work, "eval", "checks.json")))["max_rest_ferror_steps"]
if rest_ferror > 1.0:
    failures.append("LinuxCNC's following error at rest reached %.3f steps" % rest_ferror)
summary = json.load(open(os.path.join(work, "rest.csv.json")))
if not summary.get("ok") or summary["errors"]:
    failures.append("LinuxCNC run: %s %s" % (summary.get("exception"), summary["errors"]))
print("joint compensation: %d stops checked, largest |applied - file| %.2e mm; following error "
      "at rest %.3f steps" % (checked, worst, rest_ferror))
if failures:
    print("FAILED:\n  " + "\n  ".join(failures[:20]))
    sys.exit(1)
