#!/usr/bin/env python3
"""Runs the `volcomp` commands printed in a Markdown document, in order, as a test.

usage: run_doc_commands.py --volcomp BIN --volcomp-sim BIN --source-dir DIR DOC.md [--keep]

Every ```sh block of DOC.md is read; a logical line (continuation lines ending in `\\` joined)
whose command starts with `volcomp` or `build/host/tools/volcomp`, or pipes into it, is run with
bash in a scratch directory that holds a copy of samples/, with `volcomp` on PATH and $CAN naming
a simulated board (`volcomp-sim node` over SLCAN-TCP with its own flash directory) started for
this document. Other lines (export, volcomp-sim, scripts, cmake, cansend) are not run: the
harness provides the board and $CAN itself.

Marks in a command's trailing comment (keep them rare; they are printed in the document):
  [exit N]            the command is expected to exit with N (a refusal the text shows)
  [not run: reason]   the command is shown but not run

Outside code blocks, `<!-- doc-test: COMMAND -->` runs COMMAND at that point (exit 0 expected):
a stand-in for what the reader does by hand, e.g. entering readings into a template
($DOC_TEST_DIR is this script's directory).

Exit status 0 when every command ran with its expected exit code; else 1, with the document's
line, the command, its exit code and the end of its output for each failure.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

VOLCOMP_COMMAND = re.compile(r"(^|\|)\s*(build/host/tools/)?volcomp\s")
FIXTURE = re.compile(r"^\s*<!--\s*doc-test:\s*(.*?)\s*-->\s*$")
EXIT_MARK = re.compile(r"\[exit (\d+)\]")
SKIP_MARK = re.compile(r"\[not run: ([^\]]+)\]")


def split_comment(line):
    """Returns (command, comment): the comment starts at a '#' after white space, outside quotes."""
    quote = None
    for i, c in enumerate(line):
        if quote:
            if c == quote:
                quote = None
        elif c in "'\"":
            quote = c
        elif c == "#" and (i == 0 or line[i - 1] in " \t"):
            return line[:i].rstrip(), line[i + 1:].strip()
    return line.rstrip(), ""


def extract(path):
    """Yields (line_number, kind, command, expected_exit, skip_reason) in document order."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    in_sh = False
    i = 0
    while i < len(lines):
        raw = lines[i]
        number = i + 1
        stripped = raw.strip()
        if stripped.startswith("```"):
            in_sh = not in_sh and stripped[3:].strip() in ("sh", "bash", "shell")
            i += 1
            continue
        if not in_sh:
            m = FIXTURE.match(raw)
            if m:
                yield number, "fixture", m.group(1), 0, None
            i += 1
            continue
        logical = raw
        while logical.rstrip().endswith("\\") and i + 1 < len(lines):
            i += 1
            logical = logical.rstrip()[:-1] + " " + lines[i].strip()
        i += 1
        command, comment = split_comment(logical.strip())
        if not command or not VOLCOMP_COMMAND.search(command):
            continue
        expected = EXIT_MARK.search(comment)
        skip = SKIP_MARK.search(comment)
        yield (number, "command", command, int(expected.group(1)) if expected else 0,
               skip.group(1) if skip else None)


def start_node(sim, work):
    flash = os.path.join(work, "flash")
    os.makedirs(flash, exist_ok=True)
    ready = os.path.join(work, "node.ready")
    log = open(os.path.join(work, "node.log"), "w")
    node = subprocess.Popen([sim, "node", "--slcan-tcp", "0", "--flash-dir", flash,
                             "--ready-file", ready, "--duration", "900"],
                            stdout=log, stderr=subprocess.STDOUT)
    for _ in range(200):
        if os.path.exists(ready) and os.path.getsize(ready) > 0:
            with open(ready) as f:
                return node, f.read().strip()
        if node.poll() is not None:
            break
        time.sleep(0.05)
    node.kill()
    raise SystemExit("the simulated node did not start (see %s)" % log.name)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--volcomp", required=True)
    ap.add_argument("--volcomp-sim", required=True)
    ap.add_argument("--source-dir", required=True)
    ap.add_argument("--keep", action="store_true", help="keep the scratch directory")
    ap.add_argument("doc")
    a = ap.parse_args()

    doc = os.path.join(a.source_dir, a.doc)
    work = tempfile.mkdtemp(prefix="volcomp_doc_")
    scratch = os.path.join(work, "scratch")
    shutil.copytree(os.path.join(a.source_dir, "samples"), os.path.join(scratch, "samples"))
    bindir = os.path.join(work, "bin")
    os.makedirs(bindir)
    os.symlink(os.path.abspath(a.volcomp), os.path.join(bindir, "volcomp"))
    os.symlink(os.path.abspath(a.volcomp_sim), os.path.join(bindir, "volcomp-sim"))
    node, can = start_node(a.volcomp_sim, work)
    env = dict(os.environ, CAN=can, PATH=bindir + os.pathsep + os.environ["PATH"],
               DOC_TEST_DIR=os.path.dirname(os.path.abspath(__file__)))
    print("%s: scratch %s, simulated board at CAN=%s" % (a.doc, scratch, can))

    failures, ran, skipped = [], 0, 0
    try:
        for number, kind, command, expected, skip in extract(doc):
            where = "%s:%d" % (a.doc, number)
            if skip:
                skipped += 1
                print("SKIP %s: %s  [not run: %s]" % (where, command, skip))
                continue
            run = command.replace("build/host/tools/volcomp", os.path.abspath(a.volcomp))
            start = time.time()
            p = subprocess.run(["bash", "-c", "set -o pipefail; " + run], cwd=scratch, env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=600)
            ran += 1
            ok = p.returncode == expected
            print("%s %s (%s, exit %d%s, %.1f s): %s" % (
                "ok  " if ok else "FAIL", where, kind, p.returncode,
                "" if ok else ", expected %d" % expected, time.time() - start, command))
            if not ok:
                out = p.stdout.decode("utf-8", "replace")
                failures.append("%s: `%s` exited %d, expected %d\n%s" % (
                    where, command, p.returncode, expected, "\n".join(out.splitlines()[-15:])))
    finally:
        node.terminate()
        try:
            node.wait(timeout=5)
        except subprocess.TimeoutExpired:
            node.kill()
        if not a.keep:
            shutil.rmtree(work, ignore_errors=True)

    print("%s: %d run, %d not run, %d failed" % (a.doc, ran, skipped, len(failures)))
    for f in failures:
        print("\n" + f)
    if ran == 0:
        print("no volcomp command found in %s" % a.doc)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
