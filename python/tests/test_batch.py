# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of `python3 -m disk_uv batch` on a local dask cluster of 2 workers (ctest python_batch)."""

import csv
import json
import os
import shutil
import subprocess
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import disk_uv  # noqa: E402
from atlas_checks import obj_atlas_problems  # noqa: E402

DATA = os.environ.get("DISK_UV_DATA", os.path.join(os.path.dirname(__file__), "../../test/Disk_segmentation/data"))
# Every shipped test mesh; the last goes to a sub-folder.
GOOD = sorted(n for n in os.listdir(DATA) if n.endswith(".off") and n != "couplingdown.off") + ["couplingdown.off"]
BAD = {"garbage.obj": "not a valid", "nan.off": "non-finite", "pinched.off": "not manifold: edge (0, 1) is shared by 3 faces (--repair",
       "empty.ply": "valid"}


def batch(*args):
    return subprocess.run([sys.executable, "-m", "disk_uv", "batch", *args, "--no-progress"],
                          capture_output=True, text=True, timeout=900)


def summary(folder):
    with open(os.path.join(folder, "summary.csv"), newline="") as f:
        return {row["mesh"]: row for row in csv.DictReader(f)}


@pytest.fixture()
def meshes(tmp_path):
    folder = tmp_path / "in"
    (folder / "sub").mkdir(parents=True)
    for name in GOOD[:-1]:
        shutil.copy(os.path.join(DATA, name), folder / name)
    shutil.copy(os.path.join(DATA, GOOD[-1]), folder / "sub" / GOOD[-1])
    (folder / "garbage.obj").write_text("this is not a mesh\n")
    (folder / "nan.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n")
    # Three triangles on one edge: a non-manifold edge.
    (folder / "pinched.off").write_text("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n"
                                        "3 0 1 2\n3 1 0 3\n3 0 1 4\n")
    (folder / "empty.ply").write_bytes(b"")
    return folder


def test_batch_unwraps_good_meshes_records_bad_ones_and_resumes(meshes, tmp_path):
    out = tmp_path / "out"
    first = batch(str(meshes), str(out), "--workers", "2", "--glb")
    assert first.returncode == 1, first.stderr  # some meshes failed
    rows = summary(out)
    names = [os.path.splitext(n)[0] for n in GOOD[:-1]] + ["sub/couplingdown"]
    for name in names:
        assert rows[name]["status"] == "ok", rows[name]
        assert obj_atlas_problems(out / (name + ".obj")) == []
        assert (out / (name + ".glb")).read_bytes()[:4] == b"glTF"
        with open(out / (name + ".json")) as f:
            report = json.load(f)
        assert int(rows[name]["charts"]) == len(report["charts"]) > 0
    for file, message in BAD.items():
        name = os.path.splitext(file)[0]
        assert rows[name]["status"] == "error" and message in rows[name]["error"], rows[name]
        with open(out / (name + ".error.json")) as f:
            assert message in json.load(f)["error"]
    assert not [p for p in out.rglob("*") if p.name.endswith(".part")]
    with open(out / "summary.json") as f:
        assert len(json.load(f)) == len(names) + len(BAD)

    # A rerun does nothing: every mesh is skipped, no file is rewritten.
    stamps = {p: p.stat().st_mtime_ns for p in out.rglob("*") if not p.name.startswith("summary")}
    second = batch(str(meshes), str(out), "--workers", "2", "--glb")
    assert second.returncode == 1
    rows = summary(out)
    assert all(rows[n]["status"] == "skipped" for n in names)
    assert all(rows[os.path.splitext(f)[0]]["status"] == "error (skipped)" for f in BAD)
    assert stamps == {p: p.stat().st_mtime_ns for p in out.rglob("*") if not p.name.startswith("summary")}

    # A removed output is redone, and only it.
    (out / "knot1.obj").unlink()
    third = batch(str(meshes), str(out), "--workers", "1", "--glb")
    rows = summary(out)
    assert rows["knot1"]["status"] == "ok" and rows["eight"]["status"] == "skipped", third.stderr
    assert obj_atlas_problems(out / "knot1.obj") == []


def test_manifest_and_bad_arguments(tmp_path):
    manifest = tmp_path / "list.txt"
    shutil.copy(os.path.join(DATA, "eight.off"), tmp_path / "eight.off")
    manifest.write_text("# meshes\neight.off\n\n")
    out = tmp_path / "out"
    result = batch(str(manifest), str(out), "--workers", "1")
    assert result.returncode == 0, result.stderr
    assert summary(out)["eight"]["status"] == "ok"
    assert batch(str(tmp_path / "missing"), str(out)).returncode == 2
    wrong = batch(str(manifest), str(out), "--method", "arap", "--resolution", "-3")
    assert wrong.returncode == 2 and "resolution" in wrong.stderr
    wrong = batch(str(manifest), str(out), "--resolution", "512x")
    assert wrong.returncode == 2 and "WIDTHxHEIGHT" in wrong.stderr
    # A non-square texture and pages at a fixed density reach the module.
    wide = batch(str(manifest), str(tmp_path / "wide"), "--resolution", "2048x512", "--texels-per-unit", "0",
                 "--workers", "1")
    assert wide.returncode == 0 and summary(tmp_path / "wide")["eight"]["status"] == "ok", wide.stderr
    report = json.loads((tmp_path / "wide" / "eight.json").read_text())
    assert report["packing"]["pages"] == 1 and summary(tmp_path / "wide")["eight"]["pages"] == "1"
    wrong = batch(str(manifest), str(out), "--texels-per-unit", "-1")
    assert wrong.returncode == 2 and "error: --texels-per-unit must be" in wrong.stderr, wrong.stderr
    # The flags as typed, not the module's keywords or the library's parameters.
    wrong = batch(str(manifest), str(out), "--max-stretch", "0.5")
    assert wrong.returncode == 2 and "error: --max-stretch must be > 1" in wrong.stderr, wrong.stderr
    wrong = batch(str(manifest), str(out), "--max-charts", "-1")
    assert wrong.returncode == 2 and "error: --max-charts must be non-negative" in wrong.stderr, wrong.stderr
    # Options are checked without a mesh of the batch's own making: a density
    # that would make a unit triangle larger than a page is an ordinary one.
    dense = batch(str(manifest), str(tmp_path / "dense"), "--texels-per-unit", "1100", "--workers", "1")
    assert dense.returncode == 0 and summary(tmp_path / "dense")["eight"]["status"] == "ok", dense.stderr
    wrong = batch(str(manifest), str(out), "--max-pages", "1000")
    assert wrong.returncode == 2 and "error: --max-pages must be at most 999" in wrong.stderr, wrong.stderr
    wrong = batch(str(manifest), str(out), "--crease-penalty", "-1")
    assert wrong.returncode == 2 and "error: --crease-penalty must be a finite number >= 0" in wrong.stderr, wrong.stderr
    # The paper's distance reaches the module: eight gets the charts atlas() gives it at 0, not the default's.
    vertices, faces = disk_uv.load(os.path.join(DATA, "eight.off"))
    paper = disk_uv.atlas(vertices, faces, crease_penalty=0).number_of_charts
    assert paper != disk_uv.atlas(vertices, faces).number_of_charts
    flat = batch(str(manifest), str(tmp_path / "paper"), "--crease-penalty", "0", "--workers", "1")
    assert flat.returncode == 0 and summary(tmp_path / "paper")["eight"]["charts"] == str(paper), flat.stderr
