# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""`python3 -m disk_uv batch` against hostile inputs (ctest python_batch_hostile; issue 39).

Manifest lines leading out of OUTPUT_DIR, non-UTF-8 file names, OUTPUT_DIR
inside INPUT, meshes that take too long or whose process dies, temporaries
left by killed writers. Tiny meshes and one worker, to stay quick.
"""

import csv
import json
import os
import re
import signal
import socket
import subprocess
import sys
import threading
import time

import pytest

import disk_uv
from disk_uv import _files, batch

# The host as temporaries name it: [A-Za-z0-9.] kept, other characters as _, 32 at most.
HOST = re.sub(r"[^A-Za-z0-9.]", "_", socket.gethostname())[:32]
TRIANGLE = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"


def run(*args):
    return subprocess.run([sys.executable, "-m", "disk_uv", "batch", *args, "--no-progress"],
                          capture_output=True, text=True, timeout=300)


def summary(folder):
    with open(os.path.join(folder, "summary.csv"), newline="", encoding="utf-8") as f:
        return {row["mesh"]: row for row in csv.DictReader(f)}


def snapshot(folder, skip=None):
    """{path: (mtime, bytes), link target or "folder"} of everything under `folder`, `skip` excepted."""
    files = {}
    for root, subfolders, names in os.walk(folder):
        subfolders[:] = [s for s in subfolders if os.path.join(root, s) != skip]
        for name in names + subfolders:
            path = os.path.join(root, name)
            if os.path.islink(path) or os.path.isdir(path):
                files[path] = os.readlink(path) if os.path.islink(path) else "folder"
            else:
                with open(path, "rb") as f:
                    files[path] = (os.stat(path).st_mtime_ns, f.read())
    return files


@pytest.fixture(scope="module")
def slow_mesh(tmp_path_factory):
    """A 400 x 400 grid (320k faces): several seconds of unwrapping, 0.4 s of reading."""
    import numpy
    n = 400
    i, j = numpy.meshgrid(numpy.arange(n + 1), numpy.arange(n + 1), indexing="ij")
    x, y = i.ravel() / n, j.ravel() / n
    vertices = numpy.stack([x, y, 0.2 * numpy.sin(7 * x) * numpy.cos(5 * y)], 1)
    a = (i[:-1, :-1] * (n + 1) + j[:-1, :-1]).ravel()
    faces = numpy.concatenate([numpy.stack([a, a + n + 1, a + 1], 1), numpy.stack([a + 1, a + n + 1, a + n + 2], 1)])
    path = tmp_path_factory.mktemp("slow") / "grid.off"
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        numpy.savetxt(f, vertices, fmt="%.5f")
        numpy.savetxt(f, numpy.hstack([numpy.full((len(faces), 1), 3), faces]), fmt="%d")
    return str(path)


def test_manifest_lines_never_write_outside_output_dir(tmp_path):
    precious = tmp_path / "precious"
    precious.mkdir()
    (precious / "user_model.off").write_text(TRIANGLE)
    (precious / "user_model.obj").write_text("# the user's own model\nv 0 0 0\n")
    listing = tmp_path / "list"
    (listing / "a").mkdir(parents=True)
    (listing / "inside").mkdir()
    (listing / "b.off").write_text(TRIANGLE)
    (listing / "inside" / "c.off").write_text(TRIANGLE)
    (listing / "summary.off").write_text(TRIANGLE)
    os.symlink(precious, listing / "link")
    out = tmp_path / "out"
    out.mkdir()
    os.symlink(precious, out / "link")  # a folder of OUTPUT_DIR that leads out of it
    manifest = listing / "manifest.txt"
    manifest.write_text("a/../../precious/user_model.off\n"  # outside the manifest's folder: its file name
                        "a/../b.off\n"
                        "%s\n"  # absolute, inside the manifest's folder
                        "link/user_model.off\n"  # out/link/user_model.*: outside OUTPUT_DIR
                        "a/..\n"  # no name
                        "summary.off\n" % (listing / "inside" / "c.off"))
    before = snapshot(tmp_path, skip=str(out))
    result = run(str(manifest), str(out), "--workers", "1", "--glb")
    assert result.returncode == 1, result.stderr
    assert snapshot(tmp_path, skip=str(out)) == before  # nothing outside OUTPUT_DIR created or touched
    rows = summary(out)
    for name in ("user_model", "b", "inside/c"):
        assert rows[name]["status"] == "ok", rows[name]
        assert (out / (name + ".obj")).is_file() and (out / (name + ".json")).is_file()
    assert rows["link/user_model"]["status"] == rows["summary"]["status"] == "error"
    errors = [row["error"] for row in rows.values() if row["status"] == "error"]
    for line, why in (("line 4 of", "outside OUTPUT_DIR"), ("line 5 of", "no output name"), ("line 6 of", "summary.json")):
        assert [e for e in errors if line in e and why in e and "refused" in e], (line, errors)
    assert len(rows) == 6
    assert not (out / "summary.obj").exists()


def test_names_that_are_not_utf8(tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    inside = os.fsencode(folder)
    with open(os.path.join(inside, b"caf\xe9.off"), "w") as f:
        f.write(TRIANGLE)
    with open(os.path.join(inside, b"bad\xe9.obj"), "w") as f:
        f.write("this is not a mesh\n")
    (folder / "ok.off").write_text(TRIANGLE)
    (folder / "clash.off").write_text(TRIANGLE)
    out = tmp_path / "out"
    (out / "clash.obj").mkdir(parents=True)  # its OBJ can't be written: a message about the output
    result = run(str(folder), str(out), "--workers", "1")
    assert result.returncode == 1, result.stderr
    files = os.listdir(os.fsencode(out))
    assert {b"caf\xe9.obj", b"caf\xe9.json", b"bad\xe9.error.json", b"ok.obj"} <= set(files), files
    rows = summary(out)
    assert rows["caf\\xe9"]["status"] == "ok" and rows["ok"]["status"] == "ok", rows
    bad = rows["bad\\xe9"]
    assert bad["status"] == "error" and "not a valid .obj" in bad["error"] and "bad\\xe9.obj" in bad["error"], bad
    with open(out / "summary.json", encoding="utf-8") as f:
        assert {row["mesh"] for row in json.load(f)} == {"caf\\xe9", "bad\\xe9", "ok", "clash"}
    with open(os.path.join(os.fsencode(out), b"bad\xe9.error.json"), encoding="utf-8") as f:
        error = json.load(f)
    assert error["input"].endswith("in/bad\\xe9.obj") and "not a valid .obj" in error["error"]
    # Every error names its input file.
    assert rows["clash"]["error"].startswith(str(folder / "clash.off") + ": IsADirectoryError: "), rows["clash"]

    # A manifest naming the file by its bytes.
    manifest = tmp_path / "list.txt"
    manifest.write_bytes(b"in/caf\xe9.off\n")
    result = run(str(manifest), str(tmp_path / "out2"), "--workers", "1")
    assert result.returncode == 0, result.stderr
    assert summary(tmp_path / "out2")["in/caf\\xe9"]["status"] == "ok"
    assert os.path.isfile(os.path.join(os.fsencode(tmp_path), b"out2/in/caf\xe9.obj"))


def test_load_takes_any_path_form(tmp_path):
    name = os.path.join(os.fsencode(tmp_path), b"caf\xe9.off")
    with open(name, "w") as f:
        f.write(TRIANGLE)
    for path in (name, os.fsdecode(name), tmp_path / os.fsdecode(b"caf\xe9.off")):
        vertices, faces = disk_uv.load(path)
        assert vertices.shape == (3, 3) and faces.shape == (1, 3)
    garbage = os.path.join(os.fsencode(tmp_path), b"gar\xe9.obj")
    with open(garbage, "w") as f:
        f.write("this is not a mesh\n")
    with pytest.raises(ValueError, match="not a valid .obj") as error:
        disk_uv.load(garbage)
    assert "gar\\xe9.obj" in str(error.value)  # the path, its other bytes as \xNN
    with pytest.raises(FileNotFoundError):
        disk_uv.load(b"/nonexistent/\xe9.off")


def test_output_dir_inside_input_is_not_read(tmp_path):
    folder = tmp_path / "in"
    (folder / "sub").mkdir(parents=True)
    (folder / "tri.off").write_text(TRIANGLE)
    (folder / "sub" / "t2.off").write_text(TRIANGLE)
    for _ in range(2):
        result = run(str(folder), str(folder / "sub" / "out"), "--workers", "1")
        assert result.returncode == 0, result.stderr
        assert set(summary(folder / "sub" / "out")) == {"tri", "sub/t2"}

    # OUTPUT_DIR = INPUT: an input is never replaced, the outputs are never inputs.
    (tmp_path / "same").mkdir()
    same = tmp_path / "same"
    (same / "tri.off").write_text(TRIANGLE)
    (same / "user.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    for status in ("ok", "skipped"):
        result = run(str(same), str(same), "--workers", "1")
        rows = summary(same)
        assert set(rows) == {"tri", "user"}, result.stderr
        assert rows["tri"]["status"] == status
        assert rows["user"]["status"] == "error" and "would replace the input file" in rows["user"]["error"]
        assert (same / "user.obj").read_text() == "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"


def test_time_limit(tmp_path, slow_mesh):
    manifest = tmp_path / "list.txt"
    (tmp_path / "tri.off").write_text(TRIANGLE)
    (tmp_path / "tri2.off").write_text(TRIANGLE)
    manifest.write_text("%s\ntri.off\ntri2.off\n" % slow_mesh)
    out = tmp_path / "out"
    # One worker: the small meshes come after the slow one (largest first), on the worker it had.
    result = run(str(manifest), str(out), "--workers", "1", "--time-limit", "0.5")
    assert result.returncode == 1, result.stderr
    rows = summary(out)
    assert rows["grid"]["status"] == "error" and rows["grid"]["error"] == slow_mesh + ": time limit of 0.5 s exceeded"
    with open(out / "grid.error.json") as f:
        assert json.load(f)["error"] == slow_mesh + ": time limit of 0.5 s exceeded"
    assert rows["tri"]["status"] == rows["tri2"]["status"] == "ok"
    assert not [p for p in out.rglob("*") if p.name.endswith(".part")]
    for bad in ("0", "-1", "abc", "nan", "inf"):
        wrong = run(str(manifest), str(out), "--time-limit", bad)
        assert wrong.returncode == 2 and "--time-limit" in wrong.stderr, (bad, wrong.stderr)


def _children(pid):
    children = []
    for entry in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open("/proc/%s/stat" % entry) as f:
                if int(f.read().rsplit(")", 1)[1].split()[1]) == pid:  # after the name: state, parent
                    children.append(int(entry))
        except (OSError, ValueError, IndexError):  # gone meanwhile
            pass
    return children


def _cpu_ticks(pid):
    try:
        with open("/proc/%d/stat" % pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return int(fields[11]) + int(fields[12])  # utime + stime
    except (OSError, ValueError, IndexError):
        return 0


def _mesh_process(timeout=20):
    """The pid of the process a process_mesh() of this process runs its mesh in,
    once it computes (a child still being started would die with a broken pipe
    in its parent, which test_a_mesh_process_that_cannot_start_fails_alone covers)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        for server in _children(os.getpid()):  # the fork server, then its children
            with open("/proc/%d/cmdline" % server, "rb") as f:
                if b"forkserver" in f.read():
                    for child in _children(server):
                        if _cpu_ticks(child) >= 5:
                            return child
        time.sleep(0.02)
    raise AssertionError("no mesh process appeared")


