#!/usr/bin/env bash
# Installs the Debian packages volcomp needs (idempotent). Usage: scripts/setup-deps.sh [GROUP...]
#   build   compilers (GCC 12, clang 14), clang-format, CMake, Ninja, GoogleTest, Google Benchmark
#           (default)
#   arm     Cortex-M4F cross toolchain (GCC 12, newlib/picolibc, binutils) and QEMU (mps2-an386)
#   fuzz    clang 14 with libFuzzer and the sanitizer runtimes (the fuzz preset)
#   can     CAN test peers: Debian's python3-can (the independent SDO client), can-utils
#           (candump), user-mode-linux + kmod (real SocketCAN in a UML kernel)
#   linuxcnc  LinuxCNC 2.9 (uspace: HAL and motion in POSIX non-realtime mode) and its development
#           headers, for the HAL components and the LinuxCNC integration test (docs/linuxcnc.md)
#   report  headless Chromium and poppler-utils (pdfinfo, pdftotext): the certificate's print test
#           (`volcomp report certificate` printed to PDF, tests/certificate)
# Installs only what is missing; needs root or sudo for that, and stops with a clear message
# otherwise.
set -euo pipefail

declare -A GROUPS_PKGS=(
  [build]="g++ clang-14 clang-format-14 cmake ninja-build libgtest-dev libgmock-dev libbenchmark-dev"
  [can]="python3-can can-utils user-mode-linux kmod libgpiod-dev"
  [fuzz]="clang-14 libclang-rt-14-dev"
  [linuxcnc]="linuxcnc-uspace linuxcnc-uspace-dev python3"
  [report]="chromium poppler-utils python3"
  [arm]="gcc-arm-none-eabi binutils-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm python3"
)

groups=("$@")
[[ ${#groups[@]} -eq 0 ]] && groups=(build)

wanted=()
for g in "${groups[@]}"; do
  if [[ -z "${GROUPS_PKGS[$g]+x}" ]]; then
    echo "setup-deps: unknown group '$g' (known: ${!GROUPS_PKGS[*]})" >&2
    exit 2
  fi
  read -r -a pkgs <<<"${GROUPS_PKGS[$g]}"
  wanted+=("${pkgs[@]}")
done

missing=()
for p in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

if ! command -v apt-get >/dev/null 2>&1; then
  echo "setup-deps: missing packages: ${missing[*]}" >&2
  echo "setup-deps: this script needs Debian (bookworm) with apt-get to install them." >&2
  exit 1
fi
SUDO=""
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
  else
    echo "setup-deps: missing packages: ${missing[*]}" >&2
    echo "setup-deps: run as root, or install sudo, or install them yourself:" >&2
    echo "  apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
fi
echo "setup-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
