#!/usr/bin/env python3
"""Every RTL module's parameter defaults against the one table of hardware parameters.

    scripts/check_rtl_params.py [--root DIR]

The table (ref/model/hw_params.def, one entry per hardware parameter with its Verilog name and
default) is the home of the defaults. Every `parameter integer Name = <number>` in rtl/ (modules
and headers) whose Name is a table entry's Verilog name must declare the table's default, and
every parameter rpu_top declares with a number (rtl/top/rpu_top_params.vh, the parameter list
rpu_top and rpu_axi include) must have that number wherever another module declares it, except
where EXCEPTIONS below says why a module means something else by the name; both rpu_top.v and
rpu_axi.v must include that list.

Width formulas have one home too, rtl/common/rpu_widths.vh (tb_rpu_widths checks each against
its C++ twin in ref/model/hw_params.h): a width parameter that some module declares as a macro of
it (`parameter integer DepthW = `RPU_DEPTHW(CoordW, EdgeFrac)`), or that EXTRA_NAMES names, must
not be written out by hand elsewhere with the same value ("DepthW = CoordW + 4 + EdgeW + 2"
repeats the formula). Values are compared by evaluating both sides at random parameter values,
the module's own derived parameters resolved; a same-named parameter with another value is a
different quantity and left alone.

The testbenches' twins take the same parameters as macros (sim/tb/tb_common.h's defaults when a
registration does not set them, sim/CMakeLists.txt's rpu_tb_macro names them): each default there
must be the table's too.

Exit status 0 when every default agrees and no formula is repeated; 1 with one line per finding
("rtl/FILE:LINE: Name = V, the table says D", "... repeats `RPU_X(...)`; write the macro"); 2 on
bad usage.
"""

import argparse
import random
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

TOP_PARAMS = "top/rpu_top_params.vh"  # rpu_top's parameter list
INCLUDERS = ("top/rpu_top.v", "axi/rpu_axi.v")
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


# The Verilog parameter a macro argument stands for (rpu_widths.vh names them in lower case).
ARG_PARAM = {"coordw": "CoordW", "tfrac": "TFrac", "unitfrac": "UnitFrac", "dirfrac": "DirFrac",
             "edgefrac": "EdgeFrac", "surfw": "SurfW", "n1": "N1", "n": "N", "ind": "Indicators",
             "tagw": "TagW", "k": "K"}
DEFINE = re.compile(r"^`define\s+(RPU_\w+)(?:\(([^)]*)\))?\s+(.*?)\s*(?://.*)?$")
CALL = re.compile(r"`(RPU_\w+)(?:\(([^()]*(?:\([^()]*\))*[^()]*)\))?")


def macros(text):
    """name -> (argument names, body) of every `define RPU_* in rpu_widths.vh."""
    out = {}
    for line in text.splitlines():
        m = DEFINE.match(line)
        if m:
            args = [a.strip() for a in m.group(2).split(",")] if m.group(2) else []
            out[m.group(1)] = (args, m.group(3))
    return out


def split_args(s):
    depth, cur, out = 0, "", []
    for ch in s:
        if ch == "," and depth == 0:
            out.append(cur.strip()); cur = ""; continue
        depth += ch == "("; depth -= ch == ")"
        cur += ch
    out.append(cur.strip())
    return out


def expand(expr, mac, depth=0):
    """Macro calls replaced by their bodies (arguments substituted), recursively."""
    if depth > 10: raise ValueError("macro nesting")
    def one(m):
        name = m.group(1)
        if name not in mac: return m.group(0)
        args, body = mac[name]
        vals = split_args(m.group(2)) if m.group(2) is not None and args else []
        for a, v in zip(args, vals):
            body = re.sub(rf"\b{re.escape(a)}\b", f"({v})", body)
        return f"({body})"
    new = CALL.sub(one, expr)
    return new if new == expr else expand(new, mac, depth + 1)


def value(expr, env):
    """The integer value of a Verilog expression of +, -, *, /, <<, parentheses; None otherwise."""
    py = expr.replace("/", "//")
    if re.search(r"[?:`$']", py): return None
    try:
        return eval(py, {"__builtins__": {}}, env)
    except Exception:
        return None


DECL1 = re.compile(r"\b(?:parameter|localparam)\s+integer\s+([A-Za-z_]\w*)\s*=\s*(.+?)\s*[,;]?\s*"
                   r"(?://.*)?$")
# Width names declared nowhere as the macro itself (a module's v̂ is DirW or VhW).
EXTRA_NAMES = {"RPU_VHATW": {"DirW", "VhW"}, "RPU_VW": {"VW"}}


def declarations_full(root):
    """(file, line, name, right-hand side) of every one-line integer parameter declaration."""
    rtl = root / "rtl"
    for path in sorted(list(rtl.rglob("*.v")) + list(rtl.rglob("*.vh"))):
        rel = path.relative_to(rtl).as_posix()
        lines = path.read_text().splitlines()
        for n, line in enumerate(lines, 1):
            m = DECL1.search(line)
            if not m: continue
            nxt = lines[n].lstrip() if n < len(lines) else ""
            rhs = m.group(2)
            if (nxt[:1] and nxt[:1] in "+-*/?:") or rhs.count("(") != rhs.count(")"): continue
            if "," in rhs and rhs.count("(") == 0: rhs = rhs.split(",")[0]
            yield rel, n, m.group(1), rhs.strip()


