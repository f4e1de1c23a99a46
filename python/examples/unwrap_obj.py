# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Unwraps a mesh as one would with the xatlas binding, with numpy alone.

    python3 unwrap_obj.py INPUT.off|.obj|.ply|.stl OUTPUT.obj

With trimesh, `mesh = trimesh.load(path)` gives the same two arrays
(`mesh.vertices`, `mesh.faces`); switching from xatlas is the one line
`disk_uv.parametrize(...)` in place of `xatlas.parametrize(...)`.
"""

import sys

import numpy

import disk_uv


def write_obj(path, vertices, faces, uvs):
    """OBJ with one vt per output vertex (xatlas's layout: vertices[vmapping])."""
    with open(path, "w", encoding="utf-8") as out:
        numpy.savetxt(out, vertices, fmt="v %.9g %.9g %.9g")
        numpy.savetxt(out, uvs, fmt="vt %.9g %.9g")
        numpy.savetxt(out, numpy.repeat(faces + 1, 2, axis=1), fmt="f %d/%d %d/%d %d/%d")


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    vertices, faces = disk_uv.load(argv[1])
    vmapping, indices, uvs = disk_uv.parametrize(vertices, faces)
    write_obj(argv[2], vertices[vmapping], indices, uvs)
    print("%s: %d faces, %d UV vertices (%d on seams)" % (argv[2], len(indices), len(vmapping),
                                                         len(vmapping) - len(numpy.unique(vmapping))))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
