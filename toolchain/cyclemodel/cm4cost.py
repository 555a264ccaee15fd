#!/usr/bin/env python3
"""Cortex-M4 cycle-cost model: prices executed instruction paths and static worst paths.

volcomp's own model (python3 standard library only). Two independent figures per hot function:

  trace   QEMU runs the bench image with `-singlestep -d exec,nochain -dfilter <hot range>`; every
          executed instruction of the hot range is one log line. Each top-level call of the
          function under test is priced instruction by instruction with the Cortex-M4 TRM cycle
          table (ARM DDI 0439B, section 3.3.1 and the FPU table 7-1), giving a LOWER and an UPPER
          bound per call. QEMU is not cycle accurate; it only supplies the path.
  static  The longest path through the function's control-flow graph from the disassembly
          (objdump), every instruction at its UPPER cost, callees included (their own static worst
          path), loops only with an explicit bound. Indirect jumps and unknown callees fail.

Bounds (zero wait states, no interrupt entry, no lazy FPU stacking, code and data in zero-wait
memory):
  lower  taken branch refill P = 1; single loads/stores pipeline per the TRM (an access right after
         an LDR, whose address does not depend on it, costs 1); IT-block instructions that may have
         been skipped cost 1; SDIV/UDIV 2.
  upper  P = 3 on every taken branch, call and return; no load/store pipelining; +1 when a load or
         store uses an address register written by the previous instruction (AGU); +1 for LDR
         literal (fetch contention); +1 when an FPU instruction uses the result of the previous FPU
         instruction (result latency, GCC's cortex-m4-fpu.md); SDIV/UDIV 12; VDIV/VSQRT 14; +1
         for every LDR of a function named by --unaligned-loads (halfword-aligned word access).

Usage:
  cm4cost.py check --elf IMAGE --runner QEMU_SCRIPT [--budget GLOB=CYCLES ...]
                   [--target GLOB=CYCLES ...] [--loop-bound PREFIX=N ...]
                   [--unaligned-loads PREFIX ...] [--json OUT] [--markdown OUT]
    --budget   asserted: the check fails when max(trace upper, static) exceeds it
    --target   reported only: the design budget, shown next to the figures (met / OVER)
    --loop-bound PREFIX=N   every loop of the functions named PREFIX* runs its body at most N times
    --unaligned-loads PREFIX   word loads of PREFIX* functions may be halfword aligned (+1 upper)
    --isr GLOB   the scenario is a whole interrupt: exception entry/exit (+ lazy FPU stacking
                 when its code uses FPU registers) added
    --flash-data GLOB=CYCLES   wait states of its table reads from flash, added (upper, static)
    --also-static GLOB=ELF:SYMBOL   price SYMBOL in another image too; the larger static counts
    --trace-only GLOB   no static bound for the scenario (code with virtual calls, e.g. the main
                 loop): its figure is the traced worst call's upper bound
  cm4cost.py static --elf IMAGE --function SYMBOL_PREFIX [--loop-bound PREFIX=N]
                    [--unaligned-loads PREFIX ...]
  cm4cost.py selftest
"""

import argparse
import fnmatch
import json
import os
import re
import subprocess
import sys
import tempfile

OBJDUMP = os.environ.get("VOLCOMP_OBJDUMP", "arm-none-eabi-objdump")
NM = os.environ.get("VOLCOMP_NM", "arm-none-eabi-nm")

CONDS = ("eq", "ne", "cs", "hs", "cc", "lo", "mi", "pl", "vs", "vc", "hi", "ls", "ge", "lt", "gt",
         "le", "al")

# Base mnemonics by class. Costs follow the TRM tables; see cost() for the context rules.
ALU = set("""mov mvn add adc sub sbc rsb and orr eor bic orn lsl lsr asr ror rrx cmp cmn tst teq
adr addw subw movw movt uxtb uxth sxtb sxth uxtab uxtah sxtab sxtah ubfx sbfx bfi bfc clz rev rev16 revsh
rbit ssat usat ssat16 usat16 sel qadd qsub qdadd qdsub sadd8 sadd16 ssub8 ssub16 uadd8 uadd16
usub8 usub16 qadd8 qadd16 qsub8 qsub16 uqadd8 uqadd16 uqsub8 uqsub16 shadd8 shadd16 uhadd8 uhadd16
pkhbt pkhtb nop neg cpsid cpsie dmb dsb isb""".split())
MUL = set("""mul mla mls smull umull smlal umlal umaal smmul smmulr smmla smmlar smmls smmlsr
smulbb smulbt smultb smultt smulwb smulwt smlabb smlabt smlatb smlatt smlawb smlawt smlalbb smlalbt
smlaltb smlaltt smuad smuadx smusd smusdx smlad smladx smlsd smlsdx smlald smlaldx smlsld smlsldx
usad8 usada8""".split())
DIV = {"sdiv", "udiv"}
LOAD1 = {"ldr", "ldrb", "ldrh", "ldrsb", "ldrsh", "ldrex", "ldrexb", "ldrexh", "ldrt"}
STORE1 = {"str", "strb", "strh", "strex", "strexb", "strexh"}
LOAD2 = {"ldrd"}
STORE2 = {"strd"}
MULTI_LOAD = {"ldm", "ldmia", "ldmfd", "ldmdb", "pop"}
MULTI_STORE = {"stm", "stmia", "stmea", "stmdb", "stmfd", "push"}
BRANCH = {"b"}
CBZ = {"cbz", "cbnz"}
CALL = {"bl", "blx"}
BX = {"bx"}
TB = {"tbb", "tbh"}
IT = {"it"}
FP1 = {"vadd", "vsub", "vmul", "vnmul", "vabs", "vneg", "vcmp", "vcmpe", "vcvt", "vcvtr", "vmov",
       "vmrs", "vmsr"}
