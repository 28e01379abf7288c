#!/usr/bin/env python3
"""The Scene window's responsiveness in the real editor: first picture, orbit rate, refine.

Usage: bench/scene_window_orbit.py [--runs N] [--driver script|xdotool] [--cache warm|cold]
                                   [--lighting L] [--instances N] [--matevo PATH] [--display :N]

Each run starts the real editor under its own Xvfb (1920x1080 screen and window,
`--report-timings`), with the Scene window placed at (0, 0), 1280x720, showing N shader balls
(default 40) wearing the population under the studio light (`--lighting`). The editor's script
waits for the first GA run, opens the Scene window and waits for its whole picture; then the
camera is orbited three times, 3 s apart, and the editor quits:
  --driver script   the script's `scene-orbit 40` (40 moves of 4 degrees, 20 ms apart);
  --driver xdotool  xdotool holds the left button on the picture and moves it 30 times by 12
                    pixels, 100 ms apart (for editors without `scene-orbit`).
Prints one JSON object per run: the editor's `scene timings` (first picture after opening,
release to refined picture, pictures per second while orbiting, their medians over the three
orbits) and the load average before and after.

The runs share a cache folder (XDG_CACHE_HOME) holding a copy of the user's FGD tables, and
one Mesa shader cache, which an unreported warm-up run fills first. `--cache cold` removes the
prefiltered studio environment from the cache before each run, so that opening the window
builds it; `--cache warm` (the default) keeps the one the warm-up run left.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ORBITS = 3


def orbit_with_xdotool(environment):
    def xdotool(*words):
        subprocess.run(["xdotool", *words], env=environment, check=True)
    for _ in range(ORBITS):
        xdotool("mousemove", "500", "400")
        time.sleep(0.3)
        xdotool("mousedown", "1")
        for _ in range(30):
            xdotool("mousemove_relative", "--", "12", "2")
            time.sleep(0.1)
        xdotool("mouseup", "1")
        time.sleep(3.0)


def editor_script(driver, lighting, ready):
    lines = ["wait-evolution", f"lighting {lighting}", "scene-mesh shaderball", "scene open",
             "wait-scene", f"screenshot {ready}"]
    if driver == "script":
        lines += ["scene-orbit 40", "wait-scene", "idle 3000"] * ORBITS
    else:
        lines += [f"idle {int(ORBITS * 7000 + 5000)}"]
    return "\n".join(lines + ["quit", ""])


def run(args, workdir, cache):
    config = Path(workdir) / "config" / "matevo"
    config.mkdir(parents=True, exist_ok=True)
    (config / "imgui.ini").write_text(
        "[Window][Scene]\nPos=0,0\nSize=1280,720\nCollapsed=0\n\n"
        f"[MatevoView][view]\nscene_mesh=shaderball\nscene_instances={args.instances}\n"
        "scene_layout=0\n\n")
    ready = Path(workdir) / "ready.png"
    ready.unlink(missing_ok=True)
    script = Path(workdir) / "script.txt"
    script.write_text(editor_script(args.driver, args.lighting, ready))
    environment = dict(os.environ, XDG_CONFIG_HOME=str(Path(workdir) / "config"),
                       XDG_CACHE_HOME=str(cache),
                       MESA_SHADER_CACHE_DIR=str(Path(workdir) / "mesa_shader_cache"),
                       DISPLAY=args.display)
    xvfb = subprocess.Popen(["Xvfb", args.display, "-screen", "0", "1920x1080x24"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(1.0)
        editor = subprocess.Popen(
            [args.matevo, "edit", str(ROOT / "presets" / "validation_metal.json"), "--size",
             "1920x1080", "--report-timings", "--script", str(script)],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=environment)
        if args.driver == "xdotool":
            deadline = time.time() + 300
            while not ready.exists() and editor.poll() is None and time.time() < deadline:
                time.sleep(0.2)
            if ready.exists():
                orbit_with_xdotool(environment)
        output, _ = editor.communicate(timeout=600)
    finally:
        xvfb.terminate()
        xvfb.wait()
    match = re.search(r"scene timings: (\{.*\})", output)
    if editor.returncode != 0 or not match:
        sys.exit(f"scene_window_orbit: the editor failed ({editor.returncode}):\n{output}")
    return json.loads(match.group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--driver", choices=["script", "xdotool"], default="script")
    parser.add_argument("--cache", choices=["warm", "cold"], default="warm")
    parser.add_argument("--lighting", default="studio")
    parser.add_argument("--matevo", default=str(ROOT / "build" / "matevo"))
    parser.add_argument("--instances", type=int, default=40)
    parser.add_argument("--display", default=":78")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as workdir:
        cache = Path(workdir) / "cache"
        (cache / "matevo").mkdir(parents=True)
        user_cache = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "matevo"
        for tables in user_cache.glob("fgd_tir_v*.bin"):
            shutil.copy(tables, cache / "matevo")
        run(args, workdir, cache)  # the warm-up: shader and environment caches
        for number in range(1, args.runs + 1):
            if args.cache == "cold":
                for studio in (cache / "matevo").glob("studio_*.bin"):
                    studio.unlink()
            load_before = os.getloadavg()[0]
            timings = run(args, workdir, cache)
            print(json.dumps({"run": number, "driver": args.driver, "cache": args.cache,
                              "scene": timings, "load_before": load_before,
                              "load_after": os.getloadavg()[0]}), flush=True)


if __name__ == "__main__":
    main()
