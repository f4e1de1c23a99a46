// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The charts to pack, read from the user's maps into one set, and the
// similarity each one gets when placed.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CHART_SET_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CHART_SET_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Packing_method.h>
#include <CGAL/Disk_segmentation/internal/Execution/parallel.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Packing/packing_geometry.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

template <typename Id>
std::size_t checked_patch_id(const Id& id, std::size_t face, std::size_t number_of_faces)
{
  bool negative = false;
  if constexpr(std::is_signed<Id>::value)
    negative = id < 0;
  const std::size_t i = static_cast<std::size_t>(id);
  // A valid id is below the number of patches, hence below the number of faces.
  if(negative || i >= number_of_faces)
    throw Input_error("pack_patches: face #" + std::to_string(face) +
                      " has a patch id outside [0, number of faces); patch ids must be "
                      "contiguous in [0, number of patches)");
  return i;
}

template <typename UVPoint>
Planar_point to_packing_point(const UVPoint& p)
{
  return { CGAL::to_double(p.x()), CGAL::to_double(p.y()) };
}

inline Planar_point relative_to(const Planar_point& p, const Planar_point& origin)
{
  return { p.x - origin.x, p.y - origin.y };
}

inline std::string patch_name(std::size_t p) { return "patch #" + std::to_string(p); }

// A chart's placement: uv -> scale * rotation(uv) + (tx, ty).
struct Chart_similarity
{
  Packing_rotation rotation;
  double scale = 0., tx = 0., ty = 0.;
};

// The charts of the mesh and what the layouts need of them.
template <typename TriangleMesh>
struct Chart_set
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  std::vector<face_descriptor> faces;        // in faces(tm) order
  std::vector<std::size_t> patch_of;         // face -> patch
  // The UVs of the corners grouped by patch (faces(tm) order within a
  // patch), so that each chart is read from one contiguous run; patch p
  // owns the corners [3 first_face[p], 3 first_face[p + 1]).
  std::vector<Planar_point> corners;
  // Per face, in the order of `corners`: bit j is set when the edge from
  // corner j to corner j + 1 is on its chart's border (the next face is in
  // another patch or none, or the two faces give its ends different UVs).
  std::vector<unsigned char> border_edges;
  // Corners are stored relative to their chart's first UV: a chart 1e-13
  // wide placed at 0.45 would otherwise lose its shape to cancellation
  // when it is moved to its place.
  std::vector<Planar_point> origin;
  std::vector<std::size_t> first_face;       // P + 1 entries
  std::vector<double> uv_area, surface_area;
  // 3D areas are measured with lengths multiplied by this power of two.
  double length_scale = 1.;
  std::vector<Packing_rotation> rotation;    // chosen frame of each chart
  std::vector<Packing_box> box;              // bounding box of the chart's UVs in that frame

  std::size_t size() const { return uv_area.size(); }
};