@pytest.mark.parametrize("end", ["killed", "time limit", "stopped"])
def test_a_mesh_process_that_dies_or_times_out_fails_alone(tmp_path, slow_mesh, end):
    out = tmp_path / "out"
    out.mkdir()
    rows = []
    task = threading.Thread(target=lambda: rows.append(batch.process_mesh(
        "grid", slow_mesh, str(out), False, {}, {"threads": 1}, 1.0 if end == "time limit" else None)))
    task.start()
    pid = _mesh_process()
    # As if it were killed while writing a file.
    temporary = out / (".disk_uv-%s-%d-abcdefgh.part" % (HOST, pid))
    temporary.write_bytes(b"partial")
    if end != "time limit":
        os.kill(pid, signal.SIGKILL if end == "killed" else signal.SIGTERM)  # SIGKILL: as the OOM killer
    task.join(30)
    assert rows, "process_mesh() did not return"
    row = rows[0]
    message = {"killed": "killed by signal 9 (SIGKILL: out of memory?)", "time limit": "time limit of 1 s exceeded",
               "stopped": "stopped by signal 15 (SIGTERM)"}[end]
    assert row["status"] == "error" and row["error"].startswith(slow_mesh + ": ") and message in row["error"], row
    if end == "stopped":  # the batch is being stopped: no fault of the mesh, the next run does it
        assert not (out / "grid.error.json").exists()
    else:
        with open(out / "grid.error.json") as f:
            assert message in json.load(f)["error"]
    assert not temporary.exists()
    assert not os.path.exists("/proc/%d" % pid)  # killed and reaped