FP3 = {"vmla", "vmls", "vnmla", "vnmls", "vfma", "vfms", "vfnma", "vfnms"}
FP14 = {"vdiv", "vsqrt"}
FPLOAD = {"vldr"}
FPSTORE = {"vstr"}
FPMULTI = {"vldm", "vldmia", "vldmdb", "vstm", "vstmia", "vstmdb", "vpush", "vpop"}
KNOWN = (ALU | MUL | DIV | LOAD1 | STORE1 | LOAD2 | STORE2 | MULTI_LOAD | MULTI_STORE | BRANCH | CBZ
         | CALL | BX | TB | IT | FP1 | FP3 | FP14 | FPLOAD | FPSTORE | FPMULTI | {"bkpt", "udf"})

REG_NAMES = {"sb": "r9", "sl": "r10", "fp": "r11", "ip": "r12"}


def norm_reg(r):
    r = r.strip().lower().rstrip("!")
    return REG_NAMES.get(r, r)


def split_mnemonic(raw):
    """'addeq.w' -> ('add', 'eq', flags_set); 'vmul.f32' -> ('vmul', None, False)."""
    m = raw.lower().split(".")[0]
    if re.fullmatch(r"it[te]{0,3}", m):
        return "it", None, False
    if m in KNOWN:
        return m, None, False
    for c in CONDS:
        if m.endswith(c):
            base = m[:-len(c)]
            if base in KNOWN:
                return base, c, False
            if base.endswith("s") and base[:-1] in KNOWN:
                return base[:-1], c, True
    if m.endswith("s") and m[:-1] in KNOWN:
        return m[:-1], None, True
    return m, None, False


def reg_list(text):
    """'{r4, r5, r6, lr}' or '{s16-s31}' -> list of registers (d registers count as two s)."""
    m = re.search(r"\{([^}]*)\}", text)
    if not m:
        return []
    regs = []
    for part in m.group(1).split(","):
        part = part.strip()
        if "-" in part:
            a, b = part.split("-")
            a, b = norm_reg(a), norm_reg(b)
            kind = a[0]
            for i in range(int(a[1:]), int(b[1:]) + 1):
                regs.append("%s%d" % (kind, i))
        elif part:
            regs.append(norm_reg(part))
    return regs


def expand_fp(r):
    """d-registers alias two s-registers; return the s-register set of a name."""
    if r.startswith("d") and r[1:].isdigit():
        n = int(r[1:])
        return {"s%d" % (2 * n), "s%d" % (2 * n + 1)}
    return {r}


class Insn:
    __slots__ = ("addr", "size", "raw", "mn", "cond", "ops", "target", "dst", "src", "addr_regs",
                 "nregs", "func", "literal", "unaligned")

    def __init__(self, addr, size, raw, ops, func):
        self.addr, self.size, self.raw, self.func = addr, size, raw, func
        self.mn, self.cond, _ = split_mnemonic(raw)
        self.ops = ops
        self.target = None
        self.literal = False
        self.unaligned = False
        m = re.match(r"\s*([0-9a-f]+)\s*<", ops)
        if m and (self.mn in BRANCH | CALL | CBZ):
            self.target = int(m.group(1), 16)
        if self.mn in CBZ:
            m = re.search(r",\s*([0-9a-f]+)\s*<", ops)
            if m:
                self.target = int(m.group(1), 16)
        self._operands()

    def _operands(self):
        ops = self.ops.split("@")[0].split(";")[0]
        toks = [norm_reg(t) for t in re.findall(r"\b(?:r1[0-5]|r[0-9]|sb|sl|fp|ip|sp|lr|pc|[sd][0-9]+)\b",
                                                ops)]
        mem = re.search(r"\[([^\]]*)\]", ops)
        self.addr_regs = set()
        if mem:
            self.addr_regs = {norm_reg(t) for t in re.findall(
                r"\b(?:r1[0-5]|r[0-9]|sb|sl|fp|ip|sp|lr|pc)\b", mem.group(1))}
            self.literal = "pc" in self.addr_regs
        mn = self.mn
        self.nregs = 0
        dst, src = set(), set()
        if mn in MULTI_LOAD | MULTI_STORE | FPMULTI:
            regs = reg_list(ops)
            nregs = 0
            for r in regs:
                nregs += 2 if (r.startswith("d") and mn in FPMULTI) else 1
            self.nregs = nregs
            base = "sp" if mn in ("push", "pop", "vpush", "vpop") else (toks[0] if toks else "sp")
            self.addr_regs = {base}
            if mn in MULTI_LOAD or mn in ("vldm", "vldmia", "vldmdb", "vpop"):
                for r in regs:
                    dst |= expand_fp(r)
            else:
                for r in regs:
                    src |= expand_fp(r)
            if "!" in ops or mn in ("push", "pop", "vpush", "vpop"):
                dst.add(base)
        elif mn in ("cmp", "cmn", "tst", "teq", "vcmp", "vcmpe", "it", "b", "bx", "cbz", "cbnz",
                    "tbb", "tbh", "bl", "blx", "vmsr"):
            for t in toks:
                src |= expand_fp(t)
            if mn in ("bl", "blx"):
                dst |= {"r0", "r1", "r2", "r3", "r12", "lr"}
        elif mn in STORE1 | STORE2 | FPSTORE:
            for t in toks:
                src |= expand_fp(t)
            if "!" in ops or re.search(r"\],", ops):
                dst |= set(list(self.addr_regs)[:1])
        elif mn in ("smull", "umull", "smlal", "umlal", "umaal", "smlald", "smlaldx", "smlsld",
                    "smlsldx", "smlalbb", "smlalbt", "smlaltb", "smlaltt", "ldrd") or (
                        mn == "vmov" and len(toks) == 4):
            dst |= set(toks[:2])
            for t in toks[2:]:
                src |= expand_fp(t)
            if mn in ("smlal", "umlal", "umaal") or mn.startswith("smlal"):
                src |= set(toks[:2])
        else:
            if toks:
                dst |= expand_fp(toks[0])
                for t in toks[1:]:
                    src |= expand_fp(t)
            if mn in FP3:
                src |= expand_fp(toks[0]) if toks else set()
        src |= self.addr_regs
        self.dst, self.src = dst, src

    @property
    def is_load(self):
        return self.mn in LOAD1 | FPLOAD

    @property
    def is_store(self):
        return self.mn in STORE1 | FPSTORE

    @property
    def is_fp(self):
        return self.mn.startswith("v") and self.mn not in FPMULTI | FPLOAD | FPSTORE

    def writes_pc(self):
        if self.mn in ("pop", "ldm", "ldmia", "ldmfd") and "pc" in self.dst:
            return True
        if self.mn in ("ldr",) and "pc" in self.dst:
            return True
        if self.mn in ("mov", "add") and self.dst == {"pc"}:
            return True
        return False

    def is_return(self):
        if self.mn == "ldr" and "pc" in self.dst and "sp" not in self.addr_regs:
            return False  # a jump through a loaded address (a linker veneer), not a return
        return (self.mn == "bx" and "lr" in self.src) or self.writes_pc()

    def is_branch(self):
        return self.mn in BRANCH | CBZ | BX | TB or self.writes_pc()

    def __repr__(self):
        return "%x: %s %s" % (self.addr, self.raw, self.ops)


