#!/usr/bin/env python3
"""Per-module line and toggle coverage of the RTL from Verilator coverage data (docs/verification.md,
section 6; scripts/coverage.sh runs it).

    scripts/coverage_report.py [--base BASE.dat ...] [--root DIR] [--docs FILE]
                               [--print] [--gaps] [--update-docs | --check] [--write-dat OUT.dat]
                               [--require MODULE,... [--min-line 95] [--min-toggle 90]]
                               COVERAGE.dat [...]

Input: Verilator's coverage data ("# SystemC::Coverage-3", then one line per point,
`C '<key>' <count>`; the key is fields `\\x01name\\x02value`: f file, l line, n column, page
`v_line/<module>`, `v_branch/<module>` or `v_toggle/<module>`, o comment (the block kind, or the
signal and bit of a toggle point), S the lines a block spans, h the instances). Several files are
summed, as `verilator_coverage --write` does.

How points are combined. A coverage point of the source is (kind, module, file, line, column,
comment): the instance (h) is dropped, and the module is the page's name without the parameter
suffix Verilator gives a parameterised copy (`rpu_mul_vec__C3_A19_B12_T2` is `rpu_mul_vec`). So a
point is counted once however many instances, configurations and runs hold it, and it is covered
when any of them covered it (its counts summed are ≥ 1). Line points are the pages v_line and
v_branch (a statement block; each branch of an if or case); toggle points are v_toggle's, one per
bit of every signal of at most 256 bits (Verilator's --coverage-max-width), summed over every
configuration that has that bit.

--base: the counts each model wrote after its first reset (harness/coverage_file.h). A toggle point
is covered only where the end count exceeds the base: --x-initial unique starts each register and
Verilator's shadow copy of it at independent random values, so the first evaluation counts about
half of all bits as toggled. Line points take the end count.

Output: a markdown table (module | line points | line % | toggle points | toggle % | meets 95/90?),
every module of rtl/rpu.f in its order (the modules seen in the data when DIR has no rtl/rpu.f);
percentages are rounded down to 0.1 %, the verdict uses the exact fraction.
  --print        the table on stdout
  --gaps         every uncovered line point (file:line and block kind) and every signal with
                 untoggled bits (file:line name[bits]), by module, on stdout
  --update-docs  writes the table into FILE (default DIR/docs/verification.md) between the lines
                 <!-- coverage-table:begin --> and <!-- coverage-table:end -->
  --check        exit 1 (with a diff) when FILE's table is not the one the data gives
  --write-dat    the data as judged (toggle counts minus the base), for verilator_coverage --annotate
  --require      exit 1 unless each named module has line and toggle points and meets --min-line
                 and --min-toggle
Exit status 0; 1 on a failed --check or --require; 2 on bad usage or unreadable data.
"""

import argparse
import difflib
import math
import os
import re
import sys
from collections import defaultdict
from pathlib import Path

import rtl_files  # scripts/rtl_files.py: the one Python reader of rtl/rpu.f

BEGIN = "<!-- coverage-table:begin -->"
END = "<!-- coverage-table:end -->"
LINE_PAGES = ("v_line", "v_branch")
TOGGLE_PAGES = ("v_toggle",)


class DataError(Exception):
    pass


def parse_key(key):
    """Verilator's point key '\\x01f\\x02file\\x01l\\x0212...' -> {'f': 'file', 'l': '12', ...}."""
    fields = {}
    for part in key.split("\x01"):
        if not part:
            continue
        name, sep, value = part.partition("\x02")
        if not sep:
            raise DataError(f"field without a value: {part!r}")
        fields[name] = value
    return fields


def read_dat(path):
    """{key without the instance field: count}, summed over the file's points."""
    counts = defaultdict(int)
    with open(path, encoding="utf-8", errors="surrogateescape") as f:
        for n, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            # C '<key>' <count>: the key may hold any character but the pair "' ".
            m = re.fullmatch(r"C '(.*)' (\d+)", line, re.S)
            if not m:
                raise DataError(f"{path}:{n}: not a coverage point: {line[:80]!r}")
            fields = parse_key(m.group(1))
            fields.pop("h", None)
            counts[tuple(sorted(fields.items()))] += int(m.group(2))
    return counts


def read_all(paths):
    total = defaultdict(int)
    for p in paths:
        for k, c in read_dat(p).items():
            total[k] += c
    return total


def module_of(page):
    """'v_toggle/rpu_mul_vec__C3_A19' -> ('v_toggle', 'rpu_mul_vec')."""
    kind, _, name = page.partition("/")
    return kind, name.split("__", 1)[0]


