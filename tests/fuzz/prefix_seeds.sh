#!/bin/sh
# Seeds for a fuzz target whose first input byte chooses what runs (fuzz_csv): copies every file of
# IN_DIR into OUT_DIR N times (N <= 78), copy k with one more leading byte, chr(0x30 + k): '0', '1',
# ... ('0' is 48, a multiple of 12: under fuzz_csv's byte % 12, copy k goes to reader k). OUT_DIR is
# made anew.
#   prefix_seeds.sh IN_DIR OUT_DIR N
set -eu
[ $# -eq 3 ] || { echo "usage: prefix_seeds.sh IN_DIR OUT_DIR N" >&2; exit 2; }
rm -rf "$2"
mkdir -p "$2"
for f in "$1"/*; do
  k=0
  while [ "$k" -lt "$3" ]; do
    # shellcheck disable=SC2059  # the format is the octal escape of the prefix byte
    { printf "\\$(printf %03o $((48 + k)))"; cat "$f"; } >"$2/$k-$(basename "$f")"
    k=$((k + 1))
  done
done
