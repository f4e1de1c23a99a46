#!/usr/bin/env python3
# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Cost of many inputs and many pages (issue 59, item 5): time and peak
memory should grow linearly with the number of inputs and pages.

    python3 cost_curves.py build/bin/disk_uv [build/python] [--python /usr/bin/python3] [--quick] [--only a,b,c]

Generates its inputs in a temporary folder and measures, each in a child
process (wall time, peak RSS from wait4()):

  (a) disk_uv on N one-tetrahedron OFF files, and on the same N tetrahedra
      as N components of one file (-o out.obj --report r.json);
  (b) disk_uv on one file of N disconnected equilateral triangles at a
      density that puts one chart on each page of 64 texels (--padding 1),
      without and with --atlas-png (one picture per page); N at most 999,
      the UDIM tiles the tool writes (benchmark_hostile's BM_pack_pages
      measures the library's packing beyond);
  (c) the Python module's atlas([(V, F)] * N) on N tetrahedra (needs the
      folder holding the disk_uv package).

Prints a table per case and the ratio of the time (and memory) per input
or page between the largest and the smallest N: 1 is linear.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import textwrap
import time

TETRAHEDRON_V = [(0., 0., 0.), (1., 0., 0.), (0., 1., 0.), (0., 0., 1.)]
TETRAHEDRON_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def write_off(path, vertices, faces):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        out.writelines("%r %r %r\n" % v for v in vertices)
        out.writelines("3 %d %d %d\n" % f for f in faces)


