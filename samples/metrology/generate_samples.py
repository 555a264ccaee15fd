#!/usr/bin/env python3
"""Regenerates the synthetic sample data of samples/metrology/ (deterministic, seed fixed).

Run from this folder: python3 generate_samples.py
The GOST 27843-88 example files are not generated here: they are the reconstructed worked example
(see docs/metrology.md and tests/tools/metrology/data/gost27843_example_reconstructed.csv); this script
only converts the wide table to the long layout.
"""
import csv
import math
import random

HERE = "."


def gost_long():
    rows = [r for r in csv.reader(open("../../tests/tools/metrology/data/gost27843_example_reconstructed.csv"))
            if r and not r[0].startswith("#")]
    header, targets, runs = rows[0], rows[1], rows[2:]
    with open(f"{HERE}/gost27843_example_long.csv", "w") as f:
        f.write("# GOST 27843-88 worked example (reconstructed readings), long layout\n")
        f.write("target_mm,direction,run,deviation_um\n")
        for c in range(1, len(header)):
            d = "up" if header[c].endswith("+") else "down"
            for r in runs:
                f.write(f"{targets[c]},{d},{r[0]},{r[c]}\n")


def rotary_table_positioning(rng):
    """A rotary table (C axis) tested at 12 positions every 30° incl. 0/90/180/270, 5 runs each
    direction; worm-wheel errors: once-per-rev 6″, 4-per-rev 2″, reversal 3″, noise 0.8″."""
    with open(f"{HERE}/rotary_table_positioning.csv", "w") as f:
        f.write("# synthetic rotary table positioning test (GOST 27843-88 §2.8), arc-seconds\n")
        f.write("target_deg,direction,run,deviation_arcsec\n")
        for run in range(1, 6):
            for d in ("up", "down"):
                for j in range(12):
                    a = 30.0 * j
                    t = math.radians(a)
                    dev = 6 * math.sin(t + 0.4) + 2 * math.sin(4 * t) + (1.5 if d == "up" else -1.5)
                    dev += rng.gauss(0, 0.8)
                    f.write(f"{a:.3f},{d},{run},{dev:.2f}\n")


def diagonals(rng):
    """Four body diagonals and two XY face diagonals of an 800 × 500 × 400 mm volume. Machine
    model: scale errors X +12, Y −8, Z +5 µm/m; squareness XY 20 µrad; backlash X 4, Y 3, Z 2 µm;
    noise 0.3 µm. Deviation = projection of the error vector on the diagonal direction."""
    size = (800.0, 500.0, 400.0)
    scale = (12e-3, -8e-3, 5e-3)  # µm per mm
    backlash = (4.0, 3.0, 2.0)
    sq_xy = 20e-6  # rad

    def error(p, move):
        e = [scale[i] * p[i] + 0.5 * backlash[i] * math.copysign(1.0, move[i]) if move[i] else
             scale[i] * p[i] for i in range(3)]
        e[0] += sq_xy * p[1] * 1000.0  # µm
        return e

    def corner(signs):
        return [size[i] if s > 0 else 0.0 for i, s in enumerate(signs)]

    specs = [("+X+Y+Z", (1, 1, 1), None), ("+X+Y-Z", (1, 1, -1), None),
             ("+X-Y+Z", (1, -1, 1), None), ("-X+Y+Z", (-1, 1, 1), None),
             ("+X+Y Z200", (1, 1, 0), 200.0), ("+X-Y Z200", (1, -1, 0), 200.0)]
    with open(f"{HERE}/diagonals.csv", "w") as f:
        f.write("# synthetic ISO 230-6 test: 4 body diagonals and 2 face diagonals (XY at Z200)\n")
        f.write("# target_mm = distance from the diagonal's start corner; deviation along it\n")
        f.write("diagonal,target_mm,direction,run,deviation_um\n")
        for name, signs, z in specs:
            p1 = corner(signs)
            if z is not None:
                p1[2] = z
            p2 = [size[i] - p1[i] if signs[i] else p1[i] for i in range(3)]
            v = [p2[i] - p1[i] for i in range(3)]
            length = math.sqrt(sum(c * c for c in v))
            u = [c / length for c in v]
            steps = round(length / 100.0)
            for run in range(1, 6):
                for d in ("up", "down"):
                    order = range(steps + 1) if d == "up" else range(steps, -1, -1)
                    for i in order:
                        t = i * length / steps
                        p = [p1[k] + t * u[k] for k in range(3)]
                        move = [c if d == "up" else -c for c in v]
                        e = error(p, move)
                        dev = sum(e[k] * u[k] for k in range(3)) + rng.gauss(0, 0.3)
                        f.write(f"\"{name}\",{t:.3f},{d},{run},{dev:.2f}\n")


