#!/usr/bin/env bash
# The circular test of docs/simulator.md section 8, as documented: `volcomp program circular`
# writes the ISO 230-4 program, `volcomp-sim run --ballbar` runs it on the worn machine with the
# ballbar, `volcomp evaluate circular` reads the ballbar.csv the run wrote and must give the run's
# own figures. (The document's run adds the demo's table; this one runs without, to stay short.)
set -euo pipefail
sim=$1 volcomp=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
"$volcomp" program circular --plane XY --centre 200,140,100 --radius 50 --feed 2000 -o circle.ngc
"$sim" run circle.ngc --machine worn --ballbar 200,140,100 --report run --json >run.json
"$volcomp" evaluate circular run/ballbar.csv --json >eval.json
python3 - <<'PY' || fail "evaluate circular disagrees with the run"
import json
run = json.load(open("run.json"))["ballbar"]
ev = json.load(open("eval.json"))
for k in ("G_cw_um", "G_ccw_um", "G_b_um", "H_um"):
    # ballbar.csv holds deviations to 0.01 um
    assert abs(run[k] - ev[k]) <= 0.02, (k, run[k], ev[k])
assert run["G_b_um"] > 10, run  # the worn machine without a table
print("circular session: G(b) %.2f um, H %.2f um (run and evaluate agree)" % (ev["G_b_um"], ev["H_um"]))
PY
