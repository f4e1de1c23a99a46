#!/usr/bin/env python3
"""disk_uv against Blender's Smart UV Project, side by side on this machine.

For every mesh (OFF or OBJ triangle meshes; folders are searched for them),
optionally subdivided 1 -> 4 per level, the two tools run in alternating
order, RUNS times each: `disk_uv` once per thread count (its report's total,
which excludes reading the file, and its stages: segmentation,
parameterization, packing; and how many times a face was solved) and Blender's `bpy.ops.uv.smart_project()`
with its defaults (the call alone, Blender's island packing included, timed
inside Blender). Prints one Markdown row per mesh and thread count with the
medians and the ratio disk_uv / Blender, and writes every run to --csv.

    python3 benchmark/Disk_segmentation/versus_blender.py MESH_OR_FOLDER... \\
        [--disk-uv build/bin/disk_uv] [--blender blender] [--runs 3] \\
        [--threads 1,2] [--subdivide 0,1,2] [--min-faces 0] [--csv FILE] \\
        [--variant NAME="DISK_UV OPTIONS"]...

Each --variant runs disk_uv with those options too, in the same rounds
(e.g. --variant paper="--unbounded --rough-borders --crease-penalty 0");
without one, disk_uv runs with its defaults only.

Without Blender (`blender` not found), only disk_uv's times are printed.
Blender: Debian's package `blender`. Nothing here asserts a time.
"""

import argparse
import csv
import json
import os
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile

import numpy as np

# Runs inside Blender: imports the OBJ, selects everything in edit mode and
# times the unwrap alone. Prints one line that the caller parses.
BLENDER_DRIVER = r'''
import sys, time, bpy
path = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=path)
obj = bpy.context.selected_objects[0]
bpy.context.view_layer.objects.active = obj
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
start = time.perf_counter()
bpy.ops.uv.smart_project()
seconds = time.perf_counter() - start
bpy.ops.object.mode_set(mode="OBJECT")
print("SMART_UV_SECONDS %.6f FACES %d" % (seconds, len(obj.data.polygons)))
'''


def read_triangles(path):
    """Vertices (N, 3) and triangles (F, 3) of an OFF or OBJ file."""
    if path.lower().endswith(".off"):
        with open(path) as f:
            tokens = []
            for line in f:
                line = line.split("#", 1)[0].split()
                tokens.extend(line)
        if not tokens or not tokens[0].endswith("OFF"):
            raise ValueError(path + ": not an OFF file")
        nv, nf = int(tokens[1]), int(tokens[2])
        at = 4
        vertices = np.array(tokens[at:at + 3 * nv], dtype=float).reshape(nv, 3)
        at += 3 * nv
        faces = []
        for _ in range(nf):
            k = int(tokens[at])
            if k != 3:
                raise ValueError(path + ": a face is not a triangle")
            faces.append([int(t) for t in tokens[at + 1:at + 4]])
            at += 1 + k
        return vertices, np.array(faces, dtype=np.int64).reshape(-1, 3)
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                vertices.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                corners = [int(p.split("/")[0]) for p in parts[1:]]
                if len(corners) != 3:
                    raise ValueError(path + ": a face is not a triangle")
                faces.append([c - 1 if c > 0 else len(vertices) + c for c in corners])
    return np.array(vertices, dtype=float), np.array(faces, dtype=np.int64).reshape(-1, 3)


def subdivide(vertices, faces):
    """Each triangle into four at its edge midpoints (the surface is unchanged)."""
    edges = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    edges.sort(axis=1)
    unique, inverse = np.unique(edges, axis=0, return_inverse=True)
    inverse = inverse.reshape(-1)
    midpoints = 0.5 * (vertices[unique[:, 0]] + vertices[unique[:, 1]])
    m = len(vertices) + inverse.reshape(3, -1)
    a, b, c = faces[:, 0], faces[:, 1], faces[:, 2]
    ab, bc, ca = m[0], m[1], m[2]
    new_faces = np.concatenate([np.stack([a, ab, ca], 1), np.stack([ab, b, bc], 1),
                                np.stack([ca, bc, c], 1), np.stack([ab, bc, ca], 1)])
    return np.concatenate([vertices, midpoints]), new_faces


def write_obj(path, vertices, faces):
    with open(path, "w") as f:
        np.savetxt(f, vertices, fmt="v %.17g %.17g %.17g")
        np.savetxt(f, faces + 1, fmt="f %d %d %d")


def mesh_files(inputs):
    for item in inputs:
        if os.path.isdir(item):
            for name in sorted(os.listdir(item)):
                if name.lower().endswith((".off", ".obj")):
                    yield os.path.join(item, name)
        else:
            yield item


