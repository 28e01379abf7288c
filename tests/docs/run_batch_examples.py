#!/usr/bin/env python3
"""Runs the examples of docs/batch.md with the real matevo, as a user would paste them.

Usage: run_batch_examples.py PAGE MATEVO WORK_FOLDER  (PAGE: the batch page in docs)

Each fenced block after a line `<!-- example: NAME -->` is run in WORK_FOLDER/NAME with `matevo`
on the PATH. That `matevo` is a small wrapper around the built binary which adds small image
sizes and the CPU back end, so the examples run in seconds; the commands themselves are the
page's, unchanged. `parallel-*` blocks run with bash (GNU parallel from Debian); `slurm-*` blocks
are job scripts, run once per array task with the variables Slurm sets, and the merge job's
`--wrap` command after them. Then the outputs are checked: every set and export exists, the
same seed gave the same files under both schedulers, and the shares merged under either are
byte for byte the set one process writes.
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

# Added by the wrapper, per command: small renders and fits, the CPU back end.
SMALL = {
    "variants": ["--size", "32", "--fitness-size", "16", "--backend", "cpu"],
    "export": ["--fit-size", "16", "--fit-renders", "30", "--report-size", "16",
               "--backend", "cpu"],
}


def examples(page):
    found = {}
    text = page.read_text()
    for match in re.finditer(r"<!-- example: ([\w-]+) -->\n```sh\n(.*?)```", text, re.S):
        found[match.group(1)] = match.group(2)
    return found


def write_wrapper(folder, matevo, added=None):
    """A `matevo` in folder that runs the real one with `added` (default SMALL) per command."""
    folder.mkdir(parents=True, exist_ok=True)
    cases = "\n".join(f'    {command}) extra=({" ".join(args)}) ;;'
                      for command, args in (added or SMALL).items())
    wrapper = folder / "matevo"
    wrapper.write_text(f"""#!/bin/bash
extra=()
case "$1" in
{cases}
esac
exec {matevo} "$@" "${{extra[@]}}"
""")
    wrapper.chmod(0o755)


def run(script, cwd, env, label):
    result = subprocess.run(["bash", "-c", script], cwd=cwd, env=env, capture_output=True,
                            text=True, timeout=600)
    if result.returncode != 0:
        sys.exit(f"{label}: exit {result.returncode}\n{result.stdout}\n{result.stderr}")


def array_range(script):
    match = re.search(r"^#SBATCH --array=(\d+)-(\d+)$", script, re.M)
    if not match:
        sys.exit("slurm example: no #SBATCH --array=A-B line")
    return range(int(match.group(1)), int(match.group(2)) + 1)


def files_under(folder):
    return {str(p.relative_to(folder)): p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


def main():
    page, matevo, work = Path(sys.argv[1]), Path(sys.argv[2]).resolve(), Path(sys.argv[3])
    shutil.rmtree(work, ignore_errors=True)
    write_wrapper(work / "bin", matevo)
    env = dict(os.environ, PATH=f"{work / 'bin'}:{os.environ['PATH']}")
    found = examples(page)
    for name in ("parallel-sets", "slurm-sets"):
        if name not in found:
            sys.exit(f"{page}: no example '{name}'")

    parallel = work / "parallel-sets"
    parallel.mkdir()
    run(found["parallel-sets"], parallel, env, "parallel-sets")

    slurm = work / "slurm-sets"
    slurm.mkdir()
    (slurm / "sets.sbatch").write_text(found["slurm-sets"])
    seeds = array_range(found["slurm-sets"])
    for task in seeds:
        task_env = dict(env, SLURM_ARRAY_TASK_ID=str(task), SLURM_ARRAY_TASK_COUNT=str(len(seeds)),
                        SLURM_CPUS_PER_TASK="1")
        run("bash sets.sbatch", slurm, task_env, f"slurm-sets task {task}")

    for seed in seeds:
        for folder in (parallel, slurm):
            if not (folder / "sets" / str(seed) / "report.json").is_file():
                sys.exit(f"{folder.name}: no set for seed {seed}")
            if not (folder / "glb" / f"{seed}.glb").is_file():
                sys.exit(f"{folder.name}: no glb for seed {seed}")
        # The wall time in report.json differs; everything else is the same bytes.
        sets = [files_under(folder / "sets" / str(seed) / "variants")
                for folder in (parallel, slurm)]
        if sets[0] != sets[1]:
            sys.exit(f"seed {seed}: the two schedulers wrote different variant files")
        if (parallel / "glb" / f"{seed}.glb").read_bytes() != \
                (slurm / "glb" / f"{seed}.glb").read_bytes():
            sys.exit(f"seed {seed}: the two schedulers wrote different .glb files")
    print(f"batch examples: {len(seeds)} sets and exports under GNU parallel and as a Slurm "
          f"array, identical")

    # One set in shares: under GNU parallel, as a Slurm array then the merge job's command,
    # and in one process; the three folders must be the same bytes.
    for name in ("parallel-shares", "slurm-shares", "one-run"):
        if name not in found:
            sys.exit(f"{page}: no example '{name}'")
    merge_job = re.search(r"--wrap '([^']*)'", page.read_text())
    if not merge_job:
        sys.exit(f"{page}: no merge job (sbatch --wrap '...')")
    folders = {}
    for name in ("parallel-shares", "slurm-shares", "one-run"):
        folder = work / name
        folder.mkdir()
        if name == "slurm-shares":
            (folder / "shares.sbatch").write_text(found[name])
            for task in array_range(found[name]):
                run("bash shares.sbatch", folder,
                    dict(env, SLURM_ARRAY_TASK_ID=str(task), SLURM_CPUS_PER_TASK="1"),
                    f"slurm-shares task {task}")
            run(merge_job.group(1), folder, env, "slurm-shares merge job")
        else:
            run(found[name], folder, env, name)
        folders[name] = files_under(folder / "world_set")
    if not folders["one-run"]:
        sys.exit("one-run: wrote nothing")
    for name in ("parallel-shares", "slurm-shares"):
        if folders[name] != folders["one-run"]:
            differing = sorted(set(folders[name].items()) ^ set(folders["one-run"].items()))
            sys.exit(f"{name}: the merged set differs from one run: {differing[:3]}")
    print(f"batch examples: one set of {len(folders['one-run'])} files, merged from shares "
          f"under GNU parallel and a Slurm array, identical to one run")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
