// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_OBJ_H
#define CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_OBJ_H

#include <CGAL/Disk_segmentation/IO/internal/Atlas_corners.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <ios>
#include <limits>
#include <locale>
#include <numeric>
#include <ostream>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {

/// \ingroup PkgDiskSegmentationIO
///
/// Writes the per-corner UV atlas of `mesh` as a Wavefront OBJ file: one
/// `v` line per vertex in the order of `vertices(mesh)`, one `vt` line per
/// texture vertex (a vertex seen from one chart: a vertex on a seam has one
/// per chart around it), and the faces as `f v/vt ...` grouped by chart:
/// one line `g chart_<id>` per chart, in increasing id, followed by the
/// chart's faces in the order of `faces(mesh)` (so that an importer that
/// splits by group makes one object per chart). Numbers are written with
/// `std::numeric_limits<double>::max_digits10` digits in the classic locale,
/// so they read back exactly; the stream's formatting is restored. No
/// dependency beyond \cgal.
///
/// \cgal 5.5 has no writer for per-corner UVs (its OBJ writer takes one
/// point per vertex), which is what an atlas needs: a vertex on a seam has a
/// UV in each chart around it.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeGraph` with
///         an internal vertex point map whose points have a kernel
/// @tparam FacePatchMap a model of `ReadablePropertyMap` from faces to an
///         integral chart id
/// @tparam UVMap a model of `ReadablePropertyMap` from halfedges to a 2D
///         point: the UV of `target(h, mesh)` in `face(h, mesh)`, as
///         `uv_atlas()` writes it
///
/// @return whether the stream is still good after writing
///
/// Complexity: \f$ O(C + F \log F) \f$ expected time and \f$ O(C) \f$ memory for `C` corners and `F` faces.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap>
bool write_atlas_OBJ(std::ostream& out, const TriangleMesh& mesh, FacePatchMap patch, UVMap uv)
{
  static_assert(CGAL::Disk_segmentation::internal::Check_patch_map<FacePatchMap>::value, "");
  const internal::Atlas_corners a = internal::flatten(mesh, patch, uv);
  internal::Stream_state_saver saver(out);
  out.imbue(std::locale::classic());
  out.unsetf(std::ios_base::floatfield);
  out.precision(std::numeric_limits<double>::max_digits10);

  out << "# UV atlas written by CGAL::Disk_segmentation: " << a.points.size() << " vertices, " << a.textures.size()
      << " texture coordinates, " << a.number_of_faces() << " faces\n";
  for(const std::array<double, 3>& p : a.points)
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const internal::Texture_vertex& t : a.textures)
    out << "vt " << t.u << ' ' << t.v << '\n';
  std::vector<std::size_t> order(a.number_of_faces());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&a](std::size_t f, std::size_t g) { return a.face_chart[f] < a.face_chart[g]; });
  for(std::size_t i = 0; i < order.size(); ++i)
  {
    const std::size_t f = order[i];
    if(i == 0 || a.face_chart[f] != a.face_chart[order[i - 1]])
      out << "g chart_" << a.face_chart[f] << '\n';
    out << 'f';
    for(std::size_t c = a.face_begin[f]; c < a.face_begin[f + 1]; ++c)
      out << ' ' << a.corner_vertex[c] + 1 << '/' << a.corner_texture[c] + 1;
    out << '\n';
  }
  return bool(out);
}

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_OBJ_H