def base_cost(i, bound):
    """Cycles of one executed instruction without the taken-branch refill and context terms."""
    mn = i.mn
    if mn in ALU or mn in MUL or mn in IT or mn in ("bkpt", "udf"):
        return 1
    if mn in DIV:
        return 2 if bound == "lower" else 12
    if mn in LOAD1 | STORE1 | FPLOAD | FPSTORE:
        return 2
    if mn in LOAD2 | STORE2:
        return 3
    if mn in MULTI_LOAD | MULTI_STORE | FPMULTI:
        return 1 + i.nregs
    if mn in BRANCH | CBZ | CALL | BX:
        return 1
    if mn in TB:
        return 2
    if mn in FP1:
        if mn == "vmov" and len(re.findall(r"\b(?:r1[0-5]|r[0-9]|ip|lr|s[0-9]+|d[0-9]+)\b", i.ops)) == 4:
            return 2
        return 1
    if mn in FP3:
        return 3
    if mn in FP14:
        return 14
    raise ValueError("no cost for instruction %r" % (i,))


def refill(bound):
    return 1 if bound == "lower" else 3


# Function-name prefixes whose word loads (LDR) may be only halfword aligned (--unaligned-loads):
# the int16 kernels read two or three int16 elements with one LDR and take them apart with
# SMLAWB/SMLAWT. The M4 splits a halfword-aligned word access into two halfword accesses: one
# extra cycle (TRM 3.3.1, unaligned accesses). The trace does not show addresses, so in those
# functions every LDR whose result is the halfword operand of an SMLAWB/SMLAWT further down the
# same straight-line code (before the register is overwritten) is priced that way in the upper
# bound; the lower bound keeps the aligned case. The kernels load each word in the basic block
# that uses it; a use after a branch would not be seen.
UNALIGNED_PREFIXES = []
HALFWORD_USERS = {"smlawb", "smlawt", "smulwb", "smulwt"}


def halfword_operand(j):
    """The register SMLAWx/SMULWx takes a halfword of (Rm: 'smlawb rd, rn, rm, ra')."""
    regs = [norm_reg(t) for t in re.findall(r"\b(?:r1[0-5]|r[0-9]|sb|sl|fp|ip|lr)\b", j.ops)]
    return regs[2] if len(regs) > 2 else None


def mark_unaligned(image):
    for idx, a in enumerate(image.order):
        i = image.insns[a]
        i.unaligned = False
        if not (i.mn == "ldr" and not i.literal and "sp" not in i.addr_regs and i.dst
                and any(i.func.startswith(p) for p in UNALIGNED_PREFIXES)):
            continue
        reg = next(iter(i.dst))
        for b in image.order[idx + 1:]:
            j = image.insns[b]
            if j.func != i.func:
                break
            if j.mn in HALFWORD_USERS and halfword_operand(j) == reg:
                i.unaligned = True
                break
            if reg in j.dst or j.is_branch() or j.mn in CALL or j.is_return():
                break


def may_be_unaligned(i):
    return getattr(i, "unaligned", False)


def cost(i, prev, bound, taken, in_it):
    """Cost of `i` executed after `prev` (None at a path start); `taken`: control left sequentially."""
    c = base_cost(i, bound)
    if bound == "upper" and may_be_unaligned(i):
        c += 1
    if in_it and not i.is_branch() and bound == "lower":
        c = 1  # the condition may have failed: a skipped instruction takes one cycle
    if (i.is_load or i.is_store) and prev is not None:
        if bound == "lower":
            if prev.is_load and not (i.addr_regs & prev.dst):
                c = 1  # pipelined after a load (TRM 3.3.2)
        else:
            if i.addr_regs & prev.dst:
                c += 1  # address generation waits for the previous result
            if i.literal:
                c += 1
    if bound == "upper" and prev is not None and i.is_fp and prev.is_fp and (i.src & prev.dst):
        c += 1
    if taken:
        c += refill(bound)
    return c


