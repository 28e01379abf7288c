#!/usr/bin/env python3
"""Compares an independent glTF client's renders of a delivered set with matevo's, by
`matevo compare` (mean ΔE00 over the sphere), for docs/export.md's "Clients" table. Not run in CI.

    scripts/compare-client-renders.py MATEVO SET CLIENT_DIR

SET is a folder `matevo variants --deliver gltf --out SET` wrote; CLIENT_DIR holds the client's
target.png and variant_NNN.png (scripts/blender-render-set.py writes them). Prints one JSON
object: per variant the client's ΔE00 to matevo's glTF-BRDF render (SET/delivered) and to its
Belcour render (SET/variants), and to the client's target; how many variants the client keeps in
the band and at least the spacing from the others; and the Spearman rank correlation of the
client's pairwise ΔE00 with matevo's (Belcour and glTF-BRDF).
"""
import itertools
import json
import subprocess
import sys
from pathlib import Path


def delta_e(matevo, a, b):
    run = subprocess.run([matevo, "compare", str(a), str(b), "--json"], check=True,
                         capture_output=True, text=True)
    return json.loads(run.stdout)["mean_de00"]


def ranks(values):
    order = sorted(range(len(values)), key=lambda i: values[i])
    result = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            result[order[k]] = (i + j) / 2.0
        i = j + 1
    return result


def spearman(x, y):
    rx, ry = ranks(x), ranks(y)
    mx, my = sum(rx) / len(rx), sum(ry) / len(ry)
    cov = sum((a - mx) * (b - my) for a, b in zip(rx, ry))
    vx = sum((a - mx) ** 2 for a in rx) ** 0.5
    vy = sum((b - my) ** 2 for b in ry) ** 0.5
    return cov / (vx * vy) if vx > 0 and vy > 0 else float("nan")


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    matevo, folder, client = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    report = json.loads((folder / "report.json").read_text())
    low, high = report["request"]["band"]
    apart = report["request"]["min_apart"]
    count = len(report["variants"])
    stems = [f"variant_{i:03d}" for i in range(count)]
    variants = []
    for stem in stems:
        variants.append({
            "variant": stem,
            "to_matevo_gltf": delta_e(matevo, client / f"{stem}.png",
                                      folder / "delivered" / f"{stem}.png"),
            "to_matevo_belcour": delta_e(matevo, client / f"{stem}.png",
                                         folder / "variants" / f"{stem}.png"),
            "to_target": delta_e(matevo, client / f"{stem}.png", client / "target.png"),
        })
    pairs = list(itertools.combinations(range(count), 2))
    client_pairwise = [delta_e(matevo, client / f"{stems[i]}.png", client / f"{stems[j]}.png")
                       for i, j in pairs]
    belcour_pairwise = [report["pairwise_de00"][i][j] for i, j in pairs]
    gltf_pairwise = [report["delivery"]["pairwise_de00"][i][j] for i, j in pairs]
    nearest = [min((d for (i, j), d in zip(pairs, client_pairwise) if k in (i, j)),
                   default=0.0) for k in range(count)]
    in_band = [low <= v["to_target"] <= high for v in variants]
    spaced = [n >= apart for n in nearest]
    print(json.dumps({
        "preset": report["preset"],
        "target_to_matevo_gltf": delta_e(matevo, client / "target.png",
                                         folder / "delivered" / "target.png"),
        "target_to_matevo_belcour": delta_e(matevo, client / "target.png", folder / "target.png"),
        "variants": variants,
        "in_band": sum(in_band),
        "spaced": sum(spaced),
        "both": sum(a and b for a, b in zip(in_band, spaced)),
        "smallest_pairwise": min(client_pairwise) if client_pairwise else 0.0,
        "spearman_vs_belcour": spearman(client_pairwise, belcour_pairwise),
        "spearman_vs_gltf": spearman(client_pairwise, gltf_pairwise),
    }, indent=1))


main()
