#!/usr/bin/env python3
"""Checks the package's include graph against the layering the manual
describes ("How the Package Is Built"; "Building, Installing and Testing"):

  - the graph of the package's headers has no cycle;
  - a header under internal/ includes no public header that does work
    (one that itself includes internal/): only value types;
  - only IO/ headers include IO/ headers;
  - the topic folders of internal/ are floors: a header includes headers
    of its own floor or of lower ones only (FLOORS, lowest first), so that
    an upward include fails;
  - every package header a header includes is in the tree, and every
    header of the tree is reachable from the umbrella header
    or from IO/;
  - no CMake file puts examples/ or tools/ on an include path: the
    package's headers stand on their own.

Usage: check_include_layers.py SOURCE_DIR
"""
import os
import re
import sys

# The topic folders of internal/, lowest first: shared utilities (the
# parameters' checks, plane geometry, threads and progress, the indexed
# mesh) below the stages, each stage's settings in its own folder.
FLOORS = ["Parameters", "Geometry", "Execution", "Mesh", "Segmentation", "Parameterization",
          "Chart_selection", "Packing", "Atlas"]

INCLUDE = re.compile(r'^\s*#\s*include\s*<(CGAL/Disk_segmentation[^>]*)>', re.M)


def package_headers(include_dir):
    headers = {}
    for root, _, files in os.walk(include_dir):
        for name in files:
            if name.endswith(".h"):
                path = os.path.join(root, name)
                rel = os.path.relpath(path, include_dir).replace(os.sep, "/")
                with open(path, encoding="utf-8") as f:
                    headers[rel] = INCLUDE.findall(f.read())
    return headers


def find_cycle(graph):
    state = {}
    stack = []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for succ in graph.get(node, []):
            if state.get(succ) == "open":
                return stack[stack.index(succ):] + [succ]
            if succ not in state:
                cycle = visit(succ)
                if cycle:
                    return cycle
        stack.pop()
        state[node] = "done"
        return None

    for node in sorted(graph):
        if node not in state:
            cycle = visit(node)
            if cycle:
                return cycle
    return None


def main():
    source = sys.argv[1]
    include_dir = os.path.join(source, "include")
    headers = package_headers(include_dir)
    problems = []

    for h, incs in headers.items():
        for i in incs:
            if i not in headers:
                problems.append(f"{h} includes {i}, which is not in the tree")

    cycle = find_cycle(headers)
    if cycle:
        problems.append("include cycle: " + " -> ".join(cycle))

    def is_internal(h):
        return "/internal/" in h

    def is_io(h):
        return h.startswith("CGAL/Disk_segmentation/IO/")

    does_work = {h for h, incs in headers.items()
                 if not is_internal(h) and any(is_internal(i) for i in incs)}
    for h, incs in headers.items():
        if is_internal(h) and not is_io(h):
            for i in incs:
                if i in does_work:
                    problems.append(f"{h} (internal) includes the public function header {i}")
        if not is_io(h):
            for i in incs:
                if is_io(i):
                    problems.append(f"{h} (not IO) includes {i}")

    def floor(h):
        parts = h.split("/")
        if len(parts) == 5 and parts[2] == "internal":
            return parts[3]
        return None

    for h, incs in headers.items():
        if floor(h) is None:
            continue
        if floor(h) not in FLOORS:
            problems.append(f"{h} is in the topic folder {floor(h)}, which FLOORS does not order")
            continue
        for i in incs:
            if floor(i) in FLOORS and FLOORS.index(floor(i)) > FLOORS.index(floor(h)):
                problems.append(f"{h} includes {i} from the higher floor {floor(i)}")

    reachable = set()
    todo = ["CGAL/Disk_segmentation.h"] + [h for h in headers if is_io(h)]
    while todo:
        h = todo.pop()
        if h in reachable or h not in headers:
            continue
        reachable.add(h)
        todo.extend(headers[h])
    for h in sorted(set(headers) - reachable):
        problems.append(f"{h} is reachable from neither CGAL/Disk_segmentation.h nor IO/")

    for root, dirs, files in os.walk(source):
        dirs[:] = [d for d in dirs if not d.startswith(".") and not d.startswith("build")]
        for name in files:
            if name == "CMakeLists.txt" or name.endswith(".cmake"):
                path = os.path.join(root, name)
                with open(path, encoding="utf-8") as f:
                    for n, line in enumerate(f, 1):
                        for folder in ("examples", "tools"):
                            if "include_directories" in line and folder in line:
                                problems.append(f"{os.path.relpath(path, source)}:{n} puts {folder}/ on an include path")

    for p in problems:
        print("include layers:", p)
    print(f"include layers: {len(headers)} headers, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
