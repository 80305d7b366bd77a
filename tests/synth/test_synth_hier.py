#!/usr/bin/env python3
"""CTest synth_hier_flow: the cached hierarchical synthesis flow (scripts/synth_hier.py) on a
purpose-built three-level design (tests/synth/hier/: a top, two parameter sets of a unit, and
multipliers, delay lines and RAMs under them), in a copy so that it can be edited:

 1. cold: every derived module synthesised; the instance counts are the design's; the totals
    are the sum of each module's own cells times its instances, and equal a monolithic run
    (synth_xilinx + stat -top in one Yosys process) within 1 % on every column;
 2. nothing changed: nothing synthesised, no elaboration, the same totals; --dry-run plans
    nothing to synthesise;
 3. a comment added to a leaf (its lines move): nothing synthesised;
 4. the leaf's logic changed: exactly its derived modules synthesised again, the totals move,
    and they equal a monolithic run of the edited design;
 5. a derived module that times out or fails names itself, exit status 1 and no totals (never a
    partial sum); elaboration errors (an unknown top, an unknown parameter) are one line and
    exit status 2;
 6. the size bound: a run under --cache-max-mb 0 keeps its own entries and removes the others,
    which a later run synthesises again;
 7. a macro (-D) reaches the leaf that reads it: only its derived modules synthesised again, and
    the run without it keeps its cached plan.

Usage: test_synth_hier.py [WORKDIR]   (default: a temporary directory, removed at the end)
"""
import json
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
FLOW = ROOT / "scripts" / "synth_hier.py"
DESIGN = Path(__file__).resolve().parent / "hier"
failures = []


def check(cond, what):
    print(f"{'ok  ' if cond else 'FAIL'} {what}", flush=True)
    if not cond:
        failures.append(what)
    return cond


def flow(work, name, *extra, cache="cache", top="hier_top"):
    """Runs the flow on the copy; returns (exit status, report or None, stderr)."""
    out = work / f"{name}.json"
    out.unlink(missing_ok=True)
    cmd = [sys.executable, str(FLOW), "--list", str(work / "design" / "hier.f"), "--blocks",
           "blocks", "--cache", str(work / cache), "--work", str(work), "-j", "2", "--json",
           str(out), *extra, top]
    print("$ " + " ".join(cmd[1:]), flush=True)
    p = subprocess.run(cmd, capture_output=True, text=True)
    report = json.loads(out.read_text()) if out.exists() else None
    return p.returncode, report, p.stderr


def module_rows(report, hdlname):
    return [m for m in report["modules"] if m["hdlname"] == hdlname]


def check_same_module():
    """same_module: Yosys' generated names numbered in another order are the same module; the
    same names connected differently are not."""
    sys.path.insert(0, str(ROOT / "scripts"))
    import synth_hier
    a = ("  wire width 4 $1$memwr$\\m$3_DATA[3:0]$18\n  wire width 4 $1$memwr$\\m$3_EN[3:0]$19\n"
         "  connect \\d $1$memwr$\\m$3_DATA[3:0]$18\n  connect \\e $1$memwr$\\m$3_EN[3:0]$19\n")
    b = ("  wire width 4 $1$memwr$\\m$3_DATA[3:0]$19\n  wire width 4 $1$memwr$\\m$3_EN[3:0]$18\n"
         "  connect \\d $1$memwr$\\m$3_DATA[3:0]$19\n  connect \\e $1$memwr$\\m$3_EN[3:0]$18\n")
    swapped = b.replace("connect \\d", "connect \\x").replace("connect \\e", "connect \\d") \
               .replace("connect \\x", "connect \\e")
    check(synth_hier.same_module(a, b), "same_module: generated names made in another order match")
    check(not synth_hier.same_module(a, swapped),
          "same_module: the same wires connected the other way round do not match")


