#!/usr/bin/env python3
"""RTL house rules that lint does not check (docs/rtl.md, "Conventions"):

  - no part-select whose index has two or more subtracted terms (`x[A-B-C -: W]`): a packed
    word's fields are named offsets (a *O / *W localparam chain in one .vh per layout) and a
    width that is a difference gets a name;
  - no inline `verilator lint_off`: the waivers live in rtl/lint/verilator_waiver.vlt.

    scripts/check_rtl_style.py [--root DIR]

Prints one line per violation ("rtl/FILE:LINE: ...") and exits 1 when there is any.
"""
import argparse
import re
import sys
from pathlib import Path


def subtractions(expr):
    depth, count = 0, 0
    for i, ch in enumerate(expr):
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch == "-" and depth == 0 and i > 0 and expr[i - 1] not in "+-*/(:":
            count += 1
    return count


def check(root):
    problems = []
    for f in sorted((root / "rtl").rglob("*.v")) + sorted((root / "rtl").rglob("*.vh")):
        rel = f.relative_to(root)
        for n, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1):
            code = line.split("//", 1)[0]
            if re.search(r"verilator\s+lint_(off|on)", line):
                problems.append(f"{rel}:{n}: inline lint pragma; waive in rtl/lint/verilator_waiver.vlt")
            for m in re.finditer(r"\[([^\[\]:]*?)(-:|\+:|:)([^\[\]]*?)\]", code):
                if subtractions(m.group(1).strip()) >= 2:
                    problems.append(f"{rel}:{n}: part-select {m.group(0)} has two or more subtracted "
                                    "terms; name the offset or the width")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent)
    args = ap.parse_args()
    problems = check(args.root)
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        return 1
    print("rtl/: no part-select with two or more subtracted terms, no inline lint pragma")
    return 0


if __name__ == "__main__":
    sys.exit(main())
