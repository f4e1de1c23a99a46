# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of the disk_uv Python module (ctest python_module).

Environment (set by CMake): PYTHONPATH to the built package, DISK_UV_TOOL
the C++ tool, DISK_UV_DATA the shipped meshes, DISK_UV_SOURCE the repository.
"""

import os
import subprocess
import sys
import threading

import numpy
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import disk_uv  # noqa: E402
from atlas_checks import (atlas_problems, components, euler_characteristic, read_obj, signed_areas,  # noqa: E402
                          udim_atlas_problems)

DATA = os.environ.get("DISK_UV_DATA", os.path.join(os.path.dirname(__file__), "../../test/Disk_segmentation/data"))
TOOL = os.environ.get("DISK_UV_TOOL")


def mesh(name):
    return disk_uv.load(os.path.join(DATA, name))


def torus_quads(n=24, m=12):
    """A torus of n x m quads, each split into two triangles; group = quad id."""
    u, v = numpy.meshgrid(numpy.arange(n), numpy.arange(m), indexing="ij")
    a, b = 2 * numpy.pi * u / n, 2 * numpy.pi * v / m
    vertices = numpy.stack([(2 + numpy.cos(b)) * numpy.cos(a), (2 + numpy.cos(b)) * numpy.sin(a),
                            numpy.sin(b)], axis=-1).reshape(-1, 3)
    index = lambda i, j: (i % n) * m + (j % m)
    faces, groups = [], []
    for i in range(n):
        for j in range(m):
            q = [index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)]
            faces += [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]
            groups += [i * m + j] * 2
    return vertices, numpy.array(faces), numpy.array(groups)


def test_parametrize_has_the_semantics_of_xatlas():
    vertices, faces = mesh("elephant.off")
    vmapping, indices, uvs = disk_uv.parametrize(vertices, faces)
    assert vmapping.dtype == numpy.uint32 and indices.dtype == numpy.uint32 and uvs.dtype == numpy.float32
    assert vmapping.ndim == 1 and indices.shape == faces.shape and uvs.shape == (len(vmapping), 2)
    # Every output face is its input face over output vertices.
    assert (vmapping[indices] == faces).all()
    # Output vertices are used, and seams duplicate vertices.
    assert len(numpy.unique(indices)) == len(vmapping) > len(vertices)
    assert atlas_problems(uvs[indices], indices) == []
    # Each chart (component over output vertices) is one chart id of the atlas.
    atlas = disk_uv.atlas(vertices, faces)
    labels = components(indices)
    for label in numpy.unique(labels):
        assert len(numpy.unique(atlas.chart_ids[labels == label])) == 1
    assert len(numpy.unique(labels)) == atlas.number_of_charts


@pytest.mark.skipif(TOOL is None, reason="DISK_UV_TOOL not set")
@pytest.mark.parametrize("name", ["elephant.off", "knot1.off", "eight.off"])
def test_same_atlas_as_the_command_line_tool(tmp_path, name):
    ids_path, obj_path = tmp_path / "ids.txt", tmp_path / "atlas.obj"
    subprocess.run([TOOL, os.path.join(DATA, name), "--patch-ids", str(ids_path), "-o", str(obj_path), "-q"],
                   check=True)
    vertices, faces = mesh(name)
    atlas = disk_uv.atlas(vertices, faces)
    tool_ids = numpy.loadtxt(ids_path, dtype=numpy.int64)
    assert (tool_ids == atlas.chart_ids).all()
    positions, tool_uvs, tool_faces = read_obj(obj_path)
    assert len(tool_faces) == len(faces)
    # The OBJ lists the faces chart by chart, in input order within a chart.
    order = numpy.argsort(atlas.chart_ids, kind="stable")
    for f, (vs, ts) in zip(order, tool_faces):
        assert vs == list(faces[f])
        assert numpy.allclose(tool_uvs[ts], atlas.uvs[f], atol=1e-9)


def test_result_does_not_depend_on_threads():
    vertices, faces = mesh("knot1.off")
    one, two = disk_uv.atlas(vertices, faces, threads=1), disk_uv.atlas(vertices, faces, threads=2)
    assert (one.chart_ids == two.chart_ids).all() and (one.uvs == two.uvs).all()


def test_report_and_options():
    vertices, faces = mesh("elephant.off")
    atlas = disk_uv.atlas(vertices, faces, method="lscm", resolution=512, padding=4)
    report = atlas.report
    assert report["method"] == "lscm" and report["faces"] == len(faces)
    assert len(report["charts"]) == atlas.number_of_charts == atlas.chart_ids.max() + 1
    assert set(atlas.seconds) >= {"voronoi", "refine", "merge", "parameterization", "packing", "total"}
    bounded = disk_uv.atlas(vertices, faces, max_angle_distortion=0.03)
    assert all(c["angle_distortion"] <= 0.03 for c in bounded.report["charts"])
    loose = disk_uv.atlas(vertices, faces, unbounded=True, rough_borders=True)
    assert loose.number_of_charts < bounded.number_of_charts
    # The convexity bound splits bent charts: off, fewer charts; stricter, more.
    default = disk_uv.atlas(vertices, faces)
    assert disk_uv.atlas(vertices, faces, min_convexity=0).number_of_charts < default.number_of_charts
    assert disk_uv.atlas(vertices, faces, min_convexity=0.9).number_of_charts > default.number_of_charts


def test_a_chart_budget_merges_charts_into_valid_disks():
    vertices, faces = mesh("elephant.off")
    free = disk_uv.atlas(vertices, faces)
    budget = free.number_of_charts // 2
    merged = disk_uv.atlas(vertices, faces, max_charts=budget)
    assert merged.number_of_charts == budget
    report = merged.report["parameterization"]
    assert report["chart_budget_met"] and report["charts_before_budget"] == free.number_of_charts
    # The budget's merges solve unions: more solves than the free atlas.
    assert report["solved_faces_in_merges"] > free.report["parameterization"]["solved_faces_in_merges"]
    _, indices, uvs = disk_uv.parametrize(vertices, faces, max_charts=budget)
    assert atlas_problems(uvs[indices], indices) == []
    assert not disk_uv.atlas(vertices, faces, max_charts=1).report["parameterization"]["chart_budget_met"]


def test_segment_gives_disks_of_the_paper():
    vertices, faces = mesh("eight.off")
    ids = disk_uv.segment(vertices, faces, n=6, k=5)
    assert ids.shape == (len(faces),) and ids.dtype == numpy.uint32
    for p in numpy.unique(ids):
        patch = faces[ids == p]
        assert euler_characteristic(patch) == 1
        assert len(numpy.unique(components(patch))) == 1
    assert (disk_uv.segment(vertices, faces, n=6, k=5) == ids).all()


def test_polygons_stay_whole_when_face_groups_are_given():
    vertices, faces, groups = torus_quads()
    atlas = disk_uv.atlas(vertices, faces, face_groups=groups)
    across = sum(len(numpy.unique(atlas.chart_ids[groups == g])) > 1 for g in numpy.unique(groups))
    assert across == atlas.report["polygons"]["left_across_charts"] == 0
    assert atlas_problems(list(atlas.uvs)) == []


def test_several_meshes_share_one_atlas_and_keep_their_charts():
    parts = [mesh("elephant.off"), mesh("knot1.off"), mesh("eight.off")]
    atlases = disk_uv.atlas(parts)
    assert len(atlases) == 3
    first = 0
    for (vertices, faces), atlas in zip(parts, atlases):
        alone = disk_uv.atlas(vertices, faces)
        assert atlas.report["first_chart"] == first
        assert (atlas.chart_ids - first == alone.chart_ids).all()
        first += alone.number_of_charts
    assert atlases[0].report["total_charts"] == first
    # No overlap across meshes: the charts of all of them checked as one atlas.
    assert atlas_problems([uv for atlas in atlases for uv in atlas.uvs]) == []
    with pytest.raises(ValueError, match="seed takes one mesh"):
        disk_uv.atlas(parts, seed=3)
    with pytest.raises(TypeError, match=r"meshes\[1\] must be a pair"):
        disk_uv.atlas([parts[0], "mesh"])
    with pytest.raises(ValueError, match=r"meshes\[1\]: "):
        disk_uv.atlas([parts[0], (parts[1][0], parts[1][1][:, :2])])


def test_a_texture_too_small_for_the_padding_is_said():
    vertices, faces = mesh("elephant.off")
    with pytest.warns(RuntimeWarning, match=r"cover only [0-9.]+% of the texture: at resolution=32, padding=2"):
        disk_uv.atlas(vertices, faces, resolution=32)


def test_a_fixed_texel_density_spreads_the_charts_over_pages(tmp_path):
    vertices, faces = mesh("elephant.off")
    fit = disk_uv.atlas(vertices, faces)
    assert fit.number_of_pages == 1 and (fit.pages == 0).all()
    density = 2 * fit.report["packing"]["texels_per_unit"]
    paged = disk_uv.atlas(vertices, faces, texels_per_unit=density)
    packing = paged.report["packing"]
    assert paged.number_of_pages == packing["pages"] >= 2
    assert abs(packing["texels_per_unit"] - density) < 1e-6 * density
    # Same charts; each page a valid atlas of its own, each chart on one page.
    assert (paged.chart_ids == fit.chart_ids).all()
    assert paged.pages.shape == (len(faces),)
    for page in range(paged.number_of_pages):
        on_page = paged.pages == page
        assert on_page.any()
        assert atlas_problems(list(paged.uvs[on_page])) == []
        assert len(numpy.unique(paged.pages[numpy.isin(paged.chart_ids, paged.chart_ids[on_page])])) == 1
    # Written as UDIM tiles, read back by the independent checker.
    disk_uv.save_obj(tmp_path / "pages.obj", paged)
    _, uvs, obj_faces = read_obj(tmp_path / "pages.obj")
    problems, tiles = udim_atlas_problems([uvs[t] for _, t in obj_faces], [t for _, t in obj_faces])
    assert problems == [] and tiles == list(range(1001, 1001 + paged.number_of_pages))
    # Pages with several meshes in one atlas: each report lists the pages of
    # its own charts, and the meshes' faces together are a valid UDIM atlas.
    several = disk_uv.atlas([(vertices, faces), mesh("eight.off")], texels_per_unit=density)
    assert several[0].number_of_pages >= 2
    for atlas in several:
        assert len(atlas.report["packing"]["page_of_chart"]) == atlas.number_of_charts
        assert len(atlas.report["packing"]["page_efficiency"]) == atlas.number_of_pages
    problems, tiles = udim_atlas_problems([uv for atlas in several for uv in atlas.udim_uvs()])
    assert problems == [] and tiles == list(range(1001, 1001 + several[0].number_of_pages))
    with pytest.raises(ValueError, match=r"^at texels_per_unit .* need more than 1 page of .*max_pages"):
        disk_uv.atlas(vertices, faces, texels_per_unit=density, max_pages=1)
    with pytest.raises(ValueError, match=r"does not fit a page of 1024 texels \(resolution\)"):
        disk_uv.atlas(vertices, faces, texels_per_unit=10 * density, max_pages=999)
    with pytest.raises(ValueError, match=r"^texels_per_unit must be"):
        disk_uv.atlas(vertices, faces, texels_per_unit=-1.0)
    with pytest.warns(RuntimeWarning, match=r"at texels_per_unit="):
        disk_uv.atlas(vertices, faces, texels_per_unit=density / 10)


def test_a_non_square_texture_keeps_the_uvs_in_the_unit_square():
    vertices, faces = mesh("elephant.off")
    square = disk_uv.atlas(vertices, faces, resolution=1024)
    wide = disk_uv.atlas(vertices, faces, resolution=(2048, 512))
    assert (wide.chart_ids == square.chart_ids).all()
    assert wide.uvs.min() >= 0 and wide.uvs.max() <= 1
    assert atlas_problems(list(wide.uvs)) == []
    # In texels, (u * 2048, v * 512), every chart is a similar copy of the
    # square atlas's, at one density: every edge has the same length ratio.
    def edge_lengths(uvs, size):
        texels = uvs * size
        return numpy.linalg.norm(texels - numpy.roll(texels, 1, axis=1), axis=2)
    ratio = edge_lengths(wide.uvs, (2048, 512)) / edge_lengths(square.uvs, (1024, 1024))
    assert ratio.max() < ratio.min() * (1 + 1e-6)
    with pytest.raises(ValueError, match=r"resolution \(its height\) must be at least 1"):
        disk_uv.atlas(vertices, faces, resolution=(512, 0))
    with pytest.raises(ValueError, match=r"resolution must be an integer or a \(width, height\) pair"):
        disk_uv.atlas(vertices, faces, resolution=(512,))
    with pytest.raises(ValueError, match=r"non-square texture"):
        disk_uv.atlas(vertices, faces, resolution=(512, 256), packer="grid")


def test_no_chart_spans_two_materials():
    vertices, faces = mesh("elephant.off")
    centroids = vertices[faces].mean(axis=1)
    materials = (centroids[:, 0] > 0).astype(numpy.int64) + 2 * (centroids[:, 2] > 0)
    atlas = disk_uv.atlas(vertices, faces, materials=materials)
    for chart in numpy.unique(atlas.chart_ids):
        assert len(numpy.unique(materials[atlas.chart_ids == chart])) == 1
        chart_faces = faces[atlas.chart_ids == chart]
        assert euler_characteristic(chart_faces) == 1 and len(numpy.unique(components(chart_faces))) == 1
    assert atlas_problems(list(atlas.uvs)) == []
    with pytest.raises(ValueError, match="materials must have shape"):
        disk_uv.atlas(vertices, faces, materials=materials[:-1])


def test_large_face_groups_over_many_charts_leave_every_chart_a_disk():
    # Bands of a torus cut into thousands of charts: moving a band tested
    # every chart whole for every target (4.9 s and 200 MB on 11k faces).
    vertices, faces, _ = torus_quads(48, 24)
    bands = numpy.arange(len(faces)) * 4 // len(faces)
    atlas = disk_uv.atlas(vertices, faces, method="conformal", face_groups=bands, threads=1)
    polygons = atlas.report["polygons"]
    across = sum(len(numpy.unique(atlas.chart_ids[bands == g])) > 1 for g in range(4))
    assert polygons["left_across_charts"] == across
    assert polygons["moved_whole_into_one_chart"] + across <= 4
    for chart in numpy.unique(atlas.chart_ids):
        chart_faces = faces[atlas.chart_ids == chart]
        assert euler_characteristic(chart_faces) == 1 and len(numpy.unique(components(chart_faces))) == 1
    assert atlas_problems(list(atlas.uvs)) == []


def test_gil_is_released_during_the_computation():
    vertices, faces = mesh("elephant.off")
    done = threading.Event()
    counts = {"while_running": 0}

    def unwrap():
        disk_uv.atlas(vertices, faces, threads=1)
        done.set()

    worker = threading.Thread(target=unwrap)
    worker.start()
    # Python code runs in this thread only if the other releases the GIL.
    while not done.is_set():
        counts["while_running"] += 1
    worker.join()
    assert counts["while_running"] > 1000


def test_save_obj_and_glb_write_whole_files(tmp_path):
    vertices, faces = mesh("knot1.off")
    atlas = disk_uv.atlas(vertices, faces)
    disk_uv.save_obj(tmp_path / "a.obj", atlas)
    disk_uv.save_glb(tmp_path / "a.glb", atlas)
    positions, uvs, obj_faces = read_obj(tmp_path / "a.obj")
    assert numpy.allclose(positions, vertices)
    assert atlas_problems([uvs[t] for _, t in obj_faces], [t for _, t in obj_faces]) == []
    assert (tmp_path / "a.glb").read_bytes()[:4] == b"glTF"
    (tmp_path / "keep.obj").write_text("mine")
    with pytest.raises(FileExistsError):
        disk_uv.save_obj(tmp_path / "keep.obj", atlas, overwrite=False)
    assert (tmp_path / "keep.obj").read_text() == "mine"
    with pytest.raises(IsADirectoryError):
        disk_uv.save_obj(tmp_path, atlas)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.glb", "a.obj", "keep.obj"]


def test_load_names_problems_and_suggests_options(tmp_path):
    with pytest.raises(FileNotFoundError):
        disk_uv.load(tmp_path / "missing.off")
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 2\n")
    with pytest.raises(ValueError, match="repair=True"):
        disk_uv.load(bad)
    vertices, faces = disk_uv.load(bad, repair=True)
    assert len(faces) == 1
    quad = tmp_path / "quad.off"
    quad.write_text("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
    with pytest.raises(ValueError, match="triangulate=True"):
        disk_uv.load(quad)
    assert disk_uv.load(quad, triangulate=True)[1].shape == (2, 3)


@pytest.mark.parametrize("change, message", [
    (lambda v, f: (v[:, :2], f), "shape"),
    (lambda v, f: (v, f.astype(numpy.float64)), "integers"),
    (lambda v, f: (v.astype(str), f), "real numbers"),
    (lambda v, f: (v, f[:, :2]), "shape"),
    (lambda v, f: (v, f + len(v)), "refers to vertex"),
    (lambda v, f: (v, -f), "non-negative"),
    (lambda v, f: (numpy.where(v > 0.2, numpy.nan, v), f), "non-finite"),
    (lambda v, f: (v, numpy.vstack([f, f[:1]])), "duplicates"),
    (lambda v, f: (v, f[:, ::-1][:1].tolist() + f[1:].tolist()), "orient"),
    (lambda v, f: (v, numpy.zeros((0, 3), dtype=numpy.int64)), "no face"),
    (lambda v, f: ("not an array", f), "real numbers"),
])
def test_bad_arrays_raise_value_error(change, message):
    vertices, faces = mesh("eight.off")
    with pytest.raises(ValueError, match=message):
        disk_uv.atlas(*change(vertices, faces))


@pytest.mark.parametrize("options, message", [
    ({"method": "foo"}, "unknown parameterization method"),
    ({"packer": "foo"}, "unknown packer"),
    ({"resolution": -1}, "resolution"),
    ({"threads": -2}, "threads"),
    ({"n": 0}, "seed"),
    ({"max_angle_distortion": -1.0}, "angle"),
    ({"min_convexity": 1.0}, "min_convexity"),
    ({"padding": float("nan")}, "padding"),
    ({"seed": -1}, "seed"),
    ({"max_charts": 0}, "max_charts must be None or at least 1"),
    ({"face_groups": numpy.zeros(3)}, "face_groups"),
    # Floats would be truncated: 0.1 and 0.9 one material, NaN some material.
    ({"materials": "floats"}, "materials must be an array of integers, not of dtype float64"),
    ({"face_groups": "floats"}, "face_groups must be an array of integers, not of dtype float64"),
    ({"max_pages": 0}, "max_pages must be at least 1"),
    ({"max_pages": 1000}, "max_pages must be at most 999: pages are written as the UDIM tiles 1001 to 1999"),
    ({"texels_per_unit": 5, "packer": "grid"}, "texels_per_unit needs packer='tight'"),
])
def test_bad_options_raise_value_error(options, message):
    vertices, faces = mesh("eight.off")
    options = {name: (numpy.linspace(0.1, 0.9, len(faces)) if isinstance(value, str) and value == "floats"
                     else value)
               for name, value in options.items()}
    with pytest.raises(ValueError, match=message):
        disk_uv.atlas(vertices, faces, **options)
    # The same options, checked without a mesh (the batch's way).
    if "materials" not in options and "face_groups" not in options and "seed" not in options:
        with pytest.raises(ValueError, match=message):
            disk_uv.check_options(**options)


def test_check_options_takes_what_atlas_takes_and_refuses_unknown_keywords():
    assert disk_uv.check_options() is None
    assert disk_uv.check_options(texels_per_unit=1100, resolution=(2048, 512), max_pages=999) is None
    with pytest.raises(TypeError, match="unknown options: colour"):
        disk_uv.check_options(colour=3)


def test_a_list_of_meshes_with_faces_is_refused_with_a_message():
    vertices, faces = mesh("eight.off")
    with pytest.raises(TypeError, match="with a list of meshes, faces must be None"):
        disk_uv.atlas([(vertices, faces)], faces)


def test_tiny_densities_are_refused_rather_than_collapsed():
    vertices, faces = mesh("elephant.off")
    # Doubles cannot hold the charts: refused by the packing.
    with pytest.raises(ValueError, match="too small for double precision at texels_per_unit"):
        disk_uv.atlas(vertices, faces, texels_per_unit=1e-13)
    # Doubles can, float32 cannot: the arrays and the GLB are refused, the
    # atlas itself is valid, and its charts below a texel are said.
    with pytest.warns(RuntimeWarning, match="59 of 59 charts are smaller than one texel"):
        atlas = disk_uv.atlas(vertices, faces, texels_per_unit=1e-3)
    assert (signed_areas(atlas.uvs) > 0).all()
    with pytest.raises(ValueError, match="float32 UVs cannot hold this atlas: [0-9]+ triangles"):
        atlas.xatlas_arrays()
    with pytest.raises(ValueError, match="32-bit float UVs"):
        disk_uv.save_glb(os.devnull, atlas)


def test_a_per_mesh_chart_budget_over_several_meshes_is_said():
    a, b = mesh("eight.off"), mesh("elephant.off")
    with pytest.warns(RuntimeWarning, match="charts in all: max_charts=3 is a budget for each of the 2 meshes"):
        disk_uv.atlas([a, b], max_charts=3)


@pytest.mark.parametrize("options, names", [
    ({"method": 5}, ("method", "arap, conformal, lscm, mvc or tutte", "int")),
    ({"method": None}, ("method", "arap", "NoneType")),
    ({"packer": 1.5}, ("packer", "tight or grid", "float")),
    ({"resolution": 512.0}, ("resolution", "integer", "float")),
    ({"padding": "2"}, ("padding", "number", "str")),
])
def test_arguments_of_the_wrong_type_raise_a_type_error_naming_them(options, names):
    vertices, faces = mesh("eight.off")
    with pytest.raises(disk_uv.ArgumentTypeError) as raised:
        disk_uv.atlas(vertices, faces, **options)
    assert isinstance(raised.value, TypeError) and isinstance(raised.value, ValueError)
    for name in names:
        assert name in str(raised.value)


@pytest.mark.parametrize("options, message", [
    ({"resolution": 8, "padding": 3}, r"^padding \(3\) is too large"),
    ({"max_stretch": 0.5}, r"^max_stretch must be > 1"),
    ({"n": 0}, r"^n \(seeds\) must be at least 1"),
    ({"k": 1}, r"^k \(subsamples\) must be at least 2"),
    ({"threshold": -1.0}, r"^threshold must be"),
    ({"crease_penalty": -1.0}, r"^crease_penalty must be a finite number >= 0"),
])
def test_errors_name_the_arguments_as_given(options, message):
    vertices, faces = mesh("eight.off")
    with pytest.raises(ValueError, match=message) as raised:
        disk_uv.atlas(vertices, faces, **options)
    for library_name in ("pack_patches", "padding_in_texels", "texture_resolution", "number_of_seeds",
                         "number_of_subsamples", "merge_threshold"):
        assert library_name not in str(raised.value)


def test_numpy_only_example_runs(tmp_path):
    source = os.environ.get("DISK_UV_SOURCE", os.path.join(os.path.dirname(__file__), "../.."))
    out = tmp_path / "out.obj"
    subprocess.run([sys.executable, os.path.join(source, "python/examples/unwrap_obj.py"),
                    os.path.join(DATA, "elephant.off"), str(out)], check=True)
    positions, uvs, obj_faces = read_obj(out)
    assert atlas_problems([uvs[t] for _, t in obj_faces], [t for _, t in obj_faces]) == []


def test_the_independent_checker_finds_what_it_should():
    square = [numpy.array([[0.1, 0.1], [0.4, 0.1], [0.4, 0.4]]), numpy.array([[0.1, 0.1], [0.4, 0.4], [0.1, 0.4]])]
    assert atlas_problems(square, [[0, 1, 2], [0, 2, 3]]) == []
    assert any("flipped" in p for p in atlas_problems([square[0][::-1], square[1]]))
    assert any("covered twice" in p for p in atlas_problems([square[0], square[0] + 0.01]))
    assert any("outside" in p for p in atlas_problems([square[0] + 0.7]))
    assert any("degenerate" in p for p in atlas_problems([square[0], numpy.array([[0.5, 0.5]] * 3)]))
    # Two triangles glued along two edges (a cone's strip): not a disk.
    assert any("not a disk" in p for p in atlas_problems(square, [[0, 1, 2], [0, 2, 1]]))


def test_numpy_scalars_are_accepted_as_options():
    vertices, faces = mesh("eight.off")
    atlas = disk_uv.atlas(vertices.astype(numpy.float32), faces.astype(numpy.int32), resolution=numpy.int64(512),
                          padding=numpy.float32(3), threads=numpy.uint8(1), seed=numpy.int64(7))
    assert atlas_problems(list(atlas.uvs)) == []
    with pytest.raises(ValueError, match="integer"):
        disk_uv.atlas(vertices, faces, resolution=512.0)
    with pytest.raises(ValueError, match="number"):
        disk_uv.atlas(vertices, faces, padding="2")


def test_a_progress_callback_sees_the_stages_and_can_cancel():
    vertices, faces = mesh("elephant.off")
    stages = []

    def stop_in_parameterization(stage, done, total):
        stages.append(stage)
        assert 0 <= done <= total
        return stage != "parameterization"

    with pytest.raises(disk_uv.Cancelled, match="parameterization"):
        disk_uv.atlas(vertices, faces, progress=stop_in_parameterization)
    assert stages[0] == "segmentation" and stages[-1] == "parameterization"
    assert stages.count("parameterization") == 1  # not called again once it said no

    def failing(stage, done, total):
        if stage == "packing":
            raise ZeroDivisionError("raised by the callback")

    with pytest.raises(ZeroDivisionError, match="raised by the callback"):
        disk_uv.atlas(vertices, faces, progress=failing)

    class Unanswerable:
        def __bool__(self):
            raise ZeroDivisionError("raised by the answer's __bool__")

    with pytest.raises(ZeroDivisionError, match="raised by the answer's __bool__"):
        disk_uv.atlas(vertices, faces, progress=lambda *report: Unanswerable())
    with pytest.raises(disk_uv.Cancelled):
        disk_uv.segment(vertices, faces, progress=lambda *report: False)
    with pytest.raises(TypeError, match="progress must be None or a callable"):
        disk_uv.atlas(vertices, faces, progress=3)

    # A callback that returns None or True changes nothing.
    seen = []
    followed = disk_uv.atlas(vertices, faces, progress=lambda *report: seen.append(report))
    plain = disk_uv.atlas(vertices, faces)
    assert numpy.array_equal(followed.chart_ids, plain.chart_ids) and numpy.array_equal(followed.uvs, plain.uvs)
    # The packing: its start, each trial layout (out of 16), its end.
    packing = [(done, total) for stage, done, total in seen if stage == "packing"]
    assert packing[0] == (0, 1) and packing[-1] == (1, 1) and len(packing) > 2
    trials = packing[1:-1]
    assert all(total == 16 for _, total in trials) and [done for done, _ in trials] == sorted(d for d, _ in trials)
    assert numpy.array_equal(disk_uv.segment(vertices, faces, progress=lambda *report: True),
                             disk_uv.segment(vertices, faces))


CTRL_C_CHILD = r"""
import os, signal, sys, time
import disk_uv
signal.signal(signal.SIGINT, signal.default_int_handler)  # even if started with SIGINT ignored
function, stage_to_stop, path = sys.argv[1:]
vertices, faces = disk_uv.load(path)
calls = []

def progress(stage, done, total):
    calls.append(stage)
    if stage == stage_to_stop and calls.count(stage) == 2:
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(1.0)  # the interpreter's thread sees the signal meanwhile
        print("signal sent after", len(calls), "calls", flush=True)

try:
    getattr(disk_uv, function)(vertices, faces, progress=progress)
    print("finished")
except KeyboardInterrupt:
    print("KeyboardInterrupt after", len(calls), "calls")
"""


@pytest.mark.parametrize("function, stage", [("atlas", "parameterization"), ("segment", "segmentation")])
def test_ctrl_c_stops_the_computation_with_keyboard_interrupt(function, stage):
    child = subprocess.run([sys.executable, "-c", CTRL_C_CHILD, function, stage, os.path.join(DATA, "elephant.off")],
                           capture_output=True, text=True, timeout=300)
    lines = child.stdout.split("\n")
    assert lines[0].startswith("signal sent after "), child.stdout + child.stderr
    calls = lines[0].split()[3]
    # Stopped at the next report, without calling the callback again.
    assert lines[1] == "KeyboardInterrupt after %s calls" % calls, child.stdout + child.stderr