def run_disk_uv(tool, options, obj, threads, report):
    """(total, segment, parameterize, pack) seconds, peak MB, charts, solves per face."""
    done = subprocess.run([tool, obj, "-q", "--threads", str(threads), "--report", report] + options,
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("versus_blender.py: disk_uv %s failed (exit %d): %s" % (
            " ".join(options) or "with its defaults", done.returncode, done.stderr.strip()[-500:]))
    with open(report) as f:
        r = json.load(f)
    t = r["seconds"]
    stages = (t["total"], t["voronoi"] + t["refine"] + t["merge"], t["parameterization"], t["packing"])
    return stages, r["peak_rss_mb"], len(r["charts"]), r["parameterization"]["solves_per_face"]


def run_blender(blender, driver, obj):
    out = subprocess.run([blender, "-b", "--factory-startup", "--python", driver, "--", obj],
                         check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        if line.startswith("SMART_UV_SECONDS"):
            return float(line.split()[1])
    raise RuntimeError("Blender printed no time:\n" + out[-2000:])


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--disk-uv", default=os.path.join(here, "..", "..", "build", "bin", "disk_uv"))
    parser.add_argument("--blender", default="blender")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--threads", default="1,2", help="disk_uv thread counts, comma-separated")
    parser.add_argument("--subdivide", default="0", help="subdivision levels, comma-separated")
    parser.add_argument("--min-faces", type=int, default=0, help="skip meshes with fewer faces")
    parser.add_argument("--csv", help="write every run here")
    parser.add_argument("--variant", action="append", default=[], metavar='NAME="OPTIONS"',
                        help="also run disk_uv with these options (repeatable)")
    args = parser.parse_args()
    if args.runs < 1:
        parser.error("--runs must be at least 1")
    variants = [("defaults", [])]
    for v in args.variant:
        name, sep, options = v.partition("=")
        if not sep or not name or name in dict(variants):
            parser.error("--variant wants a new NAME=\"OPTIONS\", got " + repr(v))
        try:
            variants.append((name, shlex.split(options)))
        except ValueError as e:
            parser.error("--variant %s: %s" % (name, e))
    threads = [int(t) for t in args.threads.split(",")]
    levels = [int(l) for l in args.subdivide.split(",")]
    if not os.access(args.disk_uv, os.X_OK):
        parser.error("disk_uv not found at " + args.disk_uv + " (build it, or give --disk-uv)")
    blender = shutil.which(args.blender)
    if blender is None:
        print("Blender not found: disk_uv only", file=sys.stderr)

    keys = [(name, t) for name, _ in variants for t in threads]
    rows = []
    print("| mesh | faces | variant | threads | disk_uv s | segment s | parameterize s | pack s | solves per face | "
          "Blender s | ratio | charts | peak MB | KB per face |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        driver = os.path.join(tmp, "driver.py")
        with open(driver, "w") as f:
            f.write(BLENDER_DRIVER)
        for path in mesh_files(args.meshes):
            vertices, faces = read_triangles(path)
            name = os.path.splitext(os.path.basename(path))[0]
            for level in range(max(levels) + 1):
                if level > 0:
                    vertices, faces = subdivide(vertices, faces)
                if level not in levels or len(faces) < args.min_faces:
                    continue
                label = name if level == 0 else "%s x4^%d" % (name, level)
                obj = os.path.join(tmp, "mesh.obj")
                write_obj(obj, vertices, faces)
                ours = {k: [] for k in keys}
                theirs, memory, charts, solves = [], {}, {}, {}
                for run in range(args.runs):
                    # Alternate which tool goes first, so that neither always
                    # meets a cold or a warm machine.
                    order = ["blender", "disk_uv"] if run % 2 else ["disk_uv", "blender"]
                    for tool in order:
                        if tool == "blender" and blender is not None:
                            theirs.append(run_blender(blender, driver, obj))
                            rows.append([label, len(faces), "blender", "", "", run, theirs[-1]] + [""] * 6)
                        elif tool == "disk_uv":
                            for variant, options in variants:
                                for t in threads:
                                    k = (variant, t)
                                    stages, mb, n, spf = run_disk_uv(args.disk_uv, options, obj, t,
                                                                     os.path.join(tmp, "r.json"))
                                    ours[k].append(stages)
                                    memory[k], charts[k], solves[k] = mb, n, spf
                                    rows.append([label, len(faces), "disk_uv", variant, t, run] + list(stages)
                                                + [mb, n, spf])
                blender_s = statistics.median(theirs) if theirs else float("nan")
                for k in keys:
                    s, segment, parameterize, pack = [statistics.median(r[i] for r in ours[k]) for i in range(4)]
                    print("| %s | %d | %s | %d | %.3f | %.3f | %.3f | %.3f | %.2f | %s | %s | %d | %.0f | %.2f |" % (
                        label, len(faces), k[0], k[1], s, segment, parameterize, pack, solves[k],
                        "%.3f" % blender_s if theirs else "-",
                        "%.2f" % (s / blender_s) if theirs else "-", charts[k], memory[k],
                        memory[k] * 1024 / len(faces)), flush=True)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["mesh", "faces", "tool", "variant", "threads", "run", "seconds", "segment_seconds",
                        "parameterize_seconds", "pack_seconds", "peak_mb", "charts", "solves_per_face"])
            w.writerows(rows)


if __name__ == "__main__":
    main()
