#!/usr/bin/python3
"""LinuxCNC [DISPLAY] program of the volcomp integration test (docs/linuxcnc.md §4).

Runs headless inside `linuxcnc -r volcomp-sim.ini`: resets e-stop, switches the machine on, homes
to the switches (which references the board and the native component; the machine was switched on
elsewhere, so homing sets LinuxCNC's motor offsets), waits until both compensations are engaged
and settled, then runs each G-code program named in VOLCOMP_LCNC_PROGRAMS (colon-separated) in
AUTO mode. At every dwell (the programs' measured stops) it records one row of HAL values once they
have been still for a while; at the end it writes the rows (VOLCOMP_LCNC_OUT, CSV) and a summary
(VOLCOMP_LCNC_OUT + ".json"): monitored following errors, board counters, LinuxCNC errors.
Uses Debian's linuxcnc and hal modules (/usr/bin/python3).
"""
import json
import os
import re
import sys
import threading
import time

import hal
import linuxcnc
import rtapi_priority

JOINTS = 3
PROBE = hal.component("volcomp-probe")
PROBE.ready()
S = linuxcnc.stat()
C = linuxcnc.command()
E = linuxcnc.error_channel()
errors = []


def log(msg):
    print("lcnc_run: " + msg, file=sys.stderr, flush=True)


stepgen_notes = []
maxvel_reapplied = []
timing_reapplied = []


def drain_errors():
    while True:
        e = E.poll()
        if not e:
            return
        kind, text = e
        if text.startswith("STEPGEN:"):
            # stepgen's own check of maxvel against its base period (see guard_maxvel)
            stepgen_notes.append(text)
            log("stepgen: " + text.strip())
            continue
        if kind in (linuxcnc.NML_ERROR, linuxcnc.OPERATOR_ERROR):
            errors.append(text)
            log("LinuxCNC error: " + text)


def wait_for(cond, timeout_s, what):
    t0 = time.time()
    while not cond():
        drain_errors()
        if time.time() - t0 > timeout_s:
            raise RuntimeError("timeout waiting for " + what)
        time.sleep(0.01)


def g(name):
    return hal.get_value(name)


