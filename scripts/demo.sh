#!/usr/bin/env bash
# The main job (README Quick start, command 1), on the host simulator: a simulated machine (the
# STAN S500 error model) is measured with virtual instruments (GOST 27843 per axis, ISO 230-6
# diagonals, random points), its six error motions per axis are measured and turned into a
# compensation table, the table goes over a simulated CAN bus to the real firmware with the PC tool's
# protocol code, the axes are referenced, the table is activated and the machine re-measured.
# Prints what it does as it goes and a before/after summary; exit code 0 when every check passed.
#
# Extra arguments go to `volcomp-sim demo`, e.g. scripts/demo.sh --seed 2, --model FILE.conf,
# --points 500, --report DIR (default build/demo/report). See docs/simulator.md.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-deps.sh build
cmake --preset host >/dev/null
echo "building volcomp-sim and volcomp (build/host) ..."
cmake --build --preset host --target volcomp-sim volcomp -j "$(nproc 2>/dev/null || echo 2)" >/dev/null
exec build/host/host-sim/app/volcomp-sim demo --report build/demo/report "$@"
