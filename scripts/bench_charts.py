#!/usr/bin/env python3
"""Charts of a `shadowlab bench` run, drawn with matplotlib (Debian python3-matplotlib).

usage: bench_charts.py RESULTS.json OUT_DIR
       bench_charts.py SCALING.csv OUT_DIR     (shadowlab bench --scaling)

Writes
  error_vs_time.png   p99 texel footprint (pixels per texel; true normal, and bisector normal
                      below) against GPU ms per frame, one marker per method, labelled by map
                      size, one panel per view
  depth_curves.png    canonical validation: measured footprint per log-depth bin against the
                      closed forms of thesis 8.2 (SSM, PSM, LiSPSM), plus the logarithmic limit
  e_total.png         E_total (false shadow + false light) per method and case, when ground truth ran
  scaling.png         from scaling.csv: triangles per pass, draws, setup + culling CPU ms, load seconds and
                      peak RSS per million triangles against world scale, instanced and merged worlds
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"ssm": "tab:blue", "ssm-unfocused": "tab:gray", "psm": "tab:orange", "lispsm": "tab:green",
           "csm": "tab:brown", "csm-ssm": "tab:purple", "csm-stable": "tab:pink", "csm-lispsm": "tab:olive"}
MARKERS = {"ssm": "s", "ssm-unfocused": "x", "psm": "^", "lispsm": "o",
           "csm": "P", "csm-ssm": "D", "csm-stable": "v", "csm-lispsm": "*"}


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)


def view_name(case):
    scene = os.path.splitext(os.path.basename(case["scene"]))[0]
    return f"{scene} / {case['camera']}" + ("" if case["variant"] == "default" else f" [{case['variant']}]")


def error_vs_time(cases, out):
    views = sorted({view_name(c) for c in cases})
    columns = max(1, len(views))
    fig, axes = plt.subplots(2, columns, figsize=(5.5 * columns, 8.5), squeeze=False)
    # Row 0: the true footprint (what users see); row 1: the bisector footprint (perspective
    # aliasing only: what a parameterisation can change).
    for row, key, what in ((0, "footprint", "p99 footprint"), (1, "bisectorFootprint", "p99 bisector footprint")):
        for ax, view in zip(axes[row], views):
            for method in COLOURS:
                rows = [c for c in cases if view_name(c) == view and c["method"] == method]
                if not rows:
                    continue
                # GPU time from timer queries; CPU frame time where the driver reports no GPU time.
                xs = [c["gpuMsTotal"] if c["gpuMsTotal"] > 0 else c["frameMsMedian"] for c in rows]
                ys = [c[key]["p99"] for c in rows]
                ax.plot(xs, ys, marker=MARKERS[method], color=COLOURS[method], linestyle="-", label=method)
                for x, y, c in zip(xs, ys, rows):
                    ax.annotate(str(c["mapSize"]), (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
            ax.set_title(view, fontsize=9)
            ax.set_xlabel("GPU ms per frame (CPU frame ms if no GPU timer)")
            ax.set_ylabel(f"{what} (pixels per texel)")
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
    fig.suptitle("Error against run time (labels: map size)")
    save(fig, out, "error_vs_time.png")


def depth_curves(results, out):
    canonical = results.get("canonicalValidation", {})
    fig, ax = plt.subplots(figsize=(7, 4.8))
    for method, v in canonical.items():
        bins = [b for b in v["bins"] if b["pixels"] > 0]
        z = [b["zCentre"] for b in bins]
        ax.plot(z, [b["theory"] for b in bins], color=COLOURS.get(method, "k"), linestyle="--",
                label=f"{method} closed form (x r/z, off axis)")
        ax.plot(z, [b["measured"] for b in bins], color=COLOURS.get(method, "k"), marker=MARKERS.get(method, "o"),
                linestyle="none", label=f"{method} measured (max dev. {100 * v['maxDeviation']:.2f}%)")
    # The logarithmic limit K ln(f/n) of the canonical view (n = 0.1, f = 70, 720 px, 2048^2, 60 deg).
    k = (720 / 2048) / (2 * math.tan(math.radians(30)))
    ax.axhline(k * math.log(70 / 0.1), color="k", linewidth=0.8, label="logarithmic limit K ln(f/n)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("eye depth z (m)")
    ax.set_ylabel("texel footprint, bisector normal (pixels per texel)")
    ax.set_title("Canonical case (thesis Fig. 8.6) against the closed forms of ch. 8.2", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, out, "depth_curves.png")


def e_total(cases, out):
    rows = [c for c in cases if "groundTruth" in c]
    fig, ax = plt.subplots(figsize=(max(6, 0.5 * len(rows) + 2), 4.5))
    if rows:
        labels = [f"{view_name(c)}\n{c['method']} {c['mapSize']}" for c in rows]
        shadow = [100 * c["groundTruth"]["falseShadow"] for c in rows]
        light = [100 * c["groundTruth"]["falseLight"] for c in rows]
        xs = range(len(rows))
        ax.bar(xs, shadow, color=[COLOURS.get(c["method"], "k") for c in rows], label="false shadow")
        ax.bar(xs, light, bottom=shadow, color=[COLOURS.get(c["method"], "k") for c in rows], alpha=0.45,
               hatch="//", label="false light")
        ax.set_xticks(list(xs))
        ax.set_xticklabels(labels, rotation=60, ha="right", fontsize=6)
        ax.legend(fontsize=8)
    else:
        ax.text(0.5, 0.5, "no ground truth in this run", ha="center", va="center", transform=ax.transAxes)
    ax.set_ylabel("E_total (% of lit-facing receivers)")
    ax.set_title("Shadow state against Embree ground truth")
    ax.grid(True, axis="y", alpha=0.3)
    save(fig, out, "e_total.png")


def scaling(rows, out):
    panels = (("triangles per pass", (("forward_triangles", "forward"), ("shadow_triangles", "shadow"))),
              ("draw calls per pass", (("forward_draws", "forward"), ("shadow_draws", "shadow"))),
              ("CPU ms per frame", (("setup_culling_cpu_ms", "setup + culling"), ("passes_cpu_ms", "all passes"))),
              ("load s per Mtri (unique)", (("load_s_per_mtri", "load + upload, wall"),
                                            ("load_cpu_s_per_mtri", "load + upload, CPU"))),
              ("peak RSS MiB per Mtri (unique)", (("peak_rss_mib_per_mtri", "peak RSS"),)))
    fig, axes = plt.subplots(1, len(panels), figsize=(4.2 * len(panels), 4.2), squeeze=False)
    for ax, (title, series) in zip(axes[0], panels):
        for merged, style in (("0", "-"), ("1", "--")):
            world = [r for r in rows if r["merged"] == merged]
            if not world:
                continue
            world.sort(key=lambda r: float(r["scale"]))
            xs = [float(r["scale"]) for r in world]
            for key, label in series:
                ax.plot(xs, [float(r[key]) for r in world], marker="o", linestyle=style,
                        label=f"{label}{' (merged)' if merged == '1' else ''}")
        ax.set_xscale("log", base=2)
        ax.set_xlabel("world scale (forest --scale)")
        ax.set_title(title, fontsize=10)
        if title.startswith("CPU"):
            ax.set_yscale("log")  # setup + culling is a fraction of a millisecond, the passes hundreds
        else:
            ax.set_ylim(bottom=0)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle("Cost against world size: constant is the goal")
    save(fig, out, "scaling.png")


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    if argv[1].endswith(".csv"):
        with open(argv[1], encoding="utf-8", newline="") as f:
            rows = list(csv.DictReader(f))
        os.makedirs(argv[2], exist_ok=True)
        scaling(rows, argv[2])
        return 0
    with open(argv[1], encoding="utf-8") as f:
        results = json.load(f)
    cases = [c for c in results.get("cases", []) if "error" not in c]
    os.makedirs(argv[2], exist_ok=True)
    error_vs_time(cases, argv[2])
    depth_curves(results, argv[2])
    e_total(cases, argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