// Whether the edge of halfedge `h` (of a face of patch `p`) is on its
// chart's border: no face across it, a face of another patch, or one that
// gives either end another UV (a seam inside the patch). The patch id
// across is compared unchecked: an invalid one is another patch anyway.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap>
bool on_chart_border(const TriangleMesh& tm, const FacePatchMap& face_patch_map, const UVMap& uv_map, std::size_t p,
                     typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
{
  const auto o = opposite(h, tm);
  if(is_border(o, tm) || static_cast<std::size_t>(get(face_patch_map, face(o, tm))) != p)
    return true;
  const Planar_point h_source = to_packing_point(get(uv_map, prev(h, tm)));
  const Planar_point h_target = to_packing_point(get(uv_map, h));
  const Planar_point o_source = to_packing_point(get(uv_map, prev(o, tm)));
  const Planar_point o_target = to_packing_point(get(uv_map, o));
  return !(h_source.x == o_target.x && h_source.y == o_target.y && h_target.x == o_source.x &&
           h_target.y == o_source.y);
}

template <typename TriangleMesh, typename FacePatchMap, typename UVMap, typename NamedParameters>
void collect_charts(const TriangleMesh& tm, const FacePatchMap& face_patch_map, const UVMap& uv_map,
                    bool with_surface_area, const NamedParameters& np, Chart_set<TriangleMesh>& charts)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  const std::size_t number_of_faces = static_cast<std::size_t>(std::distance(faces(tm).begin(), faces(tm).end()));
  charts.faces.clear();
  charts.patch_of.clear();
  charts.faces.reserve(number_of_faces);
  charts.patch_of.reserve(number_of_faces);
  std::size_t number_of_patches = 0;
  for(face_descriptor f : faces(tm))
  {
    const std::size_t p = checked_patch_id(get(face_patch_map, f), charts.faces.size(), number_of_faces);
    number_of_patches = (std::max)(number_of_patches, p + 1);
    charts.faces.push_back(f);
    charts.patch_of.push_back(p);
  }

  charts.first_face.assign(number_of_patches + 1, 0);
  for(std::size_t p : charts.patch_of)
    ++charts.first_face[p + 1];
  for(std::size_t p = 0; p < number_of_patches; ++p)
  {
    if(charts.first_face[p + 1] == 0)
      throw Input_error("pack_patches: " + patch_name(p) + " has no face; patch ids must be "
                        "contiguous in [0, number of patches)");
    charts.first_face[p + 1] += charts.first_face[p];
  }

  // One pass in faces(tm) order, which is also memory order for the usual
  // meshes; the corners are scattered to their patch's run.
  charts.uv_area.assign(number_of_patches, 0.);
  charts.surface_area.assign(number_of_patches, 0.);
  charts.corners.resize(3 * number_of_faces);
  charts.border_edges.resize(number_of_faces);
  charts.origin.assign(number_of_patches, Planar_point());
  std::vector<std::size_t> cursor(charts.first_face.begin(), charts.first_face.end() - 1);
  const auto coordinates_of = make_coordinates_reader(tm, np);
  // Only ratios of 3D areas matter: they are measured with the mesh's
  // bounding box brought to unit size by a power of two (exact), so that
  // coordinates of 1e150 do not overflow squared quantities (tiny charts of
  // a mesh that also has huge ones underflow, and get the floor below).
  charts.length_scale = 1.;
  if(with_surface_area)
  {
    std::array<double, 3> lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    // Ends: a face's cycle in a valid halfedge graph returns to its start.
    for(face_descriptor f : charts.faces)
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      {
        const std::array<double, 3> x = coordinates_of(target(h, tm));
        for(int k = 0; k < 3; ++k)
        {
          lo[k] = (std::min)(lo[k], x[k]);
          hi[k] = (std::max)(hi[k], x[k]);
        }
      }
    charts.length_scale = unit_scale((std::max)(hi[0] - lo[0], (std::max)(hi[1] - lo[1], hi[2] - lo[2])));
  }
  const double length_scale = charts.length_scale;
  for(std::size_t i = 0; i < number_of_faces; ++i)
  {
    const std::size_t p = charts.patch_of[i];
    const halfedge_descriptor h0 = halfedge(charts.faces[i], tm);
    const halfedge_descriptor h1 = next(h0, tm), h2 = next(h1, tm);
    if(next(h2, tm) != h0)
      throw Input_error("pack_patches: face #" + std::to_string(i) + " is not a triangle");
    if(cursor[p] == charts.first_face[p])
      charts.origin[p] = to_packing_point(get(uv_map, h0));
    charts.border_edges[cursor[p]] = static_cast<unsigned char>(
      (on_chart_border(tm, face_patch_map, uv_map, p, h1) ? 1u : 0u) |
      (on_chart_border(tm, face_patch_map, uv_map, p, h2) ? 2u : 0u) |
      (on_chart_border(tm, face_patch_map, uv_map, p, h0) ? 4u : 0u));
    Planar_point* corner = &charts.corners[3 * cursor[p]++];
    corner[0] = relative_to(to_packing_point(get(uv_map, h0)), charts.origin[p]);
    corner[1] = relative_to(to_packing_point(get(uv_map, h1)), charts.origin[p]);
    corner[2] = relative_to(to_packing_point(get(uv_map, h2)), charts.origin[p]);
    // A non-finite UV makes the patch's area non-finite, reported below.
    charts.uv_area[p] += 0.5 * planar_cross(corner[0], corner[1], corner[2]);
    if(with_surface_area)
    {
      const std::array<double, 3> x = coordinates_of(target(h0, tm));
      const std::array<double, 3> y = coordinates_of(target(h1, tm));
      const std::array<double, 3> z = coordinates_of(target(h2, tm));
      const double ux = (y[0] - x[0]) * length_scale, uy = (y[1] - x[1]) * length_scale,
                 uz = (y[2] - x[2]) * length_scale;
      const double vx = (z[0] - x[0]) * length_scale, vy = (z[1] - x[1]) * length_scale,
                 vz = (z[2] - x[2]) * length_scale;
      const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      charts.surface_area[p] += 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
    }
  }

  double total_surface_area = 0.;
  for(std::size_t p = 0; p < number_of_patches; ++p)
  {
    if(!(charts.uv_area[p] > 0.) || !std::isfinite(charts.uv_area[p]))
      throw Input_error("pack_patches: " + patch_name(p) + " has a zero, negative or non-finite UV area");
    if(with_surface_area && !std::isfinite(charts.surface_area[p]))
      throw Input_error("pack_patches: " + patch_name(p) + " has a non-finite 3D area");
    total_surface_area += charts.surface_area[p];
  }
  // At one texel density, a chart of degenerate faces would shrink to a
  // point, and one 1e-60 times smaller than the others (fuzzed coordinates)
  // below what doubles resolve. Charts under a millionth of the mean chart
  // area get that footprint instead (their UV area if the whole mesh is
  // degenerate), so that they stay valid triangle sets.
  if(with_surface_area)
  {
    const double floor_area = 1e-6 * total_surface_area / double(number_of_patches);
    for(std::size_t p = 0; p < number_of_patches; ++p)
      if(!(charts.surface_area[p] > 0.) || charts.surface_area[p] < floor_area)
        charts.surface_area[p] = floor_area > 0. ? floor_area : charts.uv_area[p];
  }
}

