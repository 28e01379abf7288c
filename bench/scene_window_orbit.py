#!/usr/bin/env python3
"""The Scene window's responsiveness in the real editor: first picture, orbit rate, refine.

Usage: bench/scene_window_orbit.py [--runs N] [--matevo PATH] [--instances N] [--display :N]

Each run starts the real editor under its own Xvfb (1920x1080 screen and window,
`--report-timings`), with the Scene window placed at (0, 0), 1280x720, showing N shader balls
(default 40) wearing the population under the studio light. The script waits for the first
GA run, opens the Scene window and waits for its whole picture; then this program orbits
three times with xdotool (the left button held on the picture, 30 moves of 12 pixels, 100 ms
apart), 5 s apart, and the editor quits. Prints one JSON object per run: the editor's
`scene timings` (first picture after opening, release to refined picture, pictures per second
while orbiting) and the load average. The first run also fills Mesa's shader cache: the later
runs measure the first picture with a warm cache.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def orbit(environment, times):
    def xdotool(*words):
        subprocess.run(["xdotool", *words], env=environment, check=True)
    for _ in range(times):
        xdotool("mousemove", "500", "400")
        time.sleep(0.3)
        xdotool("mousedown", "1")
        for _ in range(30):
            xdotool("mousemove_relative", "--", "12", "2")
            time.sleep(0.1)
        xdotool("mouseup", "1")
        time.sleep(5.0)


def run(matevo, instances, display, workdir):
    config = Path(workdir) / "config" / "matevo"
    config.mkdir(parents=True, exist_ok=True)
    (config / "imgui.ini").write_text(
        "[Window][Scene]\nPos=0,0\nSize=1280,720\nCollapsed=0\n\n"
        f"[MatevoView][view]\nscene_mesh=shaderball\nscene_instances={instances}\n"
        "scene_layout=0\n\n")
    ready = Path(workdir) / "ready.png"
    ready.unlink(missing_ok=True)
    script = Path(workdir) / "script.txt"
    script.write_text("wait-evolution\nscene open\nwait-scene\n"
                      f"screenshot {ready}\nidle 45000\nquit\n")
    environment = dict(os.environ, XDG_CONFIG_HOME=str(Path(workdir) / "config"),
                       DISPLAY=display)
    xvfb = subprocess.Popen(["Xvfb", display, "-screen", "0", "1920x1080x24"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(1.0)
        editor = subprocess.Popen(
            [str(matevo), "edit", str(ROOT / "presets" / "validation_metal.json"), "--size",
             "1920x1080", "--report-timings", "--script", str(script)],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=environment)
        deadline = time.time() + 300
        while not ready.exists() and editor.poll() is None and time.time() < deadline:
            time.sleep(0.2)
        if ready.exists():
            orbit(environment, 3)
        output, _ = editor.communicate(timeout=300)
    finally:
        xvfb.terminate()
        xvfb.wait()
    match = re.search(r"scene timings: (\{.*\})", output)
    if editor.returncode != 0 or not match:
        sys.exit(f"scene_window_orbit: the editor failed ({editor.returncode}):\n{output}")
    return json.loads(match.group(1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=2)
    parser.add_argument("--matevo", default=str(ROOT / "build" / "matevo"))
    parser.add_argument("--instances", type=int, default=40)
    parser.add_argument("--display", default=":78")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as workdir:
        for number in range(1, args.runs + 1):
            load_before = os.getloadavg()[0]
            timings = run(args.matevo, args.instances, args.display, workdir)
            print(json.dumps({"run": number, "scene": timings, "load_before": load_before,
                              "load_after": os.getloadavg()[0]}), flush=True)


if __name__ == "__main__":
    main()
