#!/usr/bin/env python3
"""Cached, parallel hierarchical synthesis: the area of a whole design, priced one derived module
at a time (docs/resources.md, "How the whole top is priced").

A hierarchical `synth_xilinx` (no -flatten) maps every distinct derived module (a module at one
parameter set) on its own, and `stat -top` sums the counts over the instance tree. This script
does the same as independent jobs:

 1. elaborate once (Yosys: read_verilog -defer of every file of the list, hierarchy -check -top
    TOP with the -G parameters, write_rtlil) and list the derived modules and how many instances
    of each the tree holds;
 2. synthesise the derived modules in Yosys processes of their own, --jobs at a time: a large
    module alone, small ones in groups (one synth_xilinx for up to --group-size of them, which
    saves the 3 s of library reading each process costs). In a job, each module is elaborated
    again from the sources at its parameters, its children loaded first as black boxes (their
    ports only), then synth_xilinx -noiopad -noclkbuf (no -flatten), stat -tech xilinx, and sta
    with the 7-series cell library's timing arcs (the module's own logic: paths end at its
    children's ports). A module's result is the one a whole-design run gives it, whatever else
    its job holds (see JOB_SCRIPT), and the job checks that it elaborated the module of the
    key;
 3. cache each result under the SHA-256 of what can change it: the module's elaborated RTLIL
    (canonical: no source locations, Yosys' auto-numbered names numbered within the module, so
    an edit elsewhere in the design or of a comment changes nothing), its children's ports, the
    Yosys version and the job's script. A second run with nothing changed synthesises nothing;
    an edit of one leaf re-runs that leaf (and any parent whose text the edit changes: a new
    port width, say);
 4. sum LUT, INV, SRL, LUTRAM, FF, DSP48E1, BRAM, CARRY4 and MUXF7/8 over the tree, per derived
    module, per unit (a module of the design with the building blocks of --blocks under it:
    rpu_candidate with its stages, multipliers and roots) and in total.

A derived module that fails, times out or runs out of memory names itself and fails the whole
figure: exit status 1 and no totals (never a partial sum). The results that did finish stay
cached.

The cache lives in build/synth_cache (--cache moves it); after each run, the entries least
recently used are removed until it is under --cache-max-mb (the entries this run used are
kept). Concurrent runs may share one cache: each entry is written once, under a lock, and read
by the others.

Usage:
  scripts/synth_hier.py [options] TOP
  scripts/synth_hier.py -G Unrolled=0 rpu_top --md out.md --json out.json
  scripts/synth_hier.py --compare rpu_top          # also one monolithic Yosys run; fails if a
                                                   # column differs by more than --tolerance
Options: --help. Output: the summary and tables (Markdown) on stdout, progress on stderr.
Exit status: 0 ok, 1 a derived module (or the comparison) failed, 2 bad usage or elaboration.
"""
import argparse
import concurrent.futures
import fcntl
import hashlib
import json
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from collections import Counter, defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import rtl_files  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent

# Bump when the parsing of the results changes (the Yosys script is part of the key itself).
FLOW_VERSION = "synth_hier 1"

# A job synthesises one derived module, or several small ones (a group: one synth_xilinx for
# all of them, which saves the 3 s of library and techmap files each Yosys process reads):
#  - the children of its modules as black boxes with their ports (stubs.il, read first, so that
#    `hierarchy` finds them under their derived names instead of elaborating them);
#  - each module elaborated again from the sources at its parameters, as a kept instance of a
#    wrapper (group.v: its ports unconnected), so that Yosys makes its cells in the same order as in a whole-design
#    run: that order steers ABC's mapping, and an RTLIL file is sorted by name. A module's result
#    then equals its result in a whole-design run, whatever else the job holds;
#  - the elaboration written out for the check that each module is the module of its key;
#  - synth_xilinx without -flatten, stat per module, and sta (the black boxes, attribute
#    rpu_stub, go before the cell library is read again with its timing arcs: with them, that
#    read fails on their instances).
# {read}: the sources. The cache key holds this text, so a change of the job changes every key.
JOB_SCRIPT = """read_rtlil stubs.il
read_verilog -defer {read}
read_verilog -defer group.v
hierarchy -check -top rpu_synth_group
write_rtlil elaborated.il
synth_xilinx -noiopad -noclkbuf -top rpu_synth_group
tee -q -o stat.txt stat -tech xilinx
delete =A:rpu_stub
read_verilog -lib -specify -overwrite +/xilinx/cells_sim.v
tee -q -o sta.txt sta
"""
GROUP_TOP = "rpu_synth_group"

# The monolithic reference: the whole design in one Yosys process (docs/resources.md).
MONO_SCRIPT = """read_verilog -defer {read}
hierarchy -check -top {top}{chparam}
synth_xilinx -noiopad -noclkbuf -top {top}
tee -q -o {stat} stat -tech xilinx -top {top}
"""

# LUTs taken by each distributed-RAM primitive.
LUTRAM_LUTS = {"RAM32X1S": 1, "RAM64X1S": 1, "RAM128X1S": 2, "RAM256X1S": 4, "RAM32X1D": 2,
               "RAM64X1D": 2, "RAM128X1D": 4, "RAM32M": 4, "RAM64M": 4, "RAM32M16": 8,
               "RAM64M8": 8, "RAM512X1S": 8}
# Cells that take no site of the fabric.
IGNORED = {"GND", "VCC", "BUFG", "IBUF", "OBUF"}
COLUMNS = ["lut_sites", "lut", "inv", "srl", "lutram", "ff", "dsp", "bram36", "carry4", "muxf",
           "est_lcs"]


def die(msg, status=2):
    print(f"synth_hier: {msg}", file=sys.stderr)
    sys.exit(status)