// Chooses every chart's frame and boxes the chart in it. The rotation is
// chosen on the convex hull of the chart's UVs; the box is then taken over
// all of them, so that it holds the chart whatever rounding did to the hull.
// Releases the corners unless the tight layout reads them.
template <typename TriangleMesh>
void frame_charts(Packing_method method, unsigned int threads, Chart_set<TriangleMesh>& charts)
{
  charts.rotation.assign(charts.size(), Packing_rotation());
  charts.box.assign(charts.size(), Packing_box());
  for_each_index(charts.size(), threads, [&](std::size_t p) {
    std::vector<Planar_point> points, hull;
    const auto begin = charts.corners.begin() + static_cast<std::ptrdiff_t>(3 * charts.first_face[p]);
    const auto end = charts.corners.begin() + static_cast<std::ptrdiff_t>(3 * charts.first_face[p + 1]);
    points.assign(begin, end);
    convex_hull(points, hull);

    Packing_rotation r;
    if(method == Packing_method::TIGHT)
      r = Packing_rotation::aligning(minimum_area_box_direction(hull));
    else
      r = Packing_rotation::aligning(minimum_square_box_direction(hull));
    Packing_box b;
    for(auto it = begin; it != end; ++it)
      b.add(r(*it));
    // Tight packing lays the longer side horizontally.
    if(method == Packing_method::TIGHT && b.height() > b.width())
    {
      r = r.quarter_turned();
      b = b.quarter_turned();
    }
    charts.rotation[p] = r;
    charts.box[p] = b;
  });
  if(method != Packing_method::TIGHT)
  {
    std::vector<Planar_point>().swap(charts.corners);
    std::vector<unsigned char>().swap(charts.border_edges);
  }
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CHART_SET_H
