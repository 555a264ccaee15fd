#!/usr/bin/env bash
# Runs a test command on a busy machine: HOGS CPU-bound processes (default 2) spin at normal
# priority for the whole run, as another user's build would (issue 27 item 7: the tests must hold
# while two other CPU-bound processes run). Repeats it RUNS times (default 1) and stops at the
# first failure. One line per run on stdout and in LOG (default build/busy-test.log): start, end,
# wall seconds, exit status, the 1-minute load average at the end; the same figures as one JSON
# object per line in LOG with .jsonl in place of .log (for scripts).
#
#   scripts/busy-test.sh [--hogs N] [--runs N] [--log FILE] [-- COMMAND...]
#
# COMMAND defaults to scripts/test.sh (the README's test command). Exit status: the first failing
# run's, else 0.
set -euo pipefail
cd "$(dirname "$0")/.."

hogs=2
runs=1
log=build/busy-test.log
while [[ $# -gt 0 ]]; do
  case $1 in
    --hogs) hogs=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --log) log=$2; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n 2,12p "$0"; exit 0 ;;
    *) echo "busy-test: unknown option $1 (the command goes after --)" >&2; exit 2 ;;
  esac
done
[[ $hogs =~ ^[0-9]+$ && $runs =~ ^[1-9][0-9]*$ ]] || {
  echo "busy-test: --hogs and --runs take whole numbers" >&2
  exit 2
}
cmd=("$@")
[[ ${#cmd[@]} -eq 0 ]] && cmd=(scripts/test.sh)
mkdir -p "$(dirname "$log")"

hog_pids=()
stop_hogs() {
  [[ ${#hog_pids[@]} -gt 0 ]] && kill "${hog_pids[@]}" 2>/dev/null || true
  hog_pids=()
}
trap stop_hogs EXIT

for ((run = 1; run <= runs; ++run)); do
  for ((h = 0; h < hogs; ++h)); do
    sh -c 'while :; do :; done' &
    hog_pids+=($!)
  done
  start=$(date +%s)
  status=0
  "${cmd[@]}" || status=$?
  end=$(date +%s)
  stop_hogs
  load=$(cut -d' ' -f1 /proc/loadavg)
  line="run $run/$runs hogs $hogs: $(date -u -d "@$start" +%FT%TZ) .. $(date -u -d "@$end" +%FT%TZ) wall $((end - start)) s exit $status load $load: ${cmd[*]}"
  echo "$line" | tee -a "$log"
  printf '{"run": %d, "runs": %d, "hogs": %d, "start": "%s", "end": "%s", "wall_s": %d, "exit": %d, "load_1min": %s, "command": "%s"}\n' \
    "$run" "$runs" "$hogs" "$(date -u -d "@$start" +%FT%TZ)" "$(date -u -d "@$end" +%FT%TZ)" \
    "$((end - start))" "$status" "$load" "${cmd[*]//\"/\\\"}" >>"${log%.log}.jsonl"
  [[ $status -eq 0 ]] || exit "$status"
done
