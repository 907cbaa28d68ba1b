#!/usr/bin/env python3
"""Chart of a `shadowlab soak --csv FILE` run, drawn with matplotlib (Debian python3-matplotlib).

usage: soak_chart.py SOAK.csv OUT.png

Top: resident memory (MB) per sample, coloured by shadow-map size, marked by method, with the end
of the warm-up cycle and the first measured cycle's peak (+5%) drawn in, and the heap in use (what
malloc has handed out and not had back; CSVs from before that column have none) as a black line. Bottom: live GL objects
and the running GL error count. Also prints the figures the soak command judges by, so a run
that was stopped early (the CSV is written as it goes) can still be read.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")  # no display
import matplotlib.pyplot as plt  # noqa: E402

SIZE_COLOURS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]
METHOD_MARKERS = {"ssm": "s", "psm": "^", "lispsm": "o", "ssm-unfocused": "x"}


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        r["frame"] = int(r["frame"])
        r["rss_mb"] = float(r["rss_mb"])
        r["heap_mb"] = float(r["heap_mb"]) if r.get("heap_mb") else None
        r["gl_objects"] = int(r["gl_objects"])
        r["gl_errors"] = int(r["gl_errors"])
        r["map_size"] = int(r["map_size"])
    return rows


def cycle_length(rows):
    """Frames per cycle of (method, map size): where the first pair comes back after all were seen."""
    pairs = [(r["method"], r["map_size"]) for r in rows]
    seen, first = set(), pairs[0]
    for i, p in enumerate(pairs):
        if p == first and len(seen) > 1 and pairs[i - 1] != first:
            return rows[i - 1]["frame"]
        seen.add(p)
    return None


def growth_line(after, cycle, key, what):
    """The soak's criterion for one column: the later cycles' peak against the first measured one's."""
    first = [r[key] for r in after if (r["frame"] - 1) // cycle == 1 and r[key] is not None]
    later = [r[key] for r in after if (r["frame"] - 1) // cycle >= 2 and r[key] is not None]
    if first and later and max(first) > 0:
        growth = (max(later) - max(first)) / max(first)
        print(f"{what}: peak of the first measured cycle {max(first):.1f} MB, of everything after it "
              f"{max(later):.1f} MB ({100 * growth:+.2f}%)")
    return max(first) if first else None


def summary(rows, cycle):
    after = [r for r in rows if cycle and r["frame"] >= cycle]
    print(f"samples: {len(rows)}, last frame {rows[-1]['frame']}, cycle {cycle} frames")
    if after:
        rss = [r["rss_mb"] for r in after]
        objects = [r["gl_objects"] for r in after]
        print(f"after warm-up: RSS {min(rss):.1f} .. {max(rss):.1f} MB, GL objects {min(objects)} .. {max(objects)}")
    first_peak = growth_line(after, cycle, "rss_mb", "resident memory")
    growth_line(after, cycle, "heap_mb", "heap in use")
    print(f"GL errors: {rows[-1]['gl_errors']}")
    return first_peak


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = read(sys.argv[1])
    if not rows:
        sys.exit("no samples in " + sys.argv[1])
    cycle = cycle_length(rows)
    first_peak = summary(rows, cycle)

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(11, 6.5), sharex=True, gridspec_kw={"height_ratios": [3, 1]})
    sizes = sorted({r["map_size"] for r in rows})
    for i, size in enumerate(sizes):
        for method, marker in METHOD_MARKERS.items():
            pts = [r for r in rows if r["map_size"] == size and r["method"] == method]
            if pts:
                top.scatter([r["frame"] for r in pts], [r["rss_mb"] for r in pts], s=12, marker=marker,
                            color=SIZE_COLOURS[i % len(SIZE_COLOURS)], label=f"{method} {size}²")
    top.plot([r["frame"] for r in rows], [r["rss_mb"] for r in rows], color="0.7", linewidth=0.6, zorder=0)
    heap = [r for r in rows if r["heap_mb"] is not None]
    if heap:
        top.plot([r["frame"] for r in heap], [r["heap_mb"] for r in heap], color="black", linewidth=0.8,
                 label="heap in use")
    if cycle:
        for ax in (top, bottom):
            ax.axvline(cycle, color="0.3", linestyle="--", linewidth=0.8)
        top.text(cycle, top.get_ylim()[1], " end of warm-up", va="top", fontsize=8)
    if first_peak:
        top.axhline(first_peak * 1.05, color="tab:red", linestyle=":", linewidth=0.8)
        top.text(rows[-1]["frame"], first_peak * 1.05, "first measured cycle's peak + 5%", ha="right", va="bottom",
                 fontsize=8, color="tab:red")
    top.set_ylabel("memory (MB)")
    top.legend(fontsize=7, ncol=3, loc="lower right")
    top.grid(alpha=0.3)
    bottom.step([r["frame"] for r in rows], [r["gl_objects"] for r in rows], where="post", label="live GL objects")
    bottom.step([r["frame"] for r in rows], [r["gl_errors"] for r in rows], where="post", label="GL errors (total)",
                color="tab:red")
    bottom.set_xlabel("frame")
    bottom.legend(fontsize=7, loc="center right")
    bottom.grid(alpha=0.3)
    fig.suptitle(f"shadowlab soak: {rows[-1]['frame']} frames")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)
    print("wrote " + sys.argv[2])


if __name__ == "__main__":
    main()