def tetrahedra(n, spacing=3.):
    """n tetrahedra side by side, as one vertex and face list."""
    vertices, faces = [], []
    for i in range(n):
        dx, dy = spacing * (i % 100), spacing * (i // 100)
        base = len(vertices)
        vertices += [(x + dx, y + dy, z) for x, y, z in TETRAHEDRON_V]
        faces += [(a + base, b + base, c + base) for a, b, c in TETRAHEDRON_F]
    return vertices, faces


def triangles(n, spacing=3.):
    """n disconnected equilateral triangles of side 1."""
    h = 3 ** 0.5 / 2
    vertices, faces = [], []
    for i in range(n):
        dx, dy = spacing * (i % 100), spacing * (i // 100)
        base = len(vertices)
        vertices += [(dx, dy, 0.), (dx + 1., dy, 0.), (dx + .5, dy + h, 0.)]
        faces.append((base, base + 1, base + 2))
    return vertices, faces


def measure(command, cwd):
    """Runs `command`; returns (seconds, peak RSS in MB, completed process)."""
    start = time.perf_counter()
    process = subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    # wait4() gives this child's own peak, not the largest of all children.
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.perf_counter() - start
    out, err = process.stdout.read(), process.stderr.read()
    process.stdout.close()
    process.stderr.close()
    process.returncode = os.waitstatus_to_exitcode(status)
    if process.returncode != 0:
        sys.exit("failed (%d): %s\n%s" % (process.returncode, " ".join(command[:8]), err.decode()[-2000:]))
    return seconds, usage.ru_maxrss / 1024., (out, err)


def report_pages(path):
    with open(path) as f:
        return json.load(f)["packing"]["pages"]


def table(title, unit, rows):
    """rows: (n, seconds, mb, extra); prints them and the per-unit ratios."""
    print("\n%s" % title)
    # The step from the row before: what one more input or page costs,
    # without the fixed cost of the process.
    print("%8s %9s %9s %10s %10s %12s %12s  %s"
          % ("N", "seconds", "peak MB", "ms/" + unit, "KB/" + unit, "step ms/" + unit, "step KB/" + unit, ""))
    previous = None
    for n, seconds, mb, extra in rows:
        step = "%12s %12s" % ("", "")
        if previous is not None:
            dn = float(n - previous[0])
            step = "%12.3f %12.1f" % (1e3 * (seconds - previous[1]) / dn, 1024. * (mb - previous[2]) / dn)
        print("%8d %9.2f %9.1f %10.3f %10.1f %s  %s" % (n, seconds, mb, 1e3 * seconds / n, 1024. * mb / n, step, extra))
        previous = (n, seconds, mb)
    if len(rows) > 1:
        (n0, s0, m0, _), (n1, s1, m1, _) = rows[0], rows[-1]
        print("  time per %s, N=%d over N=%d: %.2f; memory per %s: %.2f (1: linear)"
              % (unit, n1, n0, (s1 / n1) / (s0 / n0), unit, (m1 / n1) / (m0 / n0)))
    sys.stdout.flush()


def case_a(tool, folder, sizes):
    files_rows, one_rows = [], []
    for n in sizes:
        d = os.path.join(folder, "a%d" % n)
        os.mkdir(d)
        names = []
        for i in range(n):
            names.append("t%05d.off" % i)
            write_off(os.path.join(d, names[-1]), TETRAHEDRON_V, TETRAHEDRON_F)
        seconds, mb, _ = measure([tool, "-q", "--threads", "1", "-o", "out.obj", "--report", "r.json"] + names, d)
        size = os.path.getsize(os.path.join(d, "r.json")) / 2. ** 20
        files_rows.append((n, seconds, mb, "report %.1f MB" % size))
        v, f = tetrahedra(n)
        write_off(os.path.join(d, "all.off"), v, f)
        seconds, mb, _ = measure([tool, "-q", "--threads", "1", "-o", "one.obj", "--report", "one.json", "all.off"], d)
        one_rows.append((n, seconds, mb, ""))
        for name in names:
            os.remove(os.path.join(d, name))
    table("(a) disk_uv on N one-tetrahedron files", "input", files_rows)
    table("(a') the same N tetrahedra as N components of one file", "input", one_rows)


def case_b(tool, folder, sizes):
    # Triangles of side 1 at 56 texels per unit: 56 x 49 texels, one per
    # page of 64 with a texel of padding.
    common = ["-q", "--threads", "1", "--resolution", "64", "--padding", "1", "--texels-per-unit", "56"]
    for png in (False, True):
        rows = []
        for n in sizes:
            d = os.path.join(folder, "b%d%s" % (n, "png" if png else ""))
            os.mkdir(d)
            v, f = triangles(n)
            write_off(os.path.join(d, "tri.off"), v, f)
            command = [tool] + common + ["--max-pages", str(n), "-o", "out.obj", "--report", "r.json", "tri.off"]
            if png:
                command += ["--atlas-png", "atlas.png"]
            seconds, mb, _ = measure(command, d)
            pages = report_pages(os.path.join(d, "r.json"))
            rows.append((n, seconds, mb, "%d pages" % pages))
            for name in os.listdir(d):
                os.remove(os.path.join(d, name))
        table("(b) disk_uv, N one-chart pages%s" % (", --atlas-png" if png else ""), "page", rows)


PYTHON_CASE = textwrap.dedent("""
    import sys, time, numpy, disk_uv
    n = int(sys.argv[1])
    v = numpy.array(%r, dtype=numpy.float64)
    f = numpy.array(%r, dtype=numpy.int64)
    start = time.perf_counter()
    atlases = disk_uv.atlas([(v, f)] * n, threads=1)
    print(time.perf_counter() - start, len(atlases), atlases[-1].report["total_charts"])
""") % (TETRAHEDRON_V, TETRAHEDRON_F)


def case_c(python, module_path, folder, sizes):
    script = os.path.join(folder, "c.py")
    with open(script, "w") as out:
        out.write(PYTHON_CASE)
    env = dict(os.environ, PYTHONPATH=module_path + os.pathsep + os.environ.get("PYTHONPATH", ""))
    rows = []
    for n in sizes:
        start = time.perf_counter()
        process = subprocess.Popen([python, script, str(n)], env=env, stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE)
        _, status, usage = os.wait4(process.pid, 0)
        seconds = time.perf_counter() - start
        out, err = process.stdout.read().decode(), process.stderr.read().decode()
        if os.waitstatus_to_exitcode(status) != 0:
            sys.exit("python case failed:\n" + err[-2000:])
        inner, meshes, charts = out.split()
        rows.append((n, seconds, usage.ru_maxrss / 1024., "atlas() %.2f s, %s charts" % (float(inner), charts)))
    table("(c) Python atlas([(V, F)] * N), N tetrahedra (whole process)", "mesh", rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("tool", help="the disk_uv executable")
    parser.add_argument("module", nargs="?", help="the folder holding the disk_uv Python package (for case c)")
    parser.add_argument("--only", default="a,b,c", help="cases to run, e.g. a,b")
    parser.add_argument("--python", default=sys.executable,
                        help="the Python (with numpy) the module was built for (case c; default: this one)")
    parser.add_argument("--quick", action="store_true", help="smaller N (a check that the script works)")
    sizes = lambda text: [int(n) for n in text.split(",")]
    parser.add_argument("--a-sizes", type=sizes, default=[1000, 2000, 4000, 8000], help="N of case a")
    parser.add_argument("--b-sizes", type=sizes, default=[125, 250, 500, 999], help="N of case b (at most 999)")
    parser.add_argument("--c-sizes", type=sizes, default=[1000, 2500, 5000, 10000], help="N of case c")
    args = parser.parse_args()
    if max(args.b_sizes) > 999:
        parser.error("--b-sizes: the tool writes at most 999 pages (UDIM tiles 1001 to 1999)")
    if args.quick:
        args.a_sizes = args.b_sizes = args.c_sizes = [100, 200, 400]
    tool = os.path.abspath(args.tool)
    cases = args.only.split(",")
    with tempfile.TemporaryDirectory(prefix="cost_curves.") as folder:
        if "a" in cases:
            case_a(tool, folder, args.a_sizes)
        if "b" in cases:
            case_b(tool, folder, args.b_sizes)
        if "c" in cases:
            if args.module is None:
                print("\n(c) skipped: no module folder given")
            else:
                case_c(args.python, os.path.abspath(args.module), folder, args.c_sizes)


if __name__ == "__main__":
    main()
