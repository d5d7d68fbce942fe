#!/usr/bin/python3
"""Plots a `ptview converge` CSV: relative MSE against render time, log-log, one line per
configuration, with the reference's own noise floor; configurations biased by construction
(/clamp=VALUE, /denoise) dashed and labelled "biased". Called by `ptview converge`; needs Debian's
python3-matplotlib (scripts/setup installs it). Usage: plot_convergence.py CSV PNG [FLOOR]"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    csv_path, png_path = sys.argv[1], sys.argv[2]
    floor = float(sys.argv[3]) if len(sys.argv) > 3 else None
    series = {}
    with open(csv_path, newline="") as f:
        for row in csv.DictReader(f):
            seconds, rel_mse = float(row["seconds"]), float(row["rel_mse"])
            if seconds > 0 and rel_mse > 0:
                series.setdefault(row["config"], []).append((seconds, rel_mse, int(row["spp"])))
    fig, ax = plt.subplots(figsize=(8, 5.5), dpi=110)
    # A configuration biased by construction (/clamp=VALUE, /denoise) is drawn dashed and labelled
    # so; a /denoise curve takes the colour of the same configuration without it, when that was
    # run too, so the denoised curve sits beside its raw one.
    colours = {}
    for name in sorted(series, key=lambda n: "denoise" in n.split("/")[3:]):  # raw curves first: they pick the colours
        points = series[name]
        parts = name.split("/")
        biased = [p for p in parts[3:] if p == "denoise" or p.startswith("clamp=")]
        raw = "/".join(p for p in parts if p != "denoise")
        colour = colours.get(raw) if "denoise" in parts[3:] else None
        label = name + (" (biased: " + ", ".join("denoised" if p == "denoise" else "clamped" for p in biased) + ")"
                        if biased else "")
        (line,) = ax.loglog([p[0] for p in points], [p[1] for p in points], marker="o", markersize=3, label=label,
                            color=colour, linestyle="--" if biased else "-")
        colours.setdefault(name, line.get_color())
    if floor:
        ax.axhline(floor, color="grey", linestyle=":", label="reference's own noise")
    denoised = any("denoise" in name.split("/")[3:] for name in series)
    ax.set_xlabel("render time (s, GPU work timed with glFinish" + ("; denoised curves: denoising included)" if denoised else ")"))
    ax.set_ylabel("relative MSE against the reference")
    ax.set_title(csv_path.rsplit("/", 2)[-2] if "/" in csv_path else "convergence")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    # Drawn beside the target and renamed over it, so that an interrupted run never leaves a
    # truncated PNG in place of the last good plot.
    temporary = f"{png_path}.tmp-{os.getpid()}"
    try:
        fig.savefig(temporary, format="png")
        os.replace(temporary, png_path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


if __name__ == "__main__":
    main()