def spindle(rng):
    """Spindle with a sphere at two planes 80 mm apart and an axial sensor: eccentricity 5 µm,
    2-lobe 0.6 µm, 3-lobe 0.25 µm, half-speed whirl 0.3 µm, noise 0.02 µm; tilt 2 µrad 2-lobe;
    axial 0.4 µm once per rev + 0.15 µm 4-lobe."""
    n, k_revs, L = 256, 8, 80.0
    with open(f"{HERE}/spindle_error_motion.csv", "w") as f:
        f.write("# synthetic ISO 230-7 spindle test, 8 revolutions x 256 angles, µm\n")
        f.write("rev,angle_deg,x_um,y_um,x2_um,y2_um,z_um\n")
        for k in range(k_revs):
            for j in range(n):
                a = 360.0 * j / n
                t = math.radians(a)
                tt = t + 2 * math.pi * k
                ex, ey = 5 * math.cos(t + 0.3), 5 * math.sin(t + 0.3)  # sphere eccentricity
                rx = 0.6 * math.cos(2 * t) * math.cos(t) + 0.25 * math.cos(3 * t + 1)
                ry = 0.6 * math.cos(2 * t) * math.sin(t) + 0.25 * math.sin(3 * t + 1)
                wx, wy = 0.3 * math.cos(tt / 2), 0.3 * math.sin(tt / 2)
                x = ex + rx + wx + rng.gauss(0, 0.02)
                y = ey + ry + wy + rng.gauss(0, 0.02)
                tilt = 2e-3 * math.cos(2 * t)  # µm per mm = mrad·1e-3 -> 2 µrad
                x2 = ex + rx + wx + L * tilt * math.cos(t) + rng.gauss(0, 0.02)
                y2 = ey + ry + wy + L * tilt * math.sin(t) + rng.gauss(0, 0.02)
                z = 0.2 * math.cos(t - 0.5) + 0.15 * math.cos(4 * t) + rng.gauss(0, 0.03)
                f.write(f"{k + 1},{a:.4f},{x:.4f},{y:.4f},{x2:.4f},{y2:.4f},{z:.4f}\n")


def reversal(rng):
    """Donaldson reversal: artefact with a 3-lobe form of 0.5 µm and a 5-lobe of 0.1 µm, spindle
    (FSD along X) with a 2-lobe of 0.3 µm; setup 2 with sphere and sensor turned 180°,
    procedure P (same sign convention): T2P = P − S. 4 revolutions × 180 angles."""
    n, k_revs = 180, 4
    for setup in (1, 2):
        with open(f"{HERE}/reversal_setup{setup}.csv", "w") as f:
            f.write(f"# synthetic Donaldson reversal record, setup {setup} (ISO 230-7 annex B)\n")
            f.write("rev,angle_deg,x_um\n")
            for k in range(k_revs):
                for j in range(n):
                    a = 360.0 * j / n
                    t = math.radians(a)
                    p = 0.5 * math.cos(3 * t + 0.2) + 0.1 * math.sin(5 * t)
                    s = 0.3 * math.cos(2 * t + 0.7)
                    v = p + s if setup == 1 else p - s
                    f.write(f"{k + 1},{a:.1f},{v + rng.gauss(0, 0.01):.4f}\n")


def circular(rng):
    """An ISO 230-4 circular test in XY as a ballbar reads it: R 100 mm, 1° steps, CW then CCW.
    Setup offset of the ballbar's centre (8, -5) µm; out-of-squareness 60 µm/m (ellipse at 45°,
    ±3 µm); X/Y scale mismatch (ellipse on the axes, ±2 µm); lost motion 6 µm in X and 4 µm in Y;
    reversal spikes of 4 µm at the quadrants, decaying over 5° after each axis reverses; the
    measured radius 1.2 µm long; noise 0.15 µm."""
    with open(f"{HERE}/circular_xy.csv", "w") as f:
        f.write("# synthetic ISO 230-4 circular test (ballbar), XY plane, deviation = measured "
                "radius - 100 mm\n")
        f.write("# machine: MILL-7\n# axis: XY\n# date: 2026-11-27\n# operator: QA\n")
        f.write("# instrument: ballbar 100 mm\n# air temperature C: 20.3\n"
                "# material temperature C: 20.1\n# feed mm per min: 1000\n"
                "# instrument_u_um: 0.5\n# calibrator_u_um: 1\n# nominal_radius_mm: 100\n"
                "# drift_range_um: 0.4\n# expansion_um_per_m_K: 11.5\n")
        f.write("direction,angle_deg,deviation_um\n")
        for d in ("cw", "ccw"):
            s = 1.0 if d == "ccw" else -1.0  # the sense of travel
            for k in range(360):
                a = k if d == "ccw" else (360 - k) % 360
                t = math.radians(a)
                vx, vy = -s * math.sin(t), s * math.cos(t)  # direction of each axis's motion
                sign = lambda v: (v > 1e-12) - (v < -1e-12)
                r = 1.2 + 8 * math.cos(t) - 5 * math.sin(t)
                r += 3 * math.sin(2 * t) + 2 * math.cos(2 * t)
                r += -3 * sign(vx) * math.cos(t) - 2 * sign(vy) * math.sin(t)
                for q in (0, 90, 180, 270):
                    after = ((a - q) * s) % 360  # degrees travelled since the quadrant
                    if after < 5:
                        r += 4 * (1 - after / 5)
                r += rng.gauss(0, 0.15)
                f.write(f"{d},{a:.1f},{r:.3f}\n")