def formula_findings(root):
    """One line per width parameter written out by hand where rpu_widths.vh has its formula."""
    mac = macros((root / "rtl" / "common" / "rpu_widths.vh").read_text())
    decls = list(declarations_full(root))
    bound = {}
    for f, n, name, rhs in decls:
        m = re.fullmatch(r"`(RPU_\w+)(\(.*\))?", rhs)
        if m and mac.get(m.group(1), ([], ""))[0]:
            bound.setdefault(name, (m.group(1), f, n))
    for mname, names in EXTRA_NAMES.items():
        for name in names: bound.setdefault(name, (mname, "rtl/common/rpu_widths.vh", 0))
    by_file = {}
    for f, n, name, rhs in decls: by_file.setdefault(f, []).append((name, rhs))
    rng = random.Random(20261129)
    out = []
    for f, n, name, rhs in decls:
        if name not in bound or f"`{bound[name][0]}" in rhs: continue
        mname = bound[name][0]
        args = mac[mname][0]
        call = f"`{mname}(" + ", ".join(ARG_PARAM.get(a, a) for a in args) + ")"
        same, known = True, True
        for _ in range(4):
            env = {p: rng.randint(8, 40) for p in ARG_PARAM.values()}
            for _round in range(6):
                for dn, drhs in by_file[f]:
                    if dn in env or dn == name: continue
                    v = value(expand(drhs, mac), env)
                    if v is not None: env[dn] = v
            a, b = value(expand(rhs, mac), env), value(expand(call, mac), env)
            if a is None or b is None: known = False; break
            same = same and a == b
        if not known: continue
        where = f"rtl/{bound[name][1]}:{bound[name][2]}" if bound[name][2] else "rpu_widths.vh"
        if same:
            out.append(f"rtl/{f}:{n}: {name} = {rhs} repeats {call} ({where}); write the macro")
    return out


# The macro of a Verilog parameter in a testbench (sim/CMakeLists.txt, rpu_tb_macro, for units
# other than rpu_mul and rpu_cordic).
TB_MACRO_SPECIAL = {"N": "IP_N", "N1": "IP_N1", "N1First": "SURF_N1_FIRST", "Indicators": "SURF_IND"}


def tb_macro(name):
    if name in TB_MACRO_SPECIAL:
        return TB_MACRO_SPECIAL[name]
    m = re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", name)
    return re.sub(r"([A-Z])([A-Z][a-z])", r"\1_\2", m).upper()


def testbench_findings(root, table):
    """One line per table parameter whose default in sim/tb/tb_common.h differs or is missing."""
    path = root / "sim" / "tb" / "tb_common.h"
    if not path.exists():
        return []
    text = path.read_text()
    defaults = {m.group(1): int(m.group(2))
                for m in re.finditer(r"^#define\s+([A-Z0-9_]+)\s+(-?\d+)", text, re.M)}
    lines = text.splitlines()
    out = []
    for name, value in sorted(table.items()):
        macro = tb_macro(name)
        if macro not in defaults:
            out.append(f"sim/tb/tb_common.h: no default for {macro} (the table's {name})")
        elif defaults[macro] != value:
            n = next(i for i, l in enumerate(lines, 1) if re.match(rf"#define\s+{macro}\b", l))
            out.append(f"sim/tb/tb_common.h:{n}: {macro} = {defaults[macro]}, the table "
                       f"(ref/model/hw_params.def) says {value} for {name}")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--root", default=str(Path(__file__).resolve().parent.parent))
    a = ap.parse_args()
    root = Path(a.root)
    table = table_defaults(root)
    decls = list(declarations(root))
    top = {name: value for f, _, name, value in decls if f == TOP_PARAMS}
    if not top:
        print(f"check_rtl_params.py: rtl/{TOP_PARAMS} declares no parameters", file=sys.stderr)
        return 2
    bad = []
    for f in INCLUDERS:
        if f'`include "{Path(TOP_PARAMS).name}"' not in (root / "rtl" / f).read_text():
            bad.append(f"rtl/{f}: does not include {Path(TOP_PARAMS).name} (rpu_top's parameters)")
    checked = 0
    for f, n, name, value in decls:
        if (f, name) in EXCEPTIONS:
            continue
        if name in table:
            checked += 1
            if value != table[name]:
                bad.append(f"rtl/{f}:{n}: {name} = {value}, the table (ref/model/hw_params.def) "
                           f"says {table[name]}")
        elif name in top and f != TOP_PARAMS:
            checked += 1
            if value != top[name]:
                bad.append(f"rtl/{f}:{n}: {name} = {value}, rpu_top_params.vh declares {top[name]}")
    bad += formula_findings(root)
    bad += testbench_findings(root, table)
    for line in bad:
        print(line)
    if bad:
        return 1
    print(f"check_rtl_params.py: {checked} parameter defaults in rtl/ agree with the table and "
          f"rpu_top ({len(EXCEPTIONS)} documented exceptions), as do the testbenches' "
          f"(sim/tb/tb_common.h); no width formula of rpu_widths.vh is written out by hand")
    return 0


if __name__ == "__main__":
    sys.exit(main())
