#!/usr/bin/env python3
"""'Hold under paper and studio' (docs/variants.md, "Several lightings"), measured as a user
checks it.

For each validation preset: `matevo variants --count 12 --band 2,5 --min-apart 2 --env
paper,studio` (and the same request under the paper's light alone, `--env paper`), its wall
time, and each delivered variant rendered again on its own from its variant_NNN.json under each
lighting (`matevo render --genome ... --env L`) and measured with `matevo compare` against the
target rendered the same way from target.json: how many variants lie inside the band under each
lighting, under both, and the smallest pairwise distance under each. Prints one JSON object.
"""
import argparse
import itertools
import json
import os
import subprocess
import tempfile
import time

PRESETS = {"validation_metal": ["--hue"], "validation_metal_depth": [],
           "validation_painted_metal": []}
LIGHTINGS = ["paper", "studio"]
COUNT, LOW, HIGH, APART, SIZE = 12, 2.0, 5.0, 2.0, 256


def run(command, check=True):
    return subprocess.run(command, check=check, capture_output=True, text=True)


def remeasure(matevo, folder, report, lighting, scratch):
    """ΔE00 to the target and the pairwise matrix, re-rendered under `lighting`."""
    def render(material, name):
        out = os.path.join(scratch, f"{name}_{lighting}.png")
        run([matevo, "render", "--genome", os.path.join(folder, material), "--env", lighting,
             "--size", str(SIZE), "--out", out])
        return out

    def compare(a, b):
        return json.loads(run([matevo, "compare", "--json", a, b]).stdout)["mean_de00"]

    target = render("target.json", "target")
    images = [render(v["file"], f"v{v['index']}") for v in report["variants"]]
    to_target = [compare(target, image) for image in images]
    smallest = min((compare(a, b) for a, b in itertools.combinations(images, 2)), default=0.0)
    return to_target, smallest


def measure(matevo, preset, extra, env, seed):
    with tempfile.TemporaryDirectory() as scratch:
        folder = os.path.join(scratch, "set")
        command = [matevo, "variants", "--preset", preset, "--count", str(COUNT), "--band",
                   f"{LOW},{HIGH}", "--min-apart", str(APART), "--seed", str(seed), "--env", env,
                   "--out", folder] + extra
        started = time.monotonic()
        result = run(command, check=False)
        wall = time.monotonic() - started
        if result.returncode not in (0, 3):
            raise RuntimeError(result.stderr)
        with open(os.path.join(folder, "report.json")) as file:
            report = json.load(file)
        entry = {"env": env, "found": len(report["variants"]), "exit": result.returncode,
                 "wall_s": round(wall, 2), "load": round(os.getloadavg()[0], 1),
                 "summary": report["summary"]}
        in_band = [True] * len(report["variants"])
        for lighting in LIGHTINGS:
            to_target, smallest = remeasure(matevo, folder, report, lighting, scratch)
            inside = [LOW <= d <= HIGH for d in to_target]
            in_band = [a and b for a, b in zip(in_band, inside)]
            entry[lighting] = {"in_band": sum(inside), "smallest_pairwise": round(smallest, 3)}
        entry["in_band_under_both"] = sum(in_band)
        return entry


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--matevo", default="build/matevo")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    results = {}
    for preset, extra in PRESETS.items():
        results[preset] = [measure(args.matevo, preset, extra, env, args.seed)
                           for env in ("paper,studio", "paper")]
    print(json.dumps(results, indent=2))


if __name__ == "__main__":
    main()
