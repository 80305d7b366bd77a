#!/usr/bin/env python3
"""Mutation testing of the RTL with Yosys `mutate` (docs/verification.md).

For each testbench of the plan, the design is elaborated exactly as that testbench builds it (its
sources and parameters, read from the manifest sim/CMakeLists.txt writes), `mutate -list` samples
mutations in the cells of the family's module, and every mutation is applied behind a selector
(`-ctrl mutsel`), so one Verilated build holds all of a testbench's mutants. The selector is read
at time zero through DPI from RPU_MUTSEL (sim/mutation/rpu_mutsel.cpp): 0 is the unmutated design,
which must pass first. Each mutant then runs the testbench (its CTest arguments) with a timeout.

  killed       the testbench failed (non-zero exit or a signal)
  timeout      it ran 4x the unmutated run time + 20 s (counted as detected)
  survived     it passed: a test gap, or a mutant equivalent to the design
  dead         Yosys's opt_clean removed the mutation's selector compare: the mutated signal
               reaches no output, so the mutant is equivalent (not run, not in the score)
  not compiled the family's mutated build failed (none is counted in the score)

Survivors shown equivalent are listed in sim/mutation/equivalent/<module>.tsv (mutation, reason);
the score is detected / (mutants - equivalent). Results are kept per mutant in the build directory
(results.tsv): a rerun skips what is done, so the run is resumable. Usage:

  scripts/mutate.py                      # the full plan (opt-in; about an hour on 2 cores)
  scripts/mutate.py --families rpu_fifo,rpu_div --jobs 2
  scripts/mutate.py --smoke              # the CTest smoke: a fixed 10 mutants, all must be killed
"""
from __future__ import annotations

import argparse
import concurrent.futures
import hashlib
import os
import re
import shlex
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import rtl_files  # scripts/rtl_files.py: the one Python reader of rtl/rpu.f

ROOT = Path(__file__).resolve().parent.parent
EQUIVALENT = ROOT / "sim" / "mutation" / "equivalent"  # <module>.tsv: the equivalent survivors
RTL_LIST = ROOT / "rtl" / "rpu.f"  # the RTL file list (its +incdir+ lines: the include directories)
CTRL_W = 12  # mutant selector width: up to 4,095 mutants per testbench


@dataclass(frozen=True)
class Family:
    name: str   # the module whose cells are mutated
    tb: str     # the testbench (CTest name) that must kill them
    count: int  # mutants sampled (Yosys `mutate -list`)


# The plan: every RTL module, with the testbench that checks it against its twin. A module that
# lives only inside another (rpu_add3/delay, rpu_surface_admit, rpu_surface_ip) is mutated in place
# in its parent's testbench; rpu_top's own logic (credits, FIFO merge, resolve hookup) runs the
# co-simulation frame (tb_rpu_top: every work item and pixel against the model).
PLAN = [
    Family("rpu_fifo", "tb_rpu_fifo_narrow", 30),
    Family("rpu_mul", "tb_rpu_mul_7x6s", 30),
    Family("rpu_div", "tb_rpu_div_n10_d8_q10", 40),
    Family("rpu_sqrt", "tb_rpu_sqrt_w16", 40),
    Family("rpu_resolve", "tb_rpu_resolve", 30),
    Family("rpu_chord", "tb_rpu_chord", 40),
    Family("rpu_sphere", "tb_rpu_sphere", 80),
    Family("rpu_ray_gen", "tb_rpu_ray_gen", 60),
    Family("rpu_candidate", "tb_rpu_candidate", 50),
    Family("rpu_guide_pair", "tb_rpu_guide_pair", 50),
    Family("rpu_curve_point", "tb_rpu_curve_point", 40),
    Family("rpu_ip_step", "tb_rpu_ip_step", 50),
    Family("rpu_ip", "tb_rpu_ip_iter_n8_n1_4", 50),
    Family("rpu_capture", "tb_rpu_capture", 50),
    Family("rpu_ray_plane", "tb_rpu_ray_plane", 50),
    Family("rpu_texture", "tb_rpu_texture", 60),
    Family("rpu_cordic", "tb_rpu_cordic_w8_vec", 50),
    Family("rpu_indicator", "tb_rpu_indicator", 80),
    Family("rpu_add3", "tb_rpu_indicator", 10),
    Family("rpu_delay", "tb_rpu_indicator", 10),
    Family("rpu_surface_setup", "tb_rpu_surface_setup", 80),
    Family("rpu_surface_ip_step", "tb_rpu_surface_ip_iter_lw18", 60),
    Family("rpu_surface_ip", "tb_rpu_surface_top_lw18", 30),
    Family("rpu_surface_top", "tb_rpu_surface_top_lw18", 40),
    Family("rpu_surface_admit", "tb_rpu_surface_top_lw18", 10),
    Family("rpu_top", "tb_rpu_top", 80),
]

