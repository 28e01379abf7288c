#!/usr/bin/env python3
"""The presets' JSON Schema (docs/preset.schema.json) against the presets and the reader.

Usage: check_preset_schema.py SCHEMA PRESETS_DIR MATEVO [SAVED_PRESET...]

1. The schema is a valid JSON Schema (draft 2020-12).
2. Every shipped preset validates, and so does each SAVED_PRESET (presets as matevo saves them:
   minimal, with a format version and kept materials).
3. The schema and matevo's reader agree on broken presets: each mutation of a shipped preset
   below is refused by the schema and makes `matevo render --preset FILE` exit 2.
Exits 1 naming the first disagreement.
"""
import copy
import json
import subprocess
import sys
import tempfile
from pathlib import Path

import jsonschema


def mutations(preset):
    """(what, broken preset) pairs, each one a mistake the reader refuses."""
    def changed(edit):
        broken = copy.deepcopy(preset)
        edit(broken)
        return broken

    def set_in(path, value):
        def edit(document):
            *parents, key = path
            for parent in parents:
                document = document[parent]
            document[key] = value
        return edit

    def remove(key):
        return lambda document: document.pop(key)

    return [
        ("population as a string", changed(set_in(["ga", "population"], "50"))),
        ("population below 2", changed(set_in(["ga", "population"], 1))),
        ("unknown coat", changed(set_in(["family", "coat"], "glossy"))),
        ("no name", changed(remove("name"))),
        ("conductor without base_kappa", changed(remove("base_kappa"))),
        ("image size above 4096", changed(set_in(["scene", "image_size"], 5000))),
        ("g outside [-1, 1]", changed(set_in(["target", "g"], 2))),
        ("unknown metric", changed(set_in(["ga", "metric"], "cosine"))),
        ("a format newer than matevo's", changed(set_in(["format_version"], 3))),
    ]


def main():
    schema_file, presets_dir, matevo = sys.argv[1:4]
    saved_presets = [Path(file) for file in sys.argv[4:]]
    schema = json.loads(Path(schema_file).read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)

    presets = sorted(Path(presets_dir).glob("*.json"))
    if not presets:
        print(f"no presets in {presets_dir}", file=sys.stderr)
        return 1
    for preset_file in presets + saved_presets:
        errors = [error.message for error in validator.iter_errors(json.loads(preset_file.read_text()))]
        if errors:
            print(f"{preset_file.name} does not validate: {errors[0]}", file=sys.stderr)
            return 1

    base = json.loads((Path(presets_dir) / "validation_metal.json").read_text())
    with tempfile.TemporaryDirectory(prefix="matevo_preset_schema_") as folder:
        for what, broken in mutations(base):
            if validator.is_valid(broken):
                print(f"the schema accepts a preset with {what}", file=sys.stderr)
                return 1
            file = Path(folder) / "broken.json"
            file.write_text(json.dumps(broken))
            run = subprocess.run([matevo, "render", "--preset", str(file), "--size", "8",
                                  "--backend", "cpu", "--out", str(Path(folder) / "x.png")],
                                 capture_output=True, text=True)
            if run.returncode != 2:
                print(f"matevo exits {run.returncode}, not 2, on a preset with {what}: "
                      f"{run.stderr.strip()}", file=sys.stderr)
                return 1
    print(f"{len(presets) + len(saved_presets)} presets validate; schema and reader agree on "
          f"{len(mutations(base))} broken presets")
    return 0


if __name__ == "__main__":
    sys.exit(main())
