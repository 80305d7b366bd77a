#!/usr/bin/env python3
"""Checks the docs' parameter tables against the table of hardware parameters (issue 21, item 2).

    scripts/check_params_docs.py --rpu build/rpu [--root DIR] [--fixed-point FILE] [--readme FILE]
                                 [--write]

The table of hardware parameters is ref/model/hw_params.def; `rpu config --markdown` prints the
parameter table of docs/fixed-point.md generated from it ("| name | flag | default | range |
meaning |"), and `rpu config --markdown=readme` the README's rows for the same parameters ("| n |
`--n` | 16 | meaning |"). This script checks that docs/fixed-point.md holds exactly the generated
table, and that the rows of README.md's parameter table ("| parameter | flag | default | meaning
|") that name a hardware parameter are exactly the generated rows, in order (the README's other
rows, K, threads, ..., are its own).

--write rewrites both files to the generated tables instead (after a change to the table).

Exit status 0 when both agree (or were written); 1 with one line per difference
("FILE:LINE: ...") otherwise; 2 on bad usage or when rpu fails.
"""

import argparse
import subprocess
import sys
from pathlib import Path

README_HEADER = "| parameter | flag | default | meaning |"


def generated(rpu, which):
    args = [rpu, "config", "--markdown" if which == "docs" else "--markdown=readme"]
    r = subprocess.run(args, capture_output=True, text=True, encoding="utf-8")
    if r.returncode != 0:
        print(f"{' '.join(args)} failed (exit {r.returncode}): {r.stderr.strip()}", file=sys.stderr)
        sys.exit(2)
    return r.stdout.splitlines()


def table_block(lines, header):
    """(first index, end index) of the table whose header line is `header`, or None."""
    for k, line in enumerate(lines):
        if line.rstrip() == header:
            end = k
            while end < len(lines) and lines[end].startswith("|"):
                end += 1
            return k, end
    return None


def first_cell(row):
    return row.strip().strip("|").split("|")[0].strip()


def check_fixed_point(path, want, write):
    lines = path.read_text(encoding="utf-8").splitlines()
    block = table_block(lines, want[0])
    if block is None:
        return [f"{path}: no parameter table (a line '{want[0]}')"]
    start, end = block
    have = lines[start:end]
    if write:
        if have != want:
            lines[start:end] = want
            path.write_text("\n".join(lines) + "\n", encoding="utf-8")
            print(f"{path}: parameter table written")
        return []
    problems = []
    for k in range(max(len(have), len(want))):
        h = have[k] if k < len(have) else None
        w = want[k] if k < len(want) else None
        if h == w:
            continue
        if h is None:
            problems.append(f"{path}:{start + k + 1}: the parameter table lacks the row '{w}'")
        elif w is None:
            problems.append(f"{path}:{start + k + 1}: the parameter table has an extra row '{h}'")
        else:
            problems.append(f"{path}:{start + k + 1}: the parameter table differs from `rpu config "
                            f"--markdown`: '{h}', expected '{w}'")
    return problems


def check_readme(path, want, write):
    lines = path.read_text(encoding="utf-8").splitlines()
    block = table_block(lines, README_HEADER)
    if block is None:
        return [f"{path}: no parameter table (a line '{README_HEADER}')"]
    start, end = block
    keys = [first_cell(r) for r in want]
    rows = [k for k in range(start + 2, end) if first_cell(lines[k]) in keys]
    have = [lines[k] for k in rows]
    if write:
        if have != want:
            new = lines[:start]
            rest = list(want)
            for k in range(start, end):
                if k in rows:
                    if rest:
                        new.append(rest.pop(0))
                    if k == rows[-1]:
                        new.extend(rest)
                else:
                    new.append(lines[k])
            if not rows:
                new.extend(rest)
            new.extend(lines[end:])
            path.write_text("\n".join(new) + "\n", encoding="utf-8")
            print(f"{path}: parameter rows written")
        return []
    problems = []
    for key, w in zip(keys, want):
        found = [k for k in rows if first_cell(lines[k]) == key]
        if not found:
            problems.append(f"{path}:{start + 1}: the parameter table lacks the row '{w}'")
        elif lines[found[0]] != w:
            problems.append(f"{path}:{found[0] + 1}: the parameter row differs from `rpu config "
                            f"--markdown=readme`: '{lines[found[0]]}', expected '{w}'")
    order = [first_cell(lines[k]) for k in rows]
    if not problems and order != keys:
        problems.append(f"{path}:{start + 1}: the parameter rows are not in the table's order "
                        f"({', '.join(keys)})")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--rpu", required=True, help="the rpu executable")
    ap.add_argument("--root", default=Path(__file__).resolve().parent.parent, type=Path)
    ap.add_argument("--fixed-point", type=Path, help="default: ROOT/docs/fixed-point.md")
    ap.add_argument("--readme", type=Path, help="default: ROOT/README.md")
    ap.add_argument("--write", action="store_true", help="rewrite the tables instead of checking")
    a = ap.parse_args()
    fixed_point = a.fixed_point or a.root / "docs" / "fixed-point.md"
    readme = a.readme or a.root / "README.md"
    problems = check_fixed_point(fixed_point, generated(a.rpu, "docs"), a.write)
    problems += check_readme(readme, generated(a.rpu, "readme"), a.write)
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        print("(the tables are generated from ref/model/hw_params.def: scripts/check_params_docs.py "
              "--rpu build/rpu --write rewrites them)", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
