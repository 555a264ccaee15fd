#!/usr/bin/python3
"""A simulated CNC master and three CiA 402 CSP drives around volcomp-fw-linux, on real SocketCAN.

The master runs on the controller bus (vcan0): every cycle a SYNC, then one RPDO per axis with
controlword 0x6040 (2 bytes) and target position 0x607A (INTEGER32 at byte offset 2). The drives
run on the drive bus (vcan1): at each SYNC a drive takes over the target it received before the
SYNC (CSP: it follows perfectly) and answers with a TPDO carrying statusword 0x6041 and position
actual value 0x6064 (offset 2). The gateway sits in between.

Checked frame by frame, against expectations computed here (not by volcomp code):
  * targets seen by the drives = target sent + c, where c is 0 before a table is active and after
    deactivation, and at rest equals the table's correction at the target (trilinear interpolation
    of the grid CSV written by this test, in drive increments of 100 nm) within 1 increment;
    while moving, the correction at one of the last 10 targets within 1 increment;
  * actual positions seen by the master = exactly the target the drive took over (no following
    error, whatever the correction);
  * SYNC, NMT, SDO to and from a drive, EMCY, heartbeat, remote and extended frames are forwarded
    unchanged; the board's own SDO traffic (0x610 / 0x590) and heartbeat never reach the drive bus.
Meanwhile the PC tool uploads a table over socketcan:vcan0, activation is refused before
referencing and while moving, and succeeds at rest after `volcomp reference`.
Python-can 4.1.0 (Debian's python3-can); run inside user-mode-linux by run_uml_gateway.sh.
"""
import argparse
import struct
import subprocess
import sys
import time

import can

RPDO = [0x201, 0x202, 0x203]
TPDO = [0x181, 0x182, 0x183]
OFFSET = 2
CONTROLWORD = 0x000F
STATUSWORD = 0x1237
BOARD_NODE = 0x10
INCREMENT_UM = 0.1              # units_per_step = 0.0001 mm
HOME = [1000000, 500000, 200000]  # increments (100, 50, 20 mm); = home_position in the config
CYCLE_S = 0.002


def grid_csv(path):
    """Writes the correction grid (um at nodes 0..400 mm every 100 mm) and returns its nodes."""
    import math
    nodes = {}
    with open(path, "w") as f:
        f.write("x_mm,y_mm,z_mm,dx_um,dy_um,dz_um\n")
        for k in range(5):
            for j in range(5):
                for i in range(5):
                    x, y, z = 100 * i, 100 * j, 100 * k
                    d = (30 + 0.04 * x - 0.02 * y + 0.01 * z + 3 * math.sin(x / 60.0),
                         -12 + 0.03 * y + 0.015 * x - 2 * math.cos(y / 45.0),
                         8 - 0.01 * z + 0.02 * x * y / 400.0)
                    d = tuple(round(v, 3) for v in d)
                    nodes[(i, j, k)] = d
                    f.write("%d,%d,%d,%.3f,%.3f,%.3f\n" % (x, y, z, d[0], d[1], d[2]))
    return nodes


class Grid:
    """Trilinear interpolation of the node values (clamped to the grid), written from scratch."""

    def __init__(self, nodes):
        self.nodes = nodes

    def correction_increments(self, target):
        pos_mm = [t * INCREMENT_UM / 1000.0 for t in target]
        idx, frac = [], []
        for p in pos_mm:
            u = min(max(p / 100.0, 0.0), 4.0)
            i = min(int(u), 3)
            idx.append(i)
            frac.append(u - i)
        out = []
        for c in range(3):
            v = 0.0
            for dk in (0, 1):
                for dj in (0, 1):
                    for di in (0, 1):
                        w = ((frac[0] if di else 1 - frac[0]) * (frac[1] if dj else 1 - frac[1]) *
                             (frac[2] if dk else 1 - frac[2]))
                        v += w * self.nodes[(idx[0] + di, idx[1] + dj, idx[2] + dk)][c]
            out.append(v / INCREMENT_UM)
        return out


def i32(v):
    return (v + 2 ** 31) % 2 ** 32 - 2 ** 31


class Abort(Exception):
    """Too many failures (or out of time): stop the session."""


