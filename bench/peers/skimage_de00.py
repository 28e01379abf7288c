#!/usr/bin/env python3
"""Peer for `matevo bench`'s de00_mpix_s*: scikit-image's CIEDE2000 on the same images.

Each measurement is what a scikit-image user writes to compare two sRGB images:
rgb2lab on both, then deltaE_ciede2000 and its mean. The images are bench/BenchColor.cpp's:
channel k of image `which` is the top 24 bits of murmur3's fmix32 of 2 k + which, over 2^24,
taken as sRGB-encoded. Prints one JSON object of medians (Mpixel/s) and the mean ΔE00 of the
256^2 pair, which must match matevo's de00_mean_256.
"""
import json
import statistics
import time

import numpy as np
from skimage.color import deltaE_ciede2000, rgb2lab


def fmix32(x):
    x = x.astype(np.uint32)
    x ^= x >> np.uint32(16)
    x *= np.uint32(0x85EBCA6B)
    x ^= x >> np.uint32(13)
    x *= np.uint32(0xC2B2AE35)
    x ^= x >> np.uint32(16)
    return x


def bench_image(size, which):
    channel_index = np.arange(size * size * 3, dtype=np.uint32)
    bits = fmix32(np.uint32(2) * channel_index + np.uint32(which)) >> np.uint32(8)
    encoded = bits.astype(np.float32) / np.float32(1 << 24)
    return encoded.astype(np.float64).reshape(size, size, 3)


def measure(size, repetitions):
    a, b = bench_image(size, 0), bench_image(size, 1)
    times, mean = [], 0.0
    for _ in range(repetitions):
        start = time.perf_counter()
        mean = float(deltaE_ciede2000(rgb2lab(a), rgb2lab(b)).mean())
        times.append(time.perf_counter() - start)
    return size * size / 1e6 / statistics.median(times), mean


def main():
    rate_256, mean_256 = measure(256, 15)
    rate_2048, mean_2048 = measure(2048, 3)
    print(json.dumps({
        "skimage_de00_mpix_s_256": rate_256,
        "skimage_de00_mpix_s_2048": rate_2048,
        "skimage_de00_mpix_s": rate_2048,
        "skimage_de00_mean_256": mean_256,
        "skimage_de00_mean_2048": mean_2048,
    }))


if __name__ == "__main__":
    main()
