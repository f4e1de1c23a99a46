// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

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
#include <cstddef>
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
  const double aspect = page_aspect(settings);
  // Every halfedge of a face is written once, so nothing is moved twice.
  for(std::size_t i = 0; i < charts.faces.size(); ++i)
  {
    const std::size_t p = charts.patch_of[i];
    const Chart_similarity& sim = placement[p];
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(charts.faces[i], tm), tm))
    {
      const Packing_point q =
        sim.rotation(relative_to(to_packing_point(get(uv_map, h)), charts.origin[p]));
      put(uv_map, h, UV_point(sim.scale * q.x + sim.tx, (sim.scale * q.y + sim.ty) / aspect));
    }
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
