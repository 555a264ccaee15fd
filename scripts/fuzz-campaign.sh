#!/usr/bin/env bash
# A long fuzzing campaign: each libFuzzer target of the `fuzz` preset runs until it has executed
# --execs inputs or used --cpu-hours of CPU time, whichever comes first (issue 27: 1e8 or 8 CPU
# hours), with the target's own options (tests/fuzz/CMakeLists.txt: fuzz_options_*, stack size).
# Prints one line per target and writes DIR/summary.json with the same figures.
#
#   scripts/fuzz-campaign.sh [--execs N] [--cpu-hours H] [--workers W] [--out DIR] [--resume]
#                            [TARGET...]
#
# --resume continues a campaign that was stopped (a session's end, SIGINT): the target's corpus in
# DIR/<target>/corpus is kept and the run is one more part, with the goal less what the parts
# before used (DIR/<target>/parts.tsv: commit, executions, CPU s, wall s, coverage, corpus,
# problems, end time per part); the line and summary.json give this part and the campaign's
# totals. A target whose goal is reached is not run again. Without --resume a target starts
# afresh from its seed corpus.
#
# TARGET: table_image slcan board_can csv (default: all). W worker processes per target (default
# 1) share one corpus directory (libFuzzer -jobs/-workers); each runs N/W inputs and at most
# H*3600/W seconds. Exit 1 if a target crashed or leaked (its artifacts are in DIR/<target>/),
# 2 on a usage error. The fuzz preset must be built: cmake --preset fuzz && cmake --build --preset fuzz
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

execs=100000000
cpu_hours=8
workers=1
out=build/fuzz/campaign
resume=0
targets=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --execs) execs=$2; shift 2 ;;
    --cpu-hours) cpu_hours=$2; shift 2 ;;
    --workers) workers=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --resume) resume=1; shift ;;
    -h|--help) sed -n 2,19p "$0"; exit 0 ;;
    -*) echo "fuzz-campaign: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[[ ${#targets[@]} -eq 0 ]] && targets=(table_image slcan board_can csv)
[[ $execs =~ ^[0-9]+$ && $workers =~ ^[1-9][0-9]*$ && $cpu_hours =~ ^[0-9]+([.][0-9]+)?$ ]] || {
  echo "fuzz-campaign: --execs and --workers take whole numbers, --cpu-hours a number" >&2
  exit 2
}

# The per-target options, read from the one place that defines them.
target_option() {  # target, variable prefix -> value (empty if none)
  sed -n "s/^set(${2}_${1} \(.*\))$/\1/p" tests/fuzz/CMakeLists.txt
}