class Image:
    def __init__(self, elf):
        self.elf = elf
        self.insns = {}
        self.order = []
        self.symbols = {}
        self._disassemble()
        # Function entry address -> name (tail-call targets).
        self.entries = {}
        for name, addr in self.symbols.items():
            if addr in self.insns and self.insns[addr].func == name:
                self.entries.setdefault(addr, name)

    def _disassemble(self):
        out = subprocess.run([OBJDUMP, "-d", "-w", elf_arg(self.elf)], check=True,
                             capture_output=True, text=True).stdout
        func = None
        for line in out.splitlines():
            m = re.match(r"^([0-9a-f]{8}) <([^>]+)>:", line)
            if m:
                func = m.group(2)
                self.symbols.setdefault(func, int(m.group(1), 16))
                continue
            m = re.match(r"^\s*([0-9a-f]+):\s+((?:[0-9a-f]{4}\s)+)\s*(\S+)\s*(.*)$", line)
            if not m or func is None:
                continue
            addr = int(m.group(1), 16)
            hexes = m.group(2).split()
            raw = m.group(3)
            if raw.startswith("."):
                continue  # literal pool data
            size = 2 * len(hexes)
            insn = Insn(addr, size, raw, m.group(4), func)
            self.insns[addr] = insn
            self.order.append(addr)
        mark_unaligned(self)

    def symbol(self, prefix):
        hits = sorted(s for s in self.symbols if s.startswith(prefix))
        if len(hits) != 1:
            raise SystemExit("cm4cost: symbol prefix %r matches %s" % (prefix, hits or "nothing"))
        return hits[0], self.symbols[hits[0]]

    def range_of(self, name):
        out = subprocess.run([NM, elf_arg(self.elf)], check=True, capture_output=True,
                             text=True).stdout
        syms = {}
        for line in out.splitlines():
            p = line.split()
            if len(p) == 3:
                syms[p[2]] = int(p[0], 16)
        return syms[name + "_start"], syms[name + "_end"]


def elf_arg(p):
    return p


# ---- trace mode -----------------------------------------------------------------------------


def read_trace(path):
    pcs = []
    pat = re.compile(r"\[[0-9a-f]+/([0-9a-f]+)/")
    with open(path) as f:
        for line in f:
            m = pat.search(line)
            if m:
                pcs.append(int(m.group(1), 16))
    return pcs


def it_slots(insn):
    """Number of instructions an IT instruction covers ('itte' -> 3)."""
    return len(insn.raw) - 1 if insn.mn == "it" else 0


def price_path(image, pcs, bound):
    total, prev, it_left = 0, None, 0
    for k, pc in enumerate(pcs):
        i = image.insns.get(pc)
        if i is None:
            raise SystemExit("cm4cost: traced pc 0x%x is not an instruction of the image" % pc)
        nxt = pcs[k + 1] if k + 1 < len(pcs) else None
        taken = nxt is not None and nxt != pc + i.size
        if i.mn in CALL or i.is_return():
            taken = True
        total += cost(i, prev, bound, taken, it_left > 0)
        it_left = it_slots(i) if i.mn == "it" else max(0, it_left - 1)
        prev = None if taken else i
    return total


def split_calls(image, pcs, entry):
    """Top-level calls of the function at `entry` in an instruction stream (lists of pcs)."""
    calls, k, n = [], 0, len(pcs)
    while k < n:
        if pcs[k] != entry:
            k += 1
            continue
        depth, j = 0, k
        while j < n:
            i = image.insns[pcs[j]]
            # A call: to its target, or (BLX register: a virtual call) anywhere but the next
            # instruction.
            if i.mn in CALL and j + 1 < n and (
                    pcs[j + 1] == i.target
                    or (i.target is None and pcs[j + 1] != i.addr + i.size)):
                depth += 1
            elif i.is_return() and not (j + 1 < n and pcs[j + 1] == i.addr + i.size):
                if depth == 0:
                    break
                depth -= 1
            j += 1
        calls.append(pcs[k:j + 1])
        k = j + 1
    return calls


def check_closed(image, path, lo, hi):
    """Every call inside the measured path must land in the traced range."""
    for k, pc in enumerate(path):
        i = image.insns[pc]
        if i.mn in CALL and i.target is not None and not (lo <= i.target < hi):
            raise SystemExit("cm4cost: %s calls 0x%x outside the traced hot range: not modelled"
                             % (i.func, i.target))


# ---- static mode ----------------------------------------------------------------------------


