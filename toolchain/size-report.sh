#!/usr/bin/env bash
# Size report of Cortex-M images: for each, every allocated section with its size, where it runs
# and where it is loaded from, then totals per memory (flash = what is programmed; SRAM and CCM
# SRAM = what is used at run time, stack included).
#   toolchain/size-report.sh IMAGE.elf [IMAGE.elf ...]
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 IMAGE.elf [IMAGE.elf ...]" >&2; exit 2; }
exec python3 - "${VOLCOMP_ARM_PREFIX:-arm-none-eabi-}objdump" "$@" <<'PY'
import re, subprocess, sys
objdump, elfs = sys.argv[1], sys.argv[2:]
def mem(a):
    if 0x08000000 <= a < 0x08080000 or a < 0x00400000: return "flash"
    if 0x10000000 <= a < 0x10008000: return "ccm"
    if 0x20000000 <= a < 0x20400000: return "sram"
    return "other"
def report(elf):
    out = subprocess.run([objdump, "-h", "-w", elf], check=True, capture_output=True,
                         text=True).stdout
    print("== size report: %s" % elf.rsplit("/", 1)[-1])
    print("  %-14s %9s  %-20s %s" % ("section", "bytes", "runs in", "loaded from"))
    flash, ram = 0, {}
    for line in out.splitlines():
        p = line.split()
        if len(p) < 7 or not p[0].isdigit() or "ALLOC" not in line:
            continue
        name, size, vma, lma = p[1], int(p[2], 16), int(p[3], 16), int(p[4], 16)
        load = "LOAD" in line
        print("  %-14s %9d  %-5s 0x%08x     %s" % (name, size, mem(vma), vma,
              ("%-5s 0x%08x" % (mem(lma), lma)) if load else "-"))
        if load: flash += size
        if mem(vma) != "flash": ram[mem(vma)] = ram.get(mem(vma), 0) + size
    print("  total flash (programmed): %d bytes" % flash)
    for m in sorted(ram): print("  total %-5s (run time):   %d bytes" % (m, ram[m]))
for elf in elfs:
    report(elf)
PY
