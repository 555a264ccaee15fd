#!/usr/bin/env python3
"""The certificate printed as a customer prints it, checked by other programs than the one that
wrote it.

usage: certificate_print_test.py --volcomp BIN --source-dir DIR [--keep]

1. Before/after results as the user guide makes them: `volcomp program positioning|diagonal`
   templates (axes X, Y, Z and the body diagonals) filled by tests/docs/fill_readings.py (the documentation test's operator; --after: a
   tenth of the deviations), the sample circular test and a copy scaled by 0.1; a table image
   (`volcomp build model`, table id 3).
2. `volcomp report certificate before after -o cert --info samples/certificate_info.ini
   --table table.vct --date 2026-11-28 --json`: stdout and cert/certificate.json must agree.
3. Pass/fail recomputed here from the JSON figures and the tolerances read from the info file
   with Python's configparser (not the tool's parser): figure <= tolerance; none -> no verdict.
4. Headless Chromium prints cert/certificate.html to PDF: pdfinfo must say 1 page of A4
   (595 x 842 pt +- 1); pdftotext -layout must show each figure's row with its before, after,
   tolerance (or —) and both verdicts as recomputed, the info file's fields, the table id and
   CRC-32 (`volcomp inspect --json`), the date and the version `volcomp --version` prints.
5. A screenshot (PNG, decoded here with zlib) must not be blank.

Exit 0 when every check holds; 1 with the failed checks otherwise (also when chromium or
poppler-utils is missing: scripts/setup-deps.sh report).
"""

import argparse
import configparser
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

A4_PT = (595.28, 841.89)
AXES = (("X", "390"), ("Y", "270"), ("Z", "190"))  # the travel of the user guide's machine
DATE = "2026-11-28"
failures = []


def check(ok, message):
    print(("ok   " if ok else "FAIL ") + message)
    if not ok:
        failures.append(message)


def run(cmd, cwd, **kw):
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=180,
                       **kw)
    if p.returncode != 0:
        sys.exit("`%s` exited %d:\n%s%s" % (" ".join(cmd), p.returncode,
                                              p.stdout.decode(errors="replace"),
                                              p.stderr.decode(errors="replace")))
    return p.stdout.decode("utf-8")


def scaled_circular(src, dst, factor):
    with open(src, encoding="utf-8") as f, open(dst, "w", encoding="utf-8") as out:
        for line in f:
            m = re.match(r"^(cw|ccw),([-0-9.]+),([-0-9.]+)\s*$", line)
            if m:
                line = "%s,%s,%.4f\n" % (m.group(1), m.group(2), factor * float(m.group(3)))
            elif line.startswith("# date:"):
                line = "# date: %s\n" % DATE
            out.write(line)


def tolerances(info_path):
    """{(figure, scope): value} from the info file's [tolerance] section; scope '' = all."""
    cp = configparser.ConfigParser(inline_comment_prefixes=("#", ";"), comment_prefixes=("#", ";"))
    cp.optionxform = str
    cp.read(info_path, encoding="utf-8")
    out = {}
    for key, value in cp.items("tolerance"):
        parts = key.split(".")
        figure = ".".join(parts[:2])
        scope = ".".join(parts[2:])
        out[(figure, scope)] = float(value)
    return cp, out


def expected_verdict(value, tolerance):
    return None if tolerance is None else ("pass" if value <= tolerance else "fail")


