# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Blender add-on: UV unwrap of mesh objects by disk_uv (the Python module).

Registers ``bpy.ops.uv.disk_uv_unwrap()``, "Disk UV Unwrap" in the UV menu
of the 3D view (U in edit mode). It writes the active UV map (made if there
is none) of every selected mesh object in object mode (whole meshes), or of
the selected faces of every object in edit mode (the other faces keep their
UVs). The polygons are kept: the unwrap runs on their
triangles (Blender's loop triangles, nothing is changed in the mesh) and
each triangle's corners write the UVs of their polygon's loops; a polygon
whose triangles fell into two charts is moved whole into one (see
disk_uv.atlas(face_groups=...)). Mode and selection are left as they were.
From the menu the unwrap runs on a worker thread with its progress in the
status bar: Esc cancels it and no UV changes.

Needs the disk_uv module where Blender's Python finds it
(scripts/install_python.sh of the Disk_segmentation repository).
"""

bl_info = {
    "name": "Disk UV Unwrap",
    "author": "The Disk_segmentation authors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "3D View > Edit Mode > UV > Disk UV Unwrap",
    "description": "UV atlas through a segmentation into topological disks (disk_uv)",
    "category": "UV",
}

import threading
import warnings

import bpy
import numpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty


def mesh_arrays(obj, selected_only=False):
    """World-space vertices, loop triangles (vertex and loop indices) and their polygons.

    With `selected_only`, only the triangles of selected polygons, over the
    vertices they use (renumbered).
    """
    mesh = obj.data
    mesh.calc_loop_triangles()
    vertices = numpy.empty(len(mesh.vertices) * 3, dtype=numpy.float64)
    mesh.vertices.foreach_get("co", vertices)
    vertices = vertices.reshape(-1, 3)
    # Scale and shear change the distortion the user sees; translation does not matter.
    matrix = numpy.array(obj.matrix_world, dtype=numpy.float64)
    vertices = vertices @ matrix[:3, :3].T
    count = len(mesh.loop_triangles)
    triangles = numpy.empty(count * 3, dtype=numpy.int64)
    loops = numpy.empty(count * 3, dtype=numpy.int64)
    polygons = numpy.empty(count, dtype=numpy.int64)
    mesh.loop_triangles.foreach_get("vertices", triangles)
    mesh.loop_triangles.foreach_get("loops", loops)
    mesh.loop_triangles.foreach_get("polygon_index", polygons)
    triangles, loops = triangles.reshape(-1, 3), loops.reshape(-1, 3)
    if selected_only:
        selected = numpy.empty(len(mesh.polygons), dtype=bool)
        mesh.polygons.foreach_get("select", selected)
        keep = selected[polygons]
        triangles, loops, polygons = triangles[keep], loops[keep], polygons[keep]
        used, triangles = numpy.unique(triangles, return_inverse=True)
        vertices, triangles = vertices[used], triangles.reshape(-1, 3)
    return vertices, triangles, loops, polygons


def write_uvs(mesh, loops, corner_uvs):
    layer = mesh.uv_layers.active
    if layer is None:
        layer = mesh.uv_layers.new(name="UVMap")
        mesh.uv_layers.active = layer
    # Loops outside `loops` (faces not unwrapped) keep their UVs.
    uvs = numpy.empty(len(mesh.loops) * 2, dtype=numpy.float32)
    layer.data.foreach_get("uv", uvs)
    uvs = uvs.reshape(-1, 2)
    # Every loop is a corner of some triangle of its polygon; a polygon kept
    # whole gives all its triangles' copies of a loop the same UV.
    uvs[loops.reshape(-1)] = corner_uvs.reshape(-1, 2)
    layer.data.foreach_set("uv", uvs.reshape(-1).astype(numpy.float32))
    mesh.update()


class UV_OT_disk_uv_unwrap(bpy.types.Operator):
    """UV atlas of the selected meshes through a segmentation into topological disks"""

    bl_idname = "uv.disk_uv_unwrap"
    bl_label = "Disk UV Unwrap"
    bl_options = {"REGISTER", "UNDO"}

    method: EnumProperty(
        name="Method",
        items=[("arap", "ARAP", "As-rigid-as-possible from a free-border conformal map (default)"),
               ("conformal", "Conformal", "Discrete conformal map, border pinned on a circle"),
               ("lscm", "LSCM", "Least squares conformal map, free border"),
               ("mvc", "Mean value", "Mean value coordinates, border on a circle"),
               ("tutte", "Tutte", "Barycentric map, border on a circle")],
        default="arap")
    max_angle_distortion: FloatProperty(
        name="Angle distortion bound", description="Largest mean |log(s1/s2)| of a chart",
        default=0.06, min=0.001, soft_max=1.0)
    unbounded: BoolProperty(
        name="No distortion bound", description="Fewer, more distorted charts (the paper's, with Crease penalty 0)",
        default=False)
    crease_penalty: FloatProperty(
        name="Crease penalty", description="Seams prefer sharp edges: across an edge bent by an angle theta, "
                                           "distances count 1 + k (1 - cos theta) times (0: the paper's distance)",
        default=10.0, min=0.0, soft_max=50.0)
    split_by_material: BoolProperty(
        name="Split by material", description="No chart spans two materials of the object", default=True)
    max_charts: IntProperty(
        name="Chart budget", description="Most charts per object, merged past the bound if needed (0: no budget)",
        default=0, min=0, soft_max=1000)
    margin: FloatProperty(name="Margin (texels)", description="Gap around every chart, in texels",
                          default=2.0, min=0.0, soft_max=16.0)
    resolution: IntProperty(name="Resolution", description="Texture side in texels the margin refers to",
                            default=1024, min=16, max=65536)
    resolution_height: IntProperty(
        name="Height", description="Height in texels of a non-square texture, Resolution its width (0: square)",
        default=0, min=0, max=65536)
    texel_density: FloatProperty(
        name="Texel density", description="Texels per unit of length, fixed: the charts fill as many UDIM tiles of "
                                          "Resolution texels as they need (0: the largest that fits one tile)",
        default=0.0, min=0.0, soft_max=4096.0)

    @classmethod
    def poll(cls, context):
        return any(o.type == "MESH" for o in cls.target_objects(context))

    @staticmethod
    def target_objects(context):
        if context.mode == "EDIT_MESH":
            return list(context.objects_in_mode_unique_data)
        return [o for o in context.selected_objects if o.type == "MESH"]

    def atlas_options(self):
        return dict(method=self.method, unbounded=self.unbounded, max_angle_distortion=self.max_angle_distortion,
                    crease_penalty=self.crease_penalty,
                    padding=self.margin,
                    resolution=(self.resolution, self.resolution_height) if self.resolution_height else self.resolution,
                    max_charts=self.max_charts or None,
                    texels_per_unit=self.texel_density)

    def execute(self, context):
        """Unwraps at once (scripts, the redo panel): the UI waits."""
        job = start_job(context, self.target_objects(context), self.atlas_options(), self.split_by_material)
        if job is None:
            self.report({"ERROR"}, "the disk_uv Python module is not installed for Blender's Python "
                                   "(run scripts/install_python.sh)")
            return {"CANCELLED"}
        job.wait()
        return finish_job(context, job, self.report)

    def invoke(self, context, event):
        """Unwraps on a worker thread: the UI stays live, Esc cancels and no UV changes."""
        job = start_job(context, self.target_objects(context), self.atlas_options(), self.split_by_material)
        if job is None:
            self.report({"ERROR"}, "the disk_uv Python module is not installed for Blender's Python "
                                   "(run scripts/install_python.sh)")
            return {"CANCELLED"}
        self._job = job
        self._timer = context.window_manager.event_timer_add(0.1, window=context.window)
        context.window_manager.progress_begin(0, 100)
        context.window_manager.modal_handler_add(self)
        return {"RUNNING_MODAL"}

    def modal(self, context, event):
        if event.type == "ESC":
            self._job.cancel()
        if event.type != "TIMER":
            return {"RUNNING_MODAL"}
        context.window_manager.progress_update(int(100 * self._job.progress))
        if not self._job.done:
            return {"RUNNING_MODAL"}
        context.window_manager.event_timer_remove(self._timer)
        context.window_manager.progress_end()
        return finish_job(context, self._job, self.report)


class UnwrapJob:
    """The atlases of several objects, computed on a worker thread.

    Only arrays cross to the thread (bpy is not thread-safe); the UVs are
    written by finish_job() on Blender's thread. cancel() stops the work at
    the module's next progress report; nothing is written then.
    """

    def __init__(self, tasks, options):
        self.tasks = tasks  # (object name, vertices, triangles, loops, polygons, materials)
        self.options = options
        self.results = []  # (object name, loops, atlas)
        self.failed, self.warned = [], []
        self.cancelled = False
        self.done = False
        self.progress = 0.0
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="disk_uv unwrap", daemon=True)

    def start(self):
        self._thread.start()

    def cancel(self):
        self._stop.set()

    def wait(self):
        self._thread.join()

    def _run(self):
        import disk_uv
        try:
            for index, (name, vertices, triangles, loops, polygons, materials) in enumerate(self.tasks):
                def progress(stage, done, total, index=index):
                    stages = ("segmentation", "parameterization", "packing")
                    part = (stages.index(stage) + done / max(total, 1)) / 3 if stage in stages else 0
                    self.progress = (index + part) / len(self.tasks)
                    return not self._stop.is_set()
                try:
                    # One worker: the filter it sets is not raced by another.
                    with warnings.catch_warnings(record=True) as caught:
                        warnings.simplefilter("always", RuntimeWarning)
                        atlas = disk_uv.atlas(vertices, triangles, face_groups=polygons, materials=materials,
                                              progress=progress, **self.options)
                except disk_uv.Cancelled:
                    self.cancelled = True
                    return
                except Exception as error:  # a bad mesh or option: said, and the next object goes on
                    self.failed.append("%s: %s" % (name, str(error).replace("texels_per_unit", "texel density")))
                    continue
                for warning in caught:
                    # The module names its keywords; the panel calls them "Margin" and "Texel density".
                    message = str(warning.message).replace("padding", "margin")
                    self.warned.append("%s: %s" % (name, message.replace("texels_per_unit", "texel density")))
                self.results.append((name, loops, atlas))
            self.cancelled = self._stop.is_set()
        finally:
            self.done = True


def start_job(context, objects, options, split_by_material):
    """Reads the objects' arrays (in object mode, back to the mode it was
    in) and starts their unwrap on a worker thread; None without disk_uv."""
    try:
        import disk_uv  # noqa: F401
    except ImportError:
        return None
    objects = [o for o in objects if o.type == "MESH"]
    mode = context.mode
    active = context.view_layer.objects.active
    if mode == "EDIT_MESH":
        bpy.ops.object.mode_set(mode="OBJECT")  # writes the edit-mode mesh to obj.data
    tasks, empty = [], []
    try:
        for obj in objects:
            vertices, triangles, loops, polygons = mesh_arrays(obj, selected_only=(mode == "EDIT_MESH"))
            if len(triangles) == 0:
                empty.append("%s: no %sfaces" % (obj.name, "selected " if mode == "EDIT_MESH" else ""))
                continue
            materials = None
            if split_by_material and len(obj.data.materials) > 1:
                material_of_polygon = numpy.empty(len(obj.data.polygons), dtype=numpy.int64)
                obj.data.polygons.foreach_get("material_index", material_of_polygon)
                materials = material_of_polygon[polygons]
            tasks.append((obj.name, vertices, triangles, loops, polygons, materials))
    finally:
        if mode == "EDIT_MESH":
            context.view_layer.objects.active = active
            bpy.ops.object.mode_set(mode="EDIT")
    job = UnwrapJob(tasks, options)
    job.failed.extend(empty)
    job.start()
    return job


def finish_job(context, job, report):
    """Writes the UVs of a finished job, all of them or, if it was
    cancelled, none; reports through `report` (an operator's)."""
    if job.cancelled:
        report({"WARNING"}, "Disk UV Unwrap cancelled: no UV changed")
        return {"CANCELLED"}
    edit_mode = context.mode == "EDIT_MESH"
    active = context.view_layer.objects.active
    if edit_mode:
        bpy.ops.object.mode_set(mode="OBJECT")
    tiles, written = [], 0
    try:
        for name, loops, atlas in job.results:
            obj = bpy.data.objects.get(name)
            if obj is None or obj.type != "MESH":
                job.failed.append("%s: the object is gone" % name)
                continue
            # Several pages go to UDIM tiles 1001, 1002, ..., as Blender's tiled images read them.
            write_uvs(obj.data, loops, atlas.udim_uvs() if atlas.number_of_pages > 1 else atlas.uvs)
            written += 1
            if atlas.number_of_pages > 1:
                tiles.append("%s: %d UDIM tiles" % (name, atlas.number_of_pages))
    finally:
        if edit_mode:
            context.view_layer.objects.active = active
            bpy.ops.object.mode_set(mode="EDIT")
    for message in job.failed + job.warned:
        report({"WARNING"}, message)
    if written == 0:
        report({"ERROR"}, "no mesh unwrapped")
        return {"CANCELLED"}
    report({"INFO"}, "Disk UV Unwrap: %d mesh(es) unwrapped%s" % (written, "".join("; " + t for t in tiles)))
    return {"FINISHED"}


def menu_entry(self, context):
    self.layout.operator(UV_OT_disk_uv_unwrap.bl_idname)


def register():
    bpy.utils.register_class(UV_OT_disk_uv_unwrap)
    bpy.types.VIEW3D_MT_uv_map.append(menu_entry)


def unregister():
    bpy.types.VIEW3D_MT_uv_map.remove(menu_entry)
    bpy.utils.unregister_class(UV_OT_disk_uv_unwrap)