class StaticAnalyzer:
    def __init__(self, image, loop_bounds, default_bound=None):
        self.image = image
        self.loop_bounds = loop_bounds
        self.default_bound = default_bound
        self.memo = {}

    def bound_for(self, func):
        for prefix, n in self.loop_bounds:
            if func.startswith(prefix):
                return n
        return self.default_bound

    def uses_fpu(self, func, seen=None):
        """True when `func` or anything it calls executes an FPU instruction (VFP register use)."""
        seen = set() if seen is None else seen
        if func in seen:
            return False
        seen.add(func)
        for a in self.function_insns(func):
            i = self.image.insns[a]
            if i.mn.startswith("v"):
                return True
            callee_entry = i.target if (i.mn in CALL or (i.mn in BRANCH and i.target in
                                                          self.image.entries)) else None
            if callee_entry is not None and callee_entry in self.image.insns:
                callee = self.image.insns[callee_entry].func
                if callee != func and self.uses_fpu(callee, seen):
                    return True
        return False

    def function_insns(self, func):
        return [a for a in self.image.order if self.image.insns[a].func == func]

    def worst(self, func, stack=()):
        if func in self.memo:
            return self.memo[func]
        if func in stack:
            raise SystemExit("cm4cost: recursion through %s" % func)
        addrs = self.function_insns(func)
        if not addrs:
            raise SystemExit("cm4cost: no code for %s" % func)
        if func.endswith("_veneer"):
            raise SystemExit("cm4cost: %s calls %s: a linker veneer to code outside the hot "
                             "range (toolchain/hot-sections.ld)" % (stack[-1] if stack else "?",
                                                                   func))
        insns = self.image.insns
        addrset = set(addrs)
        entry = self.image.symbols[func]
        # Successors with edge kinds: (target, taken)
        succ = {}
        tail = {}
        it_left = 0
        inside_it = {}
        for a in addrs:
            i = insns[a]
            inside_it[a] = it_left > 0
            it_left = it_slots(i) if i.mn == "it" else max(0, it_left - 1)
        for idx, a in enumerate(addrs):
            i = insns[a]
            nxt = addrs[idx + 1] if idx + 1 < len(addrs) else None
            s = []
            if i.is_return():
                if i.cond is not None or inside_it[a]:
                    s.append((nxt, False))
            elif i.mn in BRANCH | CBZ:
                if i.target is None:
                    raise SystemExit("cm4cost: indirect branch in %s: %r" % (func, i))
                if i.target in addrset:
                    s.append((i.target, True))
                elif i.target in self.image.entries:
                    # Tail call: the callee returns to this function's caller. Priced as a call
                    # whose return ends this path (the callee's worst path is added below).
                    tail[a] = self.image.entries[i.target]
                else:
                    raise SystemExit("cm4cost: %s branches out of the function into %x, which "
                                     "is no function entry, at %r" % (func, i.target, i))
                conditional = i.cond is not None or i.mn in CBZ or inside_it[a]
                if conditional and nxt is not None:
                    s.append((nxt, False))
            elif i.mn in BX or i.mn in TB or i.writes_pc():
                raise SystemExit("cm4cost: indirect jump in %s: %r" % (func, i))
            else:
                if nxt is not None:
                    s.append((nxt, False))
            succ[a] = s
        # Call costs (callee worst path + the call's refill are added at the call site).
        extra = {}
        for a in addrs:
            i = insns[a]
            if i.mn in CALL:
                if i.target is None or i.mn == "blx" and "<" not in i.ops:
                    raise SystemExit("cm4cost: indirect call in %s: %r" % (func, i))
                callee = insns[i.target].func if i.target in insns else None
                if callee is None:
                    raise SystemExit("cm4cost: call to unknown code from %s" % func)
                extra[a] = self.worst(callee, stack + (func,))
        for a, callee in tail.items():
            extra[a] = self.worst(callee, stack + (func,))

        def node_cost(a, prev_a, taken_in):
            i = insns[a]
            prev = insns[prev_a] if prev_a is not None and not taken_in else None
            taken = i.mn in CALL or i.is_return() or a in tail
            return cost(i, prev, "upper", taken, inside_it[a]) + extra.get(a, 0)

        # Each node's cost depends on its predecessor (pipelining/AGU/FP terms); take the maximum
        # over possible predecessors, which keeps the bound sound.
        preds = {a: [] for a in addrs}
        for a in addrs:
            for t, taken in succ[a]:
                preds[t].append((a, taken))
        ncost = {}
        for a in addrs:
            cands = [node_cost(a, None, True)] if a == entry else []
            for p, taken in preds[a]:
                cands.append(node_cost(a, p, taken))
            if not cands:
                cands = [node_cost(a, None, True)]
            ncost[a] = max(cands)
        ecost = {}
        for a in addrs:
            for t, taken in succ[a]:
                ecost[(a, t)] = refill("upper") if taken else 0
        result = self._longest(func, entry, addrs, succ, ncost, ecost)
        self.memo[func] = result
        return result

    def _longest(self, func, entry, addrs, succ, ncost, ecost):
        """Longest path with loops collapsed innermost first (each loop: bound x iteration)."""
        nodes = set(addrs)
        succ = {a: [t for t, _ in succ[a]] for a in addrs}
        ncost = dict(ncost)
        ecost = dict(ecost)
        while True:
            back = self._back_edges(entry, nodes, succ)
            if not back:
                break
            n = self.bound_for(func)
            if n is None:
                raise SystemExit("cm4cost: %s has a loop (back edge %x->%x) and no --loop-bound"
                                 % (func, back[0][0], back[0][1]))
            # Innermost loop: the smallest natural loop. A header's loop is the union of the
            # natural loops of all its back edges (a loop body with a side path that rejoins at
            # the header has two latches; treating them as two nested loops would count the
            # bound twice over).
            headers = {}
            for u, h in back:
                headers.setdefault(h, []).append(u)
            loops = []
            for h, latches in headers.items():
                body = {h}
                work = list(latches)
                while work:
                    x = work.pop()
                    if x in body:
                        continue
                    body.add(x)
                    work.extend(p for p in nodes if x in succ[p] and p not in body)
                loops.append((len(body), h, body, latches))
            loops.sort(key=lambda t: t[0])
            _, h, body, latches = loops[0]
            body = set(body)
            # One iteration: longest h -> latch -> h inside the body without back edges.
            inner_succ = {a: [t for t in succ[a] if t in body and t != h] for a in body}
            dist = self._dag_longest(h, body, inner_succ, ncost, ecost)
            iter_cost = max(dist[u] + ecost[(u, h)] for u in latches if u in dist)
            exits = [(a, t) for a in body for t in succ[a] if t not in body]
            exit_cost = max((dist[a] + ecost[(a, t)] for a, t in exits if a in dist), default=0)
            # The bound n is the number of times the body runs. A bottom-tested (rotated) loop,
            # whose only exits leave from its latches, passes through the body at most n times:
            # n - 1 back edges and a last pass to the exit. Otherwise (top-tested, or a break in
            # the middle) the back edges run up to n times and a partial pass reaches the exit.
            bottom_tested = all(a in latches for a, _ in exits) and bool(exits)
            loop_cost = (max(n - 1, 0) if bottom_tested else n) * iter_cost + exit_cost
            # Collapse: the header becomes a super node with the loop's exits as successors.
            targets = sorted({t for _, t in exits})
            for a in body:
                if a != h:
                    nodes.discard(a)
                    del succ[a]
            succ[h] = targets
            ncost[h] = loop_cost
            for t in targets:
                ecost[(h, t)] = 0
            for a in nodes:
                succ[a] = [t if t not in body else h for t in succ[a]]
                succ[a] = list(dict.fromkeys(succ[a]))
                for t in succ[a]:
                    ecost.setdefault((a, t), 0)
        dist = self._dag_longest(entry, nodes, succ, ncost, ecost)
        return max(dist.values())

    def _back_edges(self, entry, nodes, succ):
        color, back = {}, []
        stack = [(entry, iter(succ[entry]))]
        color[entry] = 1
        while stack:
            a, it = stack[-1]
            for t in it:
                if t not in nodes:
                    continue
                c = color.get(t, 0)
                if c == 0:
                    color[t] = 1
                    stack.append((t, iter(succ[t])))
                    break
                if c == 1:
                    back.append((a, t))
            else:
                color[a] = 2
                stack.pop()
        return back

    def _dag_longest(self, start, nodes, succ, ncost, ecost):
        order, seen = [], set()
        stack = [(start, iter(succ.get(start, [])))]
        seen.add(start)
        while stack:
            a, it = stack[-1]
            for t in it:
                if t in nodes and t not in seen:
                    seen.add(t)
                    stack.append((t, iter(succ.get(t, []))))
                    break
            else:
                order.append(a)
                stack.pop()
        order.reverse()
        dist = {start: ncost[start]}
        for a in order:
            if a not in dist:
                continue
            for t in succ.get(a, []):
                if t in nodes:
                    d = dist[a] + ecost.get((a, t), 0) + ncost[t]
                    if d > dist.get(t, -1):
                        dist[t] = d
        return dist


