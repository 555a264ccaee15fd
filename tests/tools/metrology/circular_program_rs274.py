#!/usr/bin/env python3
"""LinuxCNC's own G-code interpreter reads `volcomp program circular` (an outside truth for the
program's geometry).

usage: circular_program_rs274.py VOLCOMP RS274

For each plane, `rs274 -g` (the standalone RS274/NGC interpreter of LinuxCNC) must accept the
program without an error, and its canonical calls must be: one STRAIGHT_TRAVERSE to the start of
the run-in on the circle, then six ARC_FEEDs about the requested centre, on the requested radius,
in the plane (the third axis at the centre's), rotation +1 (counter-clockwise) three times then
-1 three times, sweeping run, 360, run degrees each, and the measured full circles starting at the
start angle. ARC_FEED(first_end, second_end, first_centre, second_centre, rotation, axis_end, ...)
uses the interpreter's canonical plane axes: XY (X, Y), XZ (Z, X), YZ (Y, Z).
Exit 0 when every check holds, 1 with the failures otherwise.
"""

import math
import re
import subprocess
import sys
import tempfile

CALL = re.compile(r"N\.\.\.\.\.\s+(STRAIGHT_TRAVERSE|ARC_FEED)\(([^)]*)\)")
AXES = {"XY": (0, 1, 2), "XZ": (2, 0, 1), "YZ": (1, 2, 0)}  # first, second, normal (X=0)
CENTRE = (12.5, -40.0, 7.25)
RADIUS = 80.0
CASES = [("XY", 0.0, 90.0), ("XZ", 30.0, 45.0), ("YZ", -100.0, 180.0)]


def check(volcomp, rs274, plane, start, run, failures):
    with tempfile.NamedTemporaryFile("w", suffix=".ngc", delete=False) as f:
        path = f.name
    subprocess.run([volcomp, "program", "circular", "--plane", plane, "--centre",
                    ",".join(str(c) for c in CENTRE), "--radius", str(RADIUS), "--start-angle-deg",
                    str(start), "--run-in-deg", str(run), "--feed", "1500", "-o", path], check=True)
    out = subprocess.run([rs274, "-g", path], capture_output=True, text=True, timeout=60)
    text = out.stdout + out.stderr
    if out.returncode != 0 or "error" in text.lower():
        failures.append(f"{plane}: rs274 refused the program:\n{text}")
        return
    calls = [(m.group(1), [float(v) for v in m.group(2).split(",")]) for m in CALL.finditer(text)]
    first, second, normal = AXES[plane]

    def angle(p1, p2):
        return math.degrees(math.atan2(p2 - CENTRE[second], p1 - CENTRE[first]))

    if not calls or calls[0][0] != "STRAIGHT_TRAVERSE":
        failures.append(f"{plane}: no traverse to the start")
        return
    pos = calls[0][1][:3]
    arcs = [c[1] for c in calls[1:] if c[0] == "ARC_FEED"]
    if len(arcs) != 6:
        failures.append(f"{plane}: {len(arcs)} arcs, not 6")
        return
    expected_a = start - run  # where the CCW run-in begins
    if abs(math.dist(pos, CENTRE) - RADIUS) > 1e-3:
        failures.append(f"{plane}: the start {pos} is not on the circle")
    for i, a in enumerate(arcs):
        e1, e2, c1, c2, rotation, axis_end = a[:6]
        want_rotation = 1 if i < 3 else -1
        if int(rotation) != want_rotation:
            failures.append(f"{plane}: arc {i + 1} rotation {rotation}, not {want_rotation}")
        if abs(c1 - CENTRE[first]) > 1e-3 or abs(c2 - CENTRE[second]) > 1e-3:
            failures.append(f"{plane}: arc {i + 1} centre ({c1}, {c2})")
        if abs(axis_end - CENTRE[normal]) > 1e-3:
            failures.append(f"{plane}: arc {i + 1} leaves the plane ({axis_end})")
        if abs(math.hypot(e1 - CENTRE[first], e2 - CENTRE[second]) - RADIUS) > 1e-3:
            failures.append(f"{plane}: arc {i + 1} ends off the circle")
        a0 = angle(pos[first], pos[second])
        a1 = angle(e1, e2)
        sweep = ((a1 - a0) * want_rotation) % 360.0
        if abs(sweep) < 1e-3 or abs(sweep - 360.0) < 1e-3:
            sweep = 360.0
        want_sweep = 360.0 if i in (1, 4) else run
        if abs(sweep - want_sweep) > 1e-3:
            failures.append(f"{plane}: arc {i + 1} sweeps {sweep:.4f} deg, not {want_sweep}")
        if i in (1, 4) and abs((a0 - start + 180.0) % 360.0 - 180.0) > 1e-3:
            failures.append(f"{plane}: measured circle {i + 1} starts at {a0:.4f} deg, not {start}")
        if i == 0 and abs((a0 - expected_a + 180.0) % 360.0 - 180.0) > 1e-3:
            failures.append(f"{plane}: the run-in starts at {a0:.4f} deg, not {expected_a}")
        pos = [0.0, 0.0, 0.0]
        pos[first], pos[second], pos[normal] = e1, e2, axis_end


def main():
    volcomp, rs274 = sys.argv[1], sys.argv[2]
    failures = []
    for plane, start, run in CASES:
        check(volcomp, rs274, plane, start, run, failures)
    for f in failures:
        print("FAIL", f)
    print("ok" if not failures else f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
