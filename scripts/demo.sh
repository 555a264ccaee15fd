#!/usr/bin/env bash
# The main job (README Quick start, command 1). Until the host simulator lands, it shows the PC tool
# and the firmware's lookup on the sample machine: build a compensation table image from corrections
# at grid nodes, inspect it, and look up corrections at a few points with the firmware's code.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-deps.sh build
cmake --preset host >/dev/null
cmake --build --preset host --target volcomp -j "$(nproc 2>/dev/null || echo 2)" >/dev/null
VOLCOMP=build/host/tools/volcomp
out=build/demo
mkdir -p "$out"

echo "== 1. build a table image from samples/grid_example.csv (X, Y 1 um/step, Z 0.5 um/step)"
"$VOLCOMP" build grid --csv samples/grid_example.csv -o "$out/example.vct" \
  --resolution-nm X=1000,Y=1000,Z=500 --element int16 --table-id 1 --info machine=sample
echo
echo "== 2. inspect it (validated with the firmware's parser)"
"$VOLCOMP" inspect "$out/example.vct"
echo
echo "== 3. corrections at points (the firmware's trilinear lookup, Q24.8 steps)"
printf 'x_mm,y_mm,z_mm\n0,0,0\n125.5,333.25,12\n250,200,150\n499,399,299.5\n600,-50,400\n' \
  | "$VOLCOMP" lookup "$out/example.vct"