def test_a_mesh_process_that_cannot_start_fails_alone(tmp_path, monkeypatch):
    # As if the child were killed before its parent had sent it its task (the
    # parent then gets a broken pipe), or the system could not fork.
    def broken_start(process):
        raise BrokenPipeError(32, "Broken pipe")
    monkeypatch.setattr(batch._child_processes().Process, "start", broken_start)
    out = tmp_path / "out"
    out.mkdir()
    path = tmp_path / "tri.off"
    path.write_text(TRIANGLE)
    row = batch.process_mesh("tri", str(path), str(out), False, {}, {})
    assert row["status"] == "error" and row["error"].startswith(str(path) + ": "), row
    assert "could not start its process" in row["error"] and "Broken pipe" in row["error"], row
    assert os.listdir(out) == []  # not the mesh's fault: no error file, the next run does it


def test_stale_temporaries_are_removed_and_only_they(tmp_path):
    folder = tmp_path / "in"
    folder.mkdir()
    (folder / "tri.off").write_text(TRIANGLE)
    out = tmp_path / "out"
    (out / "sub").mkdir(parents=True)
    dead = subprocess.Popen(["true"])
    dead.wait()
    stale = [out / (".disk_uv-%s-%d-abcdefgh.part" % (HOST, dead.pid)),
             out / "sub" / (".disk_uv-%s-%d-ijklmnop.part" % (HOST, dead.pid)),
             out / ".disk_uv-ab_d1234.part"]  # of an earlier version: no pid
    kept = [out / (".disk_uv-%s-%d-qrstuvwx.part" % (HOST, os.getpid())),  # a running writer
            out / (".disk_uv-otherhost-%d-abcdefgh.part" % dead.pid),  # of another host
            out / ".disk_uv-notes.txt", out / "user.part", out / ".disk_uv-abcd1234.part.bak",
            out / (".disk_uv-%s-%d-abc.part" % (HOST, dead.pid))]
    for path in stale + kept:
        path.write_bytes(b"x" * 10)
    result = run(str(folder), str(out), "--workers", "1")
    assert result.returncode == 0, result.stderr
    assert [p for p in stale if p.exists()] == []
    assert [p for p in kept if not p.exists()] == []


def test_temporaries_name_their_host_and_process(tmp_path, monkeypatch):
    names = []

    def replace(source, destination):
        names.append(os.path.basename(source))
        raise OSError("stop")

    monkeypatch.setattr(_files.os, "replace", replace)
    with pytest.raises(OSError):
        _files.write_atomically(tmp_path / "x.json", b"{}")
    assert re.fullmatch(r"\.disk_uv-%s-%d-[a-z0-9_]{8}\.part" % (re.escape(HOST), os.getpid()), names[0])
    assert os.listdir(tmp_path) == []