def png_ink(path):
    """(width, height, pixels that are not near-white) of an 8-bit RGB/RGBA PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace != 0:
        raise ValueError("PNG kind %r not handled" % (header,))
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * bpp
    prev = bytearray(stride)
    ink = 0
    i = 0
    for _ in range(height):
        ftype = raw[i]
        line = bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if ftype == 1:
                line[x] = (line[x] + a) & 255
            elif ftype == 2:
                line[x] = (line[x] + b) & 255
            elif ftype == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif ftype == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        for x in range(0, stride, bpp):
            if min(line[x], line[x + 1], line[x + 2]) < 200:
                ink += 1
        prev = line
    return width, height, ink


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--volcomp", required=True)
    ap.add_argument("--source-dir", required=True)
    ap.add_argument("--keep", action="store_true")
    a = ap.parse_args()
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    missing = [n for n, p in (("chromium", chromium), ("pdfinfo", shutil.which("pdfinfo")),
                              ("pdftotext", shutil.which("pdftotext"))) if not p]
    if missing:
        print("FAIL %s not installed: run scripts/setup-deps.sh report" % ", ".join(missing))
        return 1
    volcomp = os.path.abspath(a.volcomp)
    src = os.path.abspath(a.source_dir)
    fill = os.path.join(src, "tests", "docs", "fill_readings.py")
    info = os.path.join(src, "samples", "certificate_info.ini")
    work = tempfile.mkdtemp(prefix="volcomp_certificate_")
    try:
        # 1. before/after results and a table image
        for axis, end in AXES:
            run([volcomp, "program", "positioning", "--axis", axis, "--start", "10", "--end", end,
                 "--pitch", "5", "--count", "11", "--seed", "1", "--runs", "5", "--cycle",
                 "linear", "-o", axis + ".ngc", "--targets-csv", axis + "_before.csv"], work)
        run([volcomp, "program", "diagonal", "--box", "10,10,10:390,270,190", "--increment-mm",
             "50", "--runs", "5", "-o", "diag.ngc", "--targets-csv", "diag_before.csv"], work)
        for stem in [axis for axis, _ in AXES] + ["diag"]:
            shutil.copy(os.path.join(work, stem + "_before.csv"),
                        os.path.join(work, stem + "_after.csv"))
            run([sys.executable, fill, stem + "_before.csv"], work)
            run([sys.executable, fill, stem + "_after.csv", "--after"], work)
        os.makedirs(os.path.join(work, "circ_after"))
        shutil.copy(os.path.join(src, "samples", "metrology", "circular_xy.csv"),
                    os.path.join(work, "circular_xy.csv"))
        scaled_circular(os.path.join(src, "samples", "metrology", "circular_xy.csv"),
                        os.path.join(work, "circ_after", "circular_xy.csv"), 0.1)
        for when, circular in (("before", "circular_xy.csv"),
                               ("after", "circ_after/circular_xy.csv")):
            for axis, _ in AXES:
                run([volcomp, "evaluate", "positioning", "%s_%s.csv" % (axis, when), "--standard",
                     "both", "--report", when], work)
            # The diagonals state their instrument: their figures carry U (the page's column).
            run([volcomp, "evaluate", "diagonal", "diag_%s.csv" % when, "--report", when,
                 "--instrument-u-um", "0.5"], work)
            run([volcomp, "evaluate", "circular", circular, "--report", when], work)
        run([volcomp, "build", "model", "--model",
             os.path.join(src, "samples", "model", "s500.conf"), "--resolution-nm",
             "X=1000,Y=1000,Z=1000", "--spacing-mm", "20", "--table-id", "3", "-o", "table.vct"],
            work)
        image = json.loads(run([volcomp, "inspect", "table.vct", "--json"], work))
        version = run([volcomp, "--version"], work).split()[1]

        # 2. the certificate, stdout and file
        out = run([volcomp, "report", "certificate", "before", "after", "-o", "cert", "--info",
                   info, "--table", "table.vct", "--date", DATE, "--json"], work)
        doc = json.loads(out)
        with open(os.path.join(work, "cert", "certificate.json"), encoding="utf-8") as f:
            check(json.load(f) == doc, "cert/certificate.json is what --json printed")
        figures = doc["figures"]
        check(any((f.get("uncertainty") or {}).get("after") is not None for f in figures),
              "the diagonals' figures carry their U")
        check(len(figures) == 3 * 8 + 2 + 4,
              "30 figures (ISO 230-2 and GOST 27843 of X, Y, Z; ISO 230-6; ISO 230-4): %d" %
              len(figures))
        check(doc["date"] == DATE and doc["tool_version"] == version,
              "date %s and version %s in the JSON" % (DATE, version))
        check(doc["table"]["table_id"] == image["table_id"] == 3 and
              doc["table"]["crc32"] == image["crc32"],
              "table id and CRC-32 as `inspect` reads them (%s)" % image["crc32"])

        # 3. pass/fail recomputed from the figures and the info file
        cp, tol = tolerances(info)
        fails_after = 0
        toleranced = 0
        for f in figures:
            t = tol.get((f["id"], f["scope"]), tol.get((f["id"], "")))
            f["_tol"] = t
            for when in ("before", "after"):
                want = expected_verdict(f[when], t)
                f["_" + when] = want
                check(f[when + "_result"] == want and f["tolerance"] == t,
                      "%s %s %s: %s %.2f, tolerance %s -> %s" % (
                          f["test"], f["id"], f["scope"], when, f[when], t, want))
            toleranced += t is not None
            fails_after += f["_after"] == "fail"
        check(doc["toleranced"] == toleranced and doc["failed_after"] == fails_after and
              doc["verdict"] == ("pass" if fails_after == 0 else "fail"),
              "verdict %s: %d of %d toleranced figures fail after" % (
                  doc["verdict"], fails_after, toleranced))

        # 4. printed by Chromium
        home = os.path.join(work, "home")
        os.makedirs(home)
        pdf = os.path.join(work, "certificate.pdf")
        png = os.path.join(work, "certificate.png")
        url = "file://" + os.path.join(work, "cert", "certificate.html")
        base = [chromium, "--headless", "--no-sandbox", "--disable-gpu",
                "--user-data-dir=" + os.path.join(work, "chromium-profile"),
                "--no-first-run", "--no-pdf-header-footer", "--print-to-pdf-no-header"]
        env = dict(os.environ, HOME=home)
        run(base + ["--print-to-pdf=" + pdf, url], work, env=env)
        run(base + ["--window-size=900,1300", "--screenshot=" + png, url], work, env=env)
        meta = run(["pdfinfo", pdf], work)
        pages = int(re.search(r"^Pages:\s+(\d+)", meta, re.M).group(1))
        size = re.search(r"^Page size:\s+([\d.]+) x ([\d.]+) pts", meta, re.M)
        w, h = float(size.group(1)), float(size.group(2))
        print("pdfinfo: %d page(s), %.2f x %.2f pt" % (pages, w, h))
        check(pages == 1, "the certificate prints on 1 page: %d" % pages)
        check(abs(w - A4_PT[0]) <= 1.0 and abs(h - A4_PT[1]) <= 1.0,
              "page size A4 (595 x 842 pt): %.2f x %.2f" % (w, h))
        text = run(["pdftotext", "-layout", pdf, "-"], work)
        lines = text.split("\n")

        def cell(v):
            return "—" if v is None else "%g" % v

        # Each figure must have its own row (a row matches one figure only).
        rows = list(lines)
        for f in figures:
            standard = f["standard"].split(":")[0].replace("GOST 27843-88", "GOST 27843")
            label = "%s %s" % (standard, f["symbol"])
            u = f.get("uncertainty") or {}
            if u.get("after") is not None:
                u_cell = "± %.2f" % u["after"]
            elif u.get("before") is not None:
                u_cell = "± %.2f (before)" % u["before"]
            else:
                u_cell = "not stated"
            want = ["%.2f" % f["before"], "%.2f" % f["after"], cell(f["_tol"]),
                    f["_before"] or "—", f["_after"] or "—", u_cell]
            pattern = re.compile(r"(^|\s)" + re.escape(label) + r"\s.*?" +
                                 r"\s+".join(re.escape(x) for x in want))
            match = next((i for i, l in enumerate(rows) if pattern.search(l)), None)
            if match is not None:
                del rows[match]
            check(match is not None, "PDF row of %s %s: '%s' %s" % (
                f["test"], f["scope"], label, " ".join(want)))
        for axis, _ in AXES:
            check("Positioning accuracy, %s axis" % axis in text, "title of the %s axis" % axis)
        for section in ("customer", "machine"):
            for key, value in cp.items(section):
                if value:
                    check(value in text, "PDF shows %s.%s '%s'" % (section, key, value))
        check(str(image["table_id"]) in text and image["crc32"] in text,
              "PDF shows table id %d and CRC-32 %s" % (image["table_id"], image["crc32"]))
        check(DATE in text and ("volcomp " + version) in text, "PDF shows the date and version")
        check("feed mm per min: 1000" in text and "dwell s: 2" in text and
              "ballbar 100 mm" in text and "laser interferometer" in text,
              "PDF shows the instruments and the programs' feed and dwell")
        check("operator: N. N." in text and "operator: QA" in text, "PDF shows the operators")
        check(len(re.findall(r"\bsignature\b", text)) == 2, "two signature lines")
        check(".csv" not in text, "titles say what was tested, not file names")

        # 5. the screenshot
        width, height, ink = png_ink(png)
        share = ink / float(width * height)
        print("screenshot: %d x %d, %.1f %% of the pixels not white" % (width, height, 100 * share))
        check(0.01 < share < 0.5, "screenshot is neither blank nor filled: %.1f %%" % (100 * share))
    finally:
        if a.keep:
            print("kept", work)
        else:
            shutil.rmtree(work, ignore_errors=True)
    print("%d check(s) failed" % len(failures) if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
