#!/usr/bin/env python3
"""Makes docs/experiment.md's "target beside the evolved materials" figures from a results.csv.

Usage: scripts/experiment_figures.py [--csv docs/experiment/results.csv]
                                     [--out docs/experiment/figures] [--matevo build/matevo]

For each material at 50 / 5 and each metric it takes the median run: of the 36 runs sorted by
mean dE00, the 18th (the lower of the two middle ones). It renders the target and that run's best
genome with `matevo render`, maps their difference with `matevo compare --heatmap` (dE00 and
FLIP), and prints the table's Markdown rows (the mean dE00 from the CSV, the mean FLIP measured on
the written PNGs), and on stderr the dE00 measured on the PNGs beside the CSV's value.
"""
import argparse
import csv
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
GENOME_COLUMNS = ("eta1", "eta2", "alpha1", "alpha2", "depth")
MATERIALS = ("validation metal", "validation painted metal", "validation metal depth")
METRICS = ("chebyshev", "euclidean", "manhattan")


def matevo_json(matevo, *arguments):
    done = subprocess.run([matevo, *arguments], capture_output=True, text=True, check=True)
    return json.loads(done.stdout) if done.stdout.strip() else None


def genome_of(row):
    genome = {name: float(row[name]) for name in GENOME_COLUMNS}
    genome["sigma_s"] = [float(row[f"sigma_s_{c}"]) for c in "rgb"]
    genome["sigma_a"] = [float(row[f"sigma_a_{c}"]) for c in "rgb"]
    genome["g"] = float(row["g"])
    return genome


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--csv", default=str(ROOT / "docs/experiment/results.csv"))
    parser.add_argument("--out", default=str(ROOT / "docs/experiment/figures"))
    parser.add_argument("--matevo", default=str(ROOT / "build/matevo"))
    options = parser.parse_args()
    out = Path(options.out)
    out.mkdir(parents=True, exist_ok=True)
    with open(options.csv, newline="") as table:
        rows = [row for row in csv.DictReader(table)
                if row["population"] == "50" and row["generations"] == "5"]
    with tempfile.TemporaryDirectory(prefix="matevo_figures_") as scratch:
        for material in MATERIALS:
            stem = material.replace(" ", "_")
            preset = str(ROOT / "presets" / f"{stem}.json")
            target = out / f"{stem}_target.png"
            matevo_json(options.matevo, "render", "--preset", preset, "--out", str(target))
            for index, metric in enumerate(METRICS):
                runs = sorted((row for row in rows
                               if row["preset"] == material and row["metric"] == metric),
                              key=lambda row: float(row["mean_de00"]))
                if len(runs) != 36:
                    sys.exit(f"{options.csv}: {material}, {metric}: {len(runs)} runs at 50 / 5, "
                             "expected 36")
                median = runs[17]
                genome_file = Path(scratch) / f"{stem}_{metric}.json"
                genome_file.write_text(json.dumps(genome_of(median)))
                best = out / f"{stem}_{metric}_best.png"
                matevo_json(options.matevo, "render", "--preset", preset, "--genome",
                            str(genome_file), "--out", str(best))
                de00 = matevo_json(options.matevo, "compare", str(target), str(best), "--json",
                                   "--heatmap", str(out / f"{stem}_{metric}_de00.png"))
                flip = matevo_json(options.matevo, "compare", str(target), str(best), "--json",
                                   "--metric", "flip",
                                   "--heatmap", str(out / f"{stem}_{metric}_flip.png"))
                images = [f"![](experiment/figures/{name}.png)" for name in
                          (f"{stem}_{metric}_best", f"{stem}_{metric}_de00",
                           f"{stem}_{metric}_flip")]
                shown_target = f"![](experiment/figures/{stem}_target.png)" if index == 0 else ""
                label = material.removeprefix("validation ")
                print(f"| {label}, {metric.capitalize()} | {shown_target} | "
                      f"{' | '.join(images)} | {float(median['mean_de00']):.2f} | "
                      f"{flip['mean_flip']:.3f} |")
                print(f"{label}, {metric}: run {median['run']}, dE00 on the PNGs "
                      f"{de00['mean_de00']:.3f} (CSV {float(median['mean_de00']):.3f})",
                      file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