# The order in which the elaboration reads a testbench's files. Yosys names the cells it creates
# from one counter that reading (elaborating) every file advances, and `mutate -list` samples by
# those names, so the files read and their order decide which mutants a seed draws. The rule: the
# top's file first, then the design's other files in rtl/rpu.f's order. The testbenches below keep
# the order their recorded results (docs/verification.md, sim/mutation/equivalent/) were drawn
# with (each testbench's own file list, before rtl/rpu.f), which the rule does not reproduce.
# Drop an entry once its families' results are recorded afresh (--fresh, and their survivors
# dispositioned again).
RECORDED_ORDER = {
    "tb_rpu_guide_pair": ["rpu_sqrt", "rpu_guide_pair", "rpu_mul"],
    "tb_rpu_indicator": ["rpu_indicator", "rpu_add3", "rpu_delay", "rpu_cordic",
                         "rpu_mul"],
}

# The CTest smoke: two mutants of each of five small testbenches, every one known to be killed.
SMOKE = [
    Family("rpu_fifo", "tb_rpu_fifo_narrow", 2),
    Family("rpu_mul", "tb_rpu_mul_7x6s", 2),
    Family("rpu_div", "tb_rpu_div_n10_d8_q10", 2),
    Family("rpu_sqrt", "tb_rpu_sqrt_w16", 2),
    Family("rpu_resolve", "tb_rpu_resolve", 2),
]


def die(msg: str) -> None:
    print(f"mutate.py: error: {msg}", file=sys.stderr)
    sys.exit(1)


def run(cmd: list[str], log: Path, env: dict | None = None) -> None:
    with open(log, "w") as f:
        r = subprocess.run(cmd, cwd=ROOT, stdout=f, stderr=subprocess.STDOUT, env=env)
    if r.returncode != 0:
        tail = log.read_text(errors="replace").splitlines()[-15:]
        die(f"{' '.join(cmd[:3])} ... failed (exit {r.returncode}), log {log}:\n" + "\n".join(tail))


def read_manifest(build: Path) -> dict[str, tuple[str, list[str], list[str], list[str]]]:
    path = build / "mutation" / "manifest.tsv"
    if not path.exists():
        die(f"{path}: no manifest (configure the build first)")
    out = {}
    for line in path.read_text().splitlines():
        name, top, sources, params, args = line.split("\t")
        split = lambda s: [x for x in s.split("|") if x]
        out[name] = (top, split(sources), split(params), split(args))
    return out


def rtl_include_args() -> str:
    """Yosys -I options for the include directories of rtl/rpu.f (relative to the checkout)."""
    _, incdirs = rtl_files.read_list(RTL_LIST)
    return " ".join(f"-I{rel(str(RTL_LIST.parent / d))}" for d in incdirs)


def rel(p: str) -> str:
    """A source path relative to the checkout (the src attributes and reports name no machine)."""
    try:
        return str(Path(p).resolve().relative_to(ROOT))
    except ValueError:
        return p


def cmake_env() -> dict:
    env = dict(os.environ)
    env["CCACHE_BASEDIR"] = str(ROOT)
    return env


def configure(build: Path, mutant_dir: Path | None, only: list[str]) -> None:
    build.mkdir(parents=True, exist_ok=True)
    # RPU_SIM_ONLY: only the plan's testbenches are Verilated (a configure of the whole suite
    # runs Verilator on every testbench and rpu_top configuration: minutes).
    cmd = ["cmake", "-S", str(ROOT), "-B", str(build), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
           "-DRPU_BENCH=OFF", f"-DRPU_MUTANT_DIR={mutant_dir or ''}",
           f"-DRPU_SIM_ONLY={';'.join(only)}"]
    run(cmd, build / "mutation-configure.log", cmake_env())