def main():
    check_same_module()
    if shutil.which("yosys") is None:
        print("yosys not found (scripts/setup.sh installs it)")
        return 1
    keep = len(sys.argv) > 1
    work = Path(sys.argv[1]) if keep else Path(tempfile.mkdtemp(prefix="synth_hier_test."))
    if keep:
        shutil.rmtree(work, ignore_errors=True)
        work.mkdir(parents=True)
    shutil.copytree(DESIGN, work / "design")
    columns = ["lut_sites", "lut", "inv", "srl", "lutram", "ff", "dsp", "bram36"]
    try:
        # 1. cold, against the monolithic run
        rc, r1, err = flow(work, "cold", "--compare")
        if not check(rc == 0 and r1 and r1["status"] == "ok", f"cold run ok (exit {rc})"):
            print(err)
            return 1
        check(r1["derived_modules"] == 11 and r1["synthesised"] == 11 and r1["cached"] == 0,
              f"cold: 11 derived modules, all synthesised ({r1['synthesised']}, "
              f"{r1['cached']} cached)")
        counts = {(m["hdlname"], m["parameters"]): m["instances"] for m in r1["modules"]}
        want = {("hier_top", ""): 1, ("hier_unit", "W=12"): 3, ("hier_unit", "W=20"): 1,
                ("hier_mul", "AW=12 BW=12"): 6, ("hier_mul", "AW=13 BW=13"): 3,
                ("hier_mul", "AW=20 BW=20"): 2, ("hier_mul", "AW=21 BW=21"): 1,
                ("hier_delay", "W=12 D=12"): 3, ("hier_delay", "W=20 D=20"): 1,
                ("hier_ram", "W=12 AW=5"): 3, ("hier_ram", "W=20 AW=5"): 1}
        check(counts == want, f"instance counts of the tree: {counts}")
        summed = {k: sum(m["own"][k] * m["instances"] for m in r1["modules"]) for k in columns}
        check(all(summed[k] == r1["totals"][k] for k in columns),
              f"totals = sum of own cells x instances ({summed})")
        unit = r1["units"]["hier_unit"]
        check(unit["instances"] == 4 and unit["dsp"] == r1["totals"]["dsp"],
              f"the unit hier_unit holds its 4 instances and every DSP48E1 ({unit})")
        mono = r1["monolithic"]["totals"]
        for k in columns:
            a, b = r1["totals"][k], mono[k]
            check(abs(a - b) <= 0.01 * b, f"{k}: flow {a}, monolithic {b} (within 1 %)")
        check(r1["totals"]["dsp"] > 0 and r1["totals"]["srl"] > 0 and r1["totals"]["lutram"] > 0,
              "the design exercises DSP48E1, SRL and LUTRAM")

        # 2. nothing changed
        rc, r2, _ = flow(work, "warm")
        check(rc == 0 and r2["synthesised"] == 0 and r2["cached"] == 11,
              f"warm: nothing synthesised ({r2['synthesised']}), 11 from the cache")
        check(r2["elaborated"] is False, "warm: no elaboration (the plan is cached)")
        check(r2["totals"] == r1["totals"], "warm: the same totals")

        rc, rd, _ = flow(work, "dry", "--dry-run")
        check(rc == 0 and rd["status"] == "dry run" and rd["derived_modules"] == 11 and
              rd["to_synthesise"] == 0, f"--dry-run on the warm cache: 11 modules, none to "
              f"synthesise ({rd['to_synthesise']})")

        # 3. a comment: the lines move, the logic does not
        leaf = work / "design" / "blocks" / "hier_delay.v"
        text = leaf.read_text()
        leaf.write_text("// A comment that moves every line of the module.\n\n" + text)
        rc, r3, _ = flow(work, "comment")
        check(rc == 0 and r3["synthesised"] == 0 and r3["elaborated"] is True,
              f"comment: elaborated again, nothing synthesised ({r3['synthesised']})")

        # 4. the leaf's logic changed: its two derived modules run again, nothing else
        leaf.write_text(text.replace("assign q_o = sr[D-1];", "assign q_o = ~sr[D-1];"))
        rc, r4, err = flow(work, "edit", "--compare")
        check(rc == 0 and r4["synthesised"] == 2 and r4["cached"] == 9,
              f"edit of hier_delay: 2 synthesised ({r4['synthesised']}), 9 from the cache "
              f"({r4['cached']})")
        again = sorted(m["hdlname"] for m in r4["modules"] if not m["cached"])
        check(again == ["hier_delay", "hier_delay"], f"the modules synthesised again: {again}")
        check(r4["totals"] != r1["totals"], "edit: the totals moved")
        check(r4.get("comparison", {}).get("ok") is True,
              "edit: the totals equal the monolithic run of the edited design within 1 %")

        # 5. failures name themselves; no partial sums
        rc, r5, err = flow(work, "timeout", "-t", "0.2", cache="cache_timeout")
        check(rc == 1 and r5 is not None and r5["status"] == "failed" and "totals" not in r5,
              f"timeout: exit 1, status failed, no totals (exit {rc})")
        named = r5 and all("timeout" in f and f.split(" ")[0].startswith("hier_")
                           for f in r5["failures"])
        first = ((r5 or {}).get("failures") or [""])[0]
        check(bool(named), f"timeout: each failure names its module ({first[:100]})")
        check("FAILED: hier_" in err, "timeout: stderr names a failed module")
        rc, r6, err = flow(work, "nomem", "-m", "40", "--elab-timeout", "600",
                           cache="cache_nomem")
        check(rc in (1, 2) and (r6 is None or "totals" not in r6),
              f"40 MB per Yosys process: exit {rc}, no totals")
        rc, _, err = flow(work, "notop", top="no_such_module")
        msg = [l for l in err.splitlines() if l.startswith("synth_hier:")]
        check(rc == 2 and len(msg) == 1 and "no_such_module" in msg[0],
              f"unknown top: exit 2, one line naming it ({msg})")
        rc, _, err = flow(work, "noparam", "-G", "Nope=3", top="hier_unit")
        msg = [l for l in err.splitlines() if l.startswith("synth_hier:")]
        check(rc == 2 and len(msg) == 1 and "Nope" in msg[0],
              f"unknown parameter: exit 2, one line naming it ({msg})")

        # 6. the size bound
        rc, r7, _ = flow(work, "bound", "-G", "W=14", "--cache-max-mb", "0", top="hier_unit")
        check(rc == 0 and r7["cache"]["removed"] > 0,
              f"bound 0: the entries this run did not use removed ({r7['cache']['removed']})")
        kept = [d for d in (work / "cache").glob("??/*") if d.is_dir()]
        check(len(kept) == r7["derived_modules"],
              f"bound 0: only this run's {r7['derived_modules']} entries kept ({len(kept)})")
        rc, r8, _ = flow(work, "after_bound")
        check(rc == 0 and r8["synthesised"] > 0 and r8["totals"] == r4["totals"],
              f"after the bound: the top synthesised again ({r8['synthesised']}), same totals")

        # 7. a macro (-D) is part of the plan and of each job's key: a leaf that reads it runs
        # again, nothing else does, and the plan without the macro is still the cached one
        ram = work / "design" / "blocks" / "hier_ram.v"
        ram.write_text(ram.read_text().replace(
            "  assign rd_o = mem[ra_i];",
            "`ifdef HIER_RAM_INVERT\n  assign rd_o = ~mem[ra_i];\n`else\n"
            "  assign rd_o = mem[ra_i];\n`endif"))
        rc, r9, _ = flow(work, "macro_off")
        check(rc == 0 and r9["synthesised"] == 0,
              f"-D: the leaf reads a macro it is not given: nothing synthesised ({r9['synthesised']})")
        rc, r10, _ = flow(work, "macro_on", "-D", "HIER_RAM_INVERT")
        again = sorted(m["hdlname"] for m in (r10 or {}).get("modules", []) if not m["cached"])
        check(rc == 0 and again == ["hier_ram", "hier_ram"],
              f"-D HIER_RAM_INVERT: exactly hier_ram's two derived modules synthesised ({again})")
        rc, r11, _ = flow(work, "macro_off_again")
        check(rc == 0 and r11["synthesised"] == 0 and r11["elaborated"] is False and
              r11["totals"] == r9["totals"],
              "without -D again: the cached plan and totals of the run without the macro")
    finally:
        if not keep and not failures:
            shutil.rmtree(work, ignore_errors=True)
    if failures:
        print(f"FAILED: {len(failures)} check(s); work directory {work}")
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