class Session:
    def __init__(self, args, grid):
        self.t0 = time.monotonic()
        self.deadline = self.t0 + 60
        self.args = args
        self.grid = grid
        # The master hears only what comes from the drives' side (and not the board's own frames).
        drive_ids = TPDO + [0x080 + n for n in (1, 2, 3)] + [0x580 + n for n in (1, 2, 3)] + \
            [0x700 + n for n in (1, 2, 3)]
        self.cnc = can.Bus(interface="socketcan", channel=args.cnc,
                           can_filters=[{"can_id": i, "can_mask": 0x7FF, "extended": False}
                                        for i in drive_ids] +
                           [{"can_id": 0x1ABCDE02, "can_mask": 0x1FFFFFFF, "extended": True}])
        self.drv = can.Bus(interface="socketcan", channel=args.drives)
        self.errors = []
        self.cycle = 0
        self.target = list(HOME)
        self.pending = [None] * 3          # drive: target received since the last SYNC
        self.position = [None] * 3         # drive: target taken over at the last SYNC
        self.expect_zero = True
        self.tolerance = None              # max |c - expected| checked this cycle (None: no check)
        self.lag = 0                       # cycles the correction may lag the target
        self.history = []
        self.max_dev = {"rest": 0.0, "moving": 0.0}
        self.corrections = [0] * 3
        self.max_abs_correction = 0        # largest |correction| since while_running() began
        self.frames_checked = 0
        self.stray = []                    # unexpected frames on the drive bus

    # ---- checks
    def fail(self, what):
        self.errors.append("cycle %d: %s" % (self.cycle, what))
        if len(self.errors) >= 30 or time.monotonic() > self.deadline:
            raise Abort()

    def expect_same(self, sent, got, what):
        if (got is None or got.arbitration_id != sent.arbitration_id or
                got.is_extended_id != sent.is_extended_id or
                got.is_remote_frame != sent.is_remote_frame or got.dlc != sent.dlc or
                (not sent.is_remote_frame and bytes(got.data) != bytes(sent.data))):
            self.fail("%s not forwarded unchanged: sent %s, got %s" % (what, sent, got))
        else:
            self.frames_checked += 1

    def recv_on(self, bus, want, timeout=5.0):
        """Next frame on `bus` matching want(msg); other frames on the drive bus are recorded.
        Every caller expects the frame: the timeout only bounds a failure, and is long because a
        user-mode-linux guest on a loaded host stalls as a whole for seconds (see uml_lib.sh)."""
        end = time.monotonic() + timeout
        while True:
            left = end - time.monotonic()
            if left <= 0:
                return None
            m = bus.recv(left)
            if m is None:
                return None
            if want(m):
                return m
            if bus is self.drv:
                self.stray.append(m)

    # ---- one CSP cycle
    def run_cycle(self, kind):
        self.cycle += 1
        sync = can.Message(arbitration_id=0x080, data=b"", is_extended_id=False)
        self.cnc.send(sync)
        for a in range(3):
            self.cnc.send(can.Message(arbitration_id=RPDO[a], is_extended_id=False,
                                      data=struct.pack("<Hi", CONTROLWORD, i32(self.target[a]))))
        # Drive side: the SYNC first; the drives take over and answer at once.
        got = self.recv_on(self.drv, lambda m: m.arbitration_id == 0x080 and not m.is_extended_id)
        self.expect_same(sync, got, "SYNC")
        for a in range(3):
            if self.pending[a] is not None:
                self.position[a] = self.pending[a]
                self.pending[a] = None
            if self.position[a] is not None:
                self.drv.send(can.Message(arbitration_id=TPDO[a], is_extended_id=False,
                                          data=struct.pack("<Hi", STATUSWORD, i32(self.position[a]))))
        # The RPDOs as the drives see them. While moving, the correction may belong to a target
        # up to `lag` cycles old (the control tick runs on its own 1 kHz timer and the compensator
        # refreshes its targets in 3 + axes phases, one per tick): any value between the
        # expectations of the last lag + 1 targets (+- tolerance) is right.
        expected = self.grid.correction_increments(self.target)
        self.history = (self.history + [expected])[-(self.lag + 1):]
        for a in range(3):
            m = self.recv_on(self.drv, lambda m, a=a: m.arbitration_id == RPDO[a])
            if m is None or m.dlc != 6:
                self.fail("RPDO 0x%03X missing or wrong length: %s" % (RPDO[a], m))
                continue
            cw, t = struct.unpack("<Hi", bytes(m.data))
            if cw != CONTROLWORD:
                self.fail("controlword changed in RPDO 0x%03X" % RPDO[a])
            self.pending[a] = t
            c = i32(t - self.target[a])
            self.corrections[a] = c
            self.max_abs_correction = max(self.max_abs_correction, abs(c))
            self.frames_checked += 1
            if self.expect_zero and c != 0:
                self.fail("axis %d: target corrected by %d without an active table" % (a, c))
            if self.tolerance is not None:
                lo = min(e[a] for e in self.history) - self.tolerance
                hi = max(e[a] for e in self.history) + self.tolerance
                self.max_dev[kind] = max(self.max_dev[kind], abs(c - expected[a]))
                if not lo <= c <= hi:
                    self.fail("axis %d at %d: correction %d, expected %.2f (%.2f .. %.2f)" %
                              (a, self.target[a], c, expected[a], lo, hi))
        # The master sees the actual positions minus the correction: exactly what it commanded
        # for the SYNC at which the drive sampled (the target the drive took over).
        for a in range(3):
            if self.position[a] is None:
                continue
            m = self.recv_on(self.cnc, lambda m, a=a: m.arbitration_id == TPDO[a])
            if m is None or m.dlc != 6:
                self.fail("TPDO 0x%03X missing or wrong length: %s" % (TPDO[a], m))
                continue
            sw, actual = struct.unpack("<Hi", bytes(m.data))
            if sw != STATUSWORD:
                self.fail("statusword changed in TPDO 0x%03X" % TPDO[a])
            commanded = self.commanded_at_takeover[a]
            if actual != commanded:
                self.fail("axis %d: master sees actual %d, commanded %d (following error %d)" %
                          (a, actual, commanded, actual - commanded))
            self.frames_checked += 1

    def cycles(self, n, kind="rest", path=None):
        for _ in range(n):
            self.step(kind, path)

    def step(self, kind="rest", path=None):
        start = time.monotonic()
        if path is not None:
            self.target = path(self.cycle)
        # The master's target of the previous cycle is what the drives take over at this SYNC.
        self.commanded_at_takeover = list(self.last_sent)
        self.run_cycle(kind)
        self.last_sent = list(self.target)
        left = CYCLE_S - (time.monotonic() - start)
        if left > 0:
            time.sleep(left)

    def while_running(self, argv, kind="moving", path=None, min_cycles=0, stall_s=0):
        """Runs a PC tool command while the cycles go on; returns (rc, output). stall_s: the
        master stops cycling that long right after the start (a stalled master, on purpose)."""
        p = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        n = 0
        self.max_gap = 0.0  # longest time between two cycles meanwhile (a stalled master)
        self.max_abs_correction = 0
        last = time.monotonic()
        if stall_s:
            time.sleep(stall_s)
        while p.poll() is None or n < min_cycles:
            self.step(kind, path)
            now = time.monotonic()
            self.max_gap = max(self.max_gap, now - last)
            last = now
            n += 1
        out = p.stdout.read().decode(errors="replace")
        print("$ %s -> rc %d (%d cycles meanwhile, longest gap %.0f ms)\n%s" %
              (" ".join(argv[1:]), p.returncode, n, self.max_gap * 1000, out.strip()), flush=True)
        return p.returncode, out

    def settle(self, min_s=0.15, max_s=3.0, stable_cycles=25):
        """Cycles at rest until the corrections stopped changing (the ramp is over)."""
        start = time.monotonic()
        same, last = 0, None
        while time.monotonic() - start < max_s:
            self.step()
            same = same + 1 if self.corrections == last else 0
            last = list(self.corrections)
            if same >= stable_cycles and time.monotonic() - start >= min_s:
                return
        self.fail("the correction did not settle within %.1f s" % max_s)

    # ---- the non-PDO traffic
    def passthrough_checks(self):
        def fwd(bus_in, bus_out, msg, what):
            bus_in.send(msg)
            got = self.recv_on(bus_out, lambda m: m.arbitration_id == msg.arbitration_id and
                               m.is_extended_id == msg.is_extended_id)
            self.expect_same(msg, got, what)

        std = dict(is_extended_id=False)
        fwd(self.cnc, self.drv, can.Message(arbitration_id=0x000, data=b"\x01\x00", **std),
            "NMT start all")
        fwd(self.cnc, self.drv, can.Message(arbitration_id=0x601, data=bytes.fromhex(
            "4041600000000000"), **std), "SDO request to drive 1")
        fwd(self.drv, self.cnc, can.Message(arbitration_id=0x581, data=bytes.fromhex(
            "4B41600037120000"), **std), "SDO response of drive 1")
        fwd(self.drv, self.cnc, can.Message(arbitration_id=0x082, data=bytes.fromhex(
            "1032010000000000"), **std), "EMCY of drive 2")
        fwd(self.drv, self.cnc, can.Message(arbitration_id=0x703, data=b"\x05", **std),
            "heartbeat of drive 3")
        fwd(self.cnc, self.drv, can.Message(arbitration_id=0x201, is_remote_frame=True, dlc=6,
                                            **std), "remote frame 0x201")
        fwd(self.cnc, self.drv, can.Message(arbitration_id=0x1ABCDE01, data=b"\xAA\x55",
                                            is_extended_id=True), "extended frame")
        fwd(self.drv, self.cnc, can.Message(arbitration_id=0x1ABCDE02, data=b"\x01",
                                            is_extended_id=True), "extended frame from drives")
        # A short RPDO (no room for the position at offset 2) passes untouched.
        fwd(self.cnc, self.drv, can.Message(arbitration_id=0x202, data=b"\x0F\x00\x01", **std),
            "short RPDO")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cnc", default="vcan0")
    ap.add_argument("--drives", default="vcan1")
    ap.add_argument("--volcomp", required=True)
    ap.add_argument("--table", required=True, help="table image to upload")
    ap.add_argument("--grid-csv", required=True, help="write the grid CSV here and exit")
    ap.add_argument("--write-grid-only", action="store_true")
    ap.add_argument("--timeout-ms", type=int, default=1000,
                    help="the PC tool's SDO timeout for every command of the session")
    ap.add_argument("--stall-first-attempt-s", type=float, default=0.0,
                    help="stall the master this long during the first 'activation while moving' "
                    "(tests the session's own retry path; the board then rightly accepts)")
    args = ap.parse_args()
    nodes = grid_csv(args.grid_csv)
    if args.write_grid_only:
        return 0
    grid = Grid(nodes)
    s = Session(args, grid)
    try:
        run(s, grid, args)
    except Abort:
        s.errors.append("aborted")
    return report(s)