def mutation_key(line: str) -> str:
    """A mutation without its selector value and cell name: stable while the source is."""
    toks = shlex.split(line)
    out, i = [], 0
    while i < len(toks):
        t = toks[i]
        if t == "-ctrl":
            i += 4
            continue
        if t == "-cell":
            i += 2
            continue
        out.append(t)
        i += 1
    return " ".join(out[1:])  # without "mutate"


def src_of(line: str) -> str:
    m = re.findall(r"-src (\S+)", line)
    return ", ".join(m) if m else "?"


def design_sources(tb: str, top: str, sources: list[str], params: list[str],
                   work: Path) -> list[str]:
    """The files of a testbench's design: those defining its top and every module the top
    instantiates at its parameters, in the read order of RECORDED_ORDER. The manifest names every
    file of rtl/rpu.f (the testbench lets Verilator pick), but the elaboration must read only
    these: an unused file read along would change the mutants drawn (RECORDED_ORDER)."""
    chparam = " ".join(f"-set {p[2:].split('=')[0]} {p.split('=', 1)[1]}" for p in params)
    listing = work / f"{tb}.modules"
    ys = work / f"{tb}.modules.ys"
    ys.write_text(f"read_verilog {rtl_include_args()} {' '.join(rel(s) for s in sources)}\n"
                  + (f"chparam {chparam} {top}\n" if chparam else "")
                  + f"hierarchy -check -top {top}\ntee -q -o {listing} ls\n")
    run(["yosys", "-q", "-s", str(ys)], work / f"{tb}.modules.log")
    # `ls`: "N modules:", then one module name per line: <module>, or derived with parameters
    # $paramod$<hash>\<module> or $paramod\<module>\<parameter>=<value>...
    text = listing.read_text()
    names = re.findall(r"^\s+(\S+)$", text.split("modules:", 1)[-1], flags=re.M)
    used = {n.split("\\")[1] if n.startswith("$paramod") else n for n in names}
    out = []
    for s in sources:
        defined = set(re.findall(r"^\s*module\s+([A-Za-z_][A-Za-z0-9_$]*)", Path(s).read_text(),
                                 flags=re.M))
        if defined & used:
            out.append(s)
            used -= defined
    if used:
        die(f"{tb}: no file of the manifest defines {', '.join(sorted(used))}")
    # The read order: the recorded one if any, else the top's file first (then the list's order).
    rank = {m: k for k, m in enumerate(RECORDED_ORDER.get(tb, [top]))}
    return sorted(out, key=lambda s: rank.get(Path(s).stem, len(rank)))


def elaborate(tb: str, manifest, families: list[Family], seed: int, work: Path,
              mutant_dir: Path) -> list[tuple[int, Family, str, bool]]:
    """Writes mutant_dir/<tb>.v with every family's mutations; returns (selector, family, line,
    live) — live is false when nothing reads the mutated signal (its selector compare is gone)."""
    top, sources, params, _ = manifest[tb]
    sources = design_sources(tb, top, sources, params, work)
    chparam = " ".join(f"-set {p[2:].split('=')[0]} {p.split('=', 1)[1]}" for p in params)
    reads = " ".join(rel(s) for s in sources)
    base = [f"read_verilog {rtl_include_args()} {reads}"]
    if chparam:
        base.append(f"chparam {chparam} {top}")
    # A parameterised top may come out of `hierarchy` under a derived name: name it back.
    base += [f"hierarchy -check -top {top}", f"rename -top {top}", "prep -top " + top,
             "opt -full", "wreduce", "opt_clean"]
    # The elaboration is cached: the same sources, plan and seed give the same mutants.
    h = hashlib.sha256("\n".join(base + [repr(families), str(seed), str(CTRL_W)]).encode())
    for src in sources:
        h.update(Path(src).read_bytes())
    digest = h.hexdigest()
    stamp = work / f"{tb}.elaborated"
    cached = stamp.exists() and stamp.read_text() == digest
    mutants: list[tuple[int, Family, str]] = []
    next_sel = 1
    lists = []
    for fam in families:
        lst = work / f"{tb}.{fam.name}.list"
        # The family's module: the testbench's top itself, or every elaboration of a submodule.
        sel = fam.name if fam.name == top else f"$paramod*\\{fam.name} {fam.name} %u"
        script = base + [f"mutate -list {fam.count} -seed {seed} -ctrl mutsel {CTRL_W} {next_sel} "
                         f"-o {lst} {sel} t:$mem_v2 %d"]
        ys = work / f"{tb}.{fam.name}.list.ys"
        if not cached:
            ys.write_text("\n".join(script) + "\n")
            run(["yosys", "-q", "-s", str(ys)], work / f"{tb}.{fam.name}.list.log")
        lines = [l for l in lst.read_text().splitlines() if l.startswith("mutate ")]
        if not lines:
            die(f"{tb}: no mutation candidates in module {fam.name}")
        for l in lines:
            mutants.append((next_sel, fam, l))
            next_sel += 1
        lists.append(lst)
    if next_sel >= (1 << CTRL_W):
        die(f"{tb}: {next_sel - 1} mutants exceed the selector's {CTRL_W} bits")
    raw = work / f"{tb}.mutated.v"
    if not cached:
        script = base + [f"script {l}" for l in lists] + ["opt_clean",
                                                          f"write_verilog -noattr {raw}"]
        ys = work / f"{tb}.apply.ys"
        ys.write_text("\n".join(script) + "\n")
        run(["yosys", "-q", "-s", str(ys)], work / f"{tb}.apply.log")
        stamp.write_text(digest)
    text = raw.read_text()
    (mutant_dir / f"{tb}.v").write_text(select_by_dpi(text, top))
    live = {int(h, 16) for h in re.findall(rf"mutsel == {CTRL_W}'h([0-9a-f]+)", text)}
    return [(sel, fam, line, sel in live) for sel, fam, line in mutants]