# ---- commands -------------------------------------------------------------------------------


def parse_bounds(items):
    out = []
    for it in items or []:
        k, v = it.split("=")
        out.append((k, int(v)))
    return out


def run_bench(args, image):
    lo, hi = image.range_of("__hot")
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "trace.log")
        cmd = [args.runner, args.elf, "-singlestep", "-d", "exec,nochain", "-dfilter",
               "0x%x..0x%x" % (lo, hi - 1), "-D", log]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if proc.returncode != 0:
            sys.stdout.write(proc.stdout)
            sys.stderr.write(proc.stderr)
            raise SystemExit("cm4cost: bench image failed (exit %d)" % proc.returncode)
        pcs = read_trace(log)
    return proc.stdout, pcs, lo, hi


def cmd_check(args):
    UNALIGNED_PREFIXES[:] = args.unaligned_loads or []
    image = Image(args.elf)
    stdout, pcs, lo, hi = run_bench(args, image)
    scenarios = [l.split()[1:3] for l in stdout.splitlines() if l.startswith("SCENARIO ")]
    mark = image.symbols.get("volcomp_bench_mark")
    marks = [k for k, pc in enumerate(pcs) if pc == mark]
    if len(marks) != len(scenarios):
        raise SystemExit("cm4cost: %d scenarios but %d marks in the trace" % (len(scenarios),
                                                                             len(marks)))
    analyzer = StaticAnalyzer(image, parse_bounds(args.loop_bound))
    isr_globs = args.isr or []
    also = []
    for item in args.also_static or []:
        glob, rest = item.split("=", 1)
        elf, sym = rest.rsplit(":", 1)
        also.append((glob, elf, sym))
    notes = []
    flash_data = parse_bounds(args.flash_data)
    budgets = parse_bounds(args.budget)
    targets = parse_bounds(args.target)
    rows, failed = [], False
    for n, (name, prefix) in enumerate(scenarios):
        sym, entry = image.symbol(prefix)
        seg = pcs[marks[n]:(marks[n + 1] if n + 1 < len(marks) else len(pcs))]
        calls = split_calls(image, seg, entry)
        if not calls:
            raise SystemExit("cm4cost: scenario %s: no call of %s traced" % (name, sym))
        for c in calls:
            check_closed(image, c, lo, hi)
        lows = [price_path(image, c, "lower") for c in calls]
        ups = [price_path(image, c, "upper") for c in calls]
        insns = [len(c) for c in calls]
        trace_only = any(fnmatch.fnmatch(name, g) for g in (args.trace_only or []))
        static = None if trace_only else analyzer.worst(sym)
        for glob, elf, other in also:
            if fnmatch.fnmatch(name, glob):
                other_image = Image(elf)
                other_sym, _ = other_image.symbol(other)
                other_an = StaticAnalyzer(other_image, parse_bounds(args.loop_bound))
                other_static = other_an.worst(other_sym)
                notes.append("%s: static worst path of %s in %s: %d cycles (the bench's copy: "
                             "%d); the row takes the larger" % (name, other_sym,
                                                                os.path.basename(elf),
                                                                other_static, static))
                static = max(static, other_static)
        if any(fnmatch.fnmatch(name, g) for g in isr_globs):
            fpu = analyzer.uses_fpu(sym)
            lo_x, up_x = exception_overhead(fpu)
            lows = [x + lo_x for x in lows]
            ups = [x + up_x for x in ups]
            static = None if static is None else static + up_x
            notes.append("%s: a whole interrupt: exception entry %d + exit %d cycles%s (lower "
                         "bound: entry and exit only)" % (
                             name, EXC_ENTRY, EXC_EXIT,
                             (", + lazy FPU stacking %d and unstacking %d (the ISR's code uses "
                              "FPU registers)" % (FPU_LAZY_SAVE, FPU_RESTORE)) if fpu else
                             " (the ISR's code uses no FPU register: no FPU stacking)"))
        for glob, extra_cycles in flash_data:
            if fnmatch.fnmatch(name, glob):
                ups = [x + extra_cycles for x in ups]
                static = None if static is None else static + extra_cycles
                notes.append("%s: + %d cycles for table data read from flash (4 wait states at "
                             "170 MHz on ART data-cache misses; upper and static bounds)"
                             % (name, extra_cycles))
        budget = next((b for g, b in budgets if fnmatch.fnmatch(name, g)), None)
        target = next((b for g, b in targets if fnmatch.fnmatch(name, g)), None)
        worst = max(ups) if static is None else max(max(ups), static)
        ok = budget is None or worst <= budget
        failed |= not ok
        rows.append({
            "scenario": name, "function": sym, "calls": len(calls),
            "insns_min": min(insns), "insns_max": max(insns),
            "lower_min": min(lows), "lower_max": max(lows),
            "upper_min": min(ups), "upper_max": max(ups),
            "static": static, "worst": worst, "budget": budget, "ok": ok, "target": target,
            "target_met": target is None or worst <= target,
        })
    print_table(rows)
    for n in notes:
        print(n)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"assumptions": ASSUMPTIONS, "rows": rows, "notes": notes}, f, indent=1)
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(markdown(rows))
            f.write("".join("\n" + n + "\n" for n in notes))
    missed = [r["scenario"] for r in rows if not r["target_met"]]
    if missed:
        print("cm4cost: design budget NOT met (reported, not asserted): " + ", ".join(missed))
    if failed:
        print("cm4cost: FAILED: a hot path is above its asserted cycle ceiling")
        return 1
    print("cm4cost: all hot paths within their asserted ceilings")
    return 0