mkdir -p "$out"
summary="$out/summary.json"
echo "[" >"$summary"
status=0
first=1
for t in "${targets[@]}"; do
  bin=build/fuzz/tests/fuzz/fuzz_$t
  # The seeds the build made for the target (tests/fuzz/CMakeLists.txt: fuzz_seed_prefixes_*), if
  # any, else the checked-in ones.
  seeds=$root/build/fuzz/tests/fuzz/seeds_$t
  [[ -d $seeds ]] || seeds=$root/tests/fuzz/corpus/$t
  [[ -x $bin ]] || { echo "fuzz-campaign: $bin not built (cmake --build --preset fuzz)" >&2; exit 2; }
  dir="$out/$t"
  [[ $resume -eq 1 ]] || rm -rf "$dir"
  mkdir -p "$dir/corpus"
  touch "$dir/parts.tsv"
  # The parts before this one: their executions and CPU seconds count against the goal.
  read -r done_runs done_cpu done_problems done_parts < <(awk -F'\t' \
    '{r += $2; c += $3; p += $7; n++} END {printf "%d %.1f %d %d\n", r, c, p, n}' "$dir/parts.tsv")
  left_runs=$((execs - done_runs))
  left_seconds=$(awk -v h="$cpu_hours" -v c="$done_cpu" 'BEGIN { printf "%d", h * 3600 - c }')
  if [[ $left_runs -le 0 || $left_seconds -le 0 ]]; then
    printf '%-12s goal reached in %d parts: %d executions, %.1f CPU s, problems %d\n' \
      "$t" "$done_parts" "$done_runs" "$done_cpu" "$done_problems"
    [[ $first -eq 1 ]] || echo "," >>"$summary"
    first=0
    printf '  {"target": "%s", "goal_reached": true, "parts": %d, "total_executions": %d, "total_cpu_seconds": %s, "total_problems": %d, "goal_executions": %d, "goal_cpu_hours": %s}' \
      "$t" "$done_parts" "$done_runs" "$done_cpu" "$done_problems" "$execs" "$cpu_hours" >>"$summary"
    [[ $done_problems -eq 0 ]] || status=1
    continue
  fi
  part="$dir/part-$((done_parts + 1))"
  mkdir -p "$part"
  opts=$(target_option "$t" fuzz_options)
  stack_kib=$(target_option "$t" fuzz_stack_kib)
  stack_kib=${stack_kib:-8192}
  per_worker_runs=$(((left_runs + workers - 1) / workers))
  per_worker_seconds=$((left_seconds / workers))
  parallel=()
  [[ $workers -gt 1 ]] && parallel=(-jobs="$workers" -workers="$workers")
  commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)  # of the checkout the build is of
  start=$(date +%s)
  # From inside the part's directory: with -jobs, libFuzzer writes each worker's log (fuzz-N.log)
  # to the current directory. CPU time of every worker: /usr/bin/time counts waited-for children.
  # shellcheck disable=SC2086  # $opts holds several libFuzzer options
  (cd "$part" && /usr/bin/time -f "%U %S" -o cpu.txt sh -c "ulimit -s $stack_kib && exec \"\$@\"" \
    fuzz "$root/$bin" $opts -runs="$per_worker_runs" -max_total_time="$per_worker_seconds" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 "${parallel[@]}" -artifact_prefix=./ \
    ../corpus "$seeds" >fuzz.log 2>&1) || true
  wall=$(($(date +%s) - start))
  logs=("$part/fuzz.log")
  [[ $workers -gt 1 ]] && logs=("$part"/fuzz-*.log)
  runs=$(cat "${logs[@]}" | sed -n 's/^stat::number_of_executed_units: *//p' | awk '{s += $1} END {print s + 0}')
  cov=$(cat "${logs[@]}" | grep -o 'cov: [0-9]*' | awk '{if ($2 > m) m = $2} END {print m + 0}')
  # The last line: /usr/bin/time writes "Command exited with non-zero status N" before it when
  # libFuzzer stops on a finding or an interrupt.
  cpu=$(tail -n 1 "$part/cpu.txt" | awk '{printf "%.1f", $1 + $2}')
  crashes=$(find "$part" -maxdepth 1 -name 'crash-*' -o -maxdepth 1 -name 'leak-*' -o -maxdepth 1 -name 'timeout-*' -o -maxdepth 1 -name 'oom-*' | wc -l)
  corpus=$(find "$dir/corpus" -type f | wc -l)
  per_cpu=$(awk -v r="$runs" -v c="$cpu" 'BEGIN { printf "%d", (c > 0 ? r / c : 0) }')
  printf '%s\t%d\t%s\t%d\t%d\t%d\t%d\t%s\n' "$commit" "$runs" "$cpu" "$wall" "$cov" "$corpus" \
    "$crashes" "$(date -u +%Y-%m-%dT%H:%M:%SZ)" >>"$dir/parts.tsv"
  parts=$((done_parts + 1))
  total_runs=$((done_runs + runs))
  total_cpu=$(awk -v a="$done_cpu" -v b="$cpu" 'BEGIN { printf "%.1f", a + b }')
  total_problems=$((done_problems + crashes))
  reached=$(awk -v r="$total_runs" -v n="$execs" -v c="$total_cpu" -v h="$cpu_hours" \
    'BEGIN { print (r >= n || c >= h * 3600 ? "true" : "false") }')
  printf '%-12s %12d executions  %7.1f CPU s  %7d per CPU s  wall %6d s  cov %5d  corpus %6d  problems %d\n' \
    "$t" "$runs" "$cpu" "$per_cpu" "$wall" "$cov" "$corpus" "$crashes"
  [[ $parts -gt 1 ]] && printf '%-12s campaign of %d parts: %d executions, %.1f CPU s, problems %d (%s)\n' \
    "$t" "$parts" "$total_runs" "$total_cpu" "$total_problems" "$dir/parts.tsv"
  [[ $first -eq 1 ]] || echo "," >>"$summary"
  first=0
  printf '  {"target": "%s", "executions": %d, "cpu_seconds": %s, "executions_per_cpu_second": %d, "wall_seconds": %d, "workers": %d, "options": "%s", "stack_kib": %d, "coverage": %d, "corpus_inputs": %d, "problems": %d, "goal_executions": %d, "goal_cpu_hours": %s, "goal_reached": %s, "part": %d, "total_executions": %d, "total_cpu_seconds": %s, "total_problems": %d, "commit": "%s"}' \
    "$t" "$runs" "$cpu" "$per_cpu" "$wall" "$workers" "$opts" "$stack_kib" "$cov" "$corpus" "$crashes" "$execs" "$cpu_hours" "$reached" "$parts" "$total_runs" "$total_cpu" "$total_problems" "$commit" >>"$summary"
  crashes=$total_problems
  [[ $crashes -eq 0 ]] || status=1
done
printf '\n]\n' >>"$summary"
echo "summary: $summary"
exit $status
