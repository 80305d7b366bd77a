#!/usr/bin/env python3
"""Checks that the README states no figure that a docs table does not hold (issue 20, item 3).

    scripts/check_readme_numbers.py [--readme README.md] [--root DIR]

A *figure* is a number followed by a unit of measurement (cycles, LUT sites, FF, DSP48E1, BRAM36,
ns, MHz, items/s, frames/s, %, s, minutes, hours, pixels, px, mutants, ...). The README's prose
and list items (not its code blocks, not its own tables) are read paragraph by paragraph. Every
figure must be *anchored*: its paragraph names one or more docs files (`docs/NAME.md`), and the
figure appears in a table row (a line starting with '|') of one of them. A README figure
"83.9k" matches a table's 83,869 (rounded to the README's precision), "939" matches "**939**",
"1,940" matches "1940".

The README's parameter table (header "| parameter | flag | default |") must also give every
flag the default of docs/fixed-point.md's parameter table (header "| name | flag | default |").

Exit status 0 when everything holds; 1 with one line per problem ("README.md:LINE: ...")
otherwise; 2 on bad usage.
"""

import argparse
import re
import sys
from pathlib import Path

UNITS = [
    "LUT sites", "LUTs", "LUT", "FFs", "FF", "flip-flops", "DSP48E1", "DSPs", "DSP", "BRAM36",
    "ns", "MHz", "items/s", "items/cycle", "cycles/s", "cycles", "frames/s", "fps", "%",
    "seconds", "s", "minutes", "min", "hours", "pixels", "px", "mutants", "executions",
]
NUMBER = r"(?<![\w.^/-])(\d{1,3}(?:,\d{3})+|\d+(?:\.\d+)?)(\s?[kM])?"
FIGURE = re.compile(NUMBER + r"\s?(" + "|".join(re.escape(u) for u in UNITS) + r")(?![\w/])")
DOC_REF = re.compile(r"docs/([\w.-]+\.md)")
TABLE_NUMBER = re.compile(r"(?<![\w.])(\d{1,3}(?:,\d{3})+|\d+(?:\.\d+)?)(?![\w])")


def paragraphs(text):
    """(first line number, text) of each prose paragraph or list item; code blocks and table rows
    are left out."""
    out, cur, start, in_code = [], [], 0, False
    for n, line in enumerate(text.splitlines(), 1):
        if line.lstrip().startswith("```"):
            in_code = not in_code
            if cur:
                out.append((start, " ".join(cur)))
                cur = []
            continue
        stripped = line.strip()
        new_item = re.match(r"^\s*([-*]|\d+\.)\s", line) is not None
        if in_code or not stripped or stripped.startswith("|") or stripped.startswith("#") or new_item:
            if cur:
                out.append((start, " ".join(cur)))
                cur = []
            if in_code or not stripped or stripped.startswith("|") or stripped.startswith("#"):
                continue
        if not cur:
            start = n
        cur.append(stripped)
    if cur:
        out.append((start, " ".join(cur)))
    return out


# What a table row or its header must say for a number there to be a figure of this unit.
UNIT_WORDS = {
    "LUT sites": ["lut"], "LUTs": ["lut"], "LUT": ["lut"], "FFs": ["ff"], "FF": ["ff"],
    "flip-flops": ["ff", "flip-flop"], "DSP48E1": ["dsp"], "DSPs": ["dsp"], "DSP": ["dsp"],
    "BRAM36": ["bram"], "ns": ["ns"], "MHz": ["mhz"], "items/s": ["items/s"],
    "items/cycle": ["items/cycle"], "cycles/s": ["cycles/s"], "cycles": ["cycle", "latency"],
    "frames/s": ["frames", "fps"], "fps": ["frames", "fps"], "%": ["%"],
    "seconds": [" s", "seconds"], "s": [" s", "seconds", " s |"], "minutes": ["min"],
    "min": ["min"], "hours": ["hour", " h"], "pixels": ["pixel", "px"], "px": ["pixel", "px"],
    "mutants": ["mutant"], "executions": ["execution"],
}


def table_numbers(path):
    """(number text, lower-case context) for every number in a table row of the file: the text has
    commas and bold removed, the context is the row and its table's header row."""
    numbers = []
    header = ""
    previous_was_table = False
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.lstrip().startswith("|"):
            previous_was_table = False
            continue
        if not previous_was_table:
            header = line
        previous_was_table = True
        context = (header + " " + line).lower()
        for m in TABLE_NUMBER.finditer(line.replace("*", "")):
            numbers.append((m.group(1).replace(",", ""), context))
    return numbers


def matches(figure, suffix, unit, candidates):
    plain = figure.replace(",", "")
    words = UNIT_WORDS[unit]
    scale = {"": 1.0, "k": 1000.0, "M": 1e6}[suffix.strip()]
    decimals = len(plain.split(".")[1]) if "." in plain else 0
    for text, context in candidates:
        if not any(w in context for w in words):
            continue
        if not suffix and text == plain:
            return True
        if suffix and round(float(text) / scale, decimals) == float(plain):
            return True
    return False


def parameter_table(text, first_header):
    """flag -> default of the first Markdown table whose header starts with first_header."""
    rows, found = {}, False
    for line in text.splitlines():
        if line.startswith(first_header):
            found = True
            continue
        if found:
            if not line.startswith("|"):
                break
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) >= 3 and cells[1].startswith("`--"):
                flag = re.match(r"`(--[\w-]+)", cells[1]).group(1)
                rows[flag] = re.sub(r"\s*\(.*\)|\s*=.*", "", cells[2]).strip()
    return rows


def check(readme, root):
    problems = []
    text = readme.read_text(encoding="utf-8")
    cache = {}
    for line_no, para in paragraphs(text):
        docs = sorted(set(DOC_REF.findall(para)))
        for m in FIGURE.finditer(para):
            number, suffix, unit = m.group(1), m.group(2) or "", m.group(3)
            shown = f"{number}{suffix} {unit}".replace("  ", " ")
            if not docs:
                problems.append(f"{readme.name}:{line_no}: '{shown}' names no docs table "
                                "(name the docs/*.md file whose table holds it)")
                continue
            found = False
            for d in docs:
                path = root / "docs" / d
                if not path.is_file():
                    problems.append(f"{readme.name}:{line_no}: docs/{d} does not exist")
                    continue
                if d not in cache:
                    cache[d] = table_numbers(path)
                found = found or matches(number, suffix, unit, cache[d])
            if not found:
                problems.append(f"{readme.name}:{line_no}: '{shown}' is in no table of "
                                + ", ".join(f"docs/{d}" for d in docs))
    ours = parameter_table(text, "| parameter | flag | default")
    fixed_point = root / "docs" / "fixed-point.md"
    theirs = parameter_table(fixed_point.read_text(encoding="utf-8"), "| name | flag | default")
    if not ours:
        problems.append(f"{readme.name}: no parameter table ('| parameter | flag | default')")
    for flag, default in ours.items():
        if flag in theirs and theirs[flag] != default:
            problems.append(f"{readme.name}: parameter table: {flag} default '{default}', "
                            f"docs/fixed-point.md says '{theirs[flag]}'")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--readme", type=Path)
    ap.add_argument("--root", type=Path, default=Path(__file__).resolve().parent.parent)
    args = ap.parse_args()
    readme = args.readme or args.root / "README.md"
    problems = check(readme, args.root)
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        print(f"{len(problems)} README figure(s) not held by a docs table", file=sys.stderr)
        return 1
    print(f"{readme.name}: every figure is held by a docs table")
    return 0


if __name__ == "__main__":
    sys.exit(main())