def select_by_dpi(verilog: str, top: str) -> str:
    """The top's `mutsel` input (Yosys routes it down to every mutated module) becomes a register
    read from rpu_mutsel() through DPI, so the testbench keeps the ports it was written for."""
    m = re.search(rf"^module {re.escape(top)}\(.*?^endmodule$", verilog, flags=re.M | re.S)
    if not m:
        die(f"mutated design: no module {top}")
    body = m.group(0)
    # The header (its port list may span lines): drop the port, import the function.
    body, n = re.subn(r"^(module [^(;]*\((?:[^;])*?),\s*mutsel\s*\);$",
                      r'\1);\n  import "DPI-C" function int rpu_mutsel();', body,
                      count=1, flags=re.M | re.S)

    def reg(d: re.Match) -> str:
        msb = d.group(1)
        return (f"  integer mutsel_dpi;\n  reg [{msb}:0] mutsel;\n  initial begin\n"
                f"    mutsel_dpi = rpu_mutsel();\n    mutsel = mutsel_dpi[{msb}:0];\n  end")

    body, k = re.subn(r"^  input \[(\d+):0\] mutsel;$", reg, body, count=1, flags=re.M)
    body = re.sub(r"^  wire \[\d+:0\] mutsel;\n", "", body, count=1, flags=re.M)
    if n != 1 or k != 1:
        die(f"mutated design: module {top} has no mutsel input")
    return verilog[:m.start()] + body + verilog[m.end():]


