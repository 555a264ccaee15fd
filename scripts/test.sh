#!/usr/bin/env bash
# Builds everything and runs every test (README Quick start, command 2; also what CI runs).
#   scripts/test.sh            release build + tests, then an ASan/UBSan build + tests
#   scripts/test.sh --fast     release build + tests only
# Long versions of the randomized tests: VOLCOMP_ENGINE_STEPS=100000000 scripts/test.sh --fast
set -euo pipefail
cd "$(dirname "$0")/.."
fast=0
[[ "${1:-}" == "--fast" ]] && fast=1

scripts/setup-deps.sh build
jobs=$(nproc 2>/dev/null || echo 2)

run_preset() {
  local preset=$1
  echo "== configure + build: $preset" >&2
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
  echo "== test: $preset" >&2
  ctest --preset "$preset" -j "$jobs"
}

run_preset host
echo "== benchmarks (figures only, not pass/fail)" >&2
build/host/tests/bench/core_bench --benchmark_min_time=0.05 2>/dev/null | tail -n +4 || true
if [[ $fast -eq 0 ]]; then
  run_preset host-asan
fi
echo "== all tests passed" >&2
