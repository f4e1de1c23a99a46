# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Headless test of the Blender add-on (ctest blender_addon):

    blender -b --factory-startup --python-exit-code 1 --python blender_addon_check.py

Checks that the operator's defaults are the library's, loads a shipped mesh,
a quad mesh and a mixed one, runs the operator on one
object, on two at once, from edit mode and on selected faces only, exports
OBJ files with UVs and checks them with the independent checker
(atlas_checks.py). Exits non-zero
on the first failure. Environment as for the other Python tests.
"""

import os
import sys
import tempfile
import traceback

here = os.path.dirname(os.path.abspath(__file__))
source = os.environ.get("DISK_UV_SOURCE", os.path.join(here, "..", ".."))
# Blender ignores PYTHONPATH unless told otherwise.
for entry in reversed(os.environ.get("PYTHONPATH", "").split(os.pathsep)):
    if entry:
        sys.path.insert(0, entry)
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(source, "python", "blender"))

import bpy  # noqa: E402
import numpy  # noqa: E402

import disk_uv  # noqa: E402
import disk_uv_unwrap  # noqa: E402
from atlas_checks import atlas_problems, components, obj_atlas_problems, read_obj, udim_atlas_problems  # noqa: E402

DATA = os.environ.get("DISK_UV_DATA", os.path.join(source, "test", "Disk_segmentation", "data"))


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def clear_scene():
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()


def add_shipped_mesh(name):
    vertices, faces = disk_uv.load(os.path.join(DATA, name))
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(vertices.tolist(), [], faces.tolist())
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.collection.objects.link(obj)
    return obj


def loop_uvs(mesh):
    uvs = numpy.empty(len(mesh.loops) * 2, dtype=numpy.float32)
    mesh.uv_layers.active.data.foreach_get("uv", uvs)
    return uvs.reshape(-1, 2)


def polygon_signature(obj):
    return [tuple(p.vertices) for p in obj.data.polygons]


def export_and_check(obj, folder, label):
    path = os.path.join(folder, label + ".obj")
    bpy.ops.object.select_all(action="DESELECT")
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj
    bpy.ops.wm.obj_export(filepath=path, export_selected_objects=True, export_uv=True, export_normals=False,
                          export_materials=False, export_triangulated_mesh=False, apply_modifiers=False,
                          forward_axis="Y", up_axis="Z")
    problems = obj_atlas_problems(path)
    check(problems == [], "%s: %s" % (label, problems))
    print("checked", label, "faces", len(obj.data.polygons))


def check_defaults_are_the_librarys():
    """The add-on's properties hold literals (it registers without the module); they must be the library's."""
    properties = bpy.ops.uv.disk_uv_unwrap.get_rna_type().properties
    library = disk_uv._disk_uv
    expected = {
        "method": library.default_parameterization_method,
        "max_angle_distortion": library.default_max_angle_distortion,
        "crease_penalty": library.default_crease_penalty,
        "margin": library.default_padding,
        "resolution": library.default_texture_resolution,
    }
    for name, value in expected.items():
        default = properties[name].default
        if isinstance(value, float):
            ok = abs(default - value) <= 1e-6 * max(1.0, abs(value))  # Blender stores floats in single precision
        else:
            ok = default == value
        check(ok, "the add-on's default %s is %r, the library's %r" % (name, default, value))
    print("checked", len(expected), "defaults against the library's")


def run():
    check(hasattr(bpy.ops.uv, "disk_uv_unwrap"), "operator not registered")
    check(any(getattr(f, "__name__", "") == "menu_entry" for f in bpy.types.VIEW3D_MT_uv_map._dyn_ui_initialize()),
          "no entry in the UV menu")
    check_defaults_are_the_librarys()
    folder = tempfile.mkdtemp(prefix="disk_uv_blender_")
    clear_scene()

    # One shipped triangle mesh, in object mode.
    elephant = add_shipped_mesh("elephant.off")
    bpy.ops.object.select_all(action="DESELECT")
    elephant.select_set(True)
    bpy.context.view_layer.objects.active = elephant
    check(bpy.ops.uv.disk_uv_unwrap() == {"FINISHED"}, "unwrap of the elephant failed")
    check(elephant.data.uv_layers.active is not None, "no UV map written")
    export_and_check(elephant, folder, "elephant")
    # A chart budget: as many UV islands as asked, still a valid atlas.
    check(bpy.ops.uv.disk_uv_unwrap(max_charts=20) == {"FINISHED"}, "unwrap with a chart budget failed")
    export_and_check(elephant, folder, "elephant_budget")
    islands = components([uv_ids for _, uv_ids in read_obj(os.path.join(folder, "elephant_budget.obj"))[2]])
    check(len(set(islands)) == 20, "max_charts=20 gave %d UV islands" % len(set(islands)))
    # The menu's path (invoke): the unwrap runs on a worker thread, Esc
    # cancels it. The job cancelled at once writes no UV and says so; a job
    # left to finish reports its progress up to the end.
    before = loop_uvs(elephant.data).copy()
    job = disk_uv_unwrap.start_job(bpy.context, [elephant], {"max_charts": 10}, True)
    job.cancel()
    job.wait()
    messages = []
    result = disk_uv_unwrap.finish_job(bpy.context, job, lambda kind, text: messages.append(text))
    check(job.cancelled and result == {"CANCELLED"}, "the cancelled job gave %s" % result)
    check(numpy.array_equal(loop_uvs(elephant.data), before), "a cancelled unwrap changed the UVs")
    check(any("cancelled: no UV changed" in m for m in messages), "the cancel is not said: %s" % messages)
    job = disk_uv_unwrap.start_job(bpy.context, [elephant], {"max_charts": 10}, True)
    job.wait()
    check(not job.cancelled and job.progress > 0.99, "a finished job: cancelled %s, progress %g"
          % (job.cancelled, job.progress))
    check(disk_uv_unwrap.finish_job(bpy.context, job, lambda kind, text: None) == {"FINISHED"}, "finish failed")
    check(not numpy.array_equal(loop_uvs(elephant.data), before), "the finished job wrote no UV")
    # A fixed texel density, twice the one-tile fit: several UDIM tiles, each
    # chart in one, each tile a valid atlas (the independent checker).
    fit = disk_uv.atlas(*disk_uv.load(os.path.join(DATA, "elephant.off")))
    density = 2 * fit.report["packing"]["texels_per_unit"]
    check(bpy.ops.uv.disk_uv_unwrap(texel_density=density) == {"FINISHED"}, "unwrap at a texel density failed")
    path = os.path.join(folder, "elephant_tiles.obj")
    bpy.ops.wm.obj_export(filepath=path, export_selected_objects=True, export_uv=True, export_normals=False,
                          export_materials=False, export_triangulated_mesh=False, apply_modifiers=False,
                          forward_axis="Y", up_axis="Z")
    _, uvs, faces = read_obj(path)
    problems, tiles = udim_atlas_problems([uvs[t] for _, t in faces], [t for _, t in faces])
    check(problems == [], "texel density: %s" % problems[:3])
    check(len(tiles) >= 2 and tiles == list(range(1001, 1001 + len(tiles))),
          "texel density %g gave the UDIM tiles %s" % (density, tiles))
    print("checked elephant at", density, "texels per unit:", len(tiles), "UDIM tiles")
    # A non-square texture: a valid atlas, wider than high in texels.
    check(bpy.ops.uv.disk_uv_unwrap(resolution=2048, resolution_height=512) == {"FINISHED"},
          "unwrap on a 2048 x 512 texture failed")
    export_and_check(elephant, folder, "elephant_wide")
    # A texture too small for the margin: unwrapped all the same (the operator warns).
    check(bpy.ops.uv.disk_uv_unwrap(resolution=32) == {"FINISHED"}, "unwrap on a small texture failed")
    export_and_check(elephant, folder, "elephant_small_texture")

    # Two quad objects at once (a torus: all quads, genus 1; a UV sphere:
    # quads and triangle fans), their polygons kept.
    bpy.ops.mesh.primitive_torus_add(major_segments=32, minor_segments=12)
    torus = bpy.context.active_object
    bpy.ops.mesh.primitive_uv_sphere_add(segments=24, ring_count=12, location=(5, 0, 0), scale=(1, 2, 1))
    sphere = bpy.context.active_object
    before = {o.name: polygon_signature(o) for o in (torus, sphere)}
    bpy.ops.object.select_all(action="DESELECT")
    torus.select_set(True)
    sphere.select_set(True)
    bpy.context.view_layer.objects.active = torus
    check(bpy.ops.uv.disk_uv_unwrap(method="arap", margin=4.0, resolution=512) == {"FINISHED"},
          "unwrap of two objects failed")
    for obj in (torus, sphere):
        check(polygon_signature(obj) == before[obj.name], "%s: polygons changed" % obj.name)
        check(all(len(p.vertices) >= 3 for p in obj.data.polygons), "bad polygons")
    check(sorted(o.name for o in bpy.context.selected_objects) == sorted([torus.name, sphere.name]),
          "selection changed")
    check(any(len(p.vertices) == 4 for p in torus.data.polygons), "the torus has no quads")
    export_and_check(torus, folder, "torus")
    export_and_check(sphere, folder, "sphere")

    # Two materials on the torus (the polygons of one half): no UV island spans both.
    for name in ("disk_uv_red", "disk_uv_blue"):
        torus.data.materials.append(bpy.data.materials.new(name))
    half = len(torus.data.polygons) // 2
    for p in torus.data.polygons:
        p.material_index = 1 if p.index < half else 0
    bpy.ops.object.select_all(action="DESELECT")
    torus.select_set(True)
    bpy.context.view_layer.objects.active = torus
    def islands_spanning_two_materials(label):
        export_and_check(torus, folder, label)
        obj_faces = read_obj(os.path.join(folder, label + ".obj"))[2]
        check(len(obj_faces) == len(torus.data.polygons), "the OBJ does not list the polygons")
        materials_of_island = {}
        for polygon, island in enumerate(components([uv_ids for _, uv_ids in obj_faces])):
            materials_of_island.setdefault(island, set()).add(torus.data.polygons[polygon].material_index)
        return sum(len(m) > 1 for m in materials_of_island.values())

    check(bpy.ops.uv.disk_uv_unwrap(split_by_material=False) == {"FINISHED"}, "unwrap ignoring materials failed")
    check(islands_spanning_two_materials("torus_mixed") > 0, "no island spans two materials anyway: void check")
    check(bpy.ops.uv.disk_uv_unwrap() == {"FINISHED"}, "unwrap with two materials failed")
    check(islands_spanning_two_materials("torus_materials") == 0, "a UV island spans two materials")

    # From edit mode: the mode is restored.
    bpy.ops.object.select_all(action="DESELECT")
    torus.select_set(True)
    bpy.context.view_layer.objects.active = torus
    bpy.ops.object.mode_set(mode="EDIT")
    check(bpy.ops.uv.disk_uv_unwrap(unbounded=True) == {"FINISHED"}, "unwrap in edit mode failed")
    check(bpy.context.mode == "EDIT_MESH", "edit mode not restored")
    bpy.ops.object.mode_set(mode="OBJECT")
    export_and_check(torus, folder, "torus_unbounded")

    # Edit mode with part of the faces selected: only their UVs change.
    mesh = torus.data
    before_uvs = loop_uvs(mesh)
    half = len(mesh.polygons) // 2
    for p in mesh.polygons:
        p.select = p.index < half
    for v in mesh.vertices:
        v.select = False
    for p in mesh.polygons[:half]:
        for v in p.vertices:
            mesh.vertices[v].select = True
    bpy.context.tool_settings.mesh_select_mode = (False, False, True)
    bpy.ops.object.mode_set(mode="EDIT")
    check(bpy.ops.uv.disk_uv_unwrap() == {"FINISHED"}, "unwrap of selected faces failed")
    bpy.ops.object.mode_set(mode="OBJECT")
    after_uvs = loop_uvs(mesh)
    selected = [p for p in mesh.polygons if p.select]
    check(0 < len(selected) < len(mesh.polygons), "the selection is not a part of the mesh")
    in_selection = numpy.zeros(len(mesh.loops), dtype=bool)
    for p in selected:
        in_selection[list(p.loop_indices)] = True
    check((after_uvs[~in_selection] == before_uvs[~in_selection]).all(), "unselected faces lost their UVs")
    check(not numpy.allclose(after_uvs[in_selection], before_uvs[in_selection]), "selected faces not unwrapped")
    problems = atlas_problems([after_uvs[list(p.loop_indices)] for p in selected])
    check(problems == [], "selected faces: %s" % problems)
    print("checked selected faces", len(selected))
    print("blender_addon_check: all checks passed")


try:
    disk_uv_unwrap.register()
    run()
except Exception:
    traceback.print_exc()
    sys.exit(1)
