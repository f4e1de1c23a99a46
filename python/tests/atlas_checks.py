# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks of UV atlases written from their definitions, with numpy alone.

Independent of the library (no disk_uv import): used on the module's
arrays, on OBJ files exported by Blender and on the batch's outputs.
"""

import numpy


def signed_areas(uv_triangles):
    """(T,) signed areas of (T, 3, 2) UV triangles (positive: counterclockwise)."""
    a, b, c = uv_triangles[:, 0], uv_triangles[:, 1], uv_triangles[:, 2]
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def overlapping_texels(uv_triangles, resolution=512):
    """Texel centres of a resolution^2 grid strictly inside two or more triangles."""
    coverage = numpy.zeros((resolution, resolution), dtype=numpy.int32)
    centres = (numpy.arange(resolution) + 0.5) / resolution
    for t in uv_triangles:
        lo = numpy.clip(numpy.floor(t.min(axis=0) * resolution - 0.5).astype(int), 0, resolution - 1)
        hi = numpy.clip(numpy.ceil(t.max(axis=0) * resolution - 0.5).astype(int), 0, resolution - 1)
        xs, ys = centres[lo[0]:hi[0] + 1], centres[lo[1]:hi[1] + 1]
        if len(xs) == 0 or len(ys) == 0:
            continue
        px, py = numpy.meshgrid(xs, ys, indexing="xy")
        inside = numpy.ones(px.shape, dtype=bool)
        area = (t[1, 0] - t[0, 0]) * (t[2, 1] - t[0, 1]) - (t[1, 1] - t[0, 1]) * (t[2, 0] - t[0, 0])
        if area == 0:
            continue
        for i in range(3):
            a, b = t[i], t[(i + 1) % 3]
            edge = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0])
            inside &= edge * numpy.sign(area) > 1e-12
        coverage[lo[1]:hi[1] + 1, lo[0]:hi[0] + 1] += inside
    return int((coverage > 1).sum())


def components(faces):
    """Connected components of faces through shared edges: (F,) labels."""
    parent = list(range(len(faces)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    edge_face = {}
    for f, face in enumerate(faces):
        for i in range(len(face)):
            e = tuple(sorted((int(face[i]), int(face[(i + 1) % len(face)]))))
            if e in edge_face:
                parent[find(f)] = find(edge_face[e])
            else:
                edge_face[e] = f
    return numpy.array([find(f) for f in range(len(faces))])


def euler_characteristic(faces):
    """V - E + F of a list of polygons (vertex ids)."""
    vertices, edges = set(), set()
    for face in faces:
        for i in range(len(face)):
            vertices.add(int(face[i]))
            edges.add(tuple(sorted((int(face[i]), int(face[(i + 1) % len(face)])))))
    return len(vertices) - len(edges) + len(faces)


def atlas_problems(uv_faces, uv_vertex_faces=None, resolution=512):
    """What is wrong with an atlas, as a list of messages (empty: valid).

    uv_faces: list of (k, 2) arrays, the UVs of each polygon's corners.
    uv_vertex_faces: optionally the polygons over UV vertex ids (as OBJ's
    vt indices): every connected chart must then be a topological disk.
    Checks: UVs finite and in [0, 1]; every polygon's fan triangles
    counterclockwise with area (no flip, no mirrored chart, no degenerate
    one); no texel centre inside two triangles.
    """
    problems = []
    triangles = []
    for corners in uv_faces:
        corners = numpy.asarray(corners, dtype=numpy.float64)
        for i in range(1, len(corners) - 1):
            triangles.append([corners[0], corners[i], corners[i + 1]])
    triangles = numpy.array(triangles, dtype=numpy.float64).reshape(-1, 3, 2)
    if not numpy.isfinite(triangles).all():
        problems.append("non-finite UVs")
        return problems
    if triangles.min() < 0 or triangles.max() > 1:
        problems.append("UVs outside [0, 1]: %g .. %g" % (triangles.min(), triangles.max()))
    areas = signed_areas(triangles)
    scale = max(float(numpy.abs(areas).max()), 1e-300)
    flipped = int((areas < 0).sum())
    degenerate = int((numpy.abs(areas) <= 1e-12 * scale).sum())
    if flipped:
        problems.append("%d flipped (clockwise) UV triangles" % flipped)
    if degenerate:
        problems.append("%d degenerate UV triangles" % degenerate)
    overlaps = overlapping_texels(triangles, resolution)
    if overlaps:
        problems.append("%d texels covered twice" % overlaps)
    if uv_vertex_faces is not None:
        labels = components(uv_vertex_faces)
        for label in numpy.unique(labels):
            chart = [uv_vertex_faces[f] for f in numpy.flatnonzero(labels == label)]
            if euler_characteristic(chart) != 1:
                problems.append("a chart of %d faces is not a disk (Euler characteristic %d)"
                                % (len(chart), euler_characteristic(chart)))
                break
    return problems


def read_obj(path):
    """Positions, UVs and faces ((vertex ids), (uv ids)) of an OBJ file."""
    positions, uvs, faces = [], [], []
    with open(path, encoding="utf-8") as obj:
        for line in obj:
            fields = line.split()
            if not fields:
                continue
            if fields[0] == "v":
                positions.append([float(x) for x in fields[1:4]])
            elif fields[0] == "vt":
                uvs.append([float(x) for x in fields[1:3]])
            elif fields[0] == "f":
                corners = [c.split("/") for c in fields[1:]]
                faces.append(([int(c[0]) - 1 for c in corners],
                              [int(c[1]) - 1 if len(c) > 1 and c[1] else -1 for c in corners]))
    return numpy.array(positions), numpy.array(uvs), faces


def obj_atlas_problems(path, resolution=512):
    """atlas_problems() of an OBJ file's vt; every face must have UVs."""
    positions, uvs, faces = read_obj(path)
    if any(min(t) < 0 for _, t in faces):
        return ["faces without UVs"]
    if len(faces) == 0:
        return ["no faces"]
    return atlas_problems([uvs[t] for _, t in faces], [t for _, t in faces], resolution)


