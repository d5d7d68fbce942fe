#!/usr/bin/python3
"""Adaptive against uniform sampling on shipped scenes (docs/sampling.md, "Adaptive sampling").

For each scene: a reference (16384 spp, sobol sampler, seed 1000) and a second one (seed 1001)
whose difference gives the references' own noise, subtracted from every error; adaptive renders
(`render --noise-threshold E`) for each E, and uniform renders at doubling spp. The true error of
each is against the reference; the uniform time and spp to reach each adaptive render's true
error are interpolated (log-log) between the uniform renders. Times are the renders' own
("after T s" / the written line), so they include no compilation. Not a test: times depend on
the machine and its load.

With several seeds (--seeds 2,3,4,5) every render is repeated at each, and the table compares
expectations: the adaptive renders' mean time, mean spp and mean true relMSE over the seeds,
against the uniform renders' mean time and mean true relMSE at each spp. One seed's error is a
few pixels' luck where rare bright paths carry it (`mis`: five pixels hold 40% to 76% of a
64x64 render's error, which can rise from 1024 to 2048 spp), so one seed's speed-up is too.

usage: bench/adaptive_vs_uniform.py PTVIEW OUTDIR SIZE SCENE... [--thresholds 0.05,0.02,0.01] [--reference-spp 16384]
       [--seeds 2]  (the seeds of the adaptive and uniform renders, comma-separated; the references keep theirs;
                     --seed S is the same as --seeds S)
       [--spp-cap N] (the adaptive renders' --spp cap; default render's own, 4096)
       [--backend fragment|compute] (of every render, references included; default fragment, as the
                     tables before 2026-12-06 stop 58 were measured. compute packs the adaptive renders'
                     passes with the pixels still sampled: docs/sampling.md, "Packed passes")
"""
import argparse, math, os, re, subprocess, sys
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "cycles"))
from pfm import read_pfm  # noqa: E402

def rel_mse(x, ref):
    return float(np.mean((x - ref) ** 2 / (ref ** 2 + 1e-2)))

def render(command, scene, size, out, *args):  # command: ptview render and its backend
    result = subprocess.run([*command, scene, '--size', size, '--out', out, *args],
                            capture_output=True, text=True, check=True)
    return result.stderr

def seconds_of(log):
    adaptive = re.search(r'adaptive: .* after ([0-9.]+) s', log)
    if adaptive: return float(adaptive.group(1))
    return float(re.search(r'spp, depth \d+, \w+ sampler, \w+ integrator, ([0-9.]+) s', log).group(1))

def interpolate(points, error):  # (seconds or spp, error) pairs, errors falling: x at which error is reached
    for (x0, e0), (x1, e1) in zip(points, points[1:]):
        if e0 >= error >= e1 and e0 > 0 and e1 > 0:
            w = (math.log(e0) - math.log(error)) / (math.log(e0) - math.log(e1))
            return math.exp((1 - w) * math.log(x0) + w * math.log(x1))
    return float('nan')

def main():
    parser = argparse.ArgumentParser(description='Adaptive against uniform sampling (see the top of this file).')
    parser.add_argument('ptview'); parser.add_argument('outdir'); parser.add_argument('size'); parser.add_argument('scenes', nargs='+')
    parser.add_argument('--thresholds', default='0.05,0.02,0.01')
    parser.add_argument('--reference-spp', type=int, default=16384)
    parser.add_argument('--seeds', '--seed', default='2')
    parser.add_argument('--spp-cap', type=int)
    parser.add_argument('--backend', choices=['fragment', 'compute'], default='fragment')
    options = parser.parse_intermixed_args()
    thresholds = [float(t) for t in options.thresholds.split(',')]
    reference_spp = options.reference_spp
    render_seeds = [str(int(seed)) for seed in options.seeds.split(',')]
    cap = ['--spp', str(options.spp_cap)] if options.spp_cap else []
    outdir, size, scenes = options.outdir, options.size, options.scenes
    ptview = [options.ptview, 'render', '--backend', options.backend]
    os.makedirs(outdir, exist_ok=True)
    print('| scene | E | adaptive: s, mean spp, true error | uniform to that error: s, spp | speed-up (time, samples) |')
    print('|---|---:|---|---|---:|', flush=True)
    for scene in scenes:
        name = os.path.splitext(os.path.basename(scene))[0]
        refs = []
        for seed in (1000, 1001):
            path = f'{outdir}/{name}-{size}-ref{reference_spp}-{seed}.pfm'
            if not os.path.exists(path):
                render(ptview, scene, size, path, '--spp', str(reference_spp), '--sampler', 'sobol', '--seed', str(seed))
            refs.append(read_pfm(path))
        floor = rel_mse(refs[1], refs[0]) / 2  # each reference's own noise
        print(f'<!-- {name}: reference noise relMSE {floor:.3g} -->', flush=True)
        true = lambda image: rel_mse(image, refs[0]) - floor
        adaptive = []
        for e in thresholds:
            runs = []
            for seed in render_seeds:
                log = render(ptview, scene, size, f'{outdir}/{name}-adaptive.pfm', '--noise-threshold', str(e), '--seed', seed, *cap)
                mean_spp = float(re.search(r'spp min/mean/max \d+/([0-9.]+)/\d+', log).group(1))
                runs.append((seconds_of(log), mean_spp, true(read_pfm(f'{outdir}/{name}-adaptive.pfm'))))
            adaptive.append((e, *np.mean(runs, axis=0)))
        smallest = min(a[3] for a in adaptive)
        uniform, spp = [], 16
        while spp <= 65536:
            runs = []
            for seed in render_seeds:
                log = render(ptview, scene, size, f'{outdir}/{name}-uniform.pfm', '--spp', str(spp), '--seed', seed)
                runs.append((seconds_of(log), true(read_pfm(f'{outdir}/{name}-uniform.pfm'))))
            uniform.append((spp, *np.mean(runs, axis=0)))
            if uniform[-1][2] < smallest / 1.5: break
            spp *= 2
        if len(render_seeds) > 1:
            print(f'<!-- {name}: means over seeds {",".join(render_seeds)} -->', flush=True)
        for e, seconds, mean_spp, error in adaptive:
            u_seconds = interpolate([(s, r) for _, s, r in uniform], error)
            u_spp = interpolate([(n, r) for n, _, r in uniform], error)
            print(f'| {name} | {e:g} | {seconds:.2f} s, {mean_spp:.0f}, {math.sqrt(max(error, 0)):.4f} | '
                  f'{u_seconds:.2f} s, {u_spp:.0f} | {u_seconds / seconds:.2f}x, {u_spp / mean_spp:.2f}x |', flush=True)

main()
