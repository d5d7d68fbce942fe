#!/usr/bin/python3
"""Efficiency of ptview builds on one scene: seconds, variance and true error at equal spp
(docs/performance.md, "Russian roulette as a weight window").

Renders SCENE with each PTVIEW (full integrator, sobol, fragment backend) at seeds 1..N, the builds alternating per seed so that the machine's
load falls on all alike, and prints per build:
  seconds      the mean of the renders' own times (`ptview render`'s, no compilation);
  variance     half the mean squared difference of the renders of seeds 1 and 2, 3 and 4, ...: the
               variance of one render, with no reference (and so none of its noise) in it;
  relMSE       with --reference R0 R1 (two independent converged renders at the same depth, averaged): each render's
               relative MSE as bench/adaptive_vs_uniform.py computes it, mean (standard error),
               median and largest over the seeds. The mean is what a variance from a few renders
               misses when rare bright samples carry the error (fireflies).
  efficiency   1 / (variance x seconds), and 1 / (relMSE x seconds), relative to the first build.
A PTVIEW may be a script that runs ptview another way (a second worktree's build, or the same
binary with other shaders bound over shaders/ in a private mount namespace:
`unshare -m --map-root-user sh -c 'mount --bind OTHER_SHADERS shaders && exec build/ptview "$@"'`).

usage: bench/efficiency.py SCENE PTVIEW... [--size WxH] [--spp 64] [--depth 64] [--seeds 4] [--reference R0 R1]
  e.g. bench/efficiency.py assets/scenes/cornell_bunny.json build/ptview OLD_PTVIEW --spp 64 --seeds 4
Not a test: times depend on the machine and its load.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "cycles"))
from pfm import read_pfm  # noqa: E402


def rel_mse(x, ref):
    return float(np.mean((x - ref) ** 2 / (ref ** 2 + 1e-2)))


def render(ptview, args, seed, out):
    command = [ptview, "render", args.scene, "--depth", str(args.depth), "--integrator", "full", "--sampler", "sobol",
               "--spp", str(args.spp), "--seed", str(seed), "--out", out, "--backend", "fragment"]
    if args.size:
        command += ["--size", args.size]
    result = subprocess.run(command, capture_output=True, text=True, env=dict(os.environ, PTVIEW_BACKEND_CACHE=""))
    match = re.search(r", ([0-9.]+) s, ", result.stderr)
    if result.returncode != 0 or not match:
        sys.exit(f"efficiency: {ptview} failed ({result.returncode}):\n{result.stderr[-2000:]}")
    return float(match.group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene")
    parser.add_argument("ptview", nargs="+")
    parser.add_argument("--size")
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--depth", type=int, default=64)
    parser.add_argument("--seeds", type=int, default=4)
    parser.add_argument("--reference", nargs=2, metavar=("R0", "R1"))
    args = parser.parse_args()
    if args.seeds < 2 or args.seeds % 2:
        sys.exit("efficiency: --seeds must be even (the variance comes from pairs of seeds)")
    reference = (read_pfm(args.reference[0]) + read_pfm(args.reference[1])) / 2 if args.reference else None

    seconds = {p: [] for p in args.ptview}
    images = {p: [] for p in args.ptview}
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "render.pfm")
        for seed in range(1, args.seeds + 1):
            for ptview in args.ptview:
                seconds[ptview].append(render(ptview, args, seed, out))
                images[ptview].append(read_pfm(out))

    first = None
    for ptview in args.ptview:
        t = float(np.mean(seconds[ptview]))
        renders = images[ptview]
        variance = float(np.mean([np.mean((renders[i] - renders[i + 1]) ** 2) / 2 for i in range(0, len(renders), 2)]))
        line = f"{ptview}: {t:.3f} s, variance {variance:.4e}"
        scores = [variance * t]
        if reference is not None:
            errors = np.array([rel_mse(x, reference) for x in renders])
            line += (f", relMSE mean {errors.mean():.4e} ({errors.std(ddof=1) / np.sqrt(len(errors)):.1e}),"
                     f" median {np.median(errors):.4e}, largest {errors.max():.4e}")
            scores.append(float(errors.mean()) * t)
        first = first or scores
        line += ", efficiency " + ", ".join(f"{f / s:.3f}x" for f, s in zip(first, scores))
        print(line)


if __name__ == "__main__":
    main()
