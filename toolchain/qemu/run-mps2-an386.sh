#!/usr/bin/env bash
# Runs a bare-metal Cortex-M4F image on QEMU's mps2-an386 machine (the CMAKE_CROSSCOMPILING_EMULATOR
# of toolchain/arm-none-eabi-cm4f.cmake). Semihosting output goes to stdout; the image's exit code
# (SYS_EXIT_EXTENDED) is this script's exit code. A hung image is killed after
# VOLCOMP_QEMU_TIMEOUT seconds (default 60) and reported as exit code 124.
#   run-mps2-an386.sh IMAGE.elf [--test=NAME] [extra qemu options...]
# --test=NAME is handed to the image as its command line (QEMU -append, read by semihosting).
set -euo pipefail
image=$1
shift
append=()
qemu_args=()
for a in "$@"; do
  case "$a" in
    --test=*) append=(-append "${a#--test=}") ;;
    *) qemu_args+=("$a") ;;
  esac
done
exec timeout --foreground -k 5 "${VOLCOMP_QEMU_TIMEOUT:-60}" \
  qemu-system-arm -M mps2-an386 -cpu cortex-m4 -nographic -monitor none -serial none \
  -chardev stdio,id=semihost0 -semihosting-config enable=on,target=native,chardev=semihost0 \
  -kernel "$image" "${append[@]}" "${qemu_args[@]}"
