#!/usr/bin/env python3
"""Measures how the build settings of the Verilated rpu_top change compile time and co-simulation
speed: the table of docs/cosim.md, "Build settings".

Each variant is a co-simulation-only build (RPU_COSIM_ONLY, one executable cosim_top at the
default hardware parameters, the unrolled form) with the cache variables of
sim/harness/CMakeLists.txt set: RPU_COSIM_OPT (the C++ optimisation of the model's evaluation
code), RPU_COSIM_X_ASSIGN, RPU_COSIM_TRACE (trace code compiled in, not switched on),
RPU_COSIM_THREADS and RPU_COSIM_DFG. The compile is timed with ccache off (a cold build of the
Verilated model on all cores; Verilator's own run, at configure time, is
timed apart); the speed is `rpu render --backend rtl --rtl-exe ...
--jobs 1` on one frame, every work item and pixel checked against the model.

    python3 scripts/cosim_build_table.py [--out DIR] [--scene builtin:curve12] [--size 128x128]
                                         [--only NAME ...] [--json FILE]

Prints the Markdown table; --json also writes the measurements. A benchmark: it reports, it
asserts nothing (a variant that fails to build or whose frame differs from the model is marked).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

import hw_params  # scripts/hw_params.py: the table of hardware parameters

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# name: (OPT_FAST, x-assign, trace, threads, dfg)
VARIANTS = [
    ("O0", "-O0", "unique", False, 1, False),
    ("O1", "-O1", "unique", False, 1, False),
    ("O2", "-O2", "unique", False, 1, False),
    ("O3", "-O3", "unique", False, 1, False),
    ("O2-xfast", "-O2", "fast", False, 1, False),
    ("O2-trace", "-O2", "unique", True, 1, False),
    ("O2-threads2", "-O2", "unique", False, 2, False),
    ("O2-dfg", "-O2", "unique", False, 1, True),
]


def default_params():
    """The Verilog parameters of rpu_top at the defaults, from the one table of parameters."""
    try:
        return ",".join(f"{k}={v}" for k, v in hw_params.verilog_defaults(ROOT).items())
    except ValueError as e:
        sys.exit(f"cosim_build_table.py: {e}")


def run(cmd, log, env=None):
    with open(log, "a") as f:
        f.write("$ " + " ".join(cmd) + "\n")
        f.flush()
        return subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, env=env).returncode


def measure(v, args, params):
    name, opt, xassign, trace, threads, dfg = v
    d = os.path.join(args.out, name)
    os.makedirs(d, exist_ok=True)
    log = os.path.join(d, "log.txt")
    open(log, "w").close()
    row = {"name": name, "opt": opt, "x_assign": xassign, "trace": trace, "threads": threads,
           "dfg": dfg}
    env = dict(os.environ, CCACHE_DISABLE="1")
    cfg = ["cmake", "-S", ROOT, "-B", d, "-G", "Ninja", "-DRPU_COSIM_ONLY=ON",
           f"-DRPU_COSIM_CONFIGS=top:{params}", f"-DRPU_COSIM_OPT={opt}",
           f"-DRPU_COSIM_X_ASSIGN={xassign}", f"-DRPU_COSIM_TRACE={'ON' if trace else 'OFF'}",
           f"-DRPU_COSIM_THREADS={threads}", f"-DRPU_COSIM_DFG={'ON' if dfg else 'OFF'}"]
    t0 = time.monotonic()
    if run(cfg, log, env) != 0:  # Verilator runs here (verilate() needs its file list)
        row["error"] = "configure failed"
        return row
    row["verilate_s"] = round(time.monotonic() - t0, 1)
    exe = os.path.join(d, "cosim_top")
    if args.run_only and os.path.exists(exe):
        old = previous(args, name)
        for k in ("verilate_s", "compile_s", "compile_cpu_s", "generated_mb"):
            if k in old:
                row[k] = old[k]
        return speed(row, exe, d, args)
    run(["ninja", "-C", d, "-t", "clean"], log, env)
    run(["ninja", "-C", d, "rpu_cosim"], log, env)  # the harness and the model: not timed
    t0 = time.monotonic()
    cpu0 = os.times()
    rc = run(["ninja", "-C", d, f"-j{os.cpu_count()}"], log, env)
    cpu1 = os.times()
    row["compile_s"] = round(time.monotonic() - t0, 1)
    # CPU seconds of the compilers: what the build costs, whatever else shares the machine.
    row["compile_cpu_s"] = round(cpu1.children_user + cpu1.children_system -
                                 cpu0.children_user - cpu0.children_system, 1)
    if rc != 0 or not os.path.exists(exe):
        row["error"] = "build failed"
        return row
    gen = os.path.join(d, "sim/harness/CMakeFiles/cosim_top.dir/Vrpu_top_top.dir")
    row["generated_mb"] = round(sum(os.path.getsize(os.path.join(gen, f)) for f in os.listdir(gen)
                                    if f.endswith((".cpp", ".h"))) / 1e6, 1) if os.path.isdir(gen) else None
    return speed(row, exe, d, args)


def previous(args, name):
    """The row of an earlier run (--json), for --run-only and the rows not measured again."""
    try:
        with open(args.json) as f:
            for r in json.load(f)["rows"]:
                if r["name"] == name:
                    return r
    except (OSError, ValueError, KeyError, TypeError):
        pass
    return {}


def speed(row, exe, d, args):
    """One frame on the build's executable, one instance: items/s and cycles/s."""
    out = subprocess.run([args.rpu, "render", args.scene, "--backend", "rtl", "--size", args.size,
                          "--jobs", "1", "--rtl-exe", exe, "-o", os.path.join(d, "frame.png")],
                         capture_output=True, text=True)
    m = re.search(r"(\d+) cycles, latency \d+, [\d.]+ items/cycle, (\d+) items/s, (\d+) cycles/s",
                  out.stderr)
    if out.returncode != 0 or not m:
        row["error"] = "frame differs from the model" if out.returncode == 2 else "run failed"
        row["stderr"] = out.stderr[-2000:]
        return row
    row["cycles"], row["items_per_s"], row["cycles_per_s"] = (int(m.group(k)) for k in (1, 2, 3))
    return row