def rel_file(f, root):
    if os.path.isabs(f):
        try:
            r = os.path.relpath(f, root)
        except ValueError:
            return f
        return f if r.startswith("..") else r
    return f


def rtl_modules(root):
    """Modules of rtl/rpu.f's source files, in the list's order; None without the list."""
    lst = Path(root) / "rtl" / "rpu.f"
    if not lst.is_file():
        return None
    mods = []
    sources, _ = rtl_files.read_list(lst)
    for line in sources:
        src = lst.parent / line
        for m in re.finditer(r"^\s*module\s+(\w+)", src.read_text(), re.M):
            mods.append(m.group(1))
    return mods


class Point:
    __slots__ = ("kind", "module", "file", "line", "column", "comment", "count")

    def __init__(self, kind, module, file, line, column, comment):
        self.kind, self.module, self.file = kind, module, file
        self.line, self.column, self.comment = line, column, comment
        self.count = 0


def judge(final, base, root):
    """Source points (see the module's doc) with their counts; toggles less the base. Also the
    judged data per original key (for --write-dat)."""
    points = {}
    judged = {}
    for key, count in final.items():
        fields = dict(key)
        page = fields.get("page", "")
        kind, module = module_of(page)
        if kind in TOGGLE_PAGES:
            count = max(0, count - base.get(key, 0))
        judged[key] = count
        if kind not in LINE_PAGES + TOGGLE_PAGES:
            continue
        file = rel_file(fields.get("f", ""), root)
        if not file.startswith("rtl/"):
            continue
        line = int(fields.get("l", "0"))
        column = int(fields.get("n", "0"))
        what = "toggle" if kind in TOGGLE_PAGES else "line"
        ident = (what, module, file, line, column, fields.get("o", ""))
        p = points.get(ident)
        if p is None:
            p = points[ident] = Point(what, module, file, line, column, fields.get("o", ""))
        p.count += count
    return list(points.values()), judged


def pct(covered, total):
    """Rounded down to 0.1 %, so that '95.0 %' always meets 95 %."""
    return "—" if total == 0 else f"{math.floor(1000 * covered / total) / 10:.1f} %"


def summarise(points, modules, min_line, min_toggle):
    per = defaultdict(lambda: {"line": [0, 0], "toggle": [0, 0]})
    for p in points:
        t = per[p.module][p.kind]
        t[0] += 1
        t[1] += p.count > 0
    if modules is None:
        modules = sorted(per)
    else:
        modules = modules + sorted(m for m in per if m not in modules)
    rows = []
    for m in modules:
        (ln, lc), (tn, tc) = per[m]["line"], per[m]["toggle"]
        if ln == 0 and tn == 0:
            verdict = "not measured"
        else:
            ok = ln > 0 and lc * 100 >= min_line * ln and tn > 0 and tc * 100 >= min_toggle * tn
            verdict = "yes" if ok else "no"
        rows.append((m, ln, lc, tn, tc, verdict))
    return rows


def table(rows, min_line, min_toggle):
    out = [f"| module | line points | line % | toggle points | toggle % | meets {min_line:g}/{min_toggle:g}? |",
           "|---|---|---|---|---|---|"]
    for m, ln, lc, tn, tc, verdict in rows:
        out.append(f"| `{m}` | {ln:,} | {pct(lc, ln)} | {tn:,} | {pct(tc, tn)} | {verdict} |")
    ln = sum(r[1] for r in rows)
    lc = sum(r[2] for r in rows)
    tn = sum(r[3] for r in rows)
    tc = sum(r[4] for r in rows)
    out.append(f"| **all** | {ln:,} | {pct(lc, ln)} | {tn:,} | {pct(tc, tn)} | |")
    return "\n".join(out) + "\n"


def bit_ranges(bits):
    """[0, 1, 2, 5] -> '5,2:0' (Verilog order, high first)."""
    bits = sorted(set(bits), reverse=True)
    out, start = [], None
    for i, b in enumerate(bits):
        if start is None:
            start = b
        if i + 1 == len(bits) or bits[i + 1] != b - 1:
            out.append(str(start) if start == b else f"{start}:{b}")
            start = None
    return ",".join(out)


