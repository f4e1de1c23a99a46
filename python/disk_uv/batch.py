# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Atlases of many meshes, one dask.distributed task per mesh.

``python3 -m disk_uv batch INPUT OUTPUT_DIR`` (see ``--help``). INPUT is a
folder (its meshes, sub-folders included, but not OUTPUT_DIR if it lies
inside, nor the batch's own outputs if INPUT lies in OUTPUT_DIR) or a
manifest: a text file with one mesh path per line (relative to the
manifest's folder; blank lines and lines starting with ``#`` are skipped).

Per mesh ``NAME`` (its path relative to the input folder or to the
manifest's folder, without extension; the file name alone for a path outside
the manifest's folder), the output folder gets ``NAME.obj`` (and
``NAME.glb`` with ``--glb``) and ``NAME.json``, the report, written last: a
mesh whose report and atlas files exist is complete and a rerun skips it. A
mesh that fails gets ``NAME.error.json`` with the message (starting with the
input file unless it names it) and is skipped by reruns too, unless
``--retry-failed``. ``summary.csv`` and ``summary.json`` list every mesh of
the run with its status.

Every output stays inside OUTPUT_DIR, symbolic links resolved: a mesh whose
outputs would not, would replace its input file, or whose name is empty,
``summary`` (the summary's name) or ends in ``.error`` (an error file's) is
refused alone, an error row of the summary naming its manifest line or file.

Each mesh is done in a child process of its worker, forked from a server
process that has disk_uv loaded. With ``--time-limit SECONDS`` a mesh that
takes longer is killed and fails ("time limit of N s exceeded"); a child
that dies (out of memory, a signal, a crash) fails its mesh alone, with the
signal; the worker goes on with the next mesh either way. A child stopped
by SIGINT (^C), SIGTERM or SIGHUP, as when the batch is stopped, gets no
error file: the next run does its mesh.

Every file is written to a temporary ``.disk_uv-HOST-PID-XXXXXXXX.part`` and
renamed, so an interrupted batch leaves no partial file. A batch removes at
its start, anywhere under OUTPUT_DIR, the temporaries of this host's
processes that are gone (killed mid-write) and those of earlier versions
(``.disk_uv-XXXXXXXX.part``); a killed child's right away.

File names need not be UTF-8: a mesh named by other bytes is read and its
outputs named by the same bytes. The text files (summaries, reports, error
files) write such a name, and messages naming it, with those bytes as
``\\xNN`` (a backslash escape), as ``readable()`` does.
"""

import argparse
import csv
import ctypes
import hashlib
import io
import json
import multiprocessing
import os
import re
import signal
import sys
import time

from ._files import remove_stale_temporaries, remove_temporaries, write_atomically

MESH_EXTENSIONS = (".off", ".obj", ".ply", ".stl", ".ts")
SUMMARY_FIELDS = ("mesh", "status", "faces", "charts", "angle_distortion", "area_distortion",
                  "packing_efficiency", "pages", "seconds", "error")
# Signals that stop a mesh's process from outside (not its fault: a rerun does it).
STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
# The first line of the OBJ files the batch writes (the C++ writer's).
OWN_OBJ_SIGNATURE = b"# UV atlas written by CGAL::Disk_segmentation"


def readable(text):
    """`text` with the bytes of a non-UTF-8 file name (surrogate escapes) as \\xNN."""
    try:
        return text.encode("utf-8", "surrogateescape").decode("utf-8", "backslashreplace")
    except UnicodeEncodeError:  # other lone surrogates (never in a file name)
        return text.encode("utf-8", "backslashreplace").decode("utf-8")


def _is_own_output(path):
    try:
        with open(path, "rb") as f:
            return f.read(len(OWN_OBJ_SIGNATURE)) == OWN_OBJ_SIGNATURE
    except OSError:
        return False


def _folder_meshes(source, output_dir):
    """(name, path, path) of the meshes of a folder, OUTPUT_DIR's files excepted."""
    output = _stat(output_dir) if output_dir is not None else None
    # INPUT in OUTPUT_DIR: its files may be outputs of the batch.
    in_output = output is not None and _inside(os.path.realpath(source), os.path.realpath(output_dir))
    meshes = []
    for folder, subfolders, files in os.walk(source):
        if output is not None:
            subfolders[:] = [s for s in subfolders if not _same(os.path.join(folder, s), output)]
        subfolders.sort()
        for file in sorted(files):
            path = os.path.join(folder, file)
            if file.lower().endswith(MESH_EXTENSIONS) and not (
                    in_output and file.lower().endswith(".obj") and _is_own_output(path)):
                meshes.append((os.path.splitext(os.path.relpath(path, source))[0], path, path))
    return meshes


def _stat(path):
    try:
        return os.stat(path)
    except OSError:
        return None


def _same(path, stat):
    """Whether `path` is the folder of os.stat() result `stat` (None: none)."""
    other = _stat(path)
    return stat is not None and other is not None and os.path.samestat(other, stat)


def _inside(path, folder):
    return os.path.commonpath([path, folder]) == folder


def _manifest_meshes(source):
    """(name, path, the line's description) of the meshes of a manifest."""
    base = os.path.dirname(os.path.abspath(source))
    meshes = []
    # Surrogate escapes: a line may name a file whose name is not UTF-8; utf-8-sig: a BOM is no path.
    with open(source, encoding="utf-8-sig", errors="surrogateescape") as manifest:
        for number, line in enumerate(manifest, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            path = os.path.join(base, line)  # the line itself if absolute
            relative = os.path.relpath(os.path.normpath(path), base)
            # Outside the manifest's folder (absolute or through ..): the file name alone.
            if relative == os.pardir or relative.startswith(os.pardir + os.sep):
                relative = os.path.basename(os.path.normpath(path))
            meshes.append((os.path.splitext(relative)[0], path, "line %d of %s (%r)" % (number, source, line)))
    return meshes


def find_meshes(source, output_dir=None):
    """(name, path, where) of every mesh of a folder or a manifest, sorted by name.

    `where` describes the entry for messages: its path, or its manifest line.
    """
    if os.path.isdir(source):
        meshes = _folder_meshes(source, output_dir)
    elif os.path.isfile(source):
        meshes = _manifest_meshes(source)
    else:
        raise FileNotFoundError("no such folder or manifest: %s" % source)
    names = [name for name, _, _ in meshes if name not in ("", ".", "..")]
    duplicates = sorted({name for name in names if names.count(name) > 1})
    if duplicates:
        raise ValueError("several meshes would write the same outputs: %s" % ", ".join(duplicates))
    return sorted(meshes)


def output_paths(output_dir, name, glb):
    base = os.path.join(output_dir, name)
    atlas_files = [base + ".obj"] + ([base + ".glb"] if glb else [])
    return atlas_files, base + ".json", base + ".error.json"


def _located(path):
    """`path` with the symbolic links of its folders resolved (not its own: a rename replaces a link)."""
    return os.path.join(os.path.realpath(os.path.dirname(os.path.abspath(path))), os.path.basename(path))


def _same_file(a, b):
    try:
        return os.path.samefile(a, b)
    except OSError:  # one of them is missing
        return False


def refusal(name, path, output_dir, glb):
    """Why the outputs of mesh `name` (read from `path`) must not be written, or None."""
    if name in ("", ".", ".."):
        return "no output name can be made of it"
    if name == "summary":
        return "its report would be the batch's summary.json"
    if name.endswith(".error"):
        return "its report would be mesh %s's error file" % name[:-len(".error")]
    real_output = os.path.realpath(output_dir)
    atlas_files, report_path, error_path = output_paths(output_dir, name, glb)
    folder = os.path.dirname(_located(report_path))  # the folder of all its outputs
    if not _inside(folder, real_output):
        return "its outputs would be in %s, outside OUTPUT_DIR %s" % (folder, real_output)
    input_location = _located(path)
    for file in atlas_files + [report_path, error_path]:
        if os.path.join(folder, os.path.basename(file)) == input_location or _same_file(file, path):
            return "its output %s would replace the input file" % file
    return None


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
                   pages=report["packing"].get("pages", 1),
                   seconds=report["seconds"]["read"] + report["seconds"]["total"] if seconds is None else seconds)
    return row


def _failed(name, path, error_path, message, seconds):
    """Records a failure in NAME.error.json; its summary row."""
    if readable(path) not in readable(message):
        message = "%s: %s" % (path, message)
    try:
        write_atomically(error_path, (json.dumps({"input": readable(path), "error": readable(message)}, indent=2)
                                      + "\n").encode())
    except OSError as error:  # the row still tells
        message += " (and %s.error.json could not be written: %s)" % (name, error)
    return summary_row(name, "error", seconds=seconds, error=message)


def process_mesh_here(name, path, output_dir, glb, load_options, atlas_options):
    """Reads, unwraps and writes one mesh in this process; returns its summary row.

    Errors of the mesh (unreadable, not manifold, ...) are recorded in
    NAME.error.json and returned as a row, not raised, so that one bad mesh
    never stops the batch.
    """
    import disk_uv

    atlas_files, report_path, error_path = output_paths(output_dir, name, glb)
    start = time.perf_counter()
    try:
        os.makedirs(os.path.dirname(report_path), exist_ok=True)
        read_start = time.perf_counter()
        vertices, faces = disk_uv.load(path, **load_options)
        read_seconds = time.perf_counter() - read_start
        atlas = disk_uv.atlas(vertices, faces, **atlas_options)
        report = dict(atlas.report)
        report["input"] = readable(path)
        report["seconds"]["read"] = read_seconds
        disk_uv.save_obj(atlas_files[0], atlas)
        if glb:
            disk_uv.save_glb(atlas_files[1], atlas)
        # The report last: its presence marks the mesh complete.
        write_atomically(report_path, (json.dumps(report, indent=2) + "\n").encode())
        if os.path.exists(error_path):
            os.unlink(error_path)
        return summary_row(name, "ok", report, time.perf_counter() - start)
    except Exception as error:
        # load() names its own keywords; here the batch's options are meant.
        message = "%s: %s" % (type(error).__name__, str(error).replace("repair=True", "--repair")
                              .replace("triangulate=True", "--triangulate"))
        return _failed(name, path, error_path, message, time.perf_counter() - start)


_context = None


def _child_processes():
    """The multiprocessing context of the meshes' processes.

    They are forked from a server process that has imported disk_uv and
    numpy once (a fresh interpreter would take ~0.2 s to).
    """
    global _context
    if _context is None:
        _context = multiprocessing.get_context("forkserver")
        _context.set_forkserver_preload(["numpy", "disk_uv", "disk_uv.batch", "multiprocessing.popen_forkserver"])
    return _context


def _child(sender, *args):
    # A ^C stops it at once (Python's handler would wait for the C++ code to return).
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    if sys.platform.startswith("linux"):
        # Killed when the server it was forked from ends, which it does with
        # the worker: no orphan goes on computing after a batch is stopped.
        ctypes.CDLL(None).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    sender.send(process_mesh_here(*args))


def process_mesh(name, path, output_dir, glb, load_options, atlas_options, time_limit=None):
    """One task: process_mesh_here() in a child process; returns the summary row.

    The C++ computation can't be interrupted and a crash (or the OOM
    killer) would take the worker along: the child is killed after
    `time_limit` seconds, and a child that dies fails its mesh alone.
    """
    context = _child_processes()
    start = time.perf_counter()
    receiver, sender = context.Pipe(duplex=False)
    child = context.Process(target=_child, args=(sender, name, path, output_dir, glb, load_options, atlas_options),
                            daemon=True)
    # Dask's workers are daemonic processes, which multiprocessing forbids to
    # have children lest they outlive them; this one is killed when it must.
    multiprocessing.current_process().daemon = False
    try:
        child.start()
    except OSError as error:  # no fork, or the child died before it got its task (a broken pipe)
        sender.close()
        receiver.close()
        # Not the mesh's fault: no error file, the next run does it.
        return summary_row(name, "error", seconds=time.perf_counter() - start,
                           error="%s: could not start its process (%s)" % (path, error))
    sender.close()
    row = None
    try:
        timed_out = not receiver.poll(time_limit)  # a row, or the end of the pipe: the child died
        if not timed_out:
            try:
                row = receiver.recv()
            except EOFError:
                pass
            child.join()
    finally:
        if child.is_alive():  # timed out, or this task was interrupted
            child.kill()
            child.join()
        receiver.close()
    if row is not None:
        return row
    try:
        remove_temporaries(os.path.dirname(os.path.join(output_dir, name)), child.pid)
    except OSError:  # no folder yet; else the next batch removes them
        pass
    if not timed_out and -child.exitcode in STOP_SIGNALS:
        # The batch is being stopped (^C, a service stopped): no fault of the mesh, no error file.
        return summary_row(name, "error", seconds=time.perf_counter() - start,
                           error="%s: stopped by signal %d (%s)" % (path, -child.exitcode,
                                                                   signal.Signals(-child.exitcode).name))
    if timed_out:
        message = "time limit of %g s exceeded" % time_limit
    elif child.exitcode < 0:
        try:
            signal_name = signal.Signals(-child.exitcode).name
        except ValueError:
            signal_name = "?"
        message = "its process was killed by signal %d (%s%s)" % (
            -child.exitcode, signal_name, ": out of memory?" if -child.exitcode == signal.SIGKILL else "")
    else:
        message = "its process exited with code %d" % child.exitcode
    return _failed(name, path, output_paths(output_dir, name, glb)[2], message, time.perf_counter() - start)


def previous_row(name, output_dir, glb, retry_failed):
    """The row of a mesh done by an earlier run, or None if it must be (re)done."""
    atlas_files, report_path, error_path = output_paths(output_dir, name, glb)
    if os.path.exists(report_path) and all(os.path.exists(f) for f in atlas_files):
        try:
            with open(report_path, encoding="utf-8") as f:
                return summary_row(name, "skipped", json.load(f))
        except (ValueError, KeyError, TypeError, OSError):
            return None
    if os.path.exists(error_path) and not retry_failed:
        try:
            with open(error_path, encoding="utf-8") as f:
                return summary_row(name, "error (skipped)", error=json.load(f)["error"])
        except (ValueError, KeyError, TypeError, OSError):
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
    # UTF-8 files: the bytes of a non-UTF-8 name as \\xNN.
    rows = [{key: readable(value) if isinstance(value, str) else value for key, value in row.items()} for row in rows]
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=SUMMARY_FIELDS, lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    write_atomically(os.path.join(output_dir, "summary.csv"), text.getvalue().encode())
    write_atomically(os.path.join(output_dir, "summary.json"), (json.dumps(rows, indent=2) + "\n").encode())


def run_batch(source, output_dir, workers=None, scheduler=None, glb=False, retry_failed=False,
              load_options=None, atlas_options=None, progress=True, time_limit=None):
    """Runs the batch; returns the summary rows (also written to OUTPUT_DIR).

    `time_limit`: None, or the seconds after which a mesh is stopped and fails.
    """
    from distributed import Client, LocalCluster, as_completed

    if time_limit is not None and not (isinstance(time_limit, (int, float)) and 0 < time_limit < float("inf")):
        raise ValueError("the time limit must be a positive number of seconds, not %r" % (time_limit,))
    load_options = dict(load_options or {})
    atlas_options = dict(atlas_options or {})
    atlas_options.setdefault("threads", 1)
    meshes = find_meshes(source, output_dir)
    os.makedirs(output_dir, exist_ok=True)
    remove_stale_temporaries(output_dir)
    rows = [None] * len(meshes)
    todo = []
    for i, (name, path, where) in enumerate(meshes):
        why = refusal(name, path, output_dir, glb)
        if why is not None:
            rows[i] = summary_row(name if name not in ("", ".", "..") else where, "error",
                                  error="%s: refused: %s" % (where, why))
        else:
            rows[i] = previous_row(name, output_dir, glb, retry_failed)
            if rows[i] is None:
                todo.append(i)
    bar = Progress(len(meshes), progress)
    for row in rows:
        if row is not None:
            bar.update(row)
    # Largest files first, so that the last task to finish is a small one.
    todo.sort(key=lambda i: (-os.path.getsize(meshes[i][1]) if os.path.exists(meshes[i][1]) else 0, meshes[i][0]))
    if todo:
        cluster = None
        if scheduler:
            client = Client(scheduler)
        else:
            cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                   processes=True, dashboard_address=None)
            client = Client(cluster)
        try:
            futures, index = [], {}
            for i in todo:
                name, path = meshes[i][:2]
                # No name in the key: dask can't send one that is not UTF-8.
                key = "disk_uv-%d-%s" % (i, hashlib.sha1(os.fsencode(name)).hexdigest()[:12])
                future = client.submit(process_mesh, name, os.path.abspath(path), os.path.abspath(output_dir), glb,
                                       load_options, atlas_options, time_limit, key=key, pure=False)
                futures.append(future)
                index[future.key] = i
            for future in as_completed(futures):
                i = index[future.key]
                try:
                    row = future.result()
                except Exception as error:  # the worker died (memory, signal): retried by the next run
                    row = summary_row(meshes[i][0], "error",
                                      error="%s: %s: %s" % (meshes[i][1], type(error).__name__, error))
                rows[i] = row
                bar.update(row)
        finally:
            client.close()
            if cluster is not None:
                cluster.close()
    bar.finish()
    write_summary(output_dir, rows)
    return rows


def add_atlas_arguments(parser):
    import disk_uv
    d = disk_uv._disk_uv
    group = parser.add_argument_group("atlas options (as the disk_uv tool's)")
    group.add_argument("--method", default=d.default_parameterization_method,
                       choices=disk_uv.METHODS)
    group.add_argument("--resolution", type=_texture_size, default=d.default_texture_resolution, metavar="N|WxH",
                       help="texture side in texels, or WIDTHxHEIGHT for a non-square texture")
    group.add_argument("--padding", type=float, default=d.default_padding)
    group.add_argument("--texels-per-unit", type=float, default=0.0,
                       help="fixed texel density; the charts fill as many pages as they need, written as UDIM "
                            "tiles (0: fit one page)")
    group.add_argument("--max-pages", type=int, default=d.default_max_pages, help="most pages --texels-per-unit may fill")
    group.add_argument("--max-angle-distortion", type=float, default=d.default_max_angle_distortion)
    group.add_argument("--max-area-distortion", type=float, default=d.default_max_area_distortion)
    group.add_argument("--max-stretch", type=float, default=d.default_max_stretch)
    group.add_argument("--max-area-scale", type=float, default=d.default_max_area_scale)
    group.add_argument("--max-stretch-p95", type=float, default=d.default_max_stretch_p95)
    group.add_argument("--min-convexity", type=float, default=d.default_min_convexity)
    group.add_argument("--unbounded", action="store_true", help="no distortion or convexity bound (with --rough-borders --crease-penalty 0: the paper's charts)")
    group.add_argument("--rough-borders", action="store_true", help="keep the paper's saw-toothed borders")
    group.add_argument("--crease-penalty", type=float, default=d.default_crease_penalty,
                       help="borders follow creases (0: the paper's geodesic distance)")
    group.add_argument("--max-charts", type=int, default=0, help="chart budget per mesh (0: no budget)")
    group.add_argument("--threads", type=int, default=1, help="threads per mesh (default 1: one mesh per core)")
    group.add_argument("--repair", action="store_true", help="repair each mesh's soup before the atlas")
    group.add_argument("--triangulate", action="store_true", help="triangulate polygons")


def _texture_size(text):
    """N or WxH (non-negative integers), read by the disk_uv tool's own parser."""
    import disk_uv
    size = disk_uv._disk_uv.parse_texture_size(text)
    if size is None:
        raise argparse.ArgumentTypeError("expected a non-negative integer or WIDTHxHEIGHT, not %r" % text)
    return size


def _seconds(text):
    try:
        seconds = float(text)
    except ValueError:
        seconds = None
    if seconds is None or not 0 < seconds < float("inf"):
        raise argparse.ArgumentTypeError("expected a positive number of seconds, not %r" % text)
    return seconds


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
    parser.add_argument("--time-limit", type=_seconds, default=None, metavar="SECONDS",
                        help="stop a mesh that takes longer and record it as failed (default: no limit)")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")
    add_atlas_arguments(parser)
    args = parser.parse_args(argv)
    if args.workers is not None and args.workers < 1:
        parser.error("--workers must be at least 1")
    atlas_options = dict(method=args.method, resolution=args.resolution, padding=args.padding,
                         max_angle_distortion=args.max_angle_distortion,
                         max_area_distortion=args.max_area_distortion, max_stretch=args.max_stretch,
                         max_area_scale=args.max_area_scale, max_stretch_p95=args.max_stretch_p95,
                         min_convexity=args.min_convexity, unbounded=args.unbounded, rough_borders=args.rough_borders, threads=args.threads,
                         max_charts=args.max_charts or None, texels_per_unit=args.texels_per_unit,
                         max_pages=args.max_pages, crease_penalty=args.crease_penalty)
    import disk_uv
    try:
        # Bad options fail here, once, rather than on every mesh; checked
        # without a mesh, so that only the users' meshes are judged.
        disk_uv.check_options(**atlas_options)
    except ValueError as error:
        # The module names its keywords; the user typed this command's flags.
        message = str(error)
        for name in sorted(atlas_options, key=len, reverse=True):
            message = re.sub(r"(?<![\w-])%s(?!\w)" % re.escape(name), "--" + name.replace("_", "-"), message)
        print("disk_uv batch: error: %s" % message, file=sys.stderr)
        return 2
    try:
        rows = run_batch(args.input, args.output, workers=args.workers, scheduler=args.scheduler, glb=args.glb,
                         retry_failed=args.retry_failed,
                         load_options=dict(repair=args.repair, triangulate=args.triangulate),
                         atlas_options=atlas_options, progress=not args.no_progress, time_limit=args.time_limit)
    except (ValueError, OSError) as error:
        print("disk_uv batch: error: %s" % readable(str(error)), file=sys.stderr)
        return 2
    counts = {}
    for row in rows:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    print("disk_uv batch: %d meshes (%s); summary in %s" % (
        len(rows), ", ".join("%d %s" % (n, s) for s, n in sorted(counts.items())),
        readable(os.path.join(args.output, "summary.csv"))))
    return 1 if any(row["status"].startswith("error") for row in rows) else 0