def run_tb(exe: Path, args: list[str], sel: int, timeout: float) -> tuple[str, float]:
    env = dict(os.environ)
    env["RPU_MUTSEL"] = str(sel)
    t0 = time.monotonic()
    try:
        r = subprocess.run([str(exe)] + args, cwd=exe.parent, env=env, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", time.monotonic() - t0
    return ("survived" if r.returncode == 0 else "killed"), time.monotonic() - t0


def load_equivalent() -> dict[tuple[str, str], str]:
    """(module, mutation) → why the mutant is equivalent, from sim/mutation/equivalent/*.tsv."""
    eq = {}
    for path in sorted(EQUIVALENT.glob("*.tsv")):
        for n, line in enumerate(path.read_text().splitlines(), 1):
            if not line.strip() or line.startswith("#"):
                continue
            parts = line.split("\t")
            if len(parts) != 2 or not parts[1].strip():
                die(f"{path.relative_to(ROOT)}:{n}: expected 2 tab-separated fields "
                    "(mutation, reason)")
            eq[(path.stem, parts[0])] = parts[1]
    return eq


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build-dir", default=str(ROOT / "build-mutate"))
    ap.add_argument("--families", default="", help="comma-separated module names (default: all)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--scale", type=float, default=1.0, help="multiply every family's count")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--smoke", action="store_true",
                    help="the fixed CTest set: fail unless every mutant is killed")
    ap.add_argument("--report", default="", help="write the markdown report to this file")
    ap.add_argument("--fresh", action="store_true", help="forget earlier results of this build")
    ap.add_argument("--report-only", action="store_true",
                    help="no build, no run: the report from the results so far (mutants not "
                         "run yet are counted as such)")
    ap.add_argument("--rerun", default="",
                    help="comma-separated statuses to run again (e.g. survived,timeout: after "
                         "the tests improved)")
    a = ap.parse_args()

    plan = SMOKE if a.smoke else PLAN
    if a.families:
        want = a.families.split(",")
        unknown = [w for w in want if w not in {f.name for f in plan}]
        if unknown:
            die(f"--families: unknown {', '.join(unknown)} (known: "
                f"{', '.join(f.name for f in plan)})")
        plan = [f for f in plan if f.name in want]
    if a.scale != 1.0:
        plan = [Family(f.name, f.tb, max(1, round(f.count * a.scale))) for f in plan]

    build = Path(a.build_dir).resolve()
    work = build / "mutation"
    # A report does not touch the designs a running build may be compiling.
    mutant_dir = work / ("designs-report" if a.report_only else "designs")
    results_path = work / "results.tsv"
    if a.fresh and results_path.exists():
        results_path.unlink()

    # 1. The manifest (an ordinary configure), 2. the mutated designs, 3. the mutation build.
    if not a.report_only:
        configure(build, None, sorted({f.tb for f in plan}))
    manifest = read_manifest(build)
    for f in plan:
        if f.tb not in manifest:
            die(f"{f.name}: testbench {f.tb} is not in the manifest")
    mutant_dir.mkdir(parents=True, exist_ok=True)
    for stale in mutant_dir.glob("*.v"):
        stale.unlink()
    tbs: dict[str, list[Family]] = {}
    for f in plan:
        tbs.setdefault(f.tb, []).append(f)
    mutants: dict[str, list[tuple[int, Family, str, bool]]] = {}
    for tb, fams in tbs.items():
        mutants[tb] = elaborate(tb, manifest, fams, a.seed, work, mutant_dir)
        print(f"{tb}: {len(mutants[tb])} mutants of {', '.join(f.name for f in fams)}", flush=True)
    if not a.report_only:
        configure(build, mutant_dir, sorted({f.tb for f in plan}))

    done: dict[tuple[str, str], str] = {}
    if results_path.exists():
        for line in results_path.read_text().splitlines():
            tb, key, status = line.split("\t")[:3]
            done[(tb, key)] = status  # the last line of a mutant wins
    rerun = set(a.rerun.split(",")) if a.rerun else set()
    done = {k: v for k, v in done.items() if v not in rerun}
    results = open(results_path, "a")

    status_of: dict[tuple[str, int], str] = {}
    for tb, ms in (mutants.items() if a.report_only else []):
        for sel, fam, line, live in ms:
            key = mutation_key(line)
            status_of[(tb, sel)] = ("dead" if not live else done.get((tb, key), "not run"))
    for tb, ms in ([] if a.report_only else mutants.items()):
        log = work / f"{tb}.build.log"
        r = subprocess.run(["cmake", "--build", str(build), "-j", str(a.jobs), "--target", tb],
                           cwd=ROOT, stdout=open(log, "w"), stderr=subprocess.STDOUT,
                           env=cmake_env())
        if r.returncode != 0:
            print(f"{tb}: the mutated build failed (log {log}): {len(ms)} not compiled", flush=True)
            for sel, fam, line, live in ms:
                status_of[(tb, sel)] = "not compiled"
            continue
        exe = build / "sim" / tb
        _, _, _, args = manifest[tb]
        status, t0 = run_tb(exe, args, 0, 3600)
        if status != "survived":
            print(f"{tb}: the unmutated design fails its testbench ({status}): mutation build "
                  "broken", flush=True)
            for sel, fam, line, live in ms:
                status_of[(tb, sel)] = "not compiled"
            continue
        # A selector past the last mutant must pass too: the mutants are what the testbench kills.
        spare = max(m[0] for m in ms) + 1
        if run_tb(exe, args, spare, 10 * t0 + 20)[0] != "survived":
            print(f"{tb}: selector {spare} (no mutant) fails the testbench: mutation build broken",
                  flush=True)
            for sel, fam, line, live in ms:
                status_of[(tb, sel)] = "not compiled"
            continue
        timeout = 4 * t0 + 20
        todo = []
        for sel, fam, line, live in ms:
            key = mutation_key(line)
            if not live:
                status_of[(tb, sel)] = "dead"
            elif (tb, key) in done:
                status_of[(tb, sel)] = done[(tb, key)]
            else:
                todo.append((sel, fam, line, key))
        print(f"{tb}: unmutated run {t0:.1f} s; {len(todo)} mutants to run, "
              f"{len(ms) - len(todo)} done before", flush=True)
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
            futs = {pool.submit(run_tb, exe, args, sel, timeout): (sel, fam, line, key)
                    for sel, fam, line, key in todo}
            for fut in concurrent.futures.as_completed(futs):
                sel, fam, line, key = futs[fut]
                st, secs = fut.result()
                status_of[(tb, sel)] = st
                results.write(f"{tb}\t{key}\t{st}\t{secs:.1f}\n")
                results.flush()
    results.close()

    # The report.
    eq = load_equivalent()
    rows, survivors = [], []
    tot = {"mutants": 0, "killed": 0, "timeout": 0, "survived": 0, "dead": 0, "equivalent": 0,
           "not compiled": 0, "not run": 0}
    for f in plan:
        c = {k: 0 for k in tot}
        for sel, fam, line, _ in mutants[f.tb]:
            if fam != f:
                continue
            st = status_of.get((f.tb, sel), "not compiled")
            c["mutants"] += 1
            key = mutation_key(line)
            if st == "survived" and (f.name, key) in eq:
                c["equivalent"] += 1
                survivors.append((f, sel, line, "equivalent: " + eq[(f.name, key)]))
            else:
                c[st] += 1
                if st == "survived":
                    survivors.append((f, sel, line, "SURVIVED"))
        for k in tot:
            tot[k] += c[k]
        rows.append((f, c))

    def score(c) -> str:
        denom = c["mutants"] - c["dead"] - c["equivalent"] - c["not compiled"] - c["not run"]
        return f"{100.0 * (c['killed'] + c['timeout']) / denom:.1f} %" if denom else "n/a"

    lines = ["| module | testbench | mutants | killed | timeout | survived | dead | equivalent | "
             "not compiled | score |", "|---|---|---|---|---|---|---|---|---|---|"]
    for f, c in rows:
        lines.append(f"| `{f.name}` | `{f.tb}` | {c['mutants']} | {c['killed']} | {c['timeout']} | "
                     f"{c['survived']} | {c['dead']} | {c['equivalent']} | {c['not compiled']} | "
                     f"{score(c)} |")
    if tot["not run"]:
        lines.append(f"| (not run yet: {tot['not run']}) | | | | | | | | | |")
    lines.append(f"| **all** | | {tot['mutants']} | {tot['killed']} | {tot['timeout']} | "
                 f"{tot['survived']} | {tot['dead']} | {tot['equivalent']} | "
                 f"{tot['not compiled']} | **{score(tot)}** |")
    lines.append("")
    if survivors:
        lines.append("Survivors (family, selector, source, mutation, disposition):")
        lines.append("")
        for f, sel, line, disp in survivors:
            lines.append(f"- `{f.name}` #{sel} {src_of(line)}: `{mutation_key(line)}` — {disp}")
    report = "\n".join(lines) + "\n"
    print(report)
    if a.report:
        Path(a.report).write_text(report)
    (work / "report.md").write_text(report)

    open_survivors = tot["survived"]
    if a.smoke:
        bad = tot["survived"] + tot["not compiled"] + tot["equivalent"] + tot["dead"]
        if bad:
            print(f"mutate.py: smoke FAILED: {bad} of {tot['mutants']} mutants not killed")
            return 2
        print(f"mutate.py: smoke PASS: {tot['mutants']} of {tot['mutants']} mutants killed")
        return 0
    return 0 if open_survivors == 0 and tot["not compiled"] == 0 else 2


if __name__ == "__main__":
    sys.exit(main())
