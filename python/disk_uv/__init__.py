# Copyright (c) 2026 The Disk_segmentation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""UV atlases of triangle meshes through a segmentation into topological disks.

The same C++ headers as the ``disk_uv`` command-line tool, called on numpy
arrays::

    import disk_uv
    vmapping, indices, uvs = disk_uv.parametrize(vertices, faces)   # as xatlas
    atlas = disk_uv.atlas(vertices, faces, method="arap", resolution=2048)
    atlas.uvs          # (F, 3, 2) per-corner UVs in [0, 1]
    atlas.chart_ids    # (F,) chart of every face
    atlas.report       # the same fields as ``disk_uv --report``

The computation releases the GIL. Bad input raises ``ValueError`` naming the
problem (shapes, dtypes, NaN, indices out of range, non-manifold meshes).
"""

import inspect
import json
import warnings
import os

import numpy

from . import _disk_uv
from ._files import write_atomically

__all__ = ["Atlas", "ArgumentTypeError", "Cancelled", "atlas", "check_options", "parametrize", "segment", "load", "save_obj", "save_glb"]

METHODS = ("arap", "conformal", "lscm", "mvc", "tutte")

# An argument of the wrong type (a method given as a number, a count as a
# float): a TypeError, and a ValueError as earlier versions raised.
ArgumentTypeError = _disk_uv.ArgumentTypeError

# Raised when a ``progress`` callback returns False (a RuntimeError).
# Ctrl-C raises KeyboardInterrupt, also within a second or so.
Cancelled = _disk_uv.Cancelled


class Atlas:
    """The result of :func:`atlas`.

    Attributes:
        vertices, faces: the mesh the atlas belongs to (the arrays given).
        uvs: (F, 3, 2) float64, the UV of each face's corners, in [0, 1].
        chart_ids: (F,) uint32, the chart of each face (0 .. charts - 1; with
            several meshes in one atlas, numbered across them).
        report: dict with the fields of ``disk_uv --report`` (``charts``
            holds one dict per chart with its method and distortion).
        seconds: per-stage times (``report["seconds"]``).
        pages: (F,) uint32, the page of each face (all 0 unless
            ``texels_per_unit`` spread the charts over several pages; ``uvs``
            are then in the unit square of each face's page).
    """

    def __init__(self, vertices, faces, uvs, chart_ids, report):
        self.vertices = vertices
        self.faces = faces
        self.uvs = uvs
        self.chart_ids = chart_ids
        self.report = report

    @property
    def seconds(self):
        return self.report["seconds"]

    @property
    def number_of_charts(self):
        return self.report["segmentation"]["charts"]

    @property
    def number_of_pages(self):
        return self.report["packing"]["pages"]

    @property
    def pages(self):
        # With several meshes, the report lists the pages of this mesh's charts, from its first chart on.
        page_of_chart = numpy.asarray(self.report["packing"]["page_of_chart"], dtype=numpy.uint32)
        if not len(page_of_chart):
            return numpy.zeros(len(self.chart_ids), numpy.uint32)
        return page_of_chart[self.chart_ids - numpy.uint32(self.report.get("first_chart", 0))]

    def udim_uvs(self):
        """``uvs`` with each page moved to its UDIM tile: page ``p`` to
        ``(u + p % 10, v + p // 10)``, tile ``1001 + p % 10 + 10 * (p // 10)``."""
        pages = self.pages
        uvs = numpy.array(self.uvs, dtype=numpy.float64, copy=True)
        uvs[:, :, 0] += (pages % 10)[:, None]
        uvs[:, :, 1] += (pages // 10)[:, None]
        return uvs

    def _written_uvs(self):
        # Several pages are told apart in one file by their UDIM tiles.
        return self.udim_uvs() if self.number_of_pages > 1 else self.uvs

    def xatlas_arrays(self):
        """(vmapping, indices, uvs) as ``xatlas.parametrize`` returns them
        (with several pages, the UVs in their UDIM tiles)."""
        return _disk_uv.xatlas_arrays(self.faces, self._written_uvs(), self.chart_ids)

    def __repr__(self):
        pages = "" if self.number_of_pages <= 1 else ", %d pages" % self.number_of_pages
        return "<disk_uv.Atlas: %d faces, %d charts, packing %.1f%%%s>" % (
            len(self.chart_ids), self.number_of_charts, 100 * self.report["packing"]["efficiency"], pages)


# The wording and the threshold are the library's (IO/packing_warnings.h), as for the disk_uv tool.
def _warn_if_sparse(packing, charts, resolution, padding, texels_per_unit):
    message = _disk_uv.sparse_packing_warning(packing["efficiency"], packing["pages"], charts, str(resolution),
                                              padding, texels_per_unit or 0)
    if message:
        warnings.warn(message, RuntimeWarning, stacklevel=3)


def _warn_of_charts_below_a_texel(packing, resolution, texels_per_unit):
    message = _disk_uv.charts_below_a_texel_warning(packing.get("charts_below_a_texel", 0),
                                                    len(packing["page_of_chart"]), str(resolution),
                                                    texels_per_unit or 0)
    if message:
        warnings.warn(message, RuntimeWarning, stacklevel=3)


def _looks_like_meshes(vertices):
    """Whether `vertices` is a list of (vertices, faces) pairs rather than vertex coordinates."""
    if not isinstance(vertices, (list, tuple)) or not vertices:
        return False
    first = vertices[0]
    return isinstance(first, (list, tuple)) and len(first) == 2 and numpy.ndim(first[0]) == 2


def _checked_progress(progress):
    if progress is not None and not callable(progress):
        raise ArgumentTypeError("progress must be None or a callable (stage, done, total), not %s"
                                % type(progress).__name__)
    return progress


def _atlas_options(method, max_angle_distortion, max_area_distortion, max_stretch, max_area_scale,
                   max_stretch_p95, min_convexity, unbounded, rough_borders, resolution, padding, threads, seed, n, k,
                   threshold, packer, max_chart_faces, use_fallback, max_charts, texels_per_unit, max_pages,
                   crease_penalty):
    return {
        "method": method, "max_angle_distortion": max_angle_distortion,
        "max_area_distortion": max_area_distortion, "max_stretch": max_stretch,
        "max_area_scale": max_area_scale, "max_stretch_p95": max_stretch_p95,
        "min_convexity": min_convexity, "unbounded": bool(unbounded),
        "rough_borders": bool(rough_borders), "resolution": resolution, "padding": padding, "threads": threads,
        "seed": seed, "n": n, "k": k, "threshold": threshold, "packer": packer,
        "max_chart_faces": max_chart_faces, "use_fallback": bool(use_fallback), "max_charts": max_charts,
        "texels_per_unit": texels_per_unit, "max_pages": max_pages, "crease_penalty": crease_penalty,
    }


def atlas(vertices, faces=None, method=_disk_uv.default_parameterization_method,
          max_angle_distortion=_disk_uv.default_max_angle_distortion,
          max_area_distortion=_disk_uv.default_max_area_distortion,
          max_stretch=_disk_uv.default_max_stretch,
          max_area_scale=_disk_uv.default_max_area_scale,
          max_stretch_p95=_disk_uv.default_max_stretch_p95,
          min_convexity=_disk_uv.default_min_convexity,
          unbounded=False, rough_borders=False, resolution=_disk_uv.default_texture_resolution,
          padding=_disk_uv.default_padding, threads=0, seed=None,
          n=_disk_uv.default_number_of_seeds, k=_disk_uv.default_number_of_subsamples,
          threshold=_disk_uv.default_merge_threshold, packer="tight",
          max_chart_faces=_disk_uv.default_max_chart_faces, use_fallback=True, max_charts=None, face_groups=None,
          materials=None, progress=None, texels_per_unit=0.0, max_pages=_disk_uv.default_max_pages,
          crease_penalty=_disk_uv.default_crease_penalty):
    """UV atlas of a triangle mesh; the options are those of the ``disk_uv`` tool.

    ``atlas([(vertices, faces), ...])`` makes one atlas for several meshes
    (xatlas' AddMesh, then Generate): each mesh gets the charts it would get
    alone, all charts are packed together, and the result is a list of
    :class:`Atlas`, one per mesh, with chart ids numbered across the meshes
    (``report["first_chart"]``; ``report["packing"]["page_of_chart"]``
    lists the pages of the mesh's own charts, from that one on);
    ``face_groups``, ``materials`` and ``seed`` then take one mesh only.

    Args:
        vertices: (N, 3) array of real numbers, or a list of (vertices, faces) pairs.
        faces: (F, 3) array of vertex indices (counterclockwise, a manifold
            mesh); None with a list of meshes.
        method: per-chart parameterization: "arap" (default), "conformal"
            (border pinned on a circle), "lscm", "mvc" or "tutte".
        max_angle_distortion, max_area_distortion, max_stretch, max_area_scale,
        max_stretch_p95: the distortion bound every chart meets (see the manual).
        min_convexity: smallest UV area / UV convex hull area of a chart
            holding 3% of the mesh's area or more, 0.8 times it for smaller
            charts (0: no bound).
        unbounded: no distortion or convexity bound (with rough_borders=True and
            crease_penalty=0: the paper's charts).
        rough_borders: keep the saw-toothed chart borders of the paper (neither smoothed nor straightened).
        resolution, padding: texture side and gap between charts, in texels;
            ``resolution=(width, height)`` for a non-square texture ("tight"
            packer: the UVs span the unit square, the texels stay square).
        texels_per_unit: 0 (the largest density that fits the charts on one
            page) or a fixed texel density, in texels per unit of length
            ("tight" packer): the charts then fill as many pages of
            ``resolution`` texels as they need (``Atlas.pages``,
            ``report["packing"]["pages"]``); a chart larger than a page
            raises ``ValueError``.
        max_pages: the most pages ``texels_per_unit`` may fill (at most 999:
            pages are written as the UDIM tiles 1001 to 1999).
        threads: at most this many threads (0: all); the result does not depend on it.
        seed: None (deterministic default first seed) or an integer seed.
        n, k, threshold: the segmentation's seeds, subsamples and merge threshold.
        crease_penalty: Voronoi distances across bent edges are 1 + crease_penalty
            (1 - cos(dihedral angle)) times longer, so borders follow creases
            (default 10; 0: the paper's geodesic distance).
        packer: "tight" (one texel density) or "grid" (the paper's).
        max_chart_faces: larger patches are split before parameterization.
        use_fallback: redo invalid charts with other methods (else keep them, reported).
        max_charts: None (no budget) or the most charts wanted. When the
            bound leaves more, adjacent charts are merged past the bound
            (valid maps only, least added distortion first) down to this
            number if they can be; ``report["parameterization"]`` says
            ``chart_budget_met`` and ``charts_before_budget``.
        face_groups: None, or (F,) integers: faces with the same value are
            one polygon of the caller's mesh (triangulated), which should
            not be cut by a seam. A polygon split between two charts is
            moved whole into one of them when both stay disks; those charts
            are then parameterized and packed again without the distortion
            bound. ``report["polygons"]`` counts the polygons moved and
            those left across charts.
        materials: None, or (F,) integers: faces with different values
            (materials, parts) never share a chart; the mesh is cut along
            the edges between them.
        progress: None, or a callable ``progress(stage, done, total)``
            called as the work goes ("segmentation", "parameterization",
            "packing"), from another thread than the caller's; returning
            False stops the computation with :class:`Cancelled`, and an
            exception it raises stops it and is raised by ``atlas``.

    Returns:
        an :class:`Atlas`.

    Ctrl-C (SIGINT) stops the computation at its next progress report and
    raises KeyboardInterrupt.
    """
    options = _atlas_options(method, max_angle_distortion, max_area_distortion, max_stretch, max_area_scale,
                             max_stretch_p95, min_convexity, unbounded, rough_borders, resolution, padding, threads, seed, n,
                             k, threshold, packer, max_chart_faces, use_fallback, max_charts, texels_per_unit,
                             max_pages, crease_penalty)
    options["face_groups"] = face_groups
    options["materials"] = materials
    options["progress"] = _checked_progress(progress)
    if faces is not None and _looks_like_meshes(vertices):
        raise ArgumentTypeError("atlas() was given a list of (vertices, faces) pairs and faces: with a list of "
                                "meshes, faces must be None (each pair holds its own faces)")
    if faces is None:
        if not isinstance(vertices, (list, tuple)):
            raise ArgumentTypeError("atlas() takes vertices and faces, or a list of (vertices, faces) pairs, not %s"
                                    % type(vertices).__name__)
        results, packing = _disk_uv.atlas_of_meshes(list(vertices), options)
        # The pages' coverage is the common packing's: one list shared by all reports, not a copy in each.
        common = json.loads(packing)
        page_efficiency = common["page_efficiency"]
        atlases = []
        for (v, f), r in zip(vertices, results):
            report = json.loads(r["report"])
            report["packing"]["page_efficiency"] = page_efficiency
            atlases.append(Atlas(v, f, r["uvs"], r["chart_ids"], report))
        if atlases:
            _warn_if_sparse(common, atlases[0].report["total_charts"], resolution, padding, texels_per_unit)
            _warn_of_charts_below_a_texel(common, resolution, texels_per_unit)
            if max_charts is not None and atlases[0].report["total_charts"] > max_charts:
                warnings.warn("%d charts in all: max_charts=%d is a budget for each of the %d meshes, not for the "
                              "atlas" % (atlases[0].report["total_charts"], max_charts, len(atlases)),
                              RuntimeWarning, stacklevel=2)
        return atlases
    result = _disk_uv.atlas(vertices, faces, options)
    atlas = Atlas(vertices, faces, result["uvs"], result["chart_ids"], json.loads(result["report"]))
    _warn_if_sparse(atlas.report["packing"], atlas.number_of_charts, resolution, padding, texels_per_unit)
    _warn_of_charts_below_a_texel(atlas.report["packing"], resolution, texels_per_unit)
    return atlas


def check_options(**options):
    """Checks options of :func:`atlas` (its keywords, but for the per-mesh
    ``face_groups``, ``materials`` and ``progress``) without a mesh,
    as :func:`atlas` checks them first: raises ``ValueError`` (or
    :class:`ArgumentTypeError`) naming the first bad one, else returns None.
    A batch checks its options once this way before it reads any mesh."""
    names = [name for name in inspect.signature(_atlas_options).parameters]
    unknown = sorted(set(options) - set(names))
    if unknown:
        raise TypeError("check_options() got unknown options: %s" % ", ".join(unknown))
    defaults = inspect.signature(atlas).parameters
    values = {name: options.get(name, defaults[name].default) for name in names}
    _disk_uv.check_atlas_options(_atlas_options(**values))


def parametrize(vertices, faces, **options):
    """Drop-in for ``xatlas.parametrize(vertices, faces)``.

    Returns ``(vmapping, indices, uvs)``: ``vmapping`` (M,) uint32 maps each
    output vertex to its input vertex, ``indices`` (F, 3) uint32 are the
    faces, in input order, over the output vertices, and ``uvs`` (M, 2)
    float32, in [0, 1] on one page; with ``texels_per_unit`` the charts may
    fill several pages, and page ``p`` then lies in its UDIM tile
    ``[p % 10, p % 10 + 1] x [p // 10, p // 10 + 1]`` (:meth:`Atlas.udim_uvs`).
    An input vertex on a seam gets one output vertex per chart.
    ``options`` are those of :func:`atlas`. Raises ``ValueError`` if charts
    are too small for float32 UVs (a tiny ``texels_per_unit``).
    """
    return atlas(vertices, faces, **options).xatlas_arrays()


def segment(vertices, faces, n=_disk_uv.default_number_of_seeds, k=_disk_uv.default_number_of_subsamples,
            threshold=_disk_uv.default_merge_threshold, progress=None,
            crease_penalty=_disk_uv.default_crease_penalty):
    """The segmentation into topological disks alone: (F,) uint32 patch ids.

    Joint farthest-point sampling of ``n`` seeds and geodesic Voronoi cells,
    regions that are not disks re-sampled with ``k`` seeds, adjacent disks
    merged while their union stays a disk and scores below ``threshold``.
    ``crease_penalty`` lengthens distances across bent edges as in :func:`atlas`
    (``crease_penalty=0``: the paper's distance). Region borders lose their
    saw teeth before merging, as in :func:`atlas` (not in the paper).
    ``progress`` and Ctrl-C work as in :func:`atlas`.
    """
    return _disk_uv.segment(vertices, faces, {"n": n, "k": k, "threshold": threshold,
                                              "crease_penalty": crease_penalty,
                                              "progress": _checked_progress(progress)})


def load(path, repair=False, triangulate=False):
    """Reads a triangle mesh (.off .obj .ply .stl .ts) as (vertices, faces) arrays.

    ``path`` is a str, bytes or path-like object; its name need not be
    UTF-8. ``repair`` merges duplicated vertices, drops duplicated and
    degenerate faces, orients the faces and cuts non-manifold edges and
    vertices; ``triangulate`` splits polygons. Without them a mesh that needs
    either is refused with a ``ValueError`` naming the problem.
    """
    path = os.fsencode(path)  # the C++ reader takes the name's bytes, UTF-8 or not
    if not os.path.exists(path):
        raise FileNotFoundError(os.fsdecode(path))
    try:
        return _disk_uv.load(path, bool(repair), bool(triangulate))
    except ValueError as error:
        # The tool's messages name its command-line flags.
        raise ValueError(str(error).replace("--repair", "repair=True").replace("--triangulate", "triangulate=True")) \
            from None


def _save(format, path, atlas, overwrite):
    if not isinstance(atlas, Atlas):
        raise TypeError("expected a disk_uv.Atlas, not %s" % type(atlas).__name__)
    data = _disk_uv.atlas_file(format, atlas.vertices, atlas.faces, atlas._written_uvs(), atlas.chart_ids)
    write_atomically(path, data, overwrite)


def save_obj(path, atlas, overwrite=True):
    """Writes the atlas as OBJ (per-corner ``vt``, one group per chart), atomically; several pages are
    written as UDIM tiles (:meth:`Atlas.udim_uvs`)."""
    _save("obj", path, atlas, overwrite)


def save_glb(path, atlas, overwrite=True):
    """Writes the atlas as binary glTF 2.0 (TEXCOORD_0), atomically; several pages as UDIM tiles."""
    _save("glb", path, atlas, overwrite)
