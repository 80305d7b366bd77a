#!/usr/bin/env python3
"""Throughput projection of the RPU (docs/throughput.md): frames per second of each demo scene at
1920x1080 on a few FPGA parts, from measured inputs. A PROJECTION: the clock is Yosys' static
timing estimate of cell delays (no placement, no routing), the area a synthesis estimate.

Every input below names where it was measured; the area and the clock are read from the first
table of docs/resources.md. Rerun after a change of the design and paste the output into
docs/throughput.md:

    python3 scripts/throughput_projection.py > /tmp/t.md
"""

import math
import pathlib
import re

# Work items (ray/segment pairs) per 1920x1080 frame: `rpu render builtin:S --backend ref
# --size 1920x1080` ("ray/segment pairs"); equal to the co-simulation's item count (curve12 at
# 256x256: 205,824 both).
PAIRS_1080P = {
    "curve12": 7_539_776,
    "ellipse6": 3_058_729,
    "polyline9": 2_843_580,
    "airfield": 580_678,
}

# The clock: the slowest register-to-register path of the modules (the rpu_top rows' sta ns in
# docs/resources.md, Yosys `sta` with the -specify cell library). Rule of thumb from issue 10:
# 3.0 ns of cell delay is about 200 MHz after routing, i.e. routing adds about 2/3.
ROUTING_FACTOR = 5.0 / 3.0

# One unit of each form at the defaults (n = 16, n1 = 2, coord_w 24): the rpu_top rows of the
# first table of docs/resources.md (LUT sites, FF, DSP48E1, BRAM36, source, sta ns), read from
# there so that the figures have one home; items per cycle measured by the co-simulation
# (docs/rtl.md: one per cycle unrolled, 1/K = 0.124 iterative).
ITEMS_PER_CYCLE = {"unrolled": 1.0, "iterative": 0.124}


def number(cell):
    """The first number of a table cell ('**263,349**', '≤ 3.98 (modules)', '7.5')."""
    m = re.search(r"\d[\d,]*(?:\.\d+)?", cell)
    if not m:
        raise ValueError(f"no number in table cell '{cell}'")
    v = m.group(0).replace(",", "")
    return float(v) if "." in v else int(v)


def read_forms(resources):
    """The rpu_top rows of the first table of docs/resources.md ("## The current design")."""
    text = resources.read_text(encoding="utf-8")
    section = text.split("## The current design", 1)[1].split("\n## ", 1)[0]
    header, forms = None, {}
    for line in section.splitlines():
        if not line.startswith("|"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if header is None:
            header = cells
            continue
        row = dict(zip(header, cells))
        if row.get("Module", "").replace("*", "") != "rpu_top":
            continue
        kind = "unrolled" if "unrolled" in row["Configuration"] else "iterative"
        form = kind + (", curves + textures" if "Surfaces=0" in row["Configuration"] else "")
        forms[form] = {
            "lut_sites": number(row["LUT sites"]), "ff": number(row["FF"]),
            "dsp": number(row["DSP48E1"]), "bram36": number(row["BRAM36"]),
            "items_per_cycle": ITEMS_PER_CYCLE[kind], "sta_ns": number(row["sta ns"]),
            "source": "estimate" if "estimate" in row["Source"] else "synthesis",
        }
    for form in ITEMS_PER_CYCLE:
        if form not in forms:
            raise SystemExit(f"{resources}: no rpu_top row for the {form} form in the first table")
    if any(f["source"] != "synthesis" for f in forms.values()):
        raise SystemExit(f"{resources}: an rpu_top row is not a synthesised figure")
    return forms


FORMS = read_forms(pathlib.Path(__file__).resolve().parent.parent / "docs" / "resources.md")

# Device capacities (AMD/Xilinx data sheets DS180 for 7-series, DS190 for Zynq-7000, DS890 for
# UltraScale/UltraScale+): LUTs, flip-flops, DSP slices, 36 Kb block RAMs. The UltraScale parts'
# DSP48E2 (27 x 18) holds every tile of rpu_mul (25 x 18), and their LUTs count as LUT sites the
# same way; XCZU7EV's 96 UltraRAM blocks are not counted.
PARTS = [
    ("XC7A35T", 20_800, 41_600, 90, 50),
    ("XC7Z020", 53_200, 106_400, 220, 140),
    ("XC7A100T", 63_400, 126_800, 240, 135),
    ("XC7A200T", 133_800, 269_200, 740, 365),
    ("XC7K325T", 203_800, 407_600, 840, 445),
    ("XCKU040", 242_400, 484_800, 1_920, 600),
    ("XCZU7EV", 230_400, 460_800, 1_728, 312),
    ("XC7VX690T", 433_200, 866_400, 3_600, 1_470),
]


def units_per_part(form, part):
    _, lut, ff, dsp, bram = part
    limits = [lut / form["lut_sites"], ff / form["ff"]]
    if form["dsp"]:
        limits.append(dsp / form["dsp"])
    if form["bram36"]:
        limits.append(bram / form["bram36"])
    return math.floor(min(limits))


def main():
    print("| form | source | LUT sites | FF | DSP48E1 | BRAM36 | items/cycle | sta ns | "
          "clock, cells only | clock, routed (×5/3) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, f in FORMS.items():
        fmax = 1e3 / f["sta_ns"]
        print(f"| {name} | {f['source']} | {f['lut_sites']:,} | {f['ff']:,} | {f['dsp']:,} | "
              f"{f['bram36']} | {f['items_per_cycle']} | {f['sta_ns']} | {fmax:.0f} MHz | "
              f"{fmax / ROUTING_FACTOR:.0f} MHz |")
    print()
    print("Units per part (the scarcest resource decides; the rpu_top rows above at their "
          "defaults, the segment RAM of 4,096 descriptors among them):")
    print()
    print("| part | LUT | FF | DSP48E1 | BRAM36 | " + " | ".join(FORMS) + " |")
    print("|---|---|---|---|---|" + "---|" * len(FORMS))
    for part in PARTS:
        cells = [str(units_per_part(f, part)) for f in FORMS.values()]
        print(f"| {part[0]} | {part[1]:,} | {part[2]:,} | {part[3]:,} | {part[4]:,} | " +
              " | ".join(cells) + " |")
    print()
    print("Frames per second at 1920×1080 (routed clock, all units of the part working on one "
          "frame; 0 where no unit fits):")
    print()
    print("| scene (frames/s) | form | pairs per frame | " + " | ".join(p[0] for p in PARTS) + " |")
    print("|---|---|---|" + "---|" * len(PARTS))
    for scene, pairs in PAIRS_1080P.items():
        for name, f in FORMS.items():
            rate = 1e9 / (f["sta_ns"] * ROUTING_FACTOR) * f["items_per_cycle"]  # items/s
            cells = []
            for part in PARTS:
                u = units_per_part(f, part)
                cells.append(f"{u * rate / pairs:.1f}" if u else "0")
            print(f"| {scene} | {name} | {pairs:,} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
