# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Atlases of many meshes, one dask.distributed task per mesh.

``python3 -m disk_uv batch INPUT OUTPUT_DIR`` (see ``--help``). INPUT is a
folder (its meshes, sub-folders included) or a manifest: a text file with
one mesh path per line (relative to the manifest's folder; blank lines and
lines starting with ``#`` are skipped).

Per mesh ``NAME`` (its path relative to the input, without extension), the
output folder gets ``NAME.obj`` (and ``NAME.glb`` with ``--glb``) and
``NAME.json``, the report, written last: a mesh whose report and atlas files
exist is complete and a rerun skips it. A mesh that fails gets
``NAME.error.json`` with the message and is skipped by reruns too, unless
``--retry-failed``. Every file is written to a temporary name and renamed,
so an interrupted batch leaves no partial file. ``summary.csv`` and
``summary.json`` list every mesh of the run with its status.
"""

import argparse
import csv
import io
import json
import os
import sys
import time

from ._files import write_atomically

MESH_EXTENSIONS = (".off", ".obj", ".ply", ".stl", ".ts")
SUMMARY_FIELDS = ("mesh", "status", "faces", "charts", "angle_distortion", "area_distortion",
                  "packing_efficiency", "seconds", "error")


def find_meshes(source):
    """(name, path) of every mesh of a folder or a manifest, sorted by name."""
    meshes = []
    if os.path.isdir(source):
        for folder, subfolders, files in os.walk(source):
            subfolders.sort()
            for file in sorted(files):
                if file.lower().endswith(MESH_EXTENSIONS):
                    path = os.path.join(folder, file)
                    meshes.append((os.path.splitext(os.path.relpath(path, source))[0], path))
    elif os.path.isfile(source):
        base = os.path.dirname(os.path.abspath(source))
        with open(source, encoding="utf-8") as manifest:
            for line in manifest:
                line = line.strip()
                if not line or line.startswith("#"):
                    continue
                path = line if os.path.isabs(line) else os.path.join(base, line)
                name = os.path.splitext(line if not os.path.isabs(line) else os.path.basename(line))[0]
                meshes.append((name.lstrip("./"), path))
    else:
        raise FileNotFoundError("no such folder or manifest: %s" % source)
    names = [name for name, _ in meshes]
    duplicates = sorted({name for name in names if names.count(name) > 1})
    if duplicates:
        raise ValueError("several meshes would write the same outputs: %s" % ", ".join(duplicates))
    return sorted(meshes)


def output_paths(output_dir, name, glb):
    base = os.path.join(output_dir, name)
    atlas_files = [base + ".obj"] + ([base + ".glb"] if glb else [])
    return atlas_files, base + ".json", base + ".error.json"


def summary_row(name, status, report=None, seconds=None, error=""):
    row = dict.fromkeys(SUMMARY_FIELDS, "")
    row.update(mesh=name, status=status, error=error)
    if report is not None:
        charts = report["charts"]
        faces = sum(c["faces"] for c in charts) or 1
        row.update(faces=report["faces"], charts=len(charts),
                   angle_distortion=sum(c["faces"] * c["angle_distortion"] for c in charts) / faces,
                   area_distortion=sum(c["faces"] * c["area_distortion"] for c in charts) / faces,
                   packing_efficiency=report["packing"]["efficiency"],
                   seconds=report["seconds"]["read"] + report["seconds"]["total"] if seconds is None else seconds)
    return row


def process_mesh(name, path, output_dir, glb, load_options, atlas_options):
    """One task: reads, unwraps and writes one mesh; returns its summary row.

    Errors of the mesh (unreadable, not manifold, ...) are recorded in
    NAME.error.json and returned as a row, not raised, so that one bad mesh
    never stops the batch.
    """
    import disk_uv  # imported on the worker

    atlas_files, report_path, error_path = output_paths(output_dir, name, glb)
    os.makedirs(os.path.dirname(report_path), exist_ok=True)
    start = time.perf_counter()
    try:
        read_start = time.perf_counter()
        vertices, faces = disk_uv.load(path, **load_options)
        read_seconds = time.perf_counter() - read_start
        atlas = disk_uv.atlas(vertices, faces, **atlas_options)
        report = dict(atlas.report)
        report["input"] = path
        report["seconds"]["read"] = read_seconds
        disk_uv.save_obj(atlas_files[0], atlas)
        if glb:
            disk_uv.save_glb(atlas_files[1], atlas)
        # The report last: its presence marks the mesh complete.
        write_atomically(report_path, (json.dumps(report, indent=2) + "\n").encode())
        if os.path.exists(error_path):
            os.unlink(error_path)
        return summary_row(name, "ok", report, time.perf_counter() - start)
    except (ValueError, OSError, MemoryError) as error:
        # load() names its own keywords; here the batch's options are meant.
        message = "%s: %s" % (type(error).__name__, str(error).replace("repair=True", "--repair")
                              .replace("triangulate=True", "--triangulate"))
        write_atomically(error_path, (json.dumps({"input": path, "error": message}, indent=2) + "\n").encode())
        return summary_row(name, "error", seconds=time.perf_counter() - start, error=message)


def previous_row(name, output_dir, glb, retry_failed):
    """The row of a mesh done by an earlier run, or None if it must be (re)done."""
    atlas_files, report_path, error_path = output_paths(output_dir, name, glb)
    if os.path.exists(report_path) and all(os.path.exists(f) for f in atlas_files):
        try:
            with open(report_path, encoding="utf-8") as f:
                return summary_row(name, "skipped", json.load(f))
        except (ValueError, KeyError, OSError):
            return None
    if os.path.exists(error_path) and not retry_failed:
        try:
            with open(error_path, encoding="utf-8") as f:
                return summary_row(name, "error (skipped)", error=json.load(f)["error"])
        except (ValueError, KeyError, OSError):
            return None
    return None


class Progress:
    """A one-line progress bar on stderr when it is a terminal."""

    def __init__(self, total, enabled):
        self.total, self.done, self.failed = total, 0, 0
        self.enabled = enabled and sys.stderr.isatty()
        self.start = time.perf_counter()

    def update(self, row):
        self.done += 1
        self.failed += row["status"] == "error"
        if self.enabled:
            width = 30
            filled = int(width * self.done / max(self.total, 1))
            sys.stderr.write("\r[%s%s] %d/%d meshes, %d failed, %.0f s " % (
                "#" * filled, "." * (width - filled), self.done, self.total, self.failed,
                time.perf_counter() - self.start))
            sys.stderr.flush()

    def finish(self):
        if self.enabled:
            sys.stderr.write("\n")


def write_summary(output_dir, rows):
    os.makedirs(output_dir, exist_ok=True)
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=SUMMARY_FIELDS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    write_atomically(os.path.join(output_dir, "summary.csv"), text.getvalue().encode())
    write_atomically(os.path.join(output_dir, "summary.json"), (json.dumps(rows, indent=2) + "\n").encode())


def run_batch(source, output_dir, workers=None, scheduler=None, glb=False, retry_failed=False,
              load_options=None, atlas_options=None, progress=True):
    """Runs the batch; returns the summary rows (also written to OUTPUT_DIR)."""
    from distributed import Client, LocalCluster, as_completed

    load_options = dict(load_options or {})
    atlas_options = dict(atlas_options or {})
    atlas_options.setdefault("threads", 1)
    meshes = find_meshes(source)
    os.makedirs(output_dir, exist_ok=True)
    rows = {}
    todo = []
    for name, path in meshes:
        row = previous_row(name, output_dir, glb, retry_failed)
        if row is None:
            todo.append((name, path))
        else:
            rows[name] = row
    bar = Progress(len(meshes), progress)
    for row in rows.values():
        bar.update(row)
    # Largest files first, so that the last task to finish is a small one.
    todo.sort(key=lambda item: (-os.path.getsize(item[1]) if os.path.exists(item[1]) else 0, item[0]))
    if todo:
        cluster = None
        if scheduler:
            client = Client(scheduler)
        else:
            cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                   processes=True, dashboard_address=None)
            client = Client(cluster)
        try:
            futures, names = [], {}
            for i, (name, path) in enumerate(todo):
                future = client.submit(process_mesh, name, os.path.abspath(path), os.path.abspath(output_dir), glb,
                                       load_options, atlas_options, key="disk_uv-%d-%s" % (i, name), pure=False)
                futures.append(future)
                names[future.key] = name
            for future in as_completed(futures):
                name = names[future.key]
                try:
                    row = future.result()
                except Exception as error:  # the worker died (memory, signal): retried by the next run
                    row = summary_row(name, "error", error="%s: %s" % (type(error).__name__, error))
                rows[name] = row
                bar.update(row)
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
    bar.finish()
    ordered = [rows[name] for name, _ in meshes]
    write_summary(output_dir, ordered)
    return ordered


def add_atlas_arguments(parser):
    import disk_uv
    d = disk_uv._disk_uv
    group = parser.add_argument_group("atlas options (as the disk_uv tool's)")
    group.add_argument("--method", default=d.default_parameterization_method,
                       choices=disk_uv.METHODS)
    group.add_argument("--resolution", type=int, default=1024)
    group.add_argument("--padding", type=float, default=2.0)
    group.add_argument("--max-angle-distortion", type=float, default=d.default_max_angle_distortion)
    group.add_argument("--max-area-distortion", type=float, default=d.default_max_area_distortion)
    group.add_argument("--max-stretch", type=float, default=d.default_max_stretch)
    group.add_argument("--max-area-scale", type=float, default=d.default_max_area_scale)
    group.add_argument("--max-stretch-p95", type=float, default=d.default_max_stretch_p95)
    group.add_argument("--min-convexity", type=float, default=d.default_min_convexity)
    group.add_argument("--unbounded", action="store_true", help="no distortion or convexity bound (the paper's charts)")
    group.add_argument("--rough-borders", action="store_true", help="keep the paper's saw-toothed borders")
    group.add_argument("--threads", type=int, default=1, help="threads per mesh (default 1: one mesh per core)")
    group.add_argument("--repair", action="store_true", help="repair each mesh's soup before the atlas")
    group.add_argument("--triangulate", action="store_true", help="triangulate polygons")


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="python3 -m disk_uv batch",
        description="UV atlases of many meshes on dask.distributed (a local cluster, or --scheduler).")
    parser.add_argument("input", help="folder of meshes, or manifest file (one mesh path per line)")
    parser.add_argument("output", help="output folder (created if missing)")
    parser.add_argument("--workers", type=int, default=None, help="local worker processes (default: cores)")
    parser.add_argument("--scheduler", default=None,
                        help="address of an existing dask scheduler (tcp://host:port) instead of a local cluster; "
                             "its workers need disk_uv installed and the input and output paths")
    parser.add_argument("--glb", action="store_true", help="also write NAME.glb")
    parser.add_argument("--retry-failed", action="store_true", help="redo meshes that failed in an earlier run")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")
    add_atlas_arguments(parser)
    args = parser.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        parser.error("--workers must be at least 1")
    atlas_options = dict(method=args.method, resolution=args.resolution, padding=args.padding,
                         max_angle_distortion=args.max_angle_distortion,
                         max_area_distortion=args.max_area_distortion, max_stretch=args.max_stretch,
                         max_area_scale=args.max_area_scale, max_stretch_p95=args.max_stretch_p95,
                         min_convexity=args.min_convexity, unbounded=args.unbounded, rough_borders=args.rough_borders, threads=args.threads)
    try:
        # Bad options fail here, once, rather than on every mesh.
        import disk_uv
        import numpy
        disk_uv.atlas(numpy.array([[0., 0, 0], [1, 0, 0], [0, 1, 0]]), numpy.array([[0, 1, 2]]), **atlas_options)
        rows = run_batch(args.input, args.output, workers=args.workers, scheduler=args.scheduler, glb=args.glb,
                         retry_failed=args.retry_failed,
                         load_options=dict(repair=args.repair, triangulate=args.triangulate),
                         atlas_options=atlas_options, progress=not args.no_progress)
    except (ValueError, OSError) as error:
        print("disk_uv batch: error: %s" % error, file=sys.stderr)
        return 2
    counts = {}
    for row in rows:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    print("disk_uv batch: %d meshes (%s); summary in %s" % (
        len(rows), ", ".join("%d %s" % (n, s) for s, n in sorted(counts.items())),
        os.path.join(args.output, "summary.csv")))
    return 1 if any(row["status"].startswith("error") for row in rows) else 0