def note(msg):
    print(f"[{time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


def sha(text):
    return hashlib.sha256(text.encode()).hexdigest()


# ---------------------------------------------------------------- counting

def columns(cells):
    """The report's columns from a Counter of cell types (Xilinx primitives; others ignored
    here, listed by other_cells)."""
    c = dict.fromkeys(COLUMNS, 0)
    for t, n in cells.items():
        if re.fullmatch(r"LUT[1-6]", t):
            c["lut"] += n
        elif t == "INV":
            c["inv"] += n
        elif re.fullmatch(r"FD[RSCP]E|LD[CP]E", t):
            c["ff"] += n
        elif t.startswith("SRL"):
            c["srl"] += n
        elif t in LUTRAM_LUTS:
            c["lutram"] += n * LUTRAM_LUTS[t]
        elif t == "DSP48E1":
            c["dsp"] += n
        elif t == "RAMB36E1":
            c["bram36"] += n
        elif t == "RAMB18E1":
            c["bram36"] += n / 2
        elif t == "CARRY4":
            c["carry4"] += n
        elif t in ("MUXF7", "MUXF8"):
            c["muxf"] += n
        elif t == "$est_lcs":
            c["est_lcs"] += n
    c["lut_sites"] = c["lut"] + c["inv"] + c["srl"] + c["lutram"]
    return c


def known_cell(t):
    return (re.fullmatch(r"LUT[1-6]|FD[RSCP]E|LD[CP]E|SRL.*|RAMB(36|18)E1|DSP48E1|CARRY4|MUXF[78]"
                         r"|INV|\$est_lcs", t) is not None or t in LUTRAM_LUTS or t in IGNORED)


def parse_stat(text, children=(), hierarchy=False):
    """Cell counts of a `stat -tech xilinx` report: the module's own cells (children's types
    left out), or with hierarchy=True the design hierarchy's totals (`stat -top`)."""
    cells = Counter()
    counting = not hierarchy
    section = False
    for line in text.splitlines():
        if hierarchy and "=== design hierarchy ===" in line:
            section = True
            continue
        if hierarchy and section and "Number of cells:" in line:
            counting = True
            continue
        if not counting:
            continue
        m = re.search(r"Estimated number of LCs:\s+(\d+)", line)
        if m:
            cells["$est_lcs"] += int(m.group(1))
            continue
        f = line.split()
        if len(f) == 2 and f[1].isdigit() and f[0] not in children:
            cells[f[0]] += int(f[1])
    return cells


def parse_sta(text):
    m = None
    for m in re.finditer(r"Latest arrival time in .* is (-?\d+)", text):
        pass
    return int(m.group(1)) / 1000 if m else None


def parse_log_usage(text):
    """(CPU seconds, peak MB) from a Yosys log's last line, or (None, None)."""
    m = re.search(r"CPU: user ([\d.]+)s system ([\d.]+)s, MEM: ([\d.]+) MB peak", text)
    if not m:
        return None, None
    return float(m.group(1)) + float(m.group(2)), float(m.group(3))


# ---------------------------------------------------------------- the elaborated design

class Module:
    __slots__ = ("name", "attrs", "body", "hdlname", "params", "ports", "cells", "children",
                 "text", "stubs", "key", "count", "own", "sta", "meta", "cached")

    def __init__(self, name, attrs, body):
        self.name, self.attrs, self.body = name, attrs, body
        m = next((re.match(r'attribute \\hdlname "\\\\(.*)"$', a) for a in attrs
                  if a.startswith("attribute \\hdlname ")), None)
        self.hdlname = m.group(1) if m else name.lstrip("\\")
        self.params = [tuple(l.split(None, 2)[1:]) for l in body
                       if l.startswith("  parameter ") and len(l.split(None, 2)) == 3]
        self.ports = [l for l in body if re.match(r"  wire\b.*\b(input|output|inout) \d+ ", l)]
        self.cells = [l.split()[1] for l in body if l.startswith("  cell ")]
        self.children = Counter()
        self.text = self.key = self.stubs = None
        self.count = 0


def split_modules(text):
    mods, attrs, cur, body = {}, [], None, []
    for line in text.splitlines():
        if cur is None:
            if line.startswith("attribute "):
                attrs.append(line)
            elif line.startswith("module "):
                cur, body = line[len("module "):].strip(), []
            continue
        if line == "end":
            mods[cur] = Module(cur, attrs, body)
            cur, attrs = None, []
        else:
            body.append(line)
    return mods


SRC_ATTR = re.compile(r"^\s*attribute \\src ")
SRC_IN_NAME = re.compile(r"(\.(?:s?vh?)):\d+(?:\.\d+-\d+\.\d+)?(?=\$)")
AUTOIDX = re.compile(r"\$(\d+)(?=[\s_.\[\]$:]|$)")


def canonical(mod, modules):
    """The module's elaborated RTLIL as a key: the same text whatever else the design holds and
    wherever its source lines are. Dropped: source locations (attributes and the file:line in
    Yosys' generated names), the parameters on instances of derived modules (a derived module
    takes none). Yosys numbers its generated names across the whole design, so they are
    numbered again by rank within the module (the order in which Yosys made them, the same in
    any elaboration), and the wires, memories, cells and processes, which write_rtlil sorts by
    their old names, are sorted by the new ones. Returns (text, count of numbers)."""
    lines, in_child = [], False
    for line in mod.body:
        if SRC_ATTR.match(line) or line == "  attribute \\module_not_derived 1":
            continue
        if line.startswith("  cell "):
            in_child = line.split()[1] in modules
        elif line == "  end":
            in_child = False
        elif in_child and line.startswith("    parameter "):
            continue
        if "$" in line:
            line = SRC_IN_NAME.sub(r"\1", line)
        lines.append(line)
    numbers = sorted({int(n) for l in lines if "$" in l for n in AUTOIDX.findall(l)})
    rank = {str(n): str(k + 1) for k, n in enumerate(numbers)}
    lines = [AUTOIDX.sub(lambda m: "$" + rank[m.group(1)], l) if "$" in l else l for l in lines]
    # Inside processes, two kinds of line come in an order that depends on Yosys' name table,
    # not on the source: a sync rule's updates, and the proc frontend's assignments of whole
    # signals (the defaults of a case). Each run of them is sorted: an update drives its own
    # signal, and assignments to distinct whole signals (no slice, no concatenation) commute.
    def sortable(line):
        f = line.split()
        if len(f) < 3:
            return None
        if f[0] == "update":
            return "update"
        if f[0] == "assign" and not f[1].startswith("{") and not f[2].startswith("["):
            return "assign"
        return None

    k = 0
    while k < len(lines):
        kind = sortable(lines[k])
        j = k + 1
        while kind and j < len(lines) and sortable(lines[j]) == kind and \
                lines[j][:len(lines[j]) - len(lines[j].lstrip())] == \
                lines[k][:len(lines[k]) - len(lines[k].lstrip())]:
            j += 1
        if kind and j - k > 1:
            run = lines[k:j]
            if len({l.split()[1] for l in run}) == len(run):
                lines[k:j] = sorted(run)
        k = j
    # Items: attribute lines belong to the item after them; a cell or process runs to "  end".
    groups = {k: [] for k in ("parameter", "wire", "memory", "cell", "process", "connect",
                              "other")}
    item, pending = None, []
    for line in lines:
        if item is not None:
            item.append(line)
            if line == "  end":
                item = None
            continue
        word = line.split(None, 1)[0] if line.strip() else ""
        if word == "attribute" and line.startswith("  attribute "):
            pending.append(line)
            continue
        kind = word if word in groups else "other"
        entry = pending + [line]
        pending = []
        groups[kind].append((line, entry))
        if kind in ("cell", "process"):
            item = entry
    out = [a for a in mod.attrs if not SRC_ATTR.match(a) and a != "attribute \\top 1"]
    out.append(f"module {mod.name}")
    for kind, entries in groups.items():
        if kind in ("wire", "memory", "cell", "process"):
            entries = sorted(entries, key=lambda e: e[0])
        for _, entry in entries:
            out += entry
    out += pending
    out.append("end")
    return "\n".join(out) + "\n", len(numbers)


def same_module(a, b):
    """Whether two canonical module bodies are the same module. Equal text, or equal once Yosys'
    generated names are numbered by what they name rather than by the order Yosys made them:
    that order is the same in any elaboration for most cells, but not always (a memory write
    port's DATA and EN wires of rpu_fifo came in either order when the module was elaborated
    twice). Each number is ranked by the names it appears in, with itself blanked (then by its
    value), and the lines are compared as a sorted list, every name renumbered consistently, so
    a connection made differently still differs."""
    if a == b:
        return True

    def renumbered(body):
        lines = body.splitlines()
        stems = {}
        for line in lines:
            for tok in line.split():
                for m in AUTOIDX.finditer(tok):
                    stems.setdefault(m.group(1), set()).add(tok[:m.start()] + "$#" + tok[m.end():])
        order = sorted(stems, key=lambda n: (sorted(stems[n]), int(n)))
        rank = {n: str(k + 1) for k, n in enumerate(order)}
        return sorted(AUTOIDX.sub(lambda m: "$" + rank[m.group(1)], l) for l in lines)

    return renumbered(a) == renumbered(b)


def body_of(text):
    """The lines after the module line of a canonical text (the name and its attributes
    differ between the design's elaboration and a job's)."""
    return text.split("\nmodule ", 1)[-1].split("\n", 1)[1] if "\nmodule " in text else \
        text.split("\n", 1)[1]


def stub(mod):
    """A black box with the module's ports."""
    return "attribute \\blackbox 1\nattribute \\rpu_stub 1\nmodule {}\n{}end\n".format(
        mod.name, "".join(p + "\n" for p in mod.ports))


def instance_tree(mods, top):
    """Sets each module's children (derived-module instances) and its instance count under top;
    returns the modules of the tree in topological order (top first)."""
    for m in mods.values():
        m.children = Counter(t for t in m.cells if t in mods)
    order, state = [], {}

    def visit(n):
        if state.get(n) == 2:
            return
        if state.get(n) == 1:
            die(f"the hierarchy under {top} has a cycle at {n}")
        state[n] = 1
        for c in mods[n].children:
            visit(c)
        state[n] = 2
        order.append(n)

    visit(top)
    order.reverse()
    mods[top].count = 1
    for n in order:
        for c, k in mods[n].children.items():
            mods[c].count += mods[n].count * k
    return order


def units(mods, order, top, is_block):
    """{unit name: (instances, Counter of cells)}: each instance's own cells go to its nearest
    ancestor (itself included) that is not a building block."""
    weight = defaultdict(int)  # (module, unit module) -> instances
    weight[(top, top)] = 1
    for n in order:
        for (m, u), w in list(weight.items()):
            if m != n:
                continue
            for c, k in mods[n].children.items():
                cu = u if is_block(mods[c]) else c
                weight[(c, cu)] += w * k
    out = {}
    for (m, u), w in weight.items():
        name = mods[u].hdlname
        inst, cells = out.setdefault(name, [0, Counter()])
        if m == u:
            out[name][0] += w
        for t, n in mods[m].own.items():
            cells[t] += n * w
    return out


# ---------------------------------------------------------------- the cache

class Cache:
    def __init__(self, path, max_mb):
        self.path = Path(path)
        self.max_bytes = max_mb * 1024 * 1024
        self.path.mkdir(parents=True, exist_ok=True)
        self.used = set()

    def entry(self, key):
        return self.path / key[:2] / key

    def lock(self, key):
        d = self.path / key[:2]
        d.mkdir(parents=True, exist_ok=True)
        f = open(d / (key + ".lock"), "w")
        fcntl.lockf(f, fcntl.LOCK_EX)  # POSIX locks: they hold across the hosts of an NFS mount
        return f

    def get(self, key):
        e = self.entry(key)
        meta = e / "meta.json"
        if not meta.is_file():
            return None
        self.used.add(key)
        os.utime(meta)  # least recently used goes first
        return json.loads(meta.read_text()), (e / "stat.txt").read_text(), \
            (e / "sta.txt").read_text() if (e / "sta.txt").is_file() else ""

    def put(self, key, meta, files):
        e = self.entry(key)
        tmp = Path(tempfile.mkdtemp(dir=e.parent, prefix=key[:8] + ".tmp."))
        for name, text in files.items():
            (tmp / name).write_text(text)
        (tmp / "meta.json").write_text(json.dumps(meta, indent=1) + "\n")
        if e.exists():
            shutil.rmtree(tmp)
        else:
            os.rename(tmp, e)
        self.used.add(key)

    def plan_path(self, key):
        return self.path / "plans" / (key + ".json")

    def trim(self):
        """Removes the least recently used entries (not this run's) until the cache fits."""
        entries, total = [], 0
        for d in self.path.glob("??/*"):
            if not d.is_dir() or ".tmp." in d.name:
                continue
            size = sum(f.stat().st_size for f in d.iterdir() if f.is_file())
            total += size
            meta = d / "meta.json"
            entries.append((meta.stat().st_mtime if meta.exists() else 0, size, d))
        plans = list((self.path / "plans").glob("*.json"))
        for p in plans:
            s = p.stat()
            total += s.st_size
            entries.append((s.st_mtime, s.st_size, p))
        removed = 0
        for mtime, size, d in sorted(entries, key=lambda e: e[0]):
            if total <= self.max_bytes:
                break
            if d.name in self.used or d.stem in self.used:
                continue
            if d.is_dir():
                shutil.rmtree(d, ignore_errors=True)
                lock = d.parent / (d.name + ".lock")
                lock.unlink(missing_ok=True)
            else:
                d.unlink(missing_ok=True)
            total -= size
            removed += 1
        return removed, total


# ---------------------------------------------------------------- running Yosys

PROCS = set()
PROCS_LOCK = threading.Lock()
STOPPING = threading.Event()


def run_yosys(script, cwd, log, timeout, mem_mb):
    """Runs one Yosys script; returns (status, seconds): status "ok", "timeout", "out of
    memory" or "error: <the log's first error line>"."""
    def limits():
        if mem_mb:
            resource.setrlimit(resource.RLIMIT_AS, (mem_mb << 20, mem_mb << 20))

    t0 = time.monotonic()
    with open(log.with_suffix(".out"), "w") as out:
        with PROCS_LOCK:  # stop_all holds it while it ends every run: none starts after
            if STOPPING.is_set():
                return "interrupted", 0.0
            p = subprocess.Popen(["yosys", "-q", "-l", str(log), str(script)], cwd=cwd,
                                 stdout=out, stderr=subprocess.STDOUT, preexec_fn=limits,
                                 start_new_session=True)
            PROCS.add(p)
        try:
            rc = p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
            rc = None
        finally:
            with PROCS_LOCK:
                PROCS.discard(p)
    secs = time.monotonic() - t0
    if rc is None:
        return "timeout", secs
    if rc == 0:
        return "ok", secs
    text = ""
    for f in (log, log.with_suffix(".out")):
        if f.exists():
            text += f.read_text(errors="replace")
    if STOPPING.is_set():
        return "interrupted", secs
    if re.search(r"bad_alloc|[Oo]ut of memory|Cannot allocate", text):
        return "out of memory", secs
    m = re.search(r"^.*ERROR.*$", text, re.M)
    return "error: " + (m.group(0).strip()[:200] if m else f"exit status {rc}"), secs


WORK_DIRS = []  # removed when the run is interrupted


def stop_all(signum, _frame):
    """SIGINT, SIGTERM: ends every Yosys run (each a process group), removes the work
    directories and exits at once."""
    STOPPING.set()
    with PROCS_LOCK:
        for p in PROCS:
            try:
                os.killpg(p.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        for d in WORK_DIRS:
            shutil.rmtree(d, ignore_errors=True)
        print("synth_hier: interrupted", file=sys.stderr, flush=True)
        os._exit(128 + signum)


# ---------------------------------------------------------------- the flow

def source_hash(list_path, sources, incdirs, yosys_version):
    """A hash of every file that elaboration can read: the sources, and every Verilog file of
    the include directories and of the sources' directories."""
    base = list_path.parent
    files = set(base / s for s in sources)
    for d in set(incdirs) | set(str(Path(s).parent) for s in sources):
        for f in (base / d).iterdir():
            if f.is_file() and f.suffix in (".v", ".vh", ".sv", ".svh"):
                files.add(f)
    h = hashlib.sha256(f"{FLOW_VERSION}\n{yosys_version}\n".encode())
    h.update(" ".join(sources).encode() + b"\n" + " ".join(incdirs).encode() + b"\n")
    for f in sorted(files):
        h.update(str(f.relative_to(base)).encode() + b"\0" + f.read_bytes() + b"\0")
    return h.hexdigest()


def read_args(incdirs, sources, defines):
    """read_verilog's arguments: the macros (-D), the include directories, the sources."""
    return " ".join([f"-D{d}" for d in defines] + [f"-I{d}" for d in incdirs] + list(sources))


def elaborate(args, list_path, sources, incdirs, work):
    read = read_args(incdirs, sources, args.defines)
    chparam = "".join(f" -chparam {p} {v}" for p, v in args.params)
    script = work / "elaborate.ys"
    il = work / "elaborated.il"
    script.write_text(f"read_verilog -defer {read}\nhierarchy -check -top {args.top}{chparam}\n"
                      f"write_rtlil {il}\n")
    status, secs = run_yosys(script, list_path.parent, work / "elaborate.log",
                             args.elab_timeout, args.mem)
    if status != "ok":
        die(f"elaboration of {args.top} failed ({status}); see {work / 'elaborate.log'}")
    return il.read_text(), secs


def plan_from_design(text, top):
    """The derived modules under top, in topological order, with their canonical text, their
    children's black boxes (stub text by name) and their keys."""
    mods = split_modules(text)
    tops = [n for n in mods if n in (top, "\\" + top)]
    if not tops:
        die(f"elaboration produced no module {top}")
    top = tops[0]
    order = instance_tree(mods, top)
    stubs = {}
    for n in order:
        mods[n].text = canonical(mods[n], mods)[0]
        stubs[n] = stub(mods[n])
    for n in order:
        m = mods[n]
        m.stubs = "".join(stubs[c] for c in sorted(m.children))
        m.key = sha(f"{FLOW_VERSION}\n{YOSYS_VERSION}\n{JOB_SCRIPT}\n{m.stubs}{m.text}")
    return mods, order, top, stubs


def describe_params(m):
    return " ".join(f"{p[0].lstrip(chr(92))}={p[1]}" for p in m.params)


def verilog_params(m):
    """The module's parameters as a Verilog override list: RTLIL writes a decimal or
    width'bits."""
    out = []
    for name, value in m.params:
        b = re.fullmatch(r"(\d+)'([01xz]+)", value)
        if b:
            value = f"{b.group(1)}'b{b.group(2)}"
        elif not re.fullmatch(r"-?\d+", value):
            raise RuntimeError(f"{m.hdlname} [{m.name}]: parameter {name} = {value}: only numbers "
                               "can be passed again")
        out.append(f".{name.lstrip(chr(92))}({value})")
    return f"#({', '.join(out)}) " if out else ""


def where(m):
    return f"{m.hdlname} [{m.name}]"


class GroupError(RuntimeError):
    """A job of several modules failed as a whole: its modules are run again one by one, so
    that the one at fault names itself."""


def synthesise_group(group, cache, args, work, read, cwd, stubs, progress):
    """Synthesises the modules of the group in one Yosys process. Returns {name: (meta, stat
    text, sta text, cached?)}; raises RuntimeError naming the module (one module) or
    GroupError (several)."""
    results = {}
    for m in group:
        got = cache.get(m.key)
        if got:
            results[m.name] = got + (True,)
    group = [m for m in group if m.name not in results]
    if not group:
        return results
    locks = [cache.lock(k) for k in sorted({m.key for m in group})]
    try:
        todo = []
        for m in group:
            got = cache.get(m.key)  # another run may have made it while this one waited
            if got:
                results[m.name] = got + (True,)
            elif m.text is None:
                raise RuntimeError(f"{where(m)}: left the cache during this run (another run "
                                   "trimmed it); run again")
            else:
                todo.append(m)
        if not todo:
            return results
        label = where(todo[0]) if len(todo) == 1 else f"a group of {len(todo)} modules"
        d = Path(tempfile.mkdtemp(prefix="job.", dir=work))
        children = sorted({c for m in todo for c in m.children})
        (d / "stubs.il").write_text("".join(stubs[c] for c in children))
        (d / "group.v").write_text(
            f"module {GROUP_TOP};\n" + "".join(
                f"  (* keep *) {m.hdlname} {verilog_params(m)}u{k} ();\n"
                for k, m in enumerate(todo))
            + "endmodule\n")
        script = JOB_SCRIPT.replace("{read}", read)
        for f in ("stubs.il", "group.v", "elaborated.il", "stat.txt", "sta.txt"):
            script = script.replace(f, str(d / f))
        (d / "job.ys").write_text(script)
        progress(f"{label}: started" if len(todo) == 1 else
                 f"{label} ({', '.join(sorted({m.hdlname for m in todo}))}): started", len(todo))
        status, secs = run_yosys(d / "job.ys", cwd, d / "yosys.log", args.timeout, args.mem)
        if status != "ok":
            msg = f"{status} after {secs:.0f} s; its log: {d / 'yosys.log'}"
            if len(todo) > 1:
                raise GroupError(f"{label}: {msg}")
            raise RuntimeError(f"{label}: {msg}")
        # Each module must be the module of its key, with its children as black boxes.
        job = split_modules((d / "elaborated.il").read_text())
        inst = {}
        for line in job[f"\\{GROUP_TOP}"].body if f"\\{GROUP_TOP}" in job else []:
            if line.startswith("  cell "):
                inst[line.split()[2]] = line.split()[1]
        sections = dict(zip(*[iter(re.split(r"^=== (.*) ===$", (d / "stat.txt").read_text(),
                                            flags=re.M)[1:])] * 2))
        sta_text = (d / "sta.txt").read_text()
        cpu, peak = parse_log_usage((d / "yosys.log").read_text(errors="replace"))
        bad = []
        for k, m in enumerate(todo):
            name = inst.get(f"\\u{k}")
            shown = name[1:] if name and name.startswith("\\") else name  # as Yosys prints it
            if name is None or name not in job or shown not in sections or \
                    not same_module(body_of(canonical(job[name], job)[0]), body_of(m.text)):
                bad.append(m)
                continue
            # The module's critical path: from its "Latest arrival" line to its histogram.
            arrival = re.search(r"^Latest arrival time in '" + re.escape(shown) +
                                r"' is -?\d+:\n(?:(?!Arrival histogram).*\n)*", sta_text, re.M)
            meta = {"module": m.name, "hdlname": m.hdlname, "parameters": describe_params(m),
                    "seconds": round(secs / len(todo), 1),
                    "cpu_seconds": round(cpu / len(todo), 1) if cpu else None,
                    "peak_mb": peak, "job_modules": len(todo), "yosys": YOSYS_VERSION,
                    "flow": FLOW_VERSION, "date": time.strftime("%Y-%m-%d %H:%M:%S")}
            stat = f"=== {shown} ===\n{sections[shown]}"
            sta = arrival.group(0) if arrival else ""
            cache.put(m.key, meta, {"stat.txt": stat, "sta.txt": sta})
            results[m.name] = (meta, stat, sta, False)
        if bad:
            msg = (f"elaborated again from the sources at its parameters, it is not the module of "
                   f"the design's elaboration (see {d})")
            if len(todo) > 1:
                raise GroupError(f"{', '.join(where(m) for m in bad)}: {msg}")
            raise RuntimeError(f"{label}: {msg}")
        shutil.rmtree(d, ignore_errors=True)
        progress(f"{label}: done in {secs:.0f} s", 0)
        return results
    finally:
        for lock in locks:
            lock.close()


def flop_bits(text):
    """The bits a module's processes update on a clock edge (its flip-flops before synthesis)."""
    width = {}
    for w in re.finditer(r"^  wire (?:width (\d+) )?(?:(?:input|output|inout) \d+ )?(\S+)$",
                         text, re.M):
        width[w.group(2)] = int(w.group(1) or 1)
    bits, edge = 0, False
    for line in text.splitlines():
        f = line.split()
        if not f:
            continue
        if f[0] == "sync":
            edge = len(f) > 1 and f[1] in ("posedge", "negedge")
        elif f[0] == "update":
            if edge and len(f) > 2:
                r = re.fullmatch(r"\[(\d+)(?::(\d+))?\]", f[2])
                bits += abs(int(r.group(1)) - int(r.group(2) or r.group(1))) + 1 if r else \
                    width.get(f[1], 1)
        elif f[0] != "attribute":
            edge = False
    return bits


def expected_seconds(m, cache):
    """For grouping and the run order: the last time this derived module took (by name), else
    an estimate from its elaborated text: about 33 kB of text or 670 flip-flop bits a second
    (rough, from the unrolled rpu_top: the step units' long text, the wide tags the roots
    carry; the total comes within about 10 % of the measured one)."""
    t = cache.timings.get(m.name)
    if t is not None:
        return t
    return len(m.text or "") / 33000 + flop_bits(m.text or "") / 670


def make_groups(todo, cache, args):
    """The jobs: each module expected to take --group-seconds or more alone; the smaller ones
    in groups of up to --group-size whose expected times add up to at most --group-seconds
    (a module never with its parent or child: the child would be both a black box and a member).
    The longest first."""
    est = {m.name: expected_seconds(m, cache) for m in todo}
    alone = {m.name for m in todo if est[m.name] >= args.group_seconds or args.group_size <= 1}
    big = [[m] for m in todo if m.name in alone]
    small = sorted((m for m in todo if m.name not in alone), key=lambda m: -est[m.name])
    groups, open_groups = [], []
    for m in small:
        for g in open_groups:
            if len(g[1]) < args.group_size and g[0] + est[m.name] <= args.group_seconds and \
                    not any(m.name in x.children or x.name in m.children for x in g[1]):
                g[0] += est[m.name]
                g[1].append(m)
                break
        else:
            open_groups.append([est[m.name], [m]])
    groups = big + [g[1] for g in open_groups]
    return sorted(groups, key=lambda g: -sum(est[m.name] for m in g))


def run_flow(args):
    list_path = Path(args.list).resolve()
    try:
        sources, incdirs = rtl_files.read_list(list_path)
    except ValueError as e:
        die(str(e))
    cache = Cache(args.cache, args.cache_max_mb)
    timings_file = cache.path / "timings.json"
    try:
        cache.timings = json.loads(timings_file.read_text())
    except (OSError, ValueError):
        cache.timings = {}
    t0 = time.monotonic()
    work = Path(tempfile.mkdtemp(prefix="synth_hier.", dir=args.work)) if args.work else \
        Path(tempfile.mkdtemp(prefix="synth_hier."))
    WORK_DIRS.append(work)

    # The plan (derived modules, their keys, the tree) is cached under the hash of the sources
    # and parameters: an unchanged design needs no elaboration when every job is cached.
    plan_key = sha(f"{source_hash(list_path, sources, incdirs, YOSYS_VERSION)}\n{args.top}\n"
                   f"{sorted(args.params)}" + (f"\n{sorted(args.defines)}" if args.defines else ""))
    plan_file = cache.plan_path(plan_key)
    plan, elab_secs = None, 0.0
    if plan_file.is_file():
        plan = json.loads(plan_file.read_text())
        if not all(cache.entry(e["key"]).joinpath("meta.json").is_file()
                   for e in plan["modules"].values()):
            plan = None
    if plan is None:
        note(f"elaborating {args.top} {' '.join(f'{p}={v}' for p, v in args.params)}")
        text, elab_secs = elaborate(args, list_path, sources, incdirs, work)
        mods, order, top, stubs = plan_from_design(text, args.top)
        plan = {"top": top, "order": order, "modules": {
            n: {"key": mods[n].key, "hdlname": mods[n].hdlname, "parameters":
                describe_params(mods[n]), "children": dict(mods[n].children),
                } for n in order}}
        plan_file.parent.mkdir(parents=True, exist_ok=True)
        tmp = plan_file.with_suffix(f".tmp{os.getpid()}")
        tmp.write_text(json.dumps(plan) + "\n")
        os.replace(tmp, plan_file)
        texts = {n: (mods[n].text, mods[n].stubs) for n in order}
    else:
        texts, stubs = None, {}
        os.utime(plan_file)
    cache.used.add(plan_key)

    order, top = plan["order"], plan["top"]
    mods = {}
    for n in order:
        e = plan["modules"][n]
        m = Module.__new__(Module)
        m.name, m.hdlname, m.key = n, e["hdlname"], e["key"]
        m.params = [tuple(p.split("=", 1)) for p in e["parameters"].split()] \
            if e["parameters"] else []
        m.children = Counter(e["children"])
        m.text, m.stubs = texts[n] if texts else (None, None)
        m.count = 0
        mods[n] = m
    mods[top].count = 1
    for n in order:
        for c, k in mods[n].children.items():
            mods[c].count += mods[n].count * k

    # Which building blocks are attributed to the unit above them.
    block_files = module_files(list_path, sources)

    def is_block(m):
        f = block_files.get(m.hdlname, "")
        return any(f.startswith(b.rstrip("/") + "/") for b in args.blocks)

    groups = make_groups([mods[n] for n in order
                          if not cache.entry(mods[n].key).joinpath("meta.json").is_file()],
                         cache, args)
    n_jobs = sum(len(g) for g in groups)
    note(f"{args.top}: {len(order)} derived modules, {len(order) - n_jobs} cached, {n_jobs} to "
         f"synthesise in {len(groups)} Yosys jobs (-j {args.jobs}), cache {cache.path}")
    if args.dry_run:
        shutil.rmtree(work, ignore_errors=True)
        return {"top": args.top, "parameters": dict(args.params), "status": "dry run",
                "derived_modules": len(order), "to_synthesise": n_jobs, "jobs": len(groups),
                "expected_seconds": round(sum(expected_seconds(m, cache) for g in groups
                                              for m in g), 1),
                "modules": [{"module": n, "hdlname": mods[n].hdlname, "key": mods[n].key,
                             "parameters": describe_params(mods[n]),
                             "instances": mods[n].count,
                             "cached": cache.entry(mods[n].key).joinpath("meta.json").is_file(),
                             "expected_seconds": round(expected_seconds(mods[n], cache), 2)}
                            for n in order]}, None
    started = [0]
    lock = threading.Lock()

    def progress(msg, n):
        with lock:
            started[0] += n
            note(f"({started[0]}/{n_jobs}) {msg}" if n else msg)

    results, failures = {}, []
    read = read_args(incdirs, sources, args.defines)
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        def submit(g):
            return pool.submit(synthesise_group, g, cache, args, work, read, list_path.parent,
                               stubs, progress)

        pending = {submit(g): g for g in groups}
        # The cached modules, read by the same path (each is a group of one found in the cache).
        for n in order:
            if cache.entry(mods[n].key).joinpath("meta.json").is_file():
                pending[submit([mods[n]])] = [mods[n]]
        while pending:
            done, _ = concurrent.futures.wait(pending, return_when=concurrent.futures.FIRST_COMPLETED)
            for f in done:
                g = pending.pop(f)
                try:
                    results.update(f.result())
                except GroupError as e:
                    note(f"{e}; its modules run again one by one")
                    for m in g:
                        pending[submit([m])] = [m]
                except RuntimeError as e:
                    failures.append(str(e))
                    note(f"FAILED: {e}")
    for n in order:
        if n in results:
            meta, stat, sta, cached = results[n]
            mods[n].own = parse_stat(stat, children=set(mods))
            mods[n].sta = parse_sta(sta)
            mods[n].meta, mods[n].cached = meta, cached
            cache.timings[n] = meta.get("seconds")
    try:
        tmp = timings_file.with_suffix(f".tmp{os.getpid()}")
        tmp.write_text(json.dumps(cache.timings) + "\n")
        os.replace(tmp, timings_file)
    except OSError:
        pass
    removed, size = cache.trim()
    wall = time.monotonic() - t0
    if not failures:
        shutil.rmtree(work, ignore_errors=True)
    report = {"top": args.top, "parameters": dict(args.params), "yosys": YOSYS_VERSION,
              "flow": FLOW_VERSION, "derived_modules": len(order),
              "synthesised": sum(1 for n in results if not results[n][3]),
              "cached": sum(1 for n in results if results[n][3]),
              "elaborated": texts is not None, "elaboration_seconds": round(elab_secs, 1),
              "wall_seconds": round(wall, 1),
              "cache": {"path": str(cache.path), "removed": removed, "bytes": size}}
    if failures:
        report["status"] = "failed"
        report["failures"] = sorted(failures)
        return report, None
    report["status"] = "ok"
    total = Counter()
    for n in order:
        for t, k in mods[n].own.items():
            total[t] += k * mods[n].count
    report["totals"] = columns(total)
    report["cells"] = dict(sorted(total.items()))
    other = sorted(t for t in total if not known_cell(t))
    if other:
        report["other_cells"] = {t: total[t] for t in other}
    stas = [(mods[n].sta, mods[n].hdlname) for n in order if mods[n].sta is not None]
    worst = max(stas) if stas else (None, None)
    report["sta_ns"], report["sta_module"] = worst
    report["synthesis_cpu_seconds"] = round(sum(mods[n].meta.get("cpu_seconds") or 0
                                                for n in order), 1)
    report["modules"] = [
        {"module": n, "hdlname": mods[n].hdlname, "parameters": describe_params(mods[n]),
         "instances": mods[n].count, "own": columns(mods[n].own),
         "total": columns(Counter({t: k * mods[n].count for t, k in mods[n].own.items()})),
         "sta_ns": mods[n].sta, "seconds": mods[n].meta.get("seconds"),
         "cached": mods[n].cached, "key": mods[n].key}
        for n in order]
    report["units"] = {
        u: {"instances": inst, **columns(cells)}
        for u, (inst, cells) in sorted(units(mods, order, top, is_block).items(),
                                       key=lambda kv: -columns(kv[1][1])["lut_sites"])}
    return report, total


def module_files(list_path, sources):
    """{module name: its source file, relative to the list's directory}."""
    out = {}
    for s in sources:
        text = (list_path.parent / s).read_text(errors="replace")
        for m in re.finditer(r"^\s*module\s+([A-Za-z_][A-Za-z0-9_$]*)", text, re.M):
            out.setdefault(m.group(1), s)
    return out


def run_monolithic(args):
    list_path = Path(args.list).resolve()
    sources, incdirs = rtl_files.read_list(list_path)
    work = Path(tempfile.mkdtemp(prefix="synth_hier.mono.", dir=args.work or None))
    read = read_args(incdirs, sources, args.defines)
    chparam = "".join(f" -chparam {p} {v}" for p, v in args.params)
    (work / "mono.ys").write_text(MONO_SCRIPT.format(read=read, top=args.top, chparam=chparam,
                                                     stat=work / "stat.txt"))
    note(f"monolithic run of {args.top}: one Yosys process (work dir {work})")
    status, secs = run_yosys(work / "mono.ys", list_path.parent, work / "mono.log",
                             args.mono_timeout, args.mono_mem)
    if status != "ok":
        die(f"the monolithic run of {args.top} failed ({status}); see {work / 'mono.log'}", 1)
    cpu, peak = parse_log_usage((work / "mono.log").read_text(errors="replace"))
    stat = (work / "stat.txt").read_text()
    cells = parse_stat(stat, hierarchy=True)
    # Each module's own cells (for a comparison module by module with the flow's).
    parts = re.split(r"^=== (.*) ===$", stat, flags=re.M)
    names = {parts[k] for k in range(1, len(parts), 2)}
    own = {parts[k]: columns(parse_stat(parts[k + 1], children=names))
           for k in range(1, len(parts), 2) if parts[k] != "design hierarchy"}
    shutil.rmtree(work, ignore_errors=True)
    return {"totals": columns(cells), "cells": dict(sorted(cells.items())), "modules": own,
            "wall_seconds": round(secs, 1), "cpu_seconds": cpu, "peak_mb": peak}


# ---------------------------------------------------------------- output

def fmt(v):
    if isinstance(v, float) and not v.is_integer():
        return f"{v:,.1f}"
    return f"{int(v):,}"


def markdown(report, mono=None, top_rows=None):
    out = []
    p = " ".join(f"{k}={v}" for k, v in report["parameters"].items()) or "defaults"
    out.append(f"## {report['top']} ({p})\n")
    out.append(f"{report['derived_modules']} derived modules: {report['synthesised']} synthesised, "
               f"{report['cached']} from the cache; {report['wall_seconds']:.0f} s wall "
               f"(elaboration {report['elaboration_seconds']:.0f} s), {report['yosys']}.\n")
    if report["status"] != "ok":
        out.append("**FAILED** (no totals):\n")
        out += [f"- {f}" for f in report["failures"]]
        return "\n".join(out) + "\n"
    t = report["totals"]
    out.append("| | LUT sites | LUT | INV | SRL | LUTRAM | FF | DSP48E1 | BRAM36 | CARRY4 | MUXF7/8 |")
    out.append("|---|---|---|---|---|---|---|---|---|---|---|")
    keys = ["lut_sites", "lut", "inv", "srl", "lutram", "ff", "dsp", "bram36", "carry4", "muxf"]
    out.append("| this flow | " + " | ".join(fmt(t[k]) for k in keys) + " |")
    if mono:
        out.append("| monolithic | " + " | ".join(fmt(mono["totals"][k]) for k in keys) + " |")
    sta = report["sta_ns"]
    out.append(f"\nSlowest module (sta, its own logic): {sta:.2f} ns ({report['sta_module']})."
               if sta is not None else "")
    if report.get("other_cells"):
        out.append("Other cells: " + ", ".join(f"{k} {v}" for k, v in report["other_cells"].items()))
    out.append("\n### By unit (a unit with the building blocks under it)\n")
    out.append("| unit | instances | LUT sites | of them SRL | FF | DSP48E1 | BRAM36 | "
               "share of LUT sites / FF / DSP48E1 |")
    out.append("|---|---|---|---|---|---|---|---|")

    def share(c, k):
        return f"{100 * c[k] / t[k]:.0f} %" if t[k] else "-"

    for u, c in report["units"].items():
        out.append(f"| {u} | {fmt(c['instances'])} | {fmt(c['lut_sites'])} | {fmt(c['srl'])} | "
                   f"{fmt(c['ff'])} | {fmt(c['dsp'])} | {fmt(c['bram36'])} | "
                   f"{share(c, 'lut_sites')} / {share(c, 'ff')} / {share(c, 'dsp')} |")
    rows = sorted(report["modules"], key=lambda r: -r["total"]["lut_sites"])
    if top_rows:
        rows = rows[:top_rows]
    out.append("\n### By derived module (own logic; total = own x instances)\n")
    out.append("| module | parameters | instances | LUT sites | FF | DSP48E1 | BRAM36 | "
               "total LUT sites | total FF | total DSP48E1 | sta ns | Yosys s |")
    out.append("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        o, tt = r["own"], r["total"]
        par = r["parameters"] if len(r["parameters"]) <= 48 else r["parameters"][:45] + "..."
        sta = f"{r['sta_ns']:.2f}" if r["sta_ns"] is not None else "-"
        out.append(f"| {r['hdlname']} | {par} | {r['instances']} | {fmt(o['lut_sites'])} | "
                   f"{fmt(o['ff'])} | {fmt(o['dsp'])} | {fmt(o['bram36'])} | "
                   f"{fmt(tt['lut_sites'])} | {fmt(tt['ff'])} | {fmt(tt['dsp'])} | {sta} | "
                   f"{r['seconds']} |")
    return "\n".join(out) + "\n"


# The columns --compare holds to the tolerance (the area of docs/resources.md); CARRY4 and
# MUXF7/8 are shown beside them.
CHECKED = ["lut_sites", "lut", "inv", "srl", "lutram", "ff", "dsp", "bram36"]


def compare(report, mono, tolerance):
    """Lines of the comparison and whether every checked column is within tolerance (a
    fraction of the monolithic count)."""
    lines, ok = [], True
    for k in CHECKED + ["carry4", "muxf"]:
        a, b = report["totals"][k], mono["totals"][k]
        d = (a - b) / b if b else (0.0 if a == b else float("inf"))
        if k in CHECKED:
            good = abs(d) <= tolerance
            ok &= good
            verdict = "ok  " if good else "FAIL"
        else:
            verdict = "    "
        lines.append(f"{verdict} {k:10s} flow {fmt(a):>10s}  monolithic {fmt(b):>10s}  "
                     f"{100 * d:+.3f} %")
    return lines, ok


def parse_args(argv):
    ap = argparse.ArgumentParser(
        prog="synth_hier.py", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("top", help="the top module")
    ap.add_argument("-G", dest="params", action="append", default=[], metavar="PARAM=VALUE",
                    help="a parameter of the top (repeatable)")
    ap.add_argument("-D", dest="defines", action="append", default=[], metavar="MACRO[=VALUE]",
                    help="a Verilog macro for every read_verilog (repeatable), e.g. "
                         "RPU_MUL_LUT_TILE=0: rpu_mul without narrow tiles")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1,
                    help="Yosys processes at once (default: the cores)")
    ap.add_argument("-t", "--timeout", type=float, default=3600,
                    help="time limit per derived module, s (default 3600)")
    ap.add_argument("--group-seconds", type=float, default=20,
                    help="a module expected to take less than this goes into a job with others "
                         "(default 20 s; each Yosys process costs about 3 s of reading)")
    ap.add_argument("--group-size", type=int, default=32,
                    help="the most modules in one job (default 32; 1: every module alone)")
    ap.add_argument("--elab-timeout", type=float, default=1800,
                    help="time limit of the elaboration, s (default 1800)")
    ap.add_argument("-m", "--mem", type=int, default=8000,
                    help="memory limit per Yosys process, MB of address space (default 8000)")
    ap.add_argument("--list", default=str(ROOT / "rtl" / "rpu.f"),
                    help="the RTL file list (default rtl/rpu.f)")
    ap.add_argument("--blocks", action="append", default=None, metavar="DIR",
                    help="building blocks: modules of this directory of the list count to the "
                         "unit above them (repeatable; default common)")
    ap.add_argument("--cache", default=str(ROOT / "build" / "synth_cache"),
                    help="the cache directory (default build/synth_cache)")
    ap.add_argument("--cache-max-mb", type=int, default=1024,
                    help="the cache's size bound, MB (default 1024)")
    ap.add_argument("--work", default=None,
                    help="where the jobs run (default: a temporary directory; kept on failure)")
    ap.add_argument("-n", "--dry-run", action="store_true",
                    help="elaborate and plan only: the derived modules, which are cached, the "
                         "jobs and their expected time; nothing synthesised")
    ap.add_argument("--json", help="write the whole report as JSON to this file")
    ap.add_argument("--md", help="write the Markdown tables to this file")
    ap.add_argument("--rows", type=int, default=0,
                    help="derived-module rows in the Markdown (largest first; default all)")
    ap.add_argument("--compare", action="store_true",
                    help="also run the monolithic hierarchical synthesis (one Yosys process) "
                         "and compare the totals")
    ap.add_argument("--monolithic-only", action="store_true",
                    help="only the monolithic run (its totals as the report)")
    ap.add_argument("--tolerance", type=float, default=1.0,
                    help="--compare: the largest difference per column, %% (default 1)")
    ap.add_argument("--mono-timeout", type=float, default=4 * 3600)
    ap.add_argument("--mono-mem", type=int, default=24000)
    args = ap.parse_args(argv)
    params = []
    for g in args.params:
        m = re.fullmatch(r"([A-Za-z_][A-Za-z0-9_]*)=(\S+)", g)
        if not m:
            die(f"-G {g}: expected PARAM=VALUE")
        params = [p for p in params if p[0] != m.group(1)] + [(m.group(1), m.group(2))]
    args.params = params
    if args.jobs < 1:
        die("-j needs a positive number")
    if min(args.timeout, args.mono_timeout, args.elab_timeout) <= 0:
        die("a time limit must be positive")
    if args.cache_max_mb < 0:
        die("--cache-max-mb cannot be negative")
    args.blocks = args.blocks or ["common"]
    return args


def main(argv):
    global YOSYS_VERSION
    args = parse_args(argv)
    if shutil.which("yosys") is None:
        die("yosys not found (scripts/setup.sh installs it)")
    YOSYS_VERSION = subprocess.run(["yosys", "-V"], capture_output=True, text=True).stdout.strip()
    signal.signal(signal.SIGINT, stop_all)
    signal.signal(signal.SIGTERM, stop_all)
    mono = None
    if args.monolithic_only:
        mono = run_monolithic(args)
        report = {"top": args.top, "parameters": dict(args.params), "status": "ok",
                  "yosys": YOSYS_VERSION, "monolithic": mono, "totals": mono["totals"],
                  "cells": mono["cells"]}
        text = json.dumps(report, indent=1)
        if args.json:
            Path(args.json).write_text(text + "\n")
        print(text)
        return 0
    report, _ = run_flow(args)
    if args.dry_run:
        text = json.dumps(report, indent=1)
        if args.json:
            Path(args.json).write_text(text + "\n")
        print(f"{report['derived_modules']} derived modules, {report['to_synthesise']} to "
              f"synthesise in {report['jobs']} jobs, about {report['expected_seconds']:.0f} s of "
              "Yosys")
        return 0
    status = 0 if report["status"] == "ok" else 1
    if args.compare and status == 0:
        mono = run_monolithic(args)
        report["monolithic"] = mono
        lines, ok = compare(report, mono, args.tolerance / 100)
        report["comparison"] = {"tolerance_percent": args.tolerance, "ok": ok, "lines": lines}
        for l in lines:
            print(f"synth_hier: {l}", file=sys.stderr)
        if not ok:
            status = 1
    md = markdown(report, mono, args.rows)
    if args.json:
        Path(args.json).write_text(json.dumps(report, indent=1) + "\n")
    if args.md:
        Path(args.md).write_text(md)
    print(md, end="")
    if status:
        for f in report.get("failures", []):
            print(f"synth_hier: FAILED: {f}", file=sys.stderr)
        if report["status"] == "ok":
            print("synth_hier: the flow's totals differ from the monolithic run's by more than "
                  f"{args.tolerance} %", file=sys.stderr)
    return status


YOSYS_VERSION = ""

if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
