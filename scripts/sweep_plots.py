#!/usr/bin/python3
"""The plots of `rpu sweep` (docs/sweeps.md), drawn by matplotlib from the plot data the sweep
writes beside its results (plots.json: app/sweep_report.cpp decides what is plotted, in which
series and colours; this script only draws it).

    /usr/bin/python3 scripts/sweep_plots.py PLOTS.json OUT_DIR

Run by `rpu sweep` (and `rpu sweep --merge`); needs Debian's python3-matplotlib (scripts/setup.sh),
hence /usr/bin/python3. One SVG per figure in OUT_DIR: its panels one above the other, a shared
legend beside them, text kept as SVG text. Every plotted point is an element of its own
(id "point-<k>") with the point's tooltip as its SVG <title>, so a browser shows the
configuration and its values on hover. Exit status 0, or 1 with one line on stderr naming the file
and the problem.
"""
import json
import math
import sys
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.lines  # noqa: E402
import matplotlib.ticker  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

matplotlib.rcParams["svg.fonttype"] = "none"  # text stays text: searchable, selectable
matplotlib.rcParams["svg.hashsalt"] = "rpu-sweep"  # the same data draws the same file
matplotlib.rcParams["font.size"] = 9
# Values near ±1e308 overflow inside matplotlib's margins; their axes get fixed ticks (below).
warnings.filterwarnings("ignore", message="overflow encountered", category=RuntimeWarning)

SVG_NS = "http://www.w3.org/2000/svg"


def dashes(text):
    """An SVG stroke-dasharray ("6 3") as a matplotlib line style."""
    if not text:
        return "-"
    return (0, tuple(float(v) for v in text.split()))


def finite_limits(values):
    """(lo, hi) for the data when matplotlib's own margins would overflow, else None."""
    lo, hi = min(values), max(values)
    span = hi - lo
    if math.isfinite(span) and math.isfinite(span * 1.2):
        return None
    return lo, hi


def draw(figure, out_path):
    panels = figure["panels"]
    fig, axes = plt.subplots(len(panels), 1, figsize=(9.0, 0.9 + 3.3 * len(panels)),
                             sharey=bool(figure.get("share_y")), squeeze=False)
    tooltips = []
    handles = {}
    for ax, panel in zip(axes[:, 0], panels):
        xs_all, ys_all = [], []
        for series in panel["series"]:
            points = series["points"]
            if series.get("line", True):
                points = sorted(points, key=lambda p: p["x"])
            xs = [p["x"] for p in points]
            ys = [p["y"] for p in points]
            xs_all += xs
            ys_all += ys
            colour = series["colour"]
            highlighted = series.get("highlighted", False)
            if series.get("line", True) and len(points) > 1:
                (line,) = ax.plot(xs, ys, linestyle=dashes(series.get("dash", "")), color=colour,
                                  linewidth=2.6 if highlighted else 1.3, zorder=2)
                line.set_gid("pareto" if highlighted else "series")
            size = 2.0 * series.get("radius", 3.5)
            for p in points:
                (marker,) = ax.plot([p["x"]], [p["y"]], linestyle="none", marker="o",
                                    markersize=size, color=colour, markeredgecolor="#222222",
                                    markeredgewidth=0.6, zorder=3)
                marker.set_gid(f"point-{len(tooltips)}")
                tooltips.append(p.get("tooltip", ""))
                if p.get("label"):
                    ax.annotate(p["label"], (p["x"], p["y"]), xytext=(5, 4),
                                textcoords="offset points", fontsize=8, color="#333333")
            if series["name"] in handles:
                continue
            handles[series["name"]] = matplotlib.lines.Line2D(
                [], [], color=colour, marker="o", markeredgecolor="#222222",
                linestyle=dashes(series.get("dash", "")) if series.get("line", True) else "none",
                linewidth=2.6 if highlighted else 1.3)
        ax.set_title(panel["title"], loc="left")
        ax.set_ylabel(panel["y_label"])
        ax.set_xlabel(figure["x_label"])
        ax.grid(True, color="#e3e3e3", linewidth=0.8)
        ax.set_axisbelow(True)
        for values, setter, axis in ((xs_all, ax.set_xlim, ax.xaxis),
                                     (ys_all, ax.set_ylim, ax.yaxis)):
            limits = finite_limits(values) if values else None
            if limits:  # beyond double's reach for nice ticks: the data's own ends, two ticks
                setter(*limits)
                axis.set_major_locator(matplotlib.ticker.FixedLocator(list(limits)))
            elif values and all(float(v).is_integer() for v in values):
                # Widths, n1, LUT sites, cycles: whole-number ticks only.
                axis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
        if panel.get("y_from_zero") and ys_all and finite_limits(ys_all) is None:
            lo, hi = ax.get_ylim()
            ax.set_ylim(min(lo, 0.0), max(hi, 0.0))
    fig.suptitle(figure["title"], x=0.02, ha="left", fontsize=12)
    fig.legend(list(handles.values()), list(handles.keys()), loc="upper left",
               bbox_to_anchor=(1.0, 0.95), frameon=False)
    fig.tight_layout()
    fig.savefig(out_path, format="svg", bbox_inches="tight")
    plt.close(fig)
    add_tooltips(out_path, tooltips)


def add_tooltips(path, tooltips):
    """Each point's <g id="point-k"> gets its tooltip as an SVG <title> (first child)."""
    ET.register_namespace("", SVG_NS)
    ET.register_namespace("xlink", "http://www.w3.org/1999/xlink")
    tree = ET.parse(path)
    found = 0
    for g in tree.iter(f"{{{SVG_NS}}}g"):
        gid = g.get("id", "")
        if gid.startswith("point-"):
            title = ET.Element(f"{{{SVG_NS}}}title")
            title.text = tooltips[int(gid[len("point-"):])]
            g.insert(0, title)
            found += 1
    if found != len(tooltips):
        raise ValueError(f"{found} of {len(tooltips)} points found in the drawing")
    tree.write(path, encoding="unicode", xml_declaration=True)


def main():
    if len(sys.argv) != 3:
        print("usage: sweep_plots.py PLOTS.json OUT_DIR", file=sys.stderr)
        return 2
    spec_path, out_dir = Path(sys.argv[1]), Path(sys.argv[2])
    try:
        spec = json.loads(spec_path.read_text())
        for figure in spec["figures"]:
            draw(figure, out_dir / figure["file"])
    except (OSError, ValueError, KeyError, TypeError) as e:
        print(f"sweep_plots.py: {spec_path}: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
