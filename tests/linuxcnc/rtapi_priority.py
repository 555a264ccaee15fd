"""SCHED_FIFO for rtapi_app's HAL threads, as LinuxCNC has on a real-time kernel, and for LinuxCNC's
task (shared by the LinuxCNC test's display programs lcnc_run.py and lcnc_recipe_run.py)."""
import os


def _raise_threads(process, priority, skip=()):
    """SCHED_FIFO `priority` for every thread of every process named `process` (root only), except
    threads named in `skip`. Returns the thread ids raised."""
    if os.geteuid() != 0:
        return []
    raised = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/comm" % pid) as f:
                if f.read().strip() != process:
                    continue
            for tid in os.listdir("/proc/%s/task" % pid):
                with open("/proc/%s/task/%s/comm" % (pid, tid)) as f:
                    if f.read().strip() in skip:
                        continue
                os.sched_setscheduler(int(tid), os.SCHED_FIFO, os.sched_param(priority))
                raised.append(int(tid))
        except (OSError, ValueError):
            continue
    return raised


def raise_rtapi_priority(priority):
    """Gives every thread of every rtapi_app SCHED_FIFO `priority` (root only), except the native
    component's table loader (`volcomp-loader`), which must stay an ordinary thread. On this
    standard kernel the HAL threads run SCHED_OTHER: other load on the machine would delay them
    (their work is not lost, only late). Returns the thread ids raised."""
    return _raise_threads("rtapi_app", priority, skip=("volcomp-loader",))


def raise_task_priority(priority):
    """SCHED_FIFO `priority` for every thread of LinuxCNC's task (milltask; root only), which runs
    the G-code's dwells and publishes the status the display programs poll. On a loaded machine an
    ordinary task was seen 0.48 s late, longer than the test's 0.3 s dwells then. Returns the
    thread ids raised."""
    return _raise_threads("milltask", priority)
