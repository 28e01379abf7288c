#!/usr/bin/env python3
"""The editor's frame time with the Scene window open, against the same editor without it,
measured in the same run.

Usage: bench/editor_scene_timings.py [--runs N] [--matevo PATH]

Each round starts the real editor twice under Xvfb (1280x800, `--report-timings`), rounds
interleaved so that a change of machine load touches both alike:
  without: wait for the first GA run to finish, leave the editor idle for 20 s, then draw
           60 frames;
  with:    the same, but open the Scene window first and wait for its first picture (the
           idle time lets any render the window's final size asks for finish, so the 60
           frames measure drawing the window, not the scene renderer beside it).
The Scene window shows its default: 24 shader balls wearing the population, studio lighting.
Prints one JSON object: per case the median of the runs' median idle frame times
(`frame_idle_ms` of `--report-timings`), the ratio with/without, and the load average before
and after.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def run_editor(matevo, script_lines, workdir):
    script = Path(workdir) / "script.txt"
    script.write_text("\n".join(script_lines) + "\n")
    environment = dict(os.environ, XDG_CONFIG_HOME=str(Path(workdir) / "config"))
    completed = subprocess.run(
        ["xvfb-run", "-a", "-s", "-screen 0 1280x800x24", str(matevo), "edit", "--size",
         "1280x800", "--report-timings", "--script", str(script)],
        capture_output=True, text=True, env=environment, timeout=600)
    if completed.returncode != 0:
        sys.exit(f"editor_scene_timings: the editor failed ({completed.returncode}):\n"
                 f"{completed.stdout}{completed.stderr}")
    match = re.search(r"editor timings: (\{.*\})", completed.stdout + completed.stderr)
    if not match:
        sys.exit("editor_scene_timings: no timings in the editor's output")
    return json.loads(match.group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--matevo", default=str(ROOT / "build" / "matevo"))
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as workdir:
        without = ["wait-evolution", "idle 20000", "wait 60", "quit"]
        with_scene = ["wait-evolution", "scene open", "wait-scene", "idle 20000", "wait 60",
                      "quit"]
        load_before = os.getloadavg()[0]
        frames = {"without": [], "with": []}
        for _ in range(args.runs):
            frames["without"].append(run_editor(args.matevo, without, workdir)["frame_idle_ms"])
            frames["with"].append(run_editor(args.matevo, with_scene, workdir)["frame_idle_ms"])
        load_after = os.getloadavg()[0]
    without_ms = statistics.median(frames["without"])
    with_ms = statistics.median(frames["with"])
    print(json.dumps({
        "frame_idle_ms_without_scene": round(without_ms, 1),
        "frame_idle_ms_with_scene": round(with_ms, 1),
        "with_over_without": round(with_ms / without_ms, 2),
        "runs": args.runs,
        "frames_without": frames["without"],
        "frames_with": frames["with"],
        "load_before": load_before,
        "load_after": load_after,
    }))


if __name__ == "__main__":
    main()