def drift_test(rng):
    """An ISO 230-3 style drift test: 5 h, the spindle running 0-3 h then stopped, points X 50 /
    300 / 550 mm and Y 50 / 450 mm read every 5 min (30 s apart within a sweep). Temperatures:
    first-order lags towards 20 °C + rise while running, the ambient drifting; spindle tau 0.6 h,
    +9 K; bed tau 2.0 h, +4 K; ambient 20.0 + 0.3 K/h·t(h) + 0.2 sin(2π t/4 h). Machine (truth):
        drift X(p) = +1.5 µm/K · ΔT_spindle + 11.5 µm/(K·m) · ΔT_bed · p/1000
        drift Y(p) = -0.8 µm/K · ΔT_spindle +  6.0 µm/(K·m) · ΔT_bed · p/1000
    (ΔT from the temperatures at t = 0, p in mm from the axis's zero); plus a fixed geometric
    deviation per point, noise 0.1 µm on the readings and 0.01 K on the temperatures. As a
    correction about p0 (the mean of the points: X 300, Y 250 mm) the expected model is
        X: offset spindle -1.5, offset bed -3.45 µm/K, slope bed -11.5 µm/(K·m)
        Y: offset spindle +0.8, offset bed -1.5 µm/K, slope bed -6.0 µm/(K·m)
    and zero on the ambient channel."""
    points = [("X", 50.0, 1.2), ("X", 300.0, -0.8), ("X", 550.0, 2.1), ("Y", 50.0, 0.4),
              ("Y", 450.0, -1.1)]
    drift_per_K = {"X": (1.5, 11.5e-3), "Y": (-0.8, 6.0e-3)}  # µm/K (spindle), µm/(K mm) (bed)

    def ambient(t_h):
        return 20.0 + 0.3 * t_h + 0.2 * math.sin(2 * math.pi * t_h / 4.0)

    def lag(t_h, tau, rise):
        # running 0..3 h: rise*(1 - e^(-t/tau)); then decays from its value at 3 h
        if t_h <= 3.0:
            return rise * (1 - math.exp(-t_h / tau))
        return rise * (1 - math.exp(-3.0 / tau)) * math.exp(-(t_h - 3.0) / tau)

    def temps(t_s):
        t_h = t_s / 3600.0
        a = ambient(t_h)
        return (a + lag(t_h, 2.0, 4.0), a + lag(t_h, 0.6, 9.0), a)

    t0 = temps(0.0)
    with open(f"{HERE}/thermal_drift.csv", "w") as f:
        f.write("# synthetic ISO 230-3 drift test (generate_samples.py drift_test: the formula)\n")
        f.write("# machine: MILL-7\n# axis: XY\n# date: 2026-11-28\n# operator: QA\n")
        f.write("# instrument: laser interferometer, 3 temperature sensors\n")
        f.write("time_s,axis,position_mm,deviation_um,T_bed_C,T_spindle_C,T_ambient_C\n")
        for sweep in range(61):
            for k, (axis, p, g) in enumerate(points):
                t = sweep * 300.0 + 30.0 * k
                bed, spindle, amb = temps(t)
                d_sp, d_bed = spindle - t0[1], bed - t0[0]
                a_sp, a_bed = drift_per_K[axis]
                dev = g + a_sp * d_sp + a_bed * d_bed * p + rng.gauss(0, 0.1)
                tt = [v + rng.gauss(0, 0.01) for v in (bed, spindle, amb)]
                f.write(f"{t:.0f},{axis},{p:.1f},{dev:.2f},{tt[0]:.2f},{tt[1]:.2f},{tt[2]:.2f}\n")


if __name__ == "__main__":
    rng = random.Random(27843)
    gost_long()
    rotary_table_positioning(rng)
    diagonals(rng)
    spindle(rng)
    reversal(rng)
    circular(random.Random(2304))
    drift_test(random.Random(23))