def table(rows, args):
    lines = [f"| build | C++ -O | `--x-assign` | trace code | `--threads` | DFG | Verilator s | "
             f"C++ compile, CPU s | generated C++ MB | items/s | cycles/s |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        tail = (f"{r['items_per_s']:,} | {r['cycles_per_s']:,}" if "items_per_s" in r
                else f"{r.get('error', '?')} | ")
        lines.append(f"| {r['name']} | {r['opt']} | {r['x_assign']} | {'yes' if r['trace'] else 'no'}"
                     f" | {r['threads']} | {'on' if r['dfg'] else 'off'} | "
                     f"{r.get('verilate_s', '')} | {r.get('compile_cpu_s', '')} | {r.get('generated_mb', '')} | "
                     f"{tail} |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "cosim_builds"))
    ap.add_argument("--rpu", default=os.path.join(ROOT, "build", "rpu"))
    ap.add_argument("--scene", default="builtin:curve12")
    ap.add_argument("--size", default="128x128")
    ap.add_argument("--only", nargs="*", help="variant names (default: all)")
    ap.add_argument("--json", help="also write the measurements here")
    ap.add_argument("--run-only", action="store_true",
                    help="measure the speed of the variants already built (their compile times "
                         "from --json), e.g. again on an idle machine")
    args = ap.parse_args()
    params = default_params()
    # Rows of an earlier run (--json) are kept unless measured again.
    rows = {v[0]: previous(args, v[0]) for v in VARIANTS} if args.json else {}
    for v in VARIANTS:
        if args.only and v[0] not in args.only:
            continue
        r = measure(v, args, params)
        print(f"{v[0]}: {r}", file=sys.stderr, flush=True)
        rows[v[0]] = r
        if args.json:
            with open(args.json, "w") as f:
                json.dump({"scene": args.scene, "size": args.size, "cores": os.cpu_count(),
                           "rows": [x for x in rows.values() if x]}, f, indent=1)
    print(table([x for x in rows.values() if x], args))


if __name__ == "__main__":
    main()
