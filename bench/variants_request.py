#!/usr/bin/env python3
"""The variants goal, measured as a user meets it (docs/variants.md, README).

For each validation preset, in one run, without and with hue variety (`--hue`):
- time: wall time and CPU time (user + system) of the whole `matevo variants --count 12
  --band 2,5 --min-apart 2` process (medians of --repeats runs), the report's own wall_time_s,
  and the load average when the preset's runs started (the machine is shared: on two cores a
  process gets about 2 / load of them once the load passes 2);
- success: every delivered variant rendered again on its own, from its variant_NNN.json, at
  256^2 on the CPU reference renderer (`matevo render --backend cpu`, independent of the search's
  renders), and measured with scikit-image's CIEDE2000 (independent of matevo's) over the pixels
  both alphas cover: the share of variants inside the band and the smallest pairwise distance;
- the paper's method at the same number of evaluations: `matevo experiment`, 36 runs of the GA
  (population 50, generations chosen so that 50 x (generations + 1) is at least the evaluations
  the variant search used), and the share of its best-of-run materials inside the same band.
Prints one JSON object.
"""
import argparse
import csv
import json
import math
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np
from skimage.color import deltaE_ciede2000, rgb2lab
from skimage.io import imread

PRESETS = ["validation_metal", "validation_metal_depth", "validation_painted_metal"]
COUNT, LOW, HIGH, APART = 12, 2.0, 5.0, 2.0


def run(command):
    return subprocess.run(command, check=True, capture_output=True, text=True)


def load(path):
    rgba = imread(path).astype(np.float64) / 255.0
    return rgb2lab(rgba[..., :3]), rgba[..., 3] > 0.5


def mean_de00(a, b):
    (lab_a, cover_a), (lab_b, cover_b) = a, b
    both = cover_a & cover_b
    return float(deltaE_ciede2000(lab_a, lab_b)[both].mean())


def children_cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def measure_preset(matevo, root, preset, hue, repeats, work):
    preset_file = os.path.join(root, "presets", preset + ".json")
    name = preset + ("_hue" if hue else "")
    load_at_start = os.getloadavg()[0]
    times, cpu_times, reports = [], [], []
    for repeat in range(repeats):
        out = os.path.join(work, f"{name}_{repeat}")
        start, cpu_start = time.perf_counter(), children_cpu_seconds()
        # Exit 3 (request not met) still writes the set: measure what was delivered.
        result = subprocess.run(
            [matevo, "variants", "--preset", preset_file, "--count", str(COUNT), "--band",
             f"{LOW},{HIGH}", "--min-apart", str(APART), "--seed", "1", "--out", out]
            + (["--hue"] if hue else []), capture_output=True, text=True)
        if result.returncode not in (0, 3):
            raise RuntimeError(result.stderr)
        times.append(time.perf_counter() - start)
        cpu_times.append(children_cpu_seconds() - cpu_start)
        with open(os.path.join(out, "report.json")) as file:
            reports.append(json.load(file))
    load_after_timing = os.getloadavg()[0]
    report, out = reports[0], os.path.join(work, f"{name}_0")

    independent = os.path.join(work, f"{name}_independent")
    os.makedirs(independent)
    target_png = os.path.join(independent, "target.png")
    run([matevo, "render", "--preset", preset_file, "--size", "256", "--backend", "cpu",
         "--out", target_png])
    target = load(target_png)
    renders = []
    for entry in report["variants"]:
        png = os.path.join(independent, os.path.basename(entry["image"]))
        # The material file names its own family, kappa (with --hue, the variant's own),
        # textures and scene: no --preset beside it.
        run([matevo, "render", "--genome", os.path.join(out, entry["file"]), "--size", "256",
             "--backend", "cpu", "--out", png])
        renders.append(load(png))
    to_target = [mean_de00(target, render) for render in renders]
    pairwise = [mean_de00(renders[i], renders[j])
                for i in range(len(renders)) for j in range(i + 1, len(renders))]
    in_band = sum(LOW <= value <= HIGH for value in to_target)

    evaluations = report["evaluations"]
    generations = max(1, math.ceil(evaluations / 50) - 1)
    experiment_dir = os.path.join(work, f"{name}_paper")
    run([matevo, "experiment", "--preset", preset_file, "--runs", "36", "--population", "50",
         "--generations", str(generations), "--metric", "euclidean", "--out", experiment_dir])
    with open(os.path.join(experiment_dir, "results.csv")) as file:
        paper = [float(row["mean_de00"]) for row in csv.DictReader(file)]
    paper_in_band = sum(LOW <= value <= HIGH for value in paper)

    return {
        "load_average_at_start": round(load_at_start, 1),
        "load_average_after_timing": round(load_after_timing, 1),
        "process_s_all": [round(t, 2) for t in times],
        "process_s_median": statistics.median(times),
        "process_cpu_s_median": statistics.median(cpu_times),
        "report_wall_time_s_median": statistics.median(r["wall_time_s"] for r in reports),
        "delivered": len(renders),
        "met": report["met"],
        "in_band_share": in_band / len(renders) if renders else 0.0,
        "smallest_pairwise_de00": min(pairwise) if pairwise else 0.0,
        "evaluations": evaluations,
        "paper_population": 50,
        "paper_generations": generations,
        "paper_in_band_share": paper_in_band / len(paper) if paper else 0.0,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--matevo", default=None, help="the executable (default build/matevo)")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    matevo = args.matevo or os.path.join(root, "build", "matevo")
    results = {}
    with tempfile.TemporaryDirectory(prefix="matevo_variants_bench_") as work:
        for preset in PRESETS:
            for hue in (False, True):
                results[preset + (" --hue" if hue else "")] = measure_preset(
                    matevo, root, preset, hue, args.repeats, work)
    json.dump(results, sys.stdout, indent=2)
    print()


if __name__ == "__main__":
    main()
