#!/usr/bin/env bash
# Fails when a C++ source of the repository differs from what clang-format (.clang-format, Google
# base style) makes of it; lists the files. `scripts/check-format.sh --fix` formats them.
set -euo pipefail
cd "$(dirname "$0")/.."
fmt=$(command -v clang-format-14 || command -v clang-format || true)
if [[ -z "$fmt" ]]; then
  echo "check-format: clang-format is missing (scripts/setup-deps.sh build installs it)" >&2
  exit 1
fi
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h' | grep -v '^tests/fuzz/corpus/')
if [[ "${1:-}" == "--fix" ]]; then
  "$fmt" -i "${files[@]}"
  exit 0
fi
drift=$("$fmt" --dry-run "${files[@]}" 2>&1 | grep 'warning: code should be clang-formatted' | cut -d: -f1 | sort -u || true)
if [[ -n "$drift" ]]; then
  echo "check-format: these files are not formatted ($fmt; scripts/check-format.sh --fix):" >&2
  echo "$drift" | sed 's/^/  /' >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted" >&2
