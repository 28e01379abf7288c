#!/usr/bin/env python3
"""Peer for bench/process_times.py: `matevo compare A B` done with scikit-image, as a process.

Reads the two PNG files, keeps the pixels both images cover (alpha >= 0.5, as matevo does),
converts them with rgb2lab and prints the mean, max and count of deltaE_ciede2000 as JSON, so
the run can check both tools found the same figures.
"""
import json
import sys

import numpy as np
import skimage.io
from skimage.color import deltaE_ciede2000, rgb2lab


def main():
    a, b = (skimage.io.imread(path) for path in sys.argv[1:3])
    covered = (a[..., 3] > 127) & (b[..., 3] > 127)  # alpha >= 0.5 in 8 bits
    colours = [image[covered][:, :3][np.newaxis] for image in (a, b)]
    difference = deltaE_ciede2000(rgb2lab(colours[0]), rgb2lab(colours[1]))
    print(json.dumps({"mean_de00": float(difference.mean()),
                      "max_de00": float(difference.max()),
                      "pixels": int(covered.sum())}))


if __name__ == "__main__":
    main()
