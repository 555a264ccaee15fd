#!/usr/bin/env python3
"""Checks one run of a docs/linuxcnc.md recipe on a LinuxCNC sample configuration.

check_recipe.py NAME RUN_DIR VOLCOMP TABLE STEP MM_PER_UNIT [servo|pid]
RUN_DIR holds recipe.csv(.json) of lcnc_recipe_run.py and linuxcnc.log. STEP: the machine's
resolution in machine units (one step or encoder count); MM_PER_UNIT: 25.4 for an inch machine.
Checks: LinuxCNC ran without error; `show thread` lists volcomp.0.feedback between the feedback
capture and motion-command-handler and volcomp.0.update right after motion-controller (the
recipe's addf positions); at every stop the correction is the table's value
at LinuxCNC's joint position (`volcomp lookup`) within one step, the drive stands at the motor
command plus the correction and LinuxCNC's following error is below a step (servo: plus pid's
deadband, [JOINT_N]DEADBAND); with `servo`, pid's command-deriv is volcomp's vel-cmd-out (the
feed-forward); with `pid`, command-deriv is unconnected (pid differentiates the corrected command);
the feedback capture is a `*.capture-position` function or a Mesa card's `hm2_*.read`; the reload checks of lcnc_recipe_run.py, when present: a reload of the same table
keeps its CRC, a damaged one is refused with the text of `volcomp inspect` and a readable reason
in the log, an unreadable one with the uid and errno text, the active table stays, and the good
table loads again. Prints the figures; exit 1 with every failed check listed.
"""
import csv
import io
import json
import os
import re
import subprocess
import sys

name, run, volcomp, table = sys.argv[1:5]
step, mm_per_unit = float(sys.argv[5]), float(sys.argv[6])
mode = sys.argv[7] if len(sys.argv) > 7 else ""
servo = mode in ("servo", "pid")
summary = json.load(open(os.path.join(run, "recipe.csv.json")))
rows = list(csv.DictReader(open(os.path.join(run, "recipe.csv"))))
log = open(os.path.join(run, "linuxcnc.log"), errors="replace").read()
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


check(summary.get("ok"), "the run did not complete: %s" % summary.get("exception"))
check(not summary.get("errors"), "LinuxCNC reported errors: %s" % summary.get("errors"))
if "reload" in summary:
    # The refusals the reload checks provoke reach LinuxCNC's error channel too, as a GUI shows.
    check(len(summary.get("expected_errors", [])) >= 2,
          "the reload refusals did not reach LinuxCNC's error channel: %s"
          % summary.get("expected_errors"))

# The recipe's addf position: volcomp.0.update right after motion-controller.
order = {}
for line in summary.get("threads", "").splitlines():
    m = re.match(r"\s+(\d+)\s+(\S+)\s*$", line)
    if m:
        order[m.group(2)] = int(m.group(1))
mc, vc = order.get("motion-controller"), order.get("volcomp.0.update")
mch, vf = order.get("motion-command-handler"), order.get("volcomp.0.feedback")
capture = min((n for f, n in order.items()
               if f.endswith("capture-position") or re.match(r"hm2_\w+\.\d+\.read$", f)),
              default=None)
check(mc is not None and vc == mc + 1,
      "show thread: volcomp.0.update at %s, motion-controller at %s (it must come right after)"
      % (vc, mc))
check(vf is not None and mch is not None and capture is not None and capture < vf < mch,
      "show thread: volcomp.0.feedback at %s, the feedback capture at %s, motion-command-handler "
      "at %s (it must come between)" % (vf, capture, mch))

joints = len([k for k in rows[0] if k.startswith("pos_cmd_")]) if rows else 0
points = "x_mm,y_mm,z_mm\n" + "".join(
    ",".join("%.6f" % (float(r["pos_cmd_%d" % j]) * mm_per_unit) for j in range(3)) + "\n"
    for r in rows)
out = subprocess.run([volcomp, "lookup", table], input=points, capture_output=True, text=True,
                     check=True).stdout
want = [[float(p["d%s_um" % a]) / 1000.0 / mm_per_unit for a in "xyz"]
        for p in csv.DictReader(io.StringIO(out))]
deadband = 0.0
if servo:
    m = re.search(r"^DEADBAND\s*=\s*([0-9.eE+-]+)", open(os.path.join(run, "machine.ini")).read(),
                  re.M)
    deadband = float(m.group(1)) if m else 0.0
