#!/usr/bin/env python3
"""Whole-process times: how long matevo takes to start and to compare two files, against
scikit-image doing the same comparison from the same files, measured in the same run.

Usage: bench/process_times.py [--runs N] [--matevo PATH]

Writes two pairs of PNG images (256^2 and 2048^2: smooth gradients with noise, a covered disc
in alpha, as a render of a sphere) into a temporary folder, then runs each command once per
round, rounds interleaved so that a change of machine load touches every command alike.
Prints one JSON object: the median wall time of each command in milliseconds, how many times
faster matevo's compare is than the scikit-image peer (bench/peers/skimage_compare_files.py),
the mean dE00 each found (they must agree), matevo's `compare --metric flip` on the same files
beside its ΔE00 compare (the time ratio and the mean FLIP) and the load average before and
after.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import skimage.io

PYTHON = "/usr/bin/python3"  # Debian's interpreter, where python3-skimage lives
PEER = Path(__file__).resolve().parent / "peers" / "skimage_compare_files.py"


def write_pair(folder, size):
    rng = np.random.default_rng(size)
    y, x = np.mgrid[0:size, 0:size] / size
    inside = np.hypot(x - 0.5, y - 0.5) < 0.45
    files = []
    for which in (0, 1):
        image = np.zeros((size, size, 4), np.uint8)
        channels = (0.3 + 0.5 * x + 0.05 * which, 0.2 + 0.6 * y, 0.5 + 0.3 * x * y - 0.04 * which)
        for c, channel in enumerate(channels):
            noisy = channel + rng.normal(0, 0.02, (size, size))
            image[..., c] = np.clip(255 * noisy, 0, 255)
        image[..., 3] = np.where(inside, 255, 0)
        path = folder / f"{'ab'[which]}{size}.png"
        skimage.io.imsave(path, image, check_contrast=False)
        files.append(str(path))
    return files


def timed(command):
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, check=True)
    return time.perf_counter() - start, done.stdout


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--matevo", default=str(Path(__file__).resolve().parents[1] / "build" / "matevo"))
    options = parser.parse_args()
    matevo = options.matevo
    load_before = os.getloadavg()[0]
    with tempfile.TemporaryDirectory(prefix="matevo_process_times_") as folder:
        small = write_pair(Path(folder), 256)
        large = write_pair(Path(folder), 2048)
        commands = {
            "matevo_help": [matevo, "--help"],
            "matevo_version": [matevo, "--version"],
            "matevo_compare_256": [matevo, "compare", "--json", *small],
            "matevo_compare_2048": [matevo, "compare", "--json", *large],
            "matevo_compare_flip_256": [matevo, "compare", "--metric", "flip", "--json", *small],
            "matevo_compare_flip_2048": [matevo, "compare", "--metric", "flip", "--json", *large],
            "skimage_compare_256": [PYTHON, str(PEER), *small],
            "skimage_compare_2048": [PYTHON, str(PEER), *large],
        }
        times = {name: [] for name in commands}
        means = {}
        for _ in range(options.runs):
            for name, command in commands.items():
                seconds, output = timed(command)
                times[name].append(seconds)
                if "compare" in name:
                    metric = "mean_flip" if "flip" in name else "mean_de00"
                    means[name] = json.loads(output)[metric]
    medians = {f"{name}_ms": 1000 * statistics.median(values) for name, values in times.items()}
    result = {
        "runs": options.runs,
        "medians": medians,
        "speedups": {
            size: medians[f"skimage_compare_{size}_ms"] / medians[f"matevo_compare_{size}_ms"]
            for size in ("256", "2048")
        },
        "flip_over_de00": {
            size: medians[f"matevo_compare_flip_{size}_ms"] / medians[f"matevo_compare_{size}_ms"]
            for size in ("256", "2048")
        },
        "mean_de00": {name: mean for name, mean in means.items() if "flip" not in name},
        "mean_flip": {name: mean for name, mean in means.items() if "flip" in name},
        "load_average_before_after": [load_before, os.getloadavg()[0]],
    }
    print(json.dumps(result, indent=2))
    for size in ("256", "2048"):
        if abs(means[f"matevo_compare_{size}"] - means[f"skimage_compare_{size}"]) > 0.01:
            print(f"matevo and scikit-image disagree at {size}^2", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
