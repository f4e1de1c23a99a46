// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What reading a mesh may change, and what it changed: plain values, apart
// from the readers, so that a report of the changes needs no reader.

#ifndef CGAL_DISK_SEGMENTATION_IO_READ_OPTIONS_H
#define CGAL_DISK_SEGMENTATION_IO_READ_OPTIONS_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {

/// \ingroup PkgDiskSegmentationIO
/// What `read_triangle_mesh()` may change in a mesh before checking it:
/// repair and triangulation are off by default, so that a bad mesh is named
/// rather than silently altered.
struct Read_options
{
  // CGAL's soup repair: merges duplicated points, removes degenerate and
  // duplicated faces and isolated points, then orients the faces
  // consistently and duplicates the points of non-manifold edges and
  // vertices (the mesh is cut there).
  bool repair = false;
  // Polygons of 4 or more vertices are triangulated (ear clipping in the
  // polygon's plane; a fan if that fails, see internal/Polygon_triangulation.h).
  bool triangulate = false;
  // Inputs that are not regular files (pipes, devices) are refused unless
  // this is set: they may never end.
  bool allow_special_input = false;
  // Such an input, when allowed, is refused beyond this size.
  std::uint64_t max_input_bytes = std::uint64_t(4) << 30;
};

/// \ingroup PkgDiskSegmentationIO
/// What `read_triangle_mesh()` changed; all zero when the file was used as it is.
struct Read_changes
{
  std::size_t polygons_triangulated = 0;
  std::size_t fan_triangulations = 0;  // polygons the planar triangulation failed on
  std::size_t faces_removed = 0;       // by the repair (net of added faces)
  std::size_t faces_added = 0;         // by the triangulation
  std::size_t vertices_removed = 0;    // merged or isolated, net of the ones the repair duplicated
  std::size_t vertices_added = 0;      // duplicated by the repair to make the mesh manifold
  // Fans beyond the first at pinched vertices: the mesh keeps such a vertex,
  // and the package's functions cut it into one vertex per fan themselves.
  std::size_t pinched_vertices_split = 0;
  // With `triangulate`: the polygon (its position among the faces read,
  // after the repair) of each face of the mesh. Empty otherwise.
  std::vector<std::size_t> polygon_of_face;
};

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_READ_OPTIONS_H
