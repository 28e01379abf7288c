#!/usr/bin/env python3
"""core's folders as layers: lists the folder -> folder include edges of core and the include
loops between folders, and (with --check) fails on a loop, on a folder that includes a folder its
CMake target does not link, on an include that does not go down docs/architecture.md's picture
of the layers, or on a folder of core without a row in that page's module table.

    check_core_layers.py SOURCE_DIR            print edges and loops
    check_core_layers.py SOURCE_DIR --check    the same, exit 1 on any fault
"""
import re
import sys
from pathlib import Path

INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z]+)/', re.MULTILINE)
ADD_LIBRARY = re.compile(r'add_library\(\s*(matevo_\w+)')
LINK = re.compile(r'target_link_libraries\(\s*(matevo_\w+)([^)]*)\)', re.DOTALL)


def folders(core):
    return sorted(p.name for p in core.iterdir() if p.is_dir())


def include_edges(core, names, suffixes=(".h", ".cpp")):
    """folder -> {included folder: first file that includes it}"""
    edges = {name: {} for name in names}
    for name in names:
        for source in sorted((core / name).rglob("*")):
            if source.suffix not in suffixes:
                continue
            for target in INCLUDE.findall(source.read_text(encoding="utf-8")):
                if target in edges and target != name:
                    edges[name].setdefault(target, source.relative_to(core.parent))
    return edges


def loops(edges):
    """Every elementary cycle between folders, each once, as a list starting at its least name."""
    found = []

    def walk(start, node, path):
        for nxt in sorted(edges[node]):
            if nxt == start:
                found.append(path[:])
            elif nxt > start and nxt not in path:
                walk(start, nxt, path + [nxt])

    for start in sorted(edges):
        walk(start, start, [start])
    return found


def linked_folders(core, names):
    """folder -> (the folders its sources may include: its libraries' direct links and, through
    those, their PUBLIC links; the folders its headers may include: those its libraries pass on
    to whoever links them, through PUBLIC links only)."""
    library_folder, public, direct = {}, {}, {}
    for name in names:
        cmake = core / name / "CMakeLists.txt"
        if not cmake.exists():
            continue
        text = re.sub(r"#[^\n]*", "", cmake.read_text(encoding="utf-8"))
        for library in ADD_LIBRARY.findall(text):
            library_folder[library] = name
        for library, arguments in LINK.findall(text):
            scope = "PUBLIC"
            for word in arguments.split():
                if word in ("PUBLIC", "PRIVATE", "INTERFACE"):
                    scope = word
                elif word.startswith("matevo_"):
                    direct.setdefault(library, set()).add(word)
                    if scope != "PRIVATE":
                        public.setdefault(library, set()).add(word)

    def exported(library, seen):
        if library in seen:
            return set()
        seen.add(library)
        result = {library}
        for dependency in public.get(library, ()):
            result |= exported(dependency, seen)
        return result

    granted = {name: set() for name in names}
    passed_on = {name: set() for name in names}
    for library, folder in library_folder.items():
        for dependency in direct.get(library, ()):
            for reachable in exported(dependency, set()):
                if reachable in library_folder:
                    granted[folder].add(library_folder[reachable])
        for reachable in exported(library, set()):
            if reachable in library_folder:
                passed_on[folder].add(library_folder[reachable])
    return granted, passed_on


def undocumented(text, names):
    return [name for name in names
            if not re.search(r"^\|\s*`core/" + name + r"`\s*\|", text, re.MULTILINE)]


def layers(text):
    """folder -> its row in the picture of the layers: the fenced block of "N  folder..." lines."""
    row = {}
    for block in re.findall(r"^```\n(.*?)^```", text, re.MULTILINE | re.DOTALL):
        lines = block.strip().split("\n")
        if all(re.fullmatch(r"\d+(\s+[a-z]+)+", line) for line in lines):
            for line in lines:
                number, *folders = line.split()
                row.update({folder: int(number) for folder in folders})
    return row


def main():
    root = Path(sys.argv[1])
    check = "--check" in sys.argv[2:]
    core = root / "core"
    names = folders(core)
    edges = include_edges(core, names)
    for name in names:
        print(f"{name} -> {' '.join(sorted(edges[name])) or '(none)'}")
    cycles = loops(edges)
    print(f"include loops between core folders: {len(cycles)}")
    faults = []
    for cycle in cycles:
        faults.append("include loop: " + " -> ".join(cycle + [cycle[0]]) + " (" +
                      ", ".join(str(edges[a][b]) for a, b in zip(cycle, cycle[1:] + cycle[:1]))
                      + ")")
    granted, passed_on = linked_folders(core, names)
    header_edges = include_edges(core, names, (".h",))
    for name in names:
        for target, source in sorted(edges[name].items()):
            if target not in granted[name]:
                faults.append(f"core/{name} includes core/{target} ({source}) without linking it")
            elif target in header_edges[name] and target not in passed_on[name]:
                faults.append(f"core/{name}'s header {header_edges[name][target]} includes "
                              f"core/{target}, which its library does not link PUBLIC")
    architecture = (root / "docs" / "architecture.md").read_text(encoding="utf-8")
    for name in undocumented(architecture, names):
        faults.append(f"core/{name} has no row in docs/architecture.md's module table")
    row = layers(architecture)
    for name in names:
        if name not in row:
            faults.append(f"core/{name} is not in docs/architecture.md's picture of the layers")
    for name in names:
        for target, source in sorted(edges[name].items()):
            if name in row and target in row and row[target] >= row[name]:
                faults.append(f"core/{name} (row {row[name]}) includes core/{target} "
                              f"(row {row[target]}), not below it in docs/architecture.md ({source})")
    for fault in faults:
        print(fault, file=sys.stderr)
    return 1 if check and faults else 0


if __name__ == "__main__":
    sys.exit(main())