worst = {"table": 0.0, "drive": 0.0, "ferror": 0.0, "correction": 0.0}
for r, w in zip(rows, want):
    for j in range(min(joints, 3)):
        corr = float(r["correction_%d" % j])
        worst["correction"] = max(worst["correction"], abs(corr))
        d_table = abs(corr - w[j])
        d_drive = abs(float(r["drive_%d" % j]) - float(r["motor_cmd_%d" % j]) - corr)
        ferror = abs(float(r["ferror_%d" % j]))
        worst["table"] = max(worst["table"], d_table / step)
        worst["drive"] = max(worst["drive"], d_drive / step)
        worst["ferror"] = max(worst["ferror"], ferror / step)
        where = "%s joint %d at %.5f (motor %.5f)" % (r["stop"], j, float(r["pos_cmd_%d" % j]),
                                                      float(r["motor_cmd_%d" % j]))
        check(d_table <= step, "%s: correction %.6f, the table there %.6f" % (where, corr, w[j]))
        check(d_drive <= step + deadband,
              "%s: drive %.6f is not the motor command plus the correction %.6f"
              % (where, float(r["drive_%d" % j]), corr))
        check(ferror <= step + deadband, "%s: following error %.6f" % (where, ferror))
check(worst["correction"] > step, "the corrections were all below a step: nothing was tested")
ff = summary.get("feed_forward", "")
linked = [l for l in ff.splitlines() if "command-deriv" in l and "<==" in l]
if mode == "servo":
    check(len(linked) >= joints,
          "pid command-deriv pins not all fed (feed-forward):\n%s" % ff)
if mode == "pid":
    check(not linked and "command-deriv" in ff,
          "pid command-deriv pins fed (the recipe assumes pid differentiates the command):\n%s" % ff)
print("%s: homed in %.1f s (motor offsets %s); %d stops: correction up to %.4f mm, within %.3f "
      "steps of the table at the joint position; drive = motor command + correction within %.3f "
      "steps; following error at rest %.3f steps; show thread: capture %s, volcomp.0.feedback %s, "
      "motion-command-handler %s, motion-controller %s, volcomp.0.update %s"
      % (name, summary.get("homing_s", 0), ["%.4f" % o for o in summary.get("motor_offset", [])],
         len(rows), worst["correction"] * mm_per_unit, worst["table"], worst["drive"],
         worst["ferror"], capture, vf, mch, mc, vc))

r = summary.get("reload")
if r is not None:
    check(r["same_table"]["table_crc"] == r["crc_before"] and r["same_table"]["table_error"] == 0,
          "reload of the same table: %s" % r["same_table"])
    check(r["damaged"]["table_error"] == 7 and r["damaged"]["table_crc"] == r["crc_before"] and
          r["damaged"]["active"],
          "a damaged table: error %s (want 7, kImageBadCrc), CRC %s, active %s"
          % (r["damaged"]["table_error"], r["damaged"]["table_crc"], r["damaged"]["active"]))
    check("refused: invalid table image: image CRC-32 does not match (kImageBadCrc); the active "
          "table stays" in log, "the log lacks the plain-text refusal of the damaged table")
    check(r["unreadable"]["table_error"] == 75 and r["unreadable"]["active"],
          "an unreadable table: error %s (want 75, kIoError)" % r["unreadable"]["table_error"])
    m = re.search(r"cannot read table \"[^\"]+\": Permission denied \(rtapi_app reads as uid "
                  r"\d+[^\n]*", log)
    check(m is not None, "the log lacks the reason for the unreadable table (errno text, uid)")
    check(r["restored"]["table_error"] == 0, "the good table did not load again: %s" %
          r["restored"])
    def med(v):
        return sorted(v)[len(v) // 2]
    print("%s: reload of a %d-byte table: volcomp.0.update.tmax (rtapi clocks, windows of 1 s) "
          "without a reload median %d max %d, with one median %d max %d (the loader thread reads, "
          "checks and prepares; the servo thread switches a pointer); damaged table refused "
          "(table-error %d), unreadable (%d): %s"
          % (name, r["table_bytes"], med(r["tmax_idle"]), max(r["tmax_idle"]),
             med(r["tmax_reload"]), max(r["tmax_reload"]), r["damaged"]["table_error"],
             r["unreadable"]["table_error"], m.group(0) if m else "?"))
if failures:
    print("FAILED (%s):\n  " % name + "\n  ".join(f for f in failures[:20] if f))
    sys.exit(1)
