// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_IO_UDIM_TILES_H
#define CGAL_DISK_SEGMENTATION_IO_UDIM_TILES_H

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {

/// \ingroup PkgDiskSegmentationIO
/// The most pages UDIM tiles name for common readers: tiles 1001 to 1999
/// (Blender's and Maya's UDIM image names stop there).
constexpr std::size_t max_udim_pages = 999;

/// \ingroup PkgDiskSegmentationIO
/// The UDIM tile number of page `page` of an atlas: pages go ten to a row,
/// page `k` to the square \f$ [k \bmod 10, k \bmod 10 + 1] \times
/// [\lfloor k / 10 \rfloor, \lfloor k / 10 \rfloor + 1] \f$, tile
/// `1001 + k % 10 + 10 * (k / 10)`, the numbering of the texture tiles
/// Blender, Maya and Mari read.
inline unsigned int udim_tile(std::size_t page)
{
  return static_cast<unsigned int>(1001 + page % 10 + 10 * (page / 10));
}

/// \ingroup PkgDiskSegmentationIO
///
/// Moves the UVs of every chart from the unit square of its page to that
/// page's UDIM tile (`udim_tile()`): \f$ (u + k \bmod 10, v + \lfloor k / 10
/// \rfloor) \f$ for a chart on page `k`. Writers then carry the page in the
/// UVs (OBJ, glTF), and `write_atlas_PNG()` draws one tile at a time.
///
/// @tparam TriangleMesh, FacePatchMap, UVMap as in `write_atlas_OBJ()`
/// @param mesh a triangle mesh
/// @param patch the chart id of every face
/// @param uv per-corner UVs (`uv[h]` is the UV of `target(h)` in `face(h)`), in
///        the unit square of each chart's page on entry, in its tile on return
/// @param page_of_chart the page of every chart, e.g. `Packing_report::page_of_chart`
///
/// @throws Input_error if a face's patch id has no entry in `page_of_chart`,
///         or its page is beyond the last tile, 1999 (`max_udim_pages`);
///         `uv` is not written then.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap>
void move_pages_to_udim_tiles(const TriangleMesh& mesh, FacePatchMap patch, UVMap uv,
                              const std::vector<std::size_t>& page_of_chart)
{
  static_assert(CGAL::Disk_segmentation::internal::Check_patch_map<FacePatchMap>::value, "");
  typedef typename boost::property_traits<UVMap>::value_type UV_point;
  for(auto f : faces(mesh))
  {
    const std::size_t chart = static_cast<std::size_t>(get(patch, f));
    if(chart >= page_of_chart.size())
      throw Input_error("move_pages_to_udim_tiles: chart " + std::to_string(chart) + " has no page (" +
                        std::to_string(page_of_chart.size()) + " pages given)");
    if(page_of_chart[chart] >= max_udim_pages)
      throw Input_error("move_pages_to_udim_tiles: chart " + std::to_string(chart) + " is on page " +
                        std::to_string(page_of_chart[chart]) + ", beyond the last UDIM tile (1999, page " +
                        std::to_string(max_udim_pages - 1) + ")");
  }
  for(auto f : faces(mesh))
  {
    const std::size_t page = page_of_chart[static_cast<std::size_t>(get(patch, f))];
    const double du = static_cast<double>(page % 10), dv = static_cast<double>(page / 10);
    for(auto h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const UV_point& t = get(uv, h);
      put(uv, h, UV_point(CGAL::to_double(t.x()) + du, CGAL::to_double(t.y()) + dv));
    }
  }
}

/// \ingroup PkgDiskSegmentationIO
///
/// The faces of each page: entry `k` lists, in the order of `faces(mesh)`,
/// the faces of the charts on page `k` (`page_of_chart`), those that
/// `write_atlas_PNG_of_faces()` draws for tile `udim_tile(k)` once the pages
/// were moved to their tiles.
///
/// @tparam TriangleMesh, FacePatchMap as in `write_atlas_OBJ()`
///
/// @throws Input_error if a face's patch id has no entry in `page_of_chart`
template <typename TriangleMesh, typename FacePatchMap>
std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> >
faces_of_pages(const TriangleMesh& mesh, FacePatchMap patch, const std::vector<std::size_t>& page_of_chart)
{
  static_assert(CGAL::Disk_segmentation::internal::Check_patch_map<FacePatchMap>::value, "");
  std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> > pages;
  for(auto f : faces(mesh))
  {
    const std::size_t chart = static_cast<std::size_t>(get(patch, f));
    if(chart >= page_of_chart.size())
      throw Input_error("faces_of_pages: chart " + std::to_string(chart) + " has no page (page_of_chart has " +
                        std::to_string(page_of_chart.size()) + " entries)");
    const std::size_t page = page_of_chart[chart];
    if(page >= pages.size())
      pages.resize(page + 1);
    pages[page].push_back(f);
  }
  return pages;
}

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_UDIM_TILES_H
