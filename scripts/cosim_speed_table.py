#!/usr/bin/env python3
"""The co-simulation speed table of docs/cosim.md ("Speed"), from an `rpu demo` run:

    build/rpu demo --size 256x256 --out out/bench256
    python3 scripts/cosim_speed_table.py out/bench256/summary.json > table.md

One row per built-in scene, in the demo's order: the work items the RTL processed, the cycles and
latency the simulation counted, the wall time of the co-simulation, items and cycles simulated
per second. A scene the RTL does not trace (surfaces, patches) shows "n/a" and why. The numbers are
a benchmark of the machine that ran the demo, reported, never asserted.
"""

import json
import sys


def fmt_int(v):
    return f"{int(v):,}"


def main():
    if len(sys.argv) != 2:
        print("usage: cosim_speed_table.py SUMMARY.json", file=sys.stderr)
        return 2
    with open(sys.argv[1], encoding="utf-8") as f:
        rows = json.load(f)
    if not isinstance(rows, list):
        print(f"{sys.argv[1]}: not an rpu demo summary (a JSON array)", file=sys.stderr)
        return 1
    out = ["| scene | size | work items | cycles | latency | co-simulation s | items/s | cycles/s |",
           "|---|---|---|---|---|---|---|---|"]
    for m in rows:
        rtl = m.get("rtl")
        cfg = m.get("config") or {}
        size = f"{m.get('width', cfg.get('width', '?'))}×{m.get('height', cfg.get('height', '?'))}"
        if not isinstance(rtl, dict) or rtl.get("cycles") is None:
            why = ", ".join(m.get("not_applicable") or []) or "not run"
            out.append(f"| {m['scene']} | {size} | n/a ({why}) | | | | | |")
            continue
        out.append(
            f"| {m['scene']} | {size} | {fmt_int(rtl['pairs'])} | {fmt_int(rtl['cycles'])} | "
            f"{fmt_int(rtl['latency_cycles'])} | {rtl['sim_seconds']:.1f} | "
            f"{fmt_int(round(rtl['items_per_second']))} | {fmt_int(round(rtl['cycles_per_second']))} |")
    print("\n".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