def run(s, grid, args):
    s.last_sent = list(HOME)
    tool = [args.volcomp]
    can_opt = ["--can", "socketcan:" + args.cnc, "--timeout-ms", str(args.timeout_ms)]

    def around(center, amp, period):
        # A triangular back-and-forth motion around `center` (amp increments).
        def path(cycle):
            ph = (cycle % period) / period
            tri = 4 * ph - 1 if ph < 0.5 else 3 - 4 * ph
            return [center[0] + int(amp * tri), center[1] - int(amp * tri / 2), center[2]]
        return path

    print("== forwarding of non-PDO traffic", flush=True)
    s.passthrough_checks()
    print("== pass-through cycles (no table)", flush=True)
    s.cycles(25)
    print("== upload while moving", flush=True)
    rc, _ = s.while_running(tool + ["upload", args.table] + can_opt + ["--quiet"],
                            path=around(HOME, 200000, 400))
    if rc != 0:
        s.fail("upload failed")
    rc, out = s.while_running(tool + ["activate"] + can_opt, path=around(HOME, 200000, 400))
    if rc == 0 or "referenced" not in out:
        s.fail("activation before referencing was not refused")
    print("== back home, reference", flush=True)
    here = list(s.target)
    steps = 50
    s.cycles(steps, path=lambda c, c0=s.cycle, a=here: [
        int(a[i] + (HOME[i] - a[i]) * min(1.0, (c - c0 + 1) / steps)) for i in range(3)])
    s.target = list(HOME)
    s.cycles(10)
    rc, _ = s.while_running(tool + ["reference", "--axes", "1,2,3"] + can_opt, kind="rest")
    if rc != 0:
        s.fail("reference failed")
    print("== activation while moving is refused", flush=True)
    # A loaded 2-core machine (CI beside a build) can stall the master past the window again and
    # again: up to 8 attempts, and a run where every one stalled says so rather than "accepted".
    stalled_attempts = 0
    for attempt in range(8):
        # Judged after the attempt: refused, the targets must have stayed uncorrected; accepted
        # during a stall of the master, the correction rightly ramps in.
        s.expect_zero = False
        rc, out = s.while_running(tool + ["activate"] + can_opt, path=around(HOME, 150000, 200),
                                  min_cycles=20,
                                  stall_s=args.stall_first_attempt_s if attempt == 0 else 0)
        s.expect_zero = True
        if rc != 0 and "at rest" not in out:
            # Refused, but not for the reason under test (a failed transfer, say): no evidence.
            s.fail("activation while moving failed without the board's 'at rest' refusal: %s" %
                   out.strip().splitlines()[-1:])
            break
        if rc != 0 and s.max_abs_correction != 0:
            s.fail("a refused activation corrected the targets (up to %d increments)" %
                   s.max_abs_correction)
        if rc != 0 or s.max_gap < 0.08:
            break
        # The master itself stalled for most of the 100 ms "at rest" window (an overloaded
        # machine), so the board rightly saw the axes at rest: undo and try again.
        stalled_attempts += 1
        print("   (the master stalled %.0f ms: not a test of 'moving'; again)" % (s.max_gap * 1000))
        s.expect_zero = False
        s.while_running(tool + ["deactivate"] + can_opt, path=around(HOME, 150000, 200))
        s.settle()
        s.expect_zero = True
        # The activation consumed the staged table: stage it again for the next attempt.
        up_rc, _ = s.while_running(tool + ["upload", args.table] + can_opt + ["--quiet"],
                                   path=around(HOME, 150000, 200))
        if up_rc != 0:
            s.fail("upload for another attempt failed")
    if rc == 0 and stalled_attempts == 8:
        s.fail("activation while moving could not be tested: the master stalled in all 8 attempts "
               "(a machine too loaded for this test)")
    elif rc == 0:
        s.fail("activation while moving was not refused")
    print("== at rest: activation, ramp-in, exact correction", flush=True)
    rest = [1800000, 2300000, 900000]
    here = list(s.target)
    s.cycles(60, path=lambda c, c0=s.cycle, a=here: [
        int(a[i] + (rest[i] - a[i]) * min(1.0, (c - c0 + 1) / 60)) for i in range(3)])
    s.target = list(rest)
    hold_until = time.monotonic() + 0.25
    while time.monotonic() < hold_until:
        s.step()
    s.expect_zero = False  # the correction ramps in as soon as the board accepts
    rc, _ = s.while_running(tool + ["activate"] + can_opt, kind="rest")
    if rc != 0:
        s.fail("activation at rest failed")
    s.settle()
    s.tolerance = 1.0
    s.cycles(50)
    print("   at rest: corrections %s increments, expected %s" %
          (s.corrections, ["%.2f" % v for v in grid.correction_increments(s.target)]), flush=True)
    print("== moving through the volume", flush=True)
    waypoints = [rest, [3500000, 800000, 3000000], [600000, 3600000, 2000000],
                 [2500000, 2500000, 400000], rest]
    per_leg = 200
    s.tolerance, s.lag = 1.0, 10  # 10 cycles >= 20 ms >> 2 ticks + 6-tick refresh
    for w in range(len(waypoints) - 1):
        a, b = waypoints[w], waypoints[w + 1]
        s.cycles(per_leg, kind="moving", path=lambda c, c0=s.cycle, a=a, b=b: [
            int(a[i] + (b[i] - a[i]) * (c - c0 + 1) / per_leg) for i in range(3)])
    s.lag = 0
    s.cycles(50)
    print("== deactivation ramps out to pass-through", flush=True)
    s.tolerance = None
    rc, _ = s.while_running(tool + ["deactivate"] + can_opt, kind="rest")
    if rc != 0:
        s.fail("deactivation failed")
    s.settle()
    s.expect_zero = True
    s.cycles(25)



def report(s):
    for m in s.stray:
        if (not m.is_extended_id and m.arbitration_id in (0x600 + BOARD_NODE, 0x580 + BOARD_NODE,
                                                          0x700 + BOARD_NODE, 0x080 + BOARD_NODE)):
            s.errors.append("the board's own frame reached the drive bus: %s" % m)
            break
    print("cycles %d, frames checked %d, max |c - expected| at rest %.2f, moving %.2f increments, "
          "%.1f s" % (s.cycle, s.frames_checked, s.max_dev["rest"], s.max_dev["moving"],
                      time.monotonic() - s.t0), flush=True)
    for e in s.errors[:20]:
        print("FAIL " + e, flush=True)
    if s.errors:
        print("%d failures" % len(s.errors), flush=True)
        return 1
    print("CSP gateway session: OK", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
