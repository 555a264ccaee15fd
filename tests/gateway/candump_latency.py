#!/usr/bin/python3
"""Per-frame forwarding latency of the gateway from a `candump -L` log of both buses.

Every forwarded frame appears twice in the log: on the bus it came from and on the other bus,
each with the kernel's receive timestamp of candump's socket (the same clock for both buses). The
k-th frame with a given identifier on its source bus is paired with the k-th frame with that
identifier on the destination bus (the gateway forwards in order), and the difference is the
forwarding latency through the kernel, the gateway process and back into the kernel.
Identifiers seen on one bus only (the board's own node traffic) are not forwarded and skipped.

usage: candump_latency.py LOG [--json OUT]
Prints the figures per direction; exit code 1 when a frame could not be paired.
"""
import json
import re
import sys

LINE = re.compile(r"^\((\d+)\.(\d{6})\) (\S+) ([0-9A-Fa-f]{3}|[0-9A-Fa-f]{8})#(\S*)")


def percentile(values, fraction):
    if not values:
        return 0.0
    k = min(len(values) - 1, max(0, int(round(fraction * len(values) + 0.5)) - 1))
    return values[k]


def summary(values):
    v = sorted(values)
    if not v:
        return {"count": 0}
    return {"count": len(v), "min_us": v[0], "p50_us": percentile(v, 0.5),
            "p99_us": percentile(v, 0.99), "max_us": v[-1], "mean_us": sum(v) / len(v)}


def main():
    path = sys.argv[1]
    out = sys.argv[sys.argv.index("--json") + 1] if "--json" in sys.argv else None
    seen = {}  # (iface, id) -> [t_us]
    ifaces = []
    with open(path) as f:
        for line in f:
            m = LINE.match(line.strip())
            if not m:
                continue
            t = int(m.group(1)) * 1000000 + int(m.group(2))
            iface, ident = m.group(3), m.group(4).upper()
            if iface not in ifaces:
                ifaces.append(iface)
            seen.setdefault((iface, ident), []).append(t)
    if len(ifaces) != 2:
        print("expected two interfaces in %s, found %s" % (path, ifaces))
        return 1
    a, b = sorted(ifaces)
    lat = {a + "->" + b: [], b + "->" + a: []}
    unpaired = 0
    for ident in sorted({i for (_, i) in seen}):
        ta, tb = seen.get((a, ident), []), seen.get((b, ident), [])
        if not ta or not tb:
            continue
        src, dst, ts, td = (a, b, ta, tb) if ta[0] <= tb[0] else (b, a, tb, ta)
        if len(ts) != len(td):
            print("identifier %s: %d frames on %s, %d on %s" % (ident, len(ts), src, len(td), dst))
            unpaired += abs(len(ts) - len(td))
        for x, y in zip(ts, td):
            if y < x:  # a frame missing from the log shifted the pairing
                unpaired += 1
            lat[src + "->" + dst].append(y - x)
    result = {k: summary(v) for k, v in lat.items()}
    for k, s in result.items():
        if s["count"]:
            print("forwarding latency %s (candump kernel timestamps): n %d, min %d us, p50 %d us, "
                  "p99 %d us, max %d us, mean %.1f us" % (k, s["count"], s["min_us"], s["p50_us"],
                                                         s["p99_us"], s["max_us"], s["mean_us"]))
    if out:
        with open(out, "w") as f:
            json.dump(result, f, indent=1)
    if unpaired:
        print("%d frames could not be paired (did candump drop frames?)" % unpaired)
    return 1 if unpaired else 0


if __name__ == "__main__":
    sys.exit(main())
