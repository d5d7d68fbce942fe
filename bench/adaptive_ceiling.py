#!/usr/bin/python3
"""How much any allocation of samples to pixels can gain on a scene (docs/sampling.md, "What it
gains, and where it cannot").

Adaptive sampling can only move samples between pixels; what that buys depends on how unevenly the
scene's noise is spread, and on how well a render can tell where it is. This renders the scene
16 times (--renders) with independent seeds at SPP samples, so each pixel's relative variance per sample v_p
is measured from the spread between renders, not from a render's own samples. Then, at equal mean
samples (at least 64 per pixel, as kAdaptiveMinSamples), the true mean relative MSE of:

  uniform                  the same samples everywhere;
  sqrt(v), own estimate    samples in proportion to the square root of v, v measured from 8 of the
                           renders, judged by the other 8 (so that a pixel's luck in the first
                           half is not rewarded in the second): the best any render can do from
                           8 x SPP samples per pixel, if it knew each pixel's variance that well;
  ... 3x3, NxN tiles       v averaged over each pixel's 3x3 neighbourhood, and the samples of an
                           NxN tile (--tile N, 2 as kAdaptiveTileSide; 4 before 2026-12-06) set by
                           its neediest pixel, as AdaptiveStopRule does;
  v (equal threshold)      samples in proportion to v, what stopping every pixel at the same error does;
  bound: v known           samples in proportion to the square root of the judging half's own v: no
                           allocation of samples to pixels does better on these renders (it is
                           judged by the samples it was chosen from, so it is an upper bound,
                           and a loose one unless the judging half's variances are well measured:
                           at 8 x 64 samples it mostly rewards that half's fireflies; use many
                           renders of many samples, e.g. --renders 32 at 4096 spp).

The gain of each is uniform's error over its own. Not a test: a measurement of the scene.

usage: bench/adaptive_ceiling.py PTVIEW OUTDIR SIZE SPP BUDGET SCENE... [--renders 16] [--tile 2]
  e.g. bench/adaptive_ceiling.py build/ptview /tmp/ceiling 64x64 64 800 assets/scenes/cornell_spheres.json
"""
import argparse, os, subprocess, sys
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "cycles"))
from pfm import read_pfm  # noqa: E402

RENDERS = 16
MIN_SAMPLES = 64

def box3(a):
    padded = np.pad(a, 1, mode='edge')
    return sum(padded[dy:dy + a.shape[0], dx:dx + a.shape[1]] for dy in range(3) for dx in range(3)) / 9.0

def tile_max(a, side):
    h, w = a.shape
    hh, ww = -(-h // side) * side, -(-w // side) * side
    padded = np.pad(a, ((0, hh - h), (0, ww - w)), mode='edge')
    tiles = padded.reshape(hh // side, side, ww // side, side).max(axis=(1, 3))
    return np.repeat(np.repeat(tiles, side, 0), side, 1)[:h, :w]

def samples_for(weights, budget):
    """Samples in proportion to weights, at least MIN_SAMPLES each, averaging budget."""
    low, high = 0.0, 1e12
    for _ in range(200):
        c = 0.5 * (low + high)
        if np.maximum(MIN_SAMPLES, c * weights).mean() > budget: high = c
        else: low = c
    return np.maximum(MIN_SAMPLES, low * weights)

def main():
    parser = argparse.ArgumentParser(description='How much any allocation of samples to pixels can gain (see the top of this file).')
    parser.add_argument('ptview'); parser.add_argument('outdir'); parser.add_argument('size')
    parser.add_argument('spp', type=int); parser.add_argument('budget', type=float); parser.add_argument('scenes', nargs='+')
    parser.add_argument('--renders', type=int, default=RENDERS, help='an even number, at least 4')
    parser.add_argument('--tile', type=int, default=2, help='the tile side, at least 1')
    options = parser.parse_intermixed_args()
    if options.renders < 4 or options.renders % 2:
        parser.error(f'--renders {options.renders}: an even number of at least 4 (two halves of at least 2)')
    if options.tile < 1:
        parser.error(f'--tile {options.tile}: at least 1')
    ptview, outdir, size, spp, budget, scenes = options.ptview, options.outdir, options.size, options.spp, options.budget, options.scenes
    renders, tile = options.renders, options.tile
    os.makedirs(outdir, exist_ok=True)
    print(f'| scene | sqrt(v), own estimate | ... 3x3, {tile}x{tile} tiles | v (equal threshold), 3x3, {tile}x{tile} tiles | bound: v known |')
    print('|---|---:|---:|---:|---:|')
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        images = []
        for seed in range(1, renders + 1):
            path = f'{outdir}/{name}-{size}-{spp}-{seed}.pfm'
            if not os.path.exists(path):
                subprocess.run([ptview, 'render', scene, '--size', size, '--spp', str(spp), '--seed', str(seed),
                                '--backend', 'fragment', '--out', path], capture_output=True, check=True)
            images.append(read_pfm(path))
        images = np.array(images)
        converged = images.mean(0)
        def variance_per_sample(part):  # relative, as ErrorMetrics.h normalizes
            return (part.var(0, ddof=1) / (converged ** 2 + 1e-2)).mean(-1) * spp
        measured, judged = variance_per_sample(images[:renders // 2]), variance_per_sample(images[renders // 2:])
        uniform = judged.mean() / budget
        def gain(weights):
            return uniform / np.mean(judged / samples_for(weights, budget))
        print(f'| {name} | {gain(np.sqrt(measured)):.2f}x | {gain(tile_max(np.sqrt(box3(measured)), tile)):.2f}x | '
              f'{gain(tile_max(box3(measured), tile)):.2f}x | {gain(np.sqrt(judged)):.2f}x |', flush=True)

if __name__ == '__main__':
    main()