def udim_atlas_problems(uv_faces, uv_vertex_faces=None, resolution=512):
    """atlas_problems() of an atlas whose pages are UDIM tiles: (problems, tiles).

    Every face belongs to the tile [i, i+1] x [j, j+1] that holds its UV
    centroid; every chart (UV-connected faces when uv_vertex_faces is given,
    else each face) must lie in one tile, and each tile, moved to [0, 1]^2,
    must be a valid atlas. ``tiles`` lists the UDIM numbers used.
    """
    centroids = numpy.array([numpy.asarray(c, dtype=numpy.float64).mean(axis=0) for c in uv_faces])
    if not numpy.isfinite(centroids).all():
        return ["non-finite UVs"], []
    tile_of = numpy.floor(centroids).astype(numpy.int64)
    problems = []
    if (tile_of < 0).any() or (tile_of[:, 0] > 9).any():
        problems.append("a face outside the UDIM tiles (u in [0, 10), v >= 0)")
        return problems, []
    if uv_vertex_faces is not None:
        labels = components(uv_vertex_faces)
        for label in numpy.unique(labels):
            tiles = {tuple(t) for t in tile_of[labels == label]}
            if len(tiles) > 1:
                problems.append("a chart spans the tiles %s" % sorted(tiles))
    numbers = sorted({1001 + int(t[0]) + 10 * int(t[1]) for t in tile_of})
    for number in numbers:
        i, j = (number - 1001) % 10, (number - 1001) // 10
        members = [f for f in range(len(uv_faces)) if tile_of[f][0] == i and tile_of[f][1] == j]
        shifted = [numpy.asarray(uv_faces[f], dtype=numpy.float64) - (i, j) for f in members]
        sub_faces = None if uv_vertex_faces is None else [uv_vertex_faces[f] for f in members]
        problems += ["tile %d: %s" % (number, p) for p in atlas_problems(shifted, sub_faces, resolution)]
    return problems, numbers