def gaps(points):
    """Text: per module, the uncovered line points and the signals with untoggled bits."""
    by_module = defaultdict(lambda: ([], defaultdict(list)))
    for p in points:
        if p.count > 0:
            continue
        lines, toggles = by_module[p.module]
        if p.kind == "line":
            lines.append(p)
        else:
            m = re.fullmatch(r"(.*)\[(\d+)\]", p.comment)
            name, bit = (m.group(1), int(m.group(2))) if m else (p.comment, None)
            toggles[(p.file, p.line, name)].append(bit)
    out = []
    for module in sorted(by_module):
        lines, toggles = by_module[module]
        out.append(f"{module}: {len(lines)} line points, "
                   f"{sum(len(b) for b in toggles.values())} toggle points not covered")
        for p in sorted(lines, key=lambda p: (p.file, p.line, p.column)):
            out.append(f"  line   {p.file}:{p.line} ({p.comment})")
        for (file, line, name), bits in sorted(toggles.items()):
            real = [b for b in bits if b is not None]
            out.append(f"  toggle {file}:{line} {name}" + (f"[{bit_ranges(real)}]" if real else ""))
    return "\n".join(out) + ("\n" if out else "")


def write_dat(judged, path):
    with open(path, "w", encoding="utf-8", errors="surrogateescape") as f:
        f.write("# SystemC::Coverage-3\n")
        for key, count in sorted(judged.items()):
            f.write("C '" + "".join(f"\x01{k}\x02{v}" for k, v in key) + f"' {count}\n")


def docs_block(text, path):
    b, e = text.find(BEGIN), text.find(END)
    if b < 0 or e < b:
        raise DataError(f"{path}: no '{BEGIN}' ... '{END}' block")
    return b + len(BEGIN), e


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dat", nargs="+", help="coverage data (summed)")
    ap.add_argument("--base", action="append", default=[], help="the base counts (summed)")
    ap.add_argument("--root", default=str(Path(__file__).resolve().parent.parent))
    ap.add_argument("--docs", help="default: ROOT/docs/verification.md")
    ap.add_argument("--print", action="store_true", dest="print_table")
    ap.add_argument("--gaps", action="store_true")
    mode = ap.add_mutually_exclusive_group()
    mode.add_argument("--update-docs", action="store_true")
    mode.add_argument("--check", action="store_true")
    ap.add_argument("--write-dat")
    ap.add_argument("--require", default="")
    ap.add_argument("--min-line", type=float, default=95)
    ap.add_argument("--min-toggle", type=float, default=90)
    a = ap.parse_args()
    root = os.path.abspath(a.root)
    docs = a.docs or os.path.join(root, "docs", "verification.md")
    try:
        final = read_all(a.dat)
        base = read_all(a.base)
        points, judged = judge(final, base, root)
        rows = summarise(points, rtl_modules(root), a.min_line, a.min_toggle)
        md = table(rows, a.min_line, a.min_toggle)
        status = 0
        if a.print_table:
            sys.stdout.write(md)
        if a.gaps:
            sys.stdout.write(gaps(points))
        if a.write_dat:
            write_dat(judged, a.write_dat)
        if a.update_docs or a.check:
            text = Path(docs).read_text()
            b, e = docs_block(text, docs)
            want = "\n" + md
            if a.update_docs:
                changed = text[b:e] != want
                if changed:
                    Path(docs).write_text(text[:b] + want + text[e:])
                print(f"coverage_report.py: {docs}: "
                      + ("the coverage table written" if changed else "the coverage table is up to date"))
            elif text[b:e] != want:
                sys.stderr.write(f"coverage_report.py: {docs}: the coverage table differs from the "
                                 "data (scripts/coverage.sh regenerates it):\n")
                sys.stderr.writelines(difflib.unified_diff(
                    text[b:e].lstrip("\n").splitlines(True), md.splitlines(True), "docs", "data"))
                status = 1
        for m in filter(None, a.require.split(",")):
            row = next((r for r in rows if r[0] == m), None)
            if row is None or row[1] == 0 or row[3] == 0:
                sys.stderr.write(f"coverage_report.py: {m}: no line or toggle points in the data\n")
                status = 1
            elif row[5] != "yes":
                sys.stderr.write(f"coverage_report.py: {m}: line {pct(row[2], row[1])} of "
                                 f"{row[1]}, toggle {pct(row[4], row[3])} of {row[3]}: below "
                                 f"{a.min_line:g}/{a.min_toggle:g}\n")
                status = 1
        return status
    except (OSError, DataError, ValueError) as e:
        sys.stderr.write(f"coverage_report.py: {e}\n")
        return 2


if __name__ == "__main__":
    sys.exit(main())