# A whole interrupt (--isr): Cortex-M4 exception entry (stacking 8 words, vector fetch) 12 cycles
# and return 10 (TRM r0p1 §5.5.1 latency figures, zero wait states); with an active FP context
# in the interrupted code (CONTROL.FPCA) and lazy stacking (FPCCR.LSPEN, the reset default), an
# ISR that uses FPU registers makes the core stack S0-S15 and FPSCR at its first FP instruction
# (17 words + 1) and restore them at the return (17).
EXC_ENTRY, EXC_EXIT = 12, 10
FPU_LAZY_SAVE, FPU_RESTORE = 18, 17


def exception_overhead(fpu):
    """(lower, upper) cycles of an interrupt's entry and exit around its handler."""
    upper = EXC_ENTRY + EXC_EXIT + ((FPU_LAZY_SAVE + FPU_RESTORE) if fpu else 0)
    return EXC_ENTRY + EXC_EXIT, upper


ASSUMPTIONS = ("Cortex-M4 r0p1 TRM cycle table; zero wait states (code and data); no interrupt "
               "entry/exit (12 cycles each) inside the figure; no lazy FPU stacking; "
               "lower: P=1, TRM load pipelining; upper: P=3, no pipelining, AGU and FP-latency "
               "stalls, SDIV 12; static: longest CFG path at upper costs; GCC 12.2 -O2")


def print_table(rows):
    print("Cortex-M4 cycle model (" + ASSUMPTIONS + ")")
    print(markdown(rows), end="")


def markdown(rows):
    out = ["| scenario | calls | insns | trace lower | trace upper | static worst | asserted "
           "ceiling | design budget |",
           "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        out.append("| %s | %d | %d–%d | %d–%d | %d–%d | %s | %s | %s |" % (
            r["scenario"], r["calls"], r["insns_min"], r["insns_max"], r["lower_min"],
            r["lower_max"], r["upper_min"], r["upper_max"],
            "—" if r["static"] is None else "%d" % r["static"],
            ("≤ %d %s" % (r["budget"], "ok" if r["ok"] else "FAIL"))
            if r["budget"] is not None else "—",
            ("≤ %d %s" % (r["target"], "met" if r["target_met"] else "OVER"))
            if r["target"] is not None else "—"))
    return "\n".join(out) + "\n"


def cmd_static(args):
    UNALIGNED_PREFIXES[:] = args.unaligned_loads or []
    image = Image(args.elf)
    sym, _ = image.symbol(args.function)
    a = StaticAnalyzer(image, parse_bounds(args.loop_bound))
    print("%s: static worst path %d cycles (upper costs)" % (sym, a.worst(sym)))
    return 0