def guard_maxvel():
    """stepgen's update-freq rounds each step timing parameter (steplen, stepspace, dirsetup,
    dirhold; ns) up to a whole number of the base period make-pulses last ran with, and stores the
    rounded value back: one late period (it happens under load in this non-real-time setup, e.g.
    64 us) leaves steplen and stepspace at 64000 ns for good, since a multiple of the late period
    is a multiple of the normal one. Its rate limit 1/(steplen + stepspace) is then 7812 steps/s
    (19.5 mm/s) and it lowers maxvel to that every servo period: motion at 70 mm/s outruns the step
    generator until the following error stops the machine. When maxvel is found lowered, set the
    timing parameters back to what the HAL file sets and maxvel to the INI's, and count both
    (reported)."""
    want = STEPGEN_MAXVEL
    if want <= 0:
        return
    for j in range(JOINTS if COMP_MODE else 2 * JOINTS):
        name = "stepgen.%d.maxvel" % j
        if abs(g(name) - want) <= 1e-9:
            continue
        for param, ns in STEP_TIMING_NS.get(j, {}).items():
            pname = "stepgen.%d.%s" % (j, param)
            if g(pname) > -(-ns // BASE_PERIOD_NS) * BASE_PERIOD_NS:  # above its normal rounding
                if len(timing_reapplied) < 12:
                    log("%s was %d ns, set to %d ns again" % (pname, g(pname), ns))
                hal.set_p(pname, str(ns))
                timing_reapplied.append(j)
        if len(maxvel_reapplied) < 12:
            log("%s was %.3f, set to %.3f again" % (name, g(name), want))
        hal.set_p(name, str(want))
        maxvel_reapplied.append(j)


def guard_maxvel_every_ms(stop):
    """guard_maxvel() every millisecond (a thread), so that a lowered maxvel lasts about one
    servo period: the lag it lets build up stays far below the following-error limit."""
    while not stop.is_set():
        guard_maxvel()
        time.sleep(0.001)


# The configured stepgen maxvel ([JOINT_0]STEPGEN_MAXVEL of the INI file linuxcnc runs with).
INI_PATH = os.environ["INI_FILE_NAME"]
STEPGEN_MAXVEL = float(linuxcnc.ini(INI_PATH).find("JOINT_0", "STEPGEN_MAXVEL") or 0)
BASE_PERIOD_NS = int(linuxcnc.ini(INI_PATH).find("EMCMOT", "BASE_PERIOD"))


def configured_step_timing():
    """{stepgen index: {parameter: ns}}: the step timing the INI's [HAL]HALFILE sets (setp)."""
    halfile = os.path.join(os.path.dirname(INI_PATH), linuxcnc.ini(INI_PATH).find("HAL", "HALFILE"))
    timing = {}
    with open(halfile) as f:
        for line in f:
            m = re.match(r"\s*setp\s+stepgen\.(\d+)\.(steplen|stepspace|dirsetup|dirhold)\s+(\d+)",
                         line)
            if m:
                timing.setdefault(int(m.group(1)), {})[m.group(2)] = int(m.group(3))
    if not timing:
        sys.exit("lcnc_run: %s sets no stepgen step timing (setp stepgen.N.steplen ...)" % halfile)
    return timing


STEP_TIMING_NS = configured_step_timing()

# VOLCOMP_LCNC_MODE=comp: the machine of volcomp-comp.hal (LinuxCNC's own joint compensation
# files, no volcomp component): joint.N.pos-cmd is the nominal, motor-pos-cmd the compensated
# command plus the motor offset (homing), the step generators' counts the drives.
COMP_MODE = os.environ.get("VOLCOMP_LCNC_MODE") == "comp"
COMP_COLUMNS = (["pos_cmd_mm_%d" % j for j in range(JOINTS)] +
                ["motor_cmd_mm_%d" % j for j in range(JOINTS)] +
                ["motor_offset_mm_%d" % j for j in range(JOINTS)] +
                ["drive_counts_%d" % j for j in range(JOINTS)] +
                ["ferror_mm_%d" % j for j in range(JOINTS)])

# cmd_mm: the joint position LinuxCNC commands (joint.N.pos-cmd, machine coordinates since
# homing); motor_cmd_mm: what it sends to the joint's motor (motor-pos-cmd = pos-cmd + the motor
# offset homing established, which the step counts since power-on include).
COLUMNS = (["cmd_mm_%d" % j for j in range(JOINTS)] +
           ["motor_cmd_mm_%d" % j for j in range(JOINTS)] +
           ["motor_offset_mm_%d" % j for j in range(JOINTS)] +
           ["lcnc_counts_%d" % j for j in range(JOINTS)] +
           ["board_in_%d" % j for j in range(JOINTS)] +
           ["board_corr_%d" % j for j in range(JOINTS)] +
           ["board_out_%d" % j for j in range(JOINTS)] +
           ["board_backlog_%d" % j for j in range(JOINTS)] +
           ["drive_counts_%d" % j for j in range(JOINTS)] +
           ["native_counts_%d" % j for j in range(JOINTS)] +
           ["native_corr_mm_%d" % j for j in range(JOINTS)] +
           ["ferror_mm_%d" % j for j in range(JOINTS)])


def snapshot():
    if COMP_MODE:
        return ([g("joint.%d.pos-cmd" % j) for j in range(JOINTS)] +
                [g("joint.%d.motor-pos-cmd" % j) for j in range(JOINTS)] +
                [g("joint.%d.motor-offset" % j) for j in range(JOINTS)] +
                [g("stepgen.%d.counts" % j) for j in range(JOINTS)] +
                [g("joint.%d.f-error" % j) for j in range(JOINTS)])
    v = []
    v += [g("joint.%d.pos-cmd" % j) for j in range(JOINTS)]
    v += [g("joint.%d.motor-pos-cmd" % j) for j in range(JOINTS)]
    v += [g("joint.%d.motor-offset" % j) for j in range(JOINTS)]
    v += [g("stepgen.%d.counts" % j) for j in range(JOINTS)]
    v += [g("volcomp-board.%d.commanded" % j) for j in range(JOINTS)]
    v += [g("volcomp-board.%d.correction" % j) for j in range(JOINTS)]
    v += [g("volcomp-board.%d.output" % j) for j in range(JOINTS)]
    v += [g("volcomp-board.%d.backlog" % j) for j in range(JOINTS)]
    v += [g("updown.%d.count" % j) for j in range(JOINTS)]
    v += [g("stepgen.%d.counts" % (j + JOINTS)) for j in range(JOINTS)]
    v += [g("volcomp.0.joint.%d.correction" % j) for j in range(JOINTS)]
    v += [g("joint.%d.f-error" % j) for j in range(JOINTS)]
    return v


def settled_snapshot(still_s, deadline):
    """A snapshot after all values stayed unchanged for still_s; None if deadline passes."""
    last = snapshot()
    since = time.time()
    while time.time() < deadline:
        time.sleep(0.01)
        now = snapshot()
        if now != last:
            last, since = now, time.time()
        elif time.time() - since >= still_s:
            return now
    return None


def run_program(path, rows):
    """Runs one program, taking the values at each dwell; returns its figures for the summary."""
    C.mode(linuxcnc.MODE_AUTO)
    C.wait_complete()
    C.program_open(path)
    C.wait_complete()
    C.auto(linuxcnc.AUTO_RUN, 0)
    name = os.path.basename(path)
    with open(path) as f:  # the measured stops: a dwell each (1-based line numbers)
        dwell_lines = [i + 1 for i, line in enumerate(f) if line.lstrip().upper().startswith("G4")]
    seen_lines = []
    stop = 0
    in_dwell = False
    dwell_line = None
    errors_before = len(errors)
    t0 = time.time()
    last_poll, max_poll_gap = time.time(), 0.0
    wait_for(lambda: S.poll() or S.interp_state != linuxcnc.INTERP_IDLE or len(errors) > errors_before,
             10, name + " to start")
    while True:
        S.poll()
        now = time.time()
        max_poll_gap, last_poll = max(max_poll_gap, now - last_poll), now
        drain_errors()
        if len(errors) > errors_before:
            raise RuntimeError("%s: %s" % (name, "; ".join(errors[errors_before:])))
        waiting = S.exec_state == linuxcnc.EXEC_WAITING_FOR_DELAY
        if os.environ.get("VOLCOMP_LCNC_DEBUG") and (S.exec_state, S.interp_state) != getattr(run_program, "last", None):
            run_program.last = (S.exec_state, S.interp_state)
            log("t=%.3f exec %d interp %d pos %.3f" % (time.time() - t0, S.exec_state, S.interp_state, S.position[0]))
        # A new dwell: waiting after not waiting, or waiting on another line (on a busy machine
        # the short move between two stops can pass while the values of one are being taken, so
        # the poller never sees the CNC not waiting between the two dwells).
        if waiting and (not in_dwell or S.current_line != dwell_line):
            dwell_line = S.current_line
            seen_lines.append(dwell_line)
            # The dwell of a measured stop: the machine stands still; take the values once they
            # have been still for 100 ms (the correction settles within a few ms at rest).
            t_stop = time.time()
            v = settled_snapshot(0.1, t_stop + 5.0)
            if v is None:
                raise RuntimeError("%s stop %d: values did not settle" % (name, stop))
            S.poll()
            if S.exec_state != linuxcnc.EXEC_WAITING_FOR_DELAY or S.current_line != dwell_line:
                # Taken after the dwell ended: the values may be the next stop's, which is then
                # missed (the evaluation's count of stops fails).
                log("%s stop %d: values still only after %.2f s, after the dwell (line %d) ended"
                    % (name, stop, time.time() - t_stop, dwell_line))
            rows.append([name, stop] + v)
            stop += 1
        in_dwell = waiting
        # AUTO_RUN has been accepted (wait_complete above): idle again means the program ended.
        if S.interp_state == linuxcnc.INTERP_IDLE and S.queue == 0 and not waiting:
            break
        if S.task_state != linuxcnc.STATE_ON:
            raise RuntimeError("%s: machine switched off (%s)" % (name, "; ".join(errors)))
        last_poll = time.time()  # the gap: this sleep and how late it returns (not a snapshot)
        time.sleep(0.005)
    log("%s: %d stops in %.1f s (longest gap between two status polls %.3f s)"
        % (name, stop, time.time() - t0, max_poll_gap))
    if stop != len(dwell_lines):
        raise RuntimeError("%s: %d stops seen for %d dwells (lines seen while dwelling: %s; the "
                           "program's dwells: %s)" % (name, stop, len(dwell_lines), seen_lines,
                                                     dwell_lines))
    return {"program": name, "stops": stop, "wall_s": round(time.time() - t0, 3),
            "max_poll_gap_s": round(max_poll_gap, 4)}


def raise_rtapi_priority():
    """SCHED_FIFO for rtapi_app's threads (VOLCOMP_LCNC_FIFO_PRIORITY): the 20 us base thread must
    not be delayed by other load (stepgen would fall behind the servo thread)."""
    prio = os.environ.get("VOLCOMP_LCNC_FIFO_PRIORITY")
    if not prio or os.geteuid() != 0:
        return []
    raised = rtapi_priority.raise_rtapi_priority(int(prio))
    # LinuxCNC's task (it runs the dwells) and this poller, below rtapi_app: the poller must see
    # every dwell of the programs.
    task = rtapi_priority.raise_task_priority(max(1, int(prio) - 20))
    os.sched_setscheduler(0, os.SCHED_FIFO, os.sched_param(max(1, int(prio) - 30)))
    log("SCHED_FIFO %s for rtapi_app threads %s, %d for milltask threads %s"
        % (prio, raised, max(1, int(prio) - 20), task))
    return raised


def main():
    out = os.environ["VOLCOMP_LCNC_OUT"]
    programs = [p for p in os.environ.get("VOLCOMP_LCNC_PROGRAMS", "").split(":") if p]
    summary = {"ok": False}
    rows = []
    summary["fifo_threads"] = len(raise_rtapi_priority())
    stop_guard = threading.Event()
    guard = threading.Thread(target=guard_maxvel_every_ms, args=(stop_guard,), daemon=True)
    guard.start()  # SCHED_FIFO like this thread (inherited)
    try:
        time.sleep(0.5)
        drain_errors()
        C.state(linuxcnc.STATE_ESTOP_RESET)
        C.wait_complete()
        C.state(linuxcnc.STATE_ON)
        C.wait_complete()
        C.mode(linuxcnc.MODE_MANUAL)
        C.wait_complete()
        # Homing moves at once (toward the switches): start it once the base thread keeps its
        # period, i.e. stepgen's maxvel check has not fired for 1.5 s (LinuxCNC's start-up load
        # delays it for a few seconds), waiting 10 s at most (homing is slower than what stepgen
        # keeps when its check fires).
        t_quiet = time.time()
        seen, since = len(maxvel_reapplied), time.time()
        while time.time() - since < 1.5 and time.time() - t_quiet < 10:
            drain_errors()
            if len(maxvel_reapplied) != seen:
                seen, since = len(maxvel_reapplied), time.time()
            time.sleep(0.05)
        summary["quiet_wait_s"] = time.time() - t_quiet
        t_home = time.time()
        C.home(-1)  # to the switches, away from where the machine was switched on
        wait_for(lambda: S.poll() or all(S.homed[:JOINTS]), 60, "homing")
        summary["homing_s"] = time.time() - t_home
        summary["motor_offset_mm"] = [g("joint.%d.motor-offset" % j) for j in range(JOINTS)]
        log("homed in %.1f s, motor offsets %s mm" % (summary["homing_s"],
                                                      summary["motor_offset_mm"]))
        if not COMP_MODE:
            wait_for(lambda: g("volcomp-board.compensating") and g("volcomp.0.active"), 10,
                     "both compensations engaged")
        home = settled_snapshot(0.3, time.time() + 10)
        if home is None:
            raise RuntimeError("the corrections did not settle at home")
        rows.append(["home", 0] + home)
        monitors = JOINTS if COMP_MODE else 2 * JOINTS
        for j in range(monitors):
            hal.set_p("minmax.%d.reset" % j, "1")
        time.sleep(0.05)
        for j in range(monitors):
            hal.set_p("minmax.%d.reset" % j, "0")
        t0 = time.time()
        for p in programs:
            summary.setdefault("programs", []).append(run_program(p, rows))
        summary["program_wall_s"] = time.time() - t0
        summary["ok"] = True
    except Exception as e:  # reported in the summary; the test fails on it
        summary["exception"] = str(e)
        log("FAILED: " + str(e))
    stop_guard.set()
    guard.join()
    drain_errors()
    S.poll()
    try:
        import subprocess
        threads = subprocess.run(["halcmd", "show", "thread"], capture_output=True, text=True,
                                 timeout=10).stdout
        log("threads:\n" + threads)
        summary["threads"] = threads
    except Exception as e:  # diagnostics only
        log("halcmd show thread: %s" % e)
    summary["errors"] = errors
    summary["stepgen_notes"] = stepgen_notes
    summary["maxvel_reapplied"] = len(maxvel_reapplied)
    summary["step_timing_reapplied"] = len(timing_reapplied)
    summary["step_timing_ns"] = {"stepgen.%d.%s" % (j, p): g("stepgen.%d.%s" % (j, p))
                                 for j in sorted(STEP_TIMING_NS) for p in STEP_TIMING_NS[j]}
    summary["stepgen_maxvel"] = [g("stepgen.%d.maxvel" % j)
                                 for j in range(JOINTS if COMP_MODE else 2 * JOINTS)]
    if COMP_MODE:
        summary["ferror_mm"] = [max(-g("minmax.%d.min" % j), g("minmax.%d.max" % j))
                                for j in range(JOINTS)]
    else:
        summary["stepgen_lag_mm"] = [max(-g("minmax.%d.min" % j), g("minmax.%d.max" % j))
                                     for j in range(JOINTS)]
        summary["ferror_mm"] = [max(-g("minmax.%d.min" % (j + JOINTS)),
                                    g("minmax.%d.max" % (j + JOINTS))) for j in range(JOINTS)]
        for pin in ("overruns", "max-backlog", "queue-overflows", "decode-errors",
                    "period-changes", "tick-hz", "fault", "compensating", "referenced"):
            summary["board_" + pin.replace("-", "_")] = g("volcomp-board." + pin)
        summary["board_table_crc"] = "%08X" % (g("volcomp-board.table-crc") & 0xFFFFFFFF)
        summary["native_table_crc"] = "%08X" % (g("volcomp.0.table-crc") & 0xFFFFFFFF)
        summary["native_clamped"] = g("volcomp.0.clamped")
        summary["pulses_out"] = [g("volcomp-board.%d.pulses-out" % j) for j in range(JOINTS)]
    with open(out, "w") as f:
        f.write("program,stop," + ",".join(COMP_COLUMNS if COMP_MODE else COLUMNS) + "\n")
        for r in rows:
            f.write(",".join(str(x) if not isinstance(x, float) else "%.9f" % x for x in r) + "\n")
    with open(out + ".json", "w") as f:
        json.dump(summary, f, indent=1)
    C.state(linuxcnc.STATE_OFF)
    return 0


if __name__ == "__main__":
    sys.exit(main())
