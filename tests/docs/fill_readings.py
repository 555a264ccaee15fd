#!/usr/bin/env python3
"""Stands in for the operator of the documentation test: enters readings into a template written
by `volcomp program ... --targets-csv FILE` and fills in its test conditions.

usage: fill_readings.py FILE [--after]

Readings are a plausible machine: deviation = 0.03 µm/mm · target + 4 µm · sin(target / 60 mm)
+ 1.2 µm reversal (↑ +, ↓ −) + a run-to-run scatter of a few tenths of a µm; with --after (the
compensated machine) a tenth of that. Rows that already hold a reading are left as they are.
"""

import math
import sys


def reading(target, direction, run, scale):
    scatter = (0.12, -0.25, 0.18, 0.03, -0.08)[run % 5]
    reversal = 1.2 if direction in ("up", "+") else -1.2
    return scale * (0.03 * target + 4.0 * math.sin(target / 60.0) + reversal + scatter)


def main():
    path = sys.argv[1]
    scale = 0.1 if "--after" in sys.argv[2:] else 1.0
    conditions = {
        "machine": "MILL-7 (documentation test)",
        "date": "2024-05-14",
        "operator": "N. N.",
        "instrument": "laser interferometer (simulated readings)",
        "air temperature C": "20.3",
        "material temperature C": "20.6",
    }
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    out, header = [], None
    for line in lines:
        if line.startswith("#"):
            key = line[1:].split(":", 1)[0].strip()
            if line.rstrip().endswith(":") and key in conditions:
                line = "# %s: %s" % (key, conditions[key])
            out.append(line)
            continue
        if not line.strip():
            out.append(line)
            continue
        if header is None:
            header = line.split(",")
            out.append(line)
            continue
        cells = line.split(",")
        if cells[-1].strip() == "":
            target = float(cells[header.index("target_mm" if "target_mm" in header else "target_deg")])
            direction = cells[header.index("direction")]
            run = int(cells[header.index("run")])
            cells[-1] = "%.3f" % reading(target, direction, run, scale)
        out.append(",".join(cells))
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(out))


if __name__ == "__main__":
    main()