def cmd_selftest(_args):
    # Mnemonic splitting and a few cost rules, independent of any image.
    assert split_mnemonic("addeq.w") == ("add", "eq", False)
    assert split_mnemonic("bls") == ("b", "ls", False)
    assert split_mnemonic("mls") == ("mls", None, False)
    assert split_mnemonic("movs") == ("mov", None, True)
    assert split_mnemonic("vmul.f32") == ("vmul", None, False)
    assert split_mnemonic("smlal") == ("smlal", None, False)
    ld1 = Insn(0, 2, "ldr", "r3, [r0, #4]", "f")
    ld2 = Insn(2, 2, "ldr", "r4, [r0, #8]", "f")
    ld3 = Insn(4, 2, "ldr", "r5, [r4, #0]", "f")
    assert cost(ld2, ld1, "lower", False, False) == 1
    assert cost(ld3, ld2, "lower", False, False) == 2
    assert cost(ld3, ld2, "upper", False, False) == 3
    pop = Insn(6, 4, "ldmia.w", "sp!, {r4, r5, r6, pc}", "f")
    assert pop.writes_pc() and pop.is_return()
    assert cost(pop, None, "upper", True, False) == 1 + 4 + 3
    smlal = Insn(8, 4, "smlal", "r0, r1, r2, r3", "f")
    assert smlal.dst == {"r0", "r1"} and {"r0", "r1", "r2", "r3"} <= smlal.src
    assert split_mnemonic("itte") == ("it", None, False)
    # Halfword-aligned word loads (--unaligned-loads): +1 in the upper bound for an LDR whose
    # value feeds SMLAWB/SMLAWT in a named function; other loads keep their cost.
    UNALIGNED_PREFIXES[:] = ["k16"]

    class FakeImage:
        pass
    fake = FakeImage()
    code = [Insn(10, 2, "ldr", "r3, [r1, #4]", "k16_row"),      # feeds smlawt: unaligned
            Insn(12, 2, "ldr", "r4, [r0, #8]", "k16_row"),      # a parameter: aligned
            Insn(14, 2, "add", "r4, r4, #1", "k16_row"),
            Insn(16, 4, "smlawt", "r5, r6, r3, r5", "k16_row"),
            Insn(20, 2, "ldrsh", "r7, [r1, #4]", "k16_row"),
            Insn(22, 2, "ldr", "r3, [r1, #4]", "other")]
    fake.order = [c.addr for c in code]
    fake.insns = {c.addr: c for c in code}
    mark_unaligned(fake)
    assert [c.unaligned for c in code] == [True, False, False, False, False, False]
    assert cost(code[0], None, "upper", False, False) == 3
    assert cost(code[0], None, "lower", False, False) == 2
    assert cost(code[1], None, "upper", False, False) == 2
    assert cost(code[4], None, "upper", False, False) == 2
    UNALIGNED_PREFIXES[:] = []
    # Loop bounds: a bottom-tested loop (exit from its latch) passes its body N times, a
    # top-tested one N times plus the test. Synthetic CFGs through _longest():
    an = StaticAnalyzer(None, [("f", 3)])
    # bottom-tested: 0 -> 1 (body, cost 10) -> 1 (back edge) | 2 (exit, cost 1)
    succ = {0: [1], 1: [1, 2], 2: []}
    ncost = {0: 1, 1: 10, 2: 1}
    ecost = {(0, 1): 0, (1, 1): 3, (1, 2): 0}
    assert an._longest("f", 0, [0, 1, 2], {a: [(t, False) for t in v] for a, v in succ.items()},
                       ncost, ecost) == 1 + 2 * (10 + 3) + 10 + 1
    # top-tested: 0 -> 1 (test, 1) -> 2 (body, 10) -> 1 | 1 -> 3 (exit, 1)
    succ = {0: [1], 1: [2, 3], 2: [1], 3: []}
    ncost = {0: 1, 1: 1, 2: 10, 3: 1}
    ecost = {(0, 1): 0, (1, 2): 0, (2, 1): 3, (1, 3): 0}
    assert an._longest("f", 0, [0, 1, 2, 3], {a: [(t, False) for t in v] for a, v in succ.items()},
                       ncost, ecost) == 1 + 3 * (1 + 10 + 3) + 1 + 1
    # Call splitting: a virtual call (BLX register) nests like a direct one, so its callee's
    # return does not end the outer call. f: push, blx r3 -> g: bx lr; f: pop {pc}.
    f0 = Insn(100, 2, "push", "{r4, lr}", "f")
    f1 = Insn(102, 2, "blx", "r3", "f")
    f2 = Insn(104, 2, "pop", "{r4, pc}", "f")
    g0 = Insn(200, 2, "bx", "lr", "g")
    fake = FakeImage()
    fake.insns = {i.addr: i for i in (f0, f1, f2, g0)}
    trace = [100, 102, 200, 104, 100, 102, 200, 104]
    assert f1.target is None and g0.is_return() and f2.is_return()
    assert split_calls(fake, trace, 100) == [[100, 102, 200, 104], [100, 102, 200, 104]]
    print("cm4cost selftest: ok")
    return 0


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("check")
    c.add_argument("--elf", required=True)
    c.add_argument("--runner", required=True)
    c.add_argument("--budget", action="append")
    c.add_argument("--target", action="append")
    c.add_argument("--loop-bound", action="append")
    c.add_argument("--unaligned-loads", action="append")
    c.add_argument("--isr", action="append",
                   help="GLOB: the scenario is a whole interrupt (exception entry/exit added)")
    c.add_argument("--trace-only", action="append",
                   help="GLOB: no static bound for the scenario (virtual calls); traced figure only")
    c.add_argument("--also-static", action="append",
                   help="GLOB=ELF:SYMBOL: also price SYMBOL in ELF statically, keep the larger")
    c.add_argument("--flash-data", action="append",
                   help="GLOB=CYCLES: flash wait states of the scenario's table reads, added to "
                        "the upper and static bounds")
    c.add_argument("--json")
    c.add_argument("--markdown")
    s = sub.add_parser("static")
    s.add_argument("--elf", required=True)
    s.add_argument("--function", required=True)
    s.add_argument("--loop-bound", action="append")
    s.add_argument("--unaligned-loads", action="append")
    sub.add_parser("selftest")
    args = p.parse_args()
    return {"check": cmd_check, "static": cmd_static, "selftest": cmd_selftest}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
