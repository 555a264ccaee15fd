#!/usr/bin/env bash
# Builds everything and runs every test (README Quick start, command 2; also what CI runs).
#   scripts/test.sh            formatting check, release build (GCC 12) + tests, Cortex-M4F build +
#                              QEMU tests + cycle budgets, then the clang 14 ASan/UBSan build +
#                              tests, and 30 s of libFuzzer per fuzz target
#   scripts/test.sh --fast     formatting check, release and Cortex-M4F builds + tests only
# Each phase prints its wall time ("== took N s: PHASE"), and the run ends (passed or not) with the
# table of them: CI stops at 90 minutes, and the table shows where a run's time went.
# Long versions (docs/reliability.md): VOLCOMP_ENGINE_STEPS, VOLCOMP_FAULT_TRIALS,
# VOLCOMP_SOAK_STEPS, VOLCOMP_FUZZ_SECONDS (cmake -DVOLCOMP_FUZZ_SECONDS=N --preset fuzz).
set -euo pipefail
cd "$(dirname "$0")/.."
fast=0
[[ "${1:-}" == "--fast" ]] && fast=1

run_start=$SECONDS
phase_times=""
timed() {
  local name=$1 start=$SECONDS
  shift
  "$@"
  local took=$((SECONDS - start))
  echo "== took ${took} s: $name" >&2
  phase_times+="$(printf '%6d s  %s' "$took" "$name")"$'\n'
}
print_phase_times() {
  echo "== wall time per phase (total $((SECONDS - run_start)) s)" >&2
  printf '%s' "$phase_times" >&2
}
trap print_phase_times EXIT

timed "setup: build can" scripts/setup-deps.sh build can
# Every C++ source as clang-format (.clang-format) writes it; a drift fails the run here.
timed "format check" scripts/check-format.sh
# LinuxCNC before the host build: its headers decide whether the HAL components are built, and
# the LinuxCNC integration test (label external) runs with the host tests.
timed "setup: linuxcnc" scripts/setup-deps.sh linuxcnc
# Headless Chromium and poppler-utils: the certificate's print test (tests/certificate, external).
timed "setup: report" scripts/setup-deps.sh report
jobs=$(nproc 2>/dev/null || echo 2)

run_preset() {
  local preset=$1
  shift
  echo "== configure + build: $preset" >&2
  cmake --preset "$preset" >/dev/null
  timed "build $preset" cmake --build --preset "$preset" -j "$jobs"
  echo "== test: $preset" >&2
  timed "test $preset" ctest --preset "$preset" -j "$jobs" "$@"
}

run_preset host
echo "== benchmarks (figures only, not pass/fail)" >&2
build/host/tests/bench/core_bench --benchmark_min_time=0.05 2>/dev/null | tail -n +4 || true
# Cortex-M4F (docs/mcu-target.md): STM32G474 image, lib tests on QEMU mps2-an386, cycle budgets.
timed "setup: arm" scripts/setup-deps.sh arm
run_preset arm-m4f
toolchain/size-report.sh build/arm-m4f/firmware/stm32g4/volcomp_stm32g474.elf \
  build/arm-m4f/firmware/stm32g4/volcomp_stm32g474_gateway.elf >&2
echo "== Cortex-M4 cycle table (toolchain/cyclemodel/cm4cost.py)" >&2
cat build/arm-m4f/tests/target/cycle_budgets.md >&2
echo "== main loop under an SDO block download (tests/target main_loop_cycles)" >&2
cat build/arm-m4f/tests/target/main_loop_cycles.md >&2
if [[ $fast -eq 0 ]]; then
  # clang 14's sanitizer runtimes (libclang-rt-14-dev) serve host-asan and the fuzz targets.
  timed "setup: fuzz" scripts/setup-deps.sh fuzz
  # The whole tree with clang 14 as well as GCC 12 (warnings are errors in lib/ under both), built
  # once, with ASan + UBSan. Tests that start other processes (python3-can, user-mode-linux,
  # LinuxCNC) run once, in the release build; the sanitizer build runs everything in-process.
  run_preset host-asan -LE external
  # libFuzzer (clang 14 + ASan + UBSan): each target 30 s on its seed corpus (docs/reliability.md).
  run_preset fuzz
fi
echo "== all tests passed" >&2
