# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Renders the README's Blender figure headless (Cycles on the CPU):

    PYTHONPATH=build/python blender -b --factory-startup --python python/blender/render_readme_figure.py -- OUT.png

The shipped elephant and a quad torus, unwrapped by the add-on's operator,
with a checker texture read through the new UV map: squares of even size
and right angles mean low distortion.
"""

import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
for entry in reversed(os.environ.get("PYTHONPATH", "").split(os.pathsep)):
    if entry:
        sys.path.insert(0, entry)
sys.path.insert(0, here)

import bpy  # noqa: E402

import disk_uv  # noqa: E402
import disk_uv_unwrap  # noqa: E402

out = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else "blender_disk_uv.png"
source = os.path.join(here, "..", "..")
disk_uv_unwrap.register()
bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.delete()

vertices, faces = disk_uv.load(os.path.join(source, "test", "Disk_segmentation", "data", "elephant.off"))
mesh = bpy.data.meshes.new("elephant")
mesh.from_pydata((vertices * 1.7).tolist(), [], faces.tolist())
for p in mesh.polygons:
    p.use_smooth = True
elephant = bpy.data.objects.new("elephant", mesh)
bpy.context.collection.objects.link(elephant)
elephant.rotation_euler = (1.5708, 0, 3.1416 + 0.7)
elephant.location = (-1.2, 0, 0.0)
bpy.ops.mesh.primitive_torus_add(major_segments=48, minor_segments=16, location=(1.25, 0, 0.0),
                                 rotation=(0.9, 0, 0.3), major_radius=0.55, minor_radius=0.22)
torus = bpy.context.active_object
bpy.ops.object.shade_smooth()

material = bpy.data.materials.new("checker")
material.use_nodes = True
nodes, links = material.node_tree.nodes, material.node_tree.links
checker = nodes.new("ShaderNodeTexChecker")
checker.inputs["Scale"].default_value = 40
checker.inputs["Color1"].default_value = (0.9, 0.9, 0.9, 1)
checker.inputs["Color2"].default_value = (0.15, 0.3, 0.7, 1)
coordinates = nodes.new("ShaderNodeTexCoord")
links.new(coordinates.outputs["UV"], checker.inputs["Vector"])
links.new(checker.outputs["Color"], nodes["Principled BSDF"].inputs["Base Color"])

for obj in (elephant, torus):
    obj.data.materials.append(material)
bpy.ops.object.select_all(action="DESELECT")
elephant.select_set(True)
torus.select_set(True)
bpy.context.view_layer.objects.active = elephant
result = bpy.ops.uv.disk_uv_unwrap()
if result != {"FINISHED"}:
    sys.exit("the unwrap failed")

bpy.ops.object.camera_add(location=(0, -6.5, 1.4), rotation=(1.36, 0, 0))
bpy.context.scene.camera = bpy.context.active_object
bpy.ops.object.light_add(type="SUN", rotation=(0.6, 0.2, 0.4))
bpy.context.active_object.data.energy = 3.0
world = bpy.data.worlds.new("world")
world.color = (0.8, 0.8, 0.8)
bpy.context.scene.world = world
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 24
scene.cycles.use_denoising = False
scene.render.resolution_x, scene.render.resolution_y = 800, 400
scene.render.filepath = os.path.abspath(out)
bpy.ops.render.render(write_still=True)
print("wrote", scene.render.filepath)
