#!/usr/bin/env python3
"""`matevo compare` against scikit-image on the same PNG files.

Usage: compare_vs_skimage.py MATEVO WORKDIR

Writes random 8-bit images (fixed seed) with and without alpha, runs `matevo compare --json` on
them and recomputes the statistics with skimage.color.rgb2lab + deltaE_ciede2000 over the pixels
where both alphas exceed 0.5. Fails (exit 1) unless the pixel counts agree exactly and the mean
ΔE00 agrees within 1e-3 (max and nearest-rank p95 within 1e-2).
"""
import json
import math
import pathlib
import subprocess
import sys

import numpy as np
import skimage.io
from skimage.color import deltaE_ciede2000, rgb2lab


def skimage_stats(file_a, file_b):
    a = skimage.io.imread(file_a)
    b = skimage.io.imread(file_b)
    lab_a = rgb2lab(a[..., :3] / 255.0)
    lab_b = rgb2lab(b[..., :3] / 255.0)
    delta_e = deltaE_ciede2000(lab_a, lab_b)
    covered = np.ones(delta_e.shape, dtype=bool)
    if a.shape[-1] == 4:
        covered &= a[..., 3] / 255.0 > 0.5
    if b.shape[-1] == 4:
        covered &= b[..., 3] / 255.0 > 0.5
    values = np.sort(delta_e[covered])
    rank = math.ceil(0.95 * values.size)
    return {"mean_de00": values.mean(), "max_de00": values[-1],
            "p95_de00": values[rank - 1], "pixels": int(values.size)}


def main():
    matevo, workdir = sys.argv[1], pathlib.Path(sys.argv[2])
    workdir.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(20240607)
    height, width = 72, 96
    base = rng.integers(0, 256, (height, width, 4), dtype=np.uint8)
    far = rng.integers(0, 256, (height, width, 4), dtype=np.uint8)
    # Small differences too, where float rounding would show most.
    near = np.clip(base.astype(int) + rng.integers(-3, 4, base.shape), 0, 255).astype(np.uint8)
    near[..., 3] = rng.integers(0, 256, (height, width), dtype=np.uint8)
    cases = {
        "far_rgba": (base, far),
        "near_rgba": (base, near),
        "far_rgb": (base[..., :3], far[..., :3]),
    }
    failures = 0
    for name, (image_a, image_b) in cases.items():
        file_a, file_b = workdir / f"{name}_a.png", workdir / f"{name}_b.png"
        skimage.io.imsave(file_a, image_a, check_contrast=False)
        skimage.io.imsave(file_b, image_b, check_contrast=False)
        run = subprocess.run([matevo, "compare", str(file_a), str(file_b), "--json"],
                             capture_output=True, text=True, check=False)
        if run.returncode != 0:
            print(f"{name}: matevo compare exited {run.returncode}: {run.stderr.strip()}")
            failures += 1
            continue
        ours = json.loads(run.stdout)
        theirs = skimage_stats(file_a, file_b)
        print(f"{name}: matevo {ours} skimage {theirs}")
        checks = [ours["pixels"] == theirs["pixels"],
                  abs(ours["mean_de00"] - theirs["mean_de00"]) <= 1e-3,
                  abs(ours["max_de00"] - theirs["max_de00"]) <= 1e-2,
                  abs(ours["p95_de00"] - theirs["p95_de00"]) <= 1e-2]
        if not all(checks) or theirs["pixels"] == 0:
            print(f"{name}: MISMATCH")
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
