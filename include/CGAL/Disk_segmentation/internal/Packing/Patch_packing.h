// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// pack_patches() on maps of the right key types, with checked settings.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PATCH_PACKING_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PATCH_PACKING_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Packing_report.h>
#include <CGAL/Disk_segmentation/internal/Packing/Chart_layouts.h>
#include <CGAL/Disk_segmentation/internal/Packing/Chart_set.h>
#include <CGAL/Disk_segmentation/internal/Packing/Packing_settings.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// pack_patches() on maps of the right key types, with checked settings;
// `np` only says where the coordinates are.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap, typename NamedParameters>
Packing_report pack_checked_patches(const TriangleMesh& tm, FacePatchMap face_patch_map, UVMap uv_map,
                                    const Packing_settings& settings, const NamedParameters& np)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<UVMap>::value_type UV_point;

  Packing_report report;
  if(faces(tm).empty())
    return report;

  const bool tight = settings.method == Packing_method::TIGHT;
  Chart_set<TriangleMesh> charts;
  collect_charts(tm, face_patch_map, uv_map, tight, np, charts);
  check_packing_capacity(settings, charts.size());
  frame_charts(settings.method, settings.threads, charts);

  double global_scale = 0.;
  std::vector<std::size_t> page_of_chart(charts.size(), 0);
  const std::vector<Chart_similarity> placement =
    tight ? tight_layout(charts, settings, global_scale, page_of_chart) : grid_layout(charts, settings);

  // The layouts are in units of the page's width; v is divided by the
  // page's aspect so that each page is the unit square of its UVs (on a
  // non-square texture, each chart is a similar copy in texels, not in UVs).
  // The new UVs are checked before any is written: a density so low that
  // rounding collapses a triangle leaves uv_map as it was.
  const double aspect = page_aspect(settings);
  std::vector<UV_point> packed;
  packed.reserve(3 * charts.faces.size());
  std::size_t collapsed = 0;
  for(std::size_t i = 0; i < charts.faces.size(); ++i)
  {
    const std::size_t p = charts.patch_of[i];
    const Chart_similarity& sim = placement[p];
    std::array<Planar_point, 3> before, after;
    std::size_t j = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(charts.faces[i], tm), tm))
    {
      before[j] = relative_to(to_packing_point(get(uv_map, h)), charts.origin[p]);
      const Planar_point q = sim.rotation(before[j]);
      after[j] = Planar_point{ sim.scale * q.x + sim.tx, (sim.scale * q.y + sim.ty) / aspect };
      packed.push_back(UV_point(after[j].x, after[j].y));
      ++j;
    }
    // A similarity keeps orientations: only rounding can take one away.
    if(planar_cross(before[0], before[1], before[2]) > 0. && !(planar_cross(after[0], after[1], after[2]) > 0.))
      ++collapsed;
  }
  if(collapsed > 0)
  {
    std::ostringstream message;
    message << "pack_patches: " << collapsed << " triangles of the charts would be degenerate or flipped in the "
            << "packed UVs: the charts are too small for double precision";
    if(settings.texels_per_unit > 0.)
      message << " at texels_per_unit " << settings.texels_per_unit << "; raise texels_per_unit";
    throw Input_error(message.str());
  }
  // Every halfedge of a face is written once, so nothing is moved twice.
  std::size_t corner = 0;
  for(std::size_t i = 0; i < charts.faces.size(); ++i)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(charts.faces[i], tm), tm))
      put(uv_map, h, packed[corner++]);
  for(std::size_t p = 0; p < charts.size(); ++p)
  {
    const double side = placement[p].scale * (std::max)(charts.box[p].width(), charts.box[p].height());
    if(side * settings.resolution < 1.)
      ++report.number_of_charts_below_a_texel;
  }
  report.number_of_pages = charts.size() == 0 ? 1 : *std::max_element(page_of_chart.begin(), page_of_chart.end()) + 1;
  report.page_efficiency.assign(report.number_of_pages, 0.);
  for(std::size_t p = 0; p < charts.size(); ++p)
    report.page_efficiency[page_of_chart[p]] +=
      placement[p].scale * placement[p].scale * charts.uv_area[p] / aspect;
  for(double e : report.page_efficiency)
    report.efficiency += e / static_cast<double>(report.number_of_pages);
  report.page_of_chart = std::move(page_of_chart);
  report.number_of_charts = charts.size();
  // Texels per unit of the input's length, not of the scaled one.
  report.texels_per_unit = tight ? global_scale * settings.resolution * charts.length_scale : 0.;
  return report;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PATCH_PACKING_H
