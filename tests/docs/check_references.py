#!/usr/bin/env python3
"""Fails on a dangling reference anywhere in the repository's sources and docs.

A reference is a Markdown link ([text](target)), a file name ending in .md, or a path into the
repository's own folders (core/documents/Preset.h, docs/scene.md, scripts/test.sh; a stem such as
ui/ImageView stands for its .h/.cpp). Each must name a file or folder that exists: relative to the
referring file, to the repository root, or (for a bare *.md name) to docs/. The repository must also
stand alone, so nothing may point outside it (OUTSIDE below lists the forms such a pointer takes).

usage: check_references.py SOURCE_DIR
"""
import os
import re
import subprocess
import sys

TEXT_SUFFIXES = {".md", ".h", ".cpp", ".c", ".glsl", ".comp", ".txt", ".cmake", ".sh", ".py",
                 ".json", ".clang-format", ""}
TOP_FOLDERS = "app|core|ui|tests|shaders|scripts|bench|docs|presets|cmake|\\.ci"
MARKDOWN_LINK = re.compile(r"\]\(([^)\s]+)\)")
MD_NAME = re.compile(r"(?<![\w/.$-])((?:\.\./|[\w.-]+/)*[\w-][\w.-]*\.md)\b")
REPO_PATH = re.compile(r"(?<![\w/.$-])((?:" + TOP_FOLDERS + r")/[\w./-]*[\w-])")
OUTSIDE = re.compile(r"/work/|\.\./shared/|shared/docs/")


def tracked_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files"], check=True, capture_output=True,
                             text=True).stdout
        return [line for line in out.splitlines() if line]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for folder, dirs, names in os.walk(root):
            dirs[:] = [d for d in dirs if not d.startswith((".git", "build"))]
            files += [os.path.relpath(os.path.join(folder, n), root) for n in names]
        return files


def exists(root, referrer, target, extra_bases=()):
    target = target.split("#")[0].rstrip(".,;:")
    if not target:
        return True
    bases = [os.path.dirname(os.path.join(root, referrer)), root]
    bases += [os.path.join(root, b) for b in extra_bases]
    for base in bases:
        candidate = os.path.normpath(os.path.join(base, target))
        # "ui/CompareMetricsPanel" names the .h/.cpp pair by its stem.
        if os.path.exists(candidate) or any(
                os.path.exists(candidate + ext) for ext in (".h", ".cpp", ".md")):
            return True
    return False


def main():
    root = os.path.abspath(sys.argv[1])
    problems = []
    for relative in tracked_files(root):
        name = os.path.basename(relative)
        suffix = os.path.splitext(name)[1]
        if suffix not in TEXT_SUFFIXES or relative.startswith("tests/data/"):
            continue
        path = os.path.join(root, relative)
        if not os.path.isfile(path):
            continue
        try:
            with open(path, encoding="utf-8") as handle:
                lines = handle.read().splitlines()
        except UnicodeDecodeError:
            continue
        if relative == "tests/docs/check_references.py":
            continue  # this file names the forbidden patterns
        for number, line in enumerate(lines, 1):
            where = f"{relative}:{number}"
            if line.lstrip().startswith("#include"):
                continue  # the compiler checks includes; some are generated in the build tree
            if OUTSIDE.search(line):
                problems.append(f"{where}: points outside the repository: {line.strip()}")
            if suffix == ".md":
                for target in MARKDOWN_LINK.findall(line):
                    if re.match(r"[a-z]+://|#|mailto:", target):
                        continue
                    if not exists(root, relative, target):
                        problems.append(f"{where}: dangling link '{target}'")
            for target in MD_NAME.findall(line):
                if not exists(root, relative, target, extra_bases=("docs",)):
                    problems.append(f"{where}: no such document '{target}'")
            for target in REPO_PATH.findall(line):
                if "*" in target or "NNN" in target:
                    continue
                if not exists(root, relative, target):
                    problems.append(f"{where}: no such file '{target}'")
    for problem in problems:
        print(problem)
    print(f"check_references: {len(problems)} dangling reference(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
