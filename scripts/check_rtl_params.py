#!/usr/bin/env python3
"""Every RTL module's parameter defaults against the one table of hardware parameters.

    scripts/check_rtl_params.py [--root DIR]

The table (ref/model/hw_params.def, one entry per hardware parameter with its Verilog name and
default) is the home of the defaults. Every `parameter integer Name = <number>` in rtl/ (modules
and headers) whose Name is a table entry's Verilog name must declare the table's default, and
every parameter rpu_top declares with a number must have that number wherever another module
declares it, except where EXCEPTIONS below says why a module means something else by the name.

Exit status 0 when every default agrees; 1 with one line per disagreement
("rtl/FILE:LINE: Name = V, the table says D"); 2 on bad usage.
"""

import argparse
import re
import sys
from pathlib import Path

import hw_params  # scripts/hw_params.py: the table of hardware parameters

# (file relative to rtl/, parameter): why this module's default differs on purpose.
EXCEPTIONS = {
    ("surface/rpu_surface_ip.v", "Unrolled"):
        "the surface search is built iterative (rpu_top's Unrolled is the curve IP's form)",
    ("surface/rpu_surface_top.v", "Unrolled"):
        "the surface search is built iterative (rpu_top's Unrolled is the curve IP's form)",
    ("curve/rpu_ip.v", "FifoLog2"):
        "the IP's own item FIFO, not rpu_top's credit count",
    ("surface/rpu_surface_ip_params.vh", "Indicators"):
        "the search unit alone defaults to 2^n1 - 1 indicators (one pass a step); rpu_top "
        "builds one",
}

DECL = re.compile(r"parameter\s+integer\s+([A-Za-z_]\w*)\s*=\s*(-?\d+)")


def table_defaults(root):
    """Verilog name -> default from hw_params.def (scripts/hw_params.py)."""
    try:
        out = hw_params.verilog_defaults(root)
    except ValueError as e:
        raise SystemExit(f"check_rtl_params.py: {e}")
    if not out:
        raise SystemExit("check_rtl_params.py: no entries read from ref/model/hw_params.def")
    return out


def declarations(root):
    """(file relative to rtl/, line, name, value) of every numeric parameter default."""
    rtl = root / "rtl"
    for path in sorted(list(rtl.rglob("*.v")) + list(rtl.rglob("*.vh"))):
        rel = path.relative_to(rtl).as_posix()
        for n, line in enumerate(path.read_text().splitlines(), 1):
            for m in DECL.finditer(line):
                yield rel, n, m.group(1), int(m.group(2))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--root", default=str(Path(__file__).resolve().parent.parent))
    a = ap.parse_args()
    root = Path(a.root)
    table = table_defaults(root)
    decls = list(declarations(root))
    top = {name: value for f, _, name, value in decls if f == "top/rpu_top.v"}
    if not top:
        print("check_rtl_params.py: rtl/top/rpu_top.v declares no parameters", file=sys.stderr)
        return 2
    bad = []
    checked = 0
    for f, n, name, value in decls:
        if (f, name) in EXCEPTIONS:
            continue
        if name in table:
            checked += 1
            if value != table[name]:
                bad.append(f"rtl/{f}:{n}: {name} = {value}, the table (ref/model/hw_params.def) "
                           f"says {table[name]}")
        elif name in top and f != "top/rpu_top.v":
            checked += 1
            if value != top[name]:
                bad.append(f"rtl/{f}:{n}: {name} = {value}, rpu_top.v declares {top[name]}")
    for line in bad:
        print(line)
    if bad:
        return 1
    print(f"check_rtl_params.py: {checked} parameter defaults in rtl/ agree with the table and "
          f"rpu_top ({len(EXCEPTIONS)} documented exceptions)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
