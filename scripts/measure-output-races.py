#!/usr/bin/env python3
"""The output races of docs/reliability.md, measured with a real matevo.

  scripts/measure-output-races.py MATEVO [--rounds-cross-host 20] [--rounds-foreign 50]
                                  [--rounds-export 50]

cross-host: an evolve run writes a folder while a run in another PID namespace (standing in for
  another host on a shared filesystem; needs unshare(1)) starts beside it; counts the files the
  first run lost against the same run made alone.
foreign: a file is put into an output folder at a random moment of an `evolve --force` run into
  it; counts the files lost.
export: two `matevo export` of different materials write one .gltf / .mtlx at once; counts the
  results whose main file is not one export's whole result or names a missing or wrong file.
Prints one line per race; exits 1 if anything was lost or broken.
"""
import argparse
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

NAMESPACE = (["unshare", "--pid", "--fork", "--mount-proc"] if os.geteuid() == 0 else
             ["unshare", "--user", "--map-root-user", "--pid", "--fork", "--mount-proc"])


def evolve(matevo, out, population, *extra):
    return [matevo, "evolve", "--size", "16", "--backend", "cpu", "--seed", "3",
            "--generations", "6", "--population", str(population), "--out", str(out), *extra]


def files_under(folder):
    return sorted(str(p.relative_to(folder)) for p in Path(folder).rglob("*") if p.is_file())


def wait_for_staging(out, process):
    pattern = "." + out.name + ".matevo-tmp-"
    while process.poll() is None:
        if any(entry.startswith(pattern) for entry in os.listdir(out.parent)):
            return True
        time.sleep(0.005)
    return False


def cross_host(matevo, work, rounds):
    reference = work / "reference"
    subprocess.run(evolve(matevo, reference, 60), check=True, capture_output=True)
    expected = files_under(reference)
    lost = overlapped = damaged = 0
    for round in range(rounds):
        shared = work / f"shared_{round}"
        shared.mkdir()
        victim = subprocess.Popen(evolve(matevo, shared / "share_1", 60),
                                  stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        wait_for_staging(shared / "share_1", victim)
        time.sleep(random.uniform(0, 0.5))
        subprocess.run(NAMESPACE + evolve(matevo, shared / "share_2", 6), capture_output=True)
        overlapped += victim.poll() is None
        victim.wait()
        have = set(files_under(shared / "share_1")) if victim.returncode == 0 else set()
        missing = sum(1 for f in expected if f not in have)
        lost += missing
        damaged += missing > 0
    return (f"cross-host race: {rounds} rounds ({overlapped} with the first run still going "
            f"when the other ended), {damaged} runs damaged, {lost} files lost", lost)


def foreign(matevo, work, rounds):
    lost = during = 0
    for round in range(rounds):
        out = work / f"foreign_{round}"
        subprocess.run(evolve(matevo, out, 6), check=True, capture_output=True)
        run = subprocess.Popen(evolve(matevo, out, 60, "--force"), stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE)
        wait_for_staging(out, run)
        time.sleep(random.uniform(0, 1.5))
        (out / "notes.txt").write_text("mine")
        during += run.poll() is None
        run.wait()
        notes = out / "notes.txt"
        if run.returncode != 0 or not notes.is_file() or notes.read_text() != "mine":
            lost += 1
    return (f"foreign-file race: {rounds} rounds ({during} with the file added while the run "
            f"went on), {lost} files lost", lost)


def referenced(main):
    text = main.read_text()
    if main.suffix == ".gltf":
        document = json.loads(text)
        return [e["uri"] for kind in ("buffers", "images") for e in document.get(kind, [])
                if "uri" in e]
    return re.findall(r'type="filename" value="([^"]+)"', text)


def export(matevo, work, rounds):
    presets = ["validation_painted_metal", "validation_metal_depth"]
    command = lambda preset, out: [matevo, "export", "--preset", preset, "--out", str(out),
                                   "--backend", "cpu", "--fit-size", "16", "--fit-renders", "30",
                                   "--report-size", "16"]
    broken = 0
    for extension in ("gltf", "mtlx"):
        solos = []
        for preset in presets:
            (work / preset).mkdir(exist_ok=True)
            solos.append(work / preset / ("out." + extension))
            subprocess.run(command(preset, solos[-1]), check=True, capture_output=True)
        for round in range(rounds):
            folder = work / f"export_{extension}_{round}"
            folder.mkdir()
            main = folder / ("out." + extension)
            runs = [subprocess.Popen(command(p, main), stdout=subprocess.DEVNULL,
                                     stderr=subprocess.DEVNULL) for p in presets]
            ok = all(r.wait() == 0 for r in runs) and main.is_file()
            solo = ok and next((s for s in solos if s.read_bytes() == main.read_bytes()), None)
            whole = bool(solo) and all(
                (folder / n).is_file() and (folder / n).read_bytes() == (solo.parent / n).read_bytes()
                for n in referenced(main))
            broken += 0 if whole else 1
    return f"concurrent-export race: {rounds} rounds each of .gltf and .mtlx, {broken} broken", broken


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("matevo")
    parser.add_argument("--rounds-cross-host", type=int, default=20)
    parser.add_argument("--rounds-foreign", type=int, default=50)
    parser.add_argument("--rounds-export", type=int, default=50)
    args = parser.parse_args()
    matevo = str(Path(args.matevo).resolve())
    failures = 0
    with tempfile.TemporaryDirectory(prefix="matevo_races_") as work:
        for race, rounds in ((cross_host, args.rounds_cross_host), (foreign, args.rounds_foreign),
                             (export, args.rounds_export)):
            if rounds <= 0:
                continue
            folder = Path(work) / race.__name__
            folder.mkdir()
            line, count = race(matevo, folder, rounds)
            print(line, flush=True)
            failures += count
            shutil.rmtree(folder)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
