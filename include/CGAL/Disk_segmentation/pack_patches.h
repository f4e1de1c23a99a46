// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PACK_PATCHES_H
#define CGAL_DISK_SEGMENTATION_PACK_PATCHES_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/parameters.h>
#include <CGAL/Disk_segmentation/internal/Canonical_parameters.h>
#include <CGAL/Disk_segmentation/internal/Chart_packer.h>
#include <CGAL/Disk_segmentation/internal/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Profile_packer.h>
#include <CGAL/Disk_segmentation/internal/Progress.h>
#include <CGAL/Disk_segmentation/internal/Raster_packer.h>
#include <CGAL/Disk_segmentation/internal/parallel.h>
#include <CGAL/Disk_segmentation/internal/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/packing_geometry.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// How `pack_patches()` places the charts in the unit square.
enum class Packing_method
{
  /// One texel density for all charts (each chart keeps its 3D size
  /// relative to the others), charts packed tightly by their shapes (or by
  /// their minimum-area rectangles when that fits better). The default.
  TIGHT,
  /// The paper's packer: a `ceil(sqrt(P)) x ceil(sqrt(P))` grid of equal
  /// square cells in patch id order, every chart rotated and scaled to fill
  /// its cell. Texel density differs from chart to chart.
  GRID
};

/// \ingroup PkgDiskSegmentationRef
/// What `pack_patches()` did.
struct Packing_report
{
  /// Number of charts (patches) placed.
  std::size_t number_of_charts = 0;
  /// Sum of the UV areas of all faces after packing over the number of
  /// pages, i.e. the covered fraction of a page, on the mean (in `[0, 1]`).
  double efficiency = 0;
  /// `Packing_method::TIGHT`: texels of the target texture per unit of 3D
  /// length, the same for all charts (the `texels_per_unit` parameter when
  /// it is given). `Packing_method::GRID`: 0.
  double texels_per_unit = 0;
  /// Number of pages (textures of `texture_resolution` texels) the charts
  /// fill: 1 unless `texels_per_unit` is given.
  std::size_t number_of_pages = 0;
  /// The page of every chart (patch id), in `[0, number_of_pages)`; each
  /// chart lies whole in the unit square of its page.
  std::vector<std::size_t> page_of_chart;
  /// Per page, the covered fraction of its square.
  std::vector<double> page_efficiency;
};

namespace internal {

struct Packing_settings
{
  Packing_method method;
  double resolution;  // the texture's width, in texels
  double height;      // its height
  double padding;     // in texels
  // Fixed texel density, charts spread over pages; 0: the largest common
  // scale that fits all charts on one page.
  double texels_per_unit = 0.;
  std::size_t max_pages = 1;
  unsigned int threads;  // 0: TBB's choice
  // Told of every trial layout, so that a cancellation stops a long
  // packing between two trials (it throws Cancelled); none if null.
  Progress* progress = nullptr;
};

// Trials of the tight packer reported to the progress callback: one for
// the rectangles, at most about eight for the profile packer and six for
// the raster packer.
constexpr std::size_t reported_packing_trials = 16;

inline void report_packing_trial(const Packing_settings& s, std::size_t& trial)
{
  if(s.progress != nullptr)
    (*s.progress)("packing", (std::min)(++trial, reported_packing_trials - 1), reported_packing_trials);
}

template <typename NamedParameters>
Packing_settings packing_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  Packing_settings s;
  s.method = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::packing_method),
                              Packing_method::TIGHT);
  if(s.method != Packing_method::TIGHT && s.method != Packing_method::GRID)
    throw Input_error("pack_patches: packing_method is not a Packing_method value");

  // Read through double so that a negative signed argument is caught rather
  // than wrapped around.
  s.resolution = static_cast<double>(count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::texture_resolution), default_texture_resolution),
    "texture_resolution"));
  if(!(s.resolution >= 1.) || !std::isfinite(s.resolution))
    throw Input_error("pack_patches: texture_resolution must be at least 1");
  s.height = s.resolution;
  if(!is_default_parameter<NamedParameters, Disk_segmentation::internal_np::texture_height_t>::value)
  {
    s.height = static_cast<double>(count_parameter(
      choose_parameter(get_parameter(np, Disk_segmentation::internal_np::texture_height), default_texture_resolution), "texture_height"));
    if(!(s.height >= 1.))
      throw Input_error("pack_patches: texture_height must be at least 1");
    if(s.height != s.resolution && s.method != Packing_method::TIGHT)
      throw Input_error("pack_patches: a non-square texture (texture_height other than texture_resolution) needs "
                        "packing_method TIGHT (the grid's cells are square)");
  }

  s.padding = static_cast<double>(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::padding_in_texels), default_padding_in_texels));
  if(!(s.padding >= 0.) || !std::isfinite(s.padding))
    throw Input_error("pack_patches: padding_in_texels must be a finite number >= 0");
  if(!(2. * s.padding < (std::min)(s.resolution, s.height)))
    throw Input_error(std::string("pack_patches: padding_in_texels leaves no room: twice the padding must be "
                                  "less than ") + (s.height < s.resolution ? "texture_height" : "texture_resolution"));
  s.texels_per_unit = static_cast<double>(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::texels_per_unit), 0.));
  if(!(s.texels_per_unit >= 0.) || !std::isfinite(s.texels_per_unit))
    throw Input_error("pack_patches: texels_per_unit must be a finite number >= 0 (0: fit one page)");
  if(s.texels_per_unit > 0. && s.method != Packing_method::TIGHT)
    throw Input_error("pack_patches: texels_per_unit needs packing_method TIGHT (the grid scales every chart to "
                      "its cell)");
  s.max_pages = count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_number_of_pages), default_max_number_of_pages),
    "max_number_of_pages");
  if(s.max_pages == 0)
    throw Input_error("pack_patches: max_number_of_pages must be at least 1");
  if(s.texels_per_unit == 0.)
    s.max_pages = 1;
  s.threads = number_of_threads_parameter(np);
  return s;
}

// The page's height over its width: in units of the width, a page is
// [0, 1] x [0, aspect].
inline double page_aspect(const Packing_settings& s) { return s.height / s.resolution; }

// "1024 texels" or "2048 x 1024 texels".
inline std::string texture_size(const Packing_settings& s)
{
  std::ostringstream text;
  text << s.resolution;
  if(s.height != s.resolution)
    text << " x " << s.height;
  text << " texels";
  return text.str();
}

// The most charts the padding leaves room for, at any scale. TIGHT: the
// rectangles, grown by the padding on their right and top and so larger
// than pad x pad, fill [pad, 1] x [pad, aspect]: fewer than
// ((1 - pad) / pad) ((aspect - pad) / pad) of them (an area bound: what the
// packer finds may be less). GRID: a cell of a c x c grid is (1 - pad) / c
// wide and keeps pad inside around a chart of positive size:
// c < (1 - pad) / pad.
inline double packing_capacity(const Packing_settings& s)
{
  const double pad = s.padding / s.resolution;
  if(!(pad > 0.))
    return std::numeric_limits<double>::infinity();
  const double across = (1. - pad) / pad;
  if(s.method == Packing_method::GRID)
  {
    const double columns = std::ceil(across) - 1.;
    return columns > 0. ? columns * columns : 0.;
  }
  return std::ceil(across * ((page_aspect(s) - pad) / pad)) - 1.;
}

// Throws when `number_of_charts` cannot be packed at any scale, before the
// work that would have found it out.
inline void check_packing_capacity(const Packing_settings& s, std::size_t number_of_charts)
{
  const double capacity = packing_capacity(s) * static_cast<double>(s.max_pages);
  if(static_cast<double>(number_of_charts) <= capacity)
    return;
  std::ostringstream message;
  message << "pack_patches: padding_in_texels (" << s.padding << ") is too large to place " << number_of_charts
          << " charts on a texture of " << texture_size(s) << " (texture_resolution): it leaves room for "
          << static_cast<std::size_t>(capacity) << " at most";
  if(s.max_pages > 1)
    message << " on " << s.max_pages << " pages (max_number_of_pages)";
  throw Input_error(message.str());
}

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
Packing_point to_packing_point(const UVPoint& p)
{
  return { CGAL::to_double(p.x()), CGAL::to_double(p.y()) };
}

inline Packing_point relative_to(const Packing_point& p, const Packing_point& origin)
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
  std::vector<Packing_point> corners;
  // Per face, in the order of `corners`: bit j is set when the edge from
  // corner j to corner j + 1 is on its chart's border (the next face is in
  // another patch or none, or the two faces give its ends different UVs).
  std::vector<unsigned char> border_edges;
  // Corners are stored relative to their chart's first UV: a chart 1e-13
  // wide placed at 0.45 would otherwise lose its shape to cancellation
  // when it is moved to its place.
  std::vector<Packing_point> origin;
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
  const Packing_point h_source = to_packing_point(get(uv_map, prev(h, tm)));
  const Packing_point h_target = to_packing_point(get(uv_map, h));
  const Packing_point o_source = to_packing_point(get(uv_map, prev(o, tm)));
  const Packing_point o_target = to_packing_point(get(uv_map, o));
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
  charts.origin.assign(number_of_patches, Packing_point());
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
    Packing_point* corner = &charts.corners[3 * cursor[p]++];
    corner[0] = relative_to(to_packing_point(get(uv_map, h0)), charts.origin[p]);
    corner[1] = relative_to(to_packing_point(get(uv_map, h1)), charts.origin[p]);
    corner[2] = relative_to(to_packing_point(get(uv_map, h2)), charts.origin[p]);
    // A non-finite UV makes the patch's area non-finite, reported below.
    charts.uv_area[p] += 0.5 * packing_cross(corner[0], corner[1], corner[2]);
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
    std::vector<Packing_point> points, hull;
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
    std::vector<Packing_point>().swap(charts.corners);
    std::vector<unsigned char>().swap(charts.border_edges);
  }
}

// Cells of at least one texel, at most 512 across: each trial costs the
// columns times the charts' widths in cells.
// Measured on 10 meshes of CGAL's data: 256 columns pack 0.551 of the
// square (median), 512 0.594, 1024 0.588 at 2.4 times the time of 512.
inline std::size_t shape_columns(const Packing_settings& s)
{
  return (std::min)(std::size_t(512), static_cast<std::size_t>(s.resolution));
}

// The page's rows of square cells (its height over a cell's side, rounded
// down: a partial row is left empty).
inline std::size_t shape_rows(const Packing_settings& s, std::size_t columns)
{
  return (std::max)(std::size_t(1),
                    static_cast<std::size_t>(std::floor(page_aspect(s) * double(columns) * (1. + 1e-12))));
}

// The padding in whole cells, rounded up.
inline std::size_t shape_pad_cells(const Packing_settings& s, std::size_t columns)
{
  return (std::max)(std::size_t(1), static_cast<std::size_t>(std::ceil(s.padding * double(columns) / s.resolution)));
}

// The charts as the shape packers read them. Not copyable: `charts` points
// into the other members.
struct Shape_input
{
  std::vector<Packing_point> framed;  // corners in the chart's frame
  std::vector<unsigned char> border_edges;
  std::vector<Profile_chart> charts;
  double total_area = 0.;  // of the charts at one UV unit per unit of length

  template <typename TriangleMesh>
  Shape_input(const Chart_set<TriangleMesh>& set, const std::vector<double>& density)
  {
    const std::size_t n = set.size();
    framed.reserve(set.corners.size());
    border_edges.reserve(set.corners.size() / 3);
    charts.resize(n);
    std::vector<std::size_t> first_corner(1, 0);  // of each chart in `framed`, and the end
    for(std::size_t p = 0; p < n; ++p)
    {
      // Only the triangles with an edge on the border: a chart's lowest and
      // highest point over any vertical slab lie on its border, and its
      // border bounds the cells it covers (about the square root of the
      // chart's triangles).
      for(std::size_t i = set.first_face[p]; i < set.first_face[p + 1]; ++i)
      {
        if(set.border_edges[i] == 0)
          continue;
        for(std::size_t j = 0; j < 3; ++j)
          framed.push_back(set.rotation[p](set.corners[3 * i + j]));
        border_edges.push_back(set.border_edges[i]);
      }
      first_corner.push_back(framed.size());
      charts[p].density = density[p];
      charts[p].area = set.uv_area[p];
      total_area += density[p] * density[p] * set.uv_area[p];
    }
    for(std::size_t p = 0; p < n; ++p)
    {
      charts[p].corners = framed.data() + first_corner[p];
      charts[p].border_edges = border_edges.data() + first_corner[p] / 3;
      charts[p].number_of_corners = first_corner[p + 1] - first_corner[p];
    }
  }
  Shape_input(const Shape_input&) = delete;
  Shape_input& operator=(const Shape_input&) = delete;
};

// The similarities of the charts placed by a shape packer at `scale`.
template <typename TriangleMesh>
std::vector<Chart_similarity> shape_similarities(const Chart_set<TriangleMesh>& charts,
                                                 const std::vector<Profile_placement>& placement,
                                                 const std::vector<double>& density, double scale)
{
  std::vector<Chart_similarity> result(charts.size());
  for(std::size_t p = 0; p < charts.size(); ++p)
  {
    Chart_similarity& sim = result[p];
    sim.rotation = charts.rotation[p];
    Packing_box b = charts.box[p];
    for(int t = 0; t < placement[p].turns; ++t)
    {
      sim.rotation = sim.rotation.quarter_turned();
      b = b.quarter_turned();
    }
    if(placement[p].diagonal)
    {
      sim.rotation = sim.rotation.eighth_turned();
      b = Packing_box();
      for(std::size_t k = 3 * charts.first_face[p]; k < 3 * charts.first_face[p + 1]; ++k)
        b.add(sim.rotation(charts.corners[k]));
    }
    sim.scale = scale * density[p];
    sim.tx = placement[p].x - sim.scale * b.xmin;
    sim.ty = placement[p].y - sim.scale * b.ymin;
  }
  return result;
}

// Above this many charts only the raster packer runs; its search starts at
// this multiple of the rectangles' scale (see shape_layout()).
constexpr std::size_t profile_packer_max_charts = 64;
constexpr double raster_start_over_rectangles = 1.2;

// The better of the two shape packers' layouts (profile, then raster) at
// the largest scale each reaches, if that is above `rectangle_scale` (the
// rectangle packing's); else an empty vector.
template <typename TriangleMesh>
std::vector<Chart_similarity> shape_layout(const Chart_set<TriangleMesh>& charts, const Packing_settings& s,
                                             const std::vector<double>& density, double rectangle_scale,
                                             double& global_scale)
{
  const std::size_t n = charts.size();
  const std::size_t columns = shape_columns(s);
  const std::size_t pad_cells = shape_pad_cells(s, columns);
  const Shape_input shapes(charts, density);
  const std::vector<Profile_chart>& input = shapes.charts;
  const double total = shapes.total_area;
  const std::size_t rows = shape_rows(s, columns);
  const double hi = total > 0. ? std::sqrt(page_aspect(s) / total) : rectangle_scale;
  std::size_t trial = 0;  // reported, after the rectangles' (see report_packing_trial())

  // The profile packer's largest scale in [rectangle_scale, hi) at which
  // every chart fits, to 1 percent (about seven trials), and its
  // placements; 0 if it does not fit them at rectangle_scale. Measured on
  // 90 atlases (30 meshes, 3 bounds): the same UV area as to 0.2 percent on
  // the mean, 10 % less packing time.
  auto profile_search = [&](std::vector<Profile_placement>& best) {
    Profile_packer packer(columns, pad_cells, rows);
    packer.set_parallel(s.threads != 1);
    std::vector<Profile_placement> placement;
    double lo = rectangle_scale, top = hi;
    report_packing_trial(s, trial);
    if(!(top > lo) || !packer.run(input, lo, placement))
      return 0.;
    best.swap(placement);
    while(top - lo > 1e-2 * lo)
    {
      const double mid = 0.5 * (lo + top);
      report_packing_trial(s, trial);
      if(packer.run(input, mid, placement))
      {
        lo = mid;
        best.swap(placement);
      }
      else
        top = mid;
    }
    return lo;
  };

  // The rows a raster packing uses grow about as the square of the scale:
  // each trial aims at the scale that would just fill the square, then
  // bisection between the best fit and the smallest failure, to 1 percent
  // (4 to 6 trials on 10 meshes of CGAL's data). It starts from the
  // profile packer's scale and gives up if it cannot reach it. Without
  // the profile packer (many charts), it starts 20 % above the rectangles'
  // scale, about where it ends, and a failure only aims lower.
  auto raster_search = [&](double profile_scale, std::vector<Profile_placement>& best) {
    Raster_packer packer(columns, pad_cells, rows);
    packer.set_parallel(s.threads != 1);
    std::vector<Profile_placement> placement;
    const bool after_profile = profile_scale > 0.;
    double fit = 0., fail = hi;
    double scale = after_profile ? (std::max)(profile_scale, rectangle_scale)
                                 : (std::min)(hi, raster_start_over_rectangles * rectangle_scale);
    const double target = double(rows);
    const double tol = 0.01;
    const int max_trials = 6;
    for(int raster_trial = 0; raster_trial < max_trials && fail > fit * (1. + tol); ++raster_trial)
    {
      report_packing_trial(s, trial);
      const bool packed = packer.run(input, scale, placement);
      const double used = double(packer.used_rows());
      if(packed)
      {
        fit = scale;
        best.swap(placement);
      }
      else if(fit == 0. && after_profile)
        break;
      else
        fail = (std::min)(fail, scale);
      double next = used > 0. ? scale * std::sqrt(target / used) : 0.;
      if(packed && !(next > fit * (1. + 0.5 * tol)))
        next = fit * (1. + tol);
      // Before any fit, bisect from the rectangles' scale, which every chart
      // fits: a trial where some chart is wider than the square at any turn
      // (a long chart) says nothing about the rows.
      if(!(next > fit) || !(next < fail))
        next = 0.5 * ((fit > 0. ? fit : rectangle_scale) + fail);
      scale = next;
    }
    return fit;
  };

  // With many charts the raster packer alone packs as much (30 meshes,
  // above 64 charts: -0.019 to +0.008 of the square, median +0.001) in
  // 0.4-0.7 of the time (ChineseDragon-10kv 256 charts, b9_mesh 455,
  // cheese 922); with few, the profile packer's layout or scale often wins
  // (anchor +0.135, head +0.090). The two searches could run side by side
  // if the raster one did not start from the profile packer's scale; on 30
  // atlases that took 1.06 times the packing time with one thread, 0.8
  // with two, for the same median UV area. Within each search, the turns
  // of each chart run side by side.
  std::vector<Profile_placement> best, raster_best;
  double lo = 0.;
  within_arena(s.threads, [&] {
    if(n <= profile_packer_max_charts)
      lo = profile_search(best);
    const double fit = raster_search(lo, raster_best);
    if(fit > lo)
    {
      lo = fit;
      best.swap(raster_best);
    }
  });
  if(!(lo > rectangle_scale * (1. + 1e-3)))
    return std::vector<Chart_similarity>();
  global_scale = lo;
  return shape_similarities(charts, best, density, lo);
}

// Extra gap, in UV units, on top of the requested padding, that absorbs the
// rounding of the final similarity (coordinates are at most 1).
constexpr double packing_rounding_margin = 1e-12;

// The layout at the fixed density `s.texels_per_unit`: pages are filled
// one after the other by the raster packer, each with the charts left that
// fit on it, largest first; `page_of_chart` says where each went.
template <typename TriangleMesh>
std::vector<Chart_similarity> paged_layout(const Chart_set<TriangleMesh>& charts, const Packing_settings& s,
                                           const std::vector<double>& density, double& global_scale,
                                           std::vector<std::size_t>& page_of_chart)
{
  const std::size_t n = charts.size();
  // Texels per unit of the input's length = scale * resolution * length_scale.
  const double scale = s.texels_per_unit / (s.resolution * charts.length_scale);
  global_scale = scale;
  const Shape_input shapes(charts, density);
  // Pages never hold more than their area: a quick "no" before any packing.
  const double least_pages = shapes.total_area * scale * scale / page_aspect(s);
  auto too_many_pages = [&] {
    std::ostringstream message;
    message << "pack_patches: at texels_per_unit " << s.texels_per_unit << " the charts need more than "
            << s.max_pages << " pages of " << texture_size(s) << " (max_number_of_pages); lower "
            << "texels_per_unit or raise texture_resolution or max_number_of_pages";
    return Input_error(message.str());
  };
  if(!(least_pages <= static_cast<double>(s.max_pages)))
    throw too_many_pages();

  const std::size_t columns = shape_columns(s);
  Raster_packer packer(columns, shape_pad_cells(s, columns), shape_rows(s, columns));
  packer.set_parallel(s.threads != 1);
  std::vector<Profile_placement> placement(n), on_page;
  std::vector<bool> placed;
  std::vector<std::size_t> left = largest_first(shapes.charts), still_left;
  page_of_chart.assign(n, 0);
  std::size_t trial = 0;
  for(std::size_t page = 0; !left.empty(); ++page)
  {
    if(page == s.max_pages)
      throw too_many_pages();
    report_packing_trial(s, trial);
    std::size_t count = 0;
    within_arena(s.threads, [&] { count = packer.fill_page(shapes.charts, left, scale, on_page, placed); });
    if(count == 0)
    {
      // None of them fits an empty page: the largest is named.
      const std::size_t p = left.front();
      const double to_texels = scale * density[p] * s.resolution;
      std::ostringstream message;
      message << "pack_patches: at texels_per_unit " << s.texels_per_unit << ", " << patch_name(p) << " is "
              << std::ceil(charts.box[p].width() * to_texels) << " x "
              << std::ceil(charts.box[p].height() * to_texels) << " texels and does not fit a page of "
              << texture_size(s) << " (texture_resolution) with padding_in_texels " << s.padding
              << "; lower texels_per_unit or raise texture_resolution";
      throw Input_error(message.str());
    }
    still_left.clear();
    for(std::size_t i : left)
      if(placed[i])
      {
        placement[i] = on_page[i];
        page_of_chart[i] = page;
      }
      else
        still_left.push_back(i);
    left.swap(still_left);
  }
  return shape_similarities(charts, placement, density, scale);
}

template <typename TriangleMesh>
std::vector<Chart_similarity> tight_layout(const Chart_set<TriangleMesh>& charts, const Packing_settings& s,
                                           double& global_scale, std::vector<std::size_t>& page_of_chart)
{
  const std::size_t n = charts.size();
  const double pad = s.padding / s.resolution + packing_rounding_margin;
  // Sizes at one UV unit per 3D unit of length.
  std::vector<double> density(n), w(n), h(n);
  for(std::size_t p = 0; p < n; ++p)
  {
    density[p] = std::sqrt(charts.surface_area[p] / charts.uv_area[p]);
    w[p] = density[p] * charts.box[p].width();
    h[p] = density[p] * charts.box[p].height();
  }
  if(s.texels_per_unit > 0.)
    return paged_layout(charts, s, density, global_scale, page_of_chart);
  page_of_chart.assign(n, 0);
  // Rectangles grown by the padding on their right and top fill [pad, 1]^2:
  // this leaves the padding between any two of them and along every side.
  const Square_packing packing = pack_in_rectangle(w, h, pad, 1. - pad, page_aspect(s) - pad);
  if(!(packing.scale > 0.))
  {
    std::ostringstream message;
    message << "pack_patches: padding_in_texels (" << s.padding << ") is too large to place " << n
            << " charts on a texture of " << texture_size(s);
    throw Input_error(message.str());
  }
  global_scale = packing.scale;
  // The chart shapes often nest better than their rectangles.
  {
    std::vector<Chart_similarity> shaped = shape_layout(charts, s, density, packing.scale, global_scale);
    if(!shaped.empty())
      return shaped;
  }

  std::vector<Chart_similarity> result(n);
  for(std::size_t p = 0; p < n; ++p)
  {
    const Packed_rectangle& rect = packing.rectangles[p];
    Chart_similarity& sim = result[p];
    sim.rotation = charts.rotation[p];
    Packing_box b = charts.box[p];
    if(rect.rotated)
    {
      sim.rotation = sim.rotation.quarter_turned();
      b = b.quarter_turned();
    }
    sim.scale = packing.scale * density[p];
    sim.tx = pad + rect.x - sim.scale * b.xmin;
    sim.ty = pad + rect.y - sim.scale * b.ymin;
  }
  return result;
}

template <typename TriangleMesh>
std::vector<Chart_similarity> grid_layout(const Chart_set<TriangleMesh>& charts, const Packing_settings& s)
{
  const std::size_t n = charts.size();
  // A step or two each: the double square root is within one of the integer one.
  std::size_t columns = static_cast<std::size_t>(std::sqrt(static_cast<double>(n)));
  while(columns * columns < n) ++columns;
  while(columns > 1 && (columns - 1) * (columns - 1) >= n) --columns;

  // Cells tile [pad/2, 1 - pad/2]^2 and every chart keeps pad/2 inside its
  // cell: charts are pad apart from each other and from the sides.
  const double pad = s.padding / s.resolution + packing_rounding_margin;
  const double cell = (1. - pad) / static_cast<double>(columns);
  const double room = cell - pad;
  if(!(room > 0.))
  {
    std::ostringstream message;
    message << "pack_patches: padding_in_texels (" << s.padding << ") is too large for a grid of " << columns
            << " x " << columns << " cells on a texture of " << s.resolution << " texels";
    throw Input_error(message.str());
  }

  std::vector<Chart_similarity> result(n);
  for(std::size_t p = 0; p < n; ++p)
  {
    const Packing_box& b = charts.box[p];
    Chart_similarity& sim = result[p];
    sim.rotation = charts.rotation[p];
    sim.scale = room / (std::max)(b.width(), b.height());
    const double cx = 0.5 * pad + (static_cast<double>(p % columns) + 0.5) * cell;
    const double cy = 0.5 * pad + (static_cast<double>(p / columns) + 0.5) * cell;
    sim.tx = cx - sim.scale * 0.5 * (b.xmin + b.xmax);
    sim.ty = cy - sim.scale * 0.5 * (b.ymin + b.ymax);
  }
  return result;
}

} // namespace internal

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

/// \ingroup PkgDiskSegmentationRef
///
/// Places the UV charts of the patches of `tm` in the unit square without
/// overlap: every chart is moved by one similarity of its own (uniform scale,
/// rotation and translation, never a reflection, so the winding of its faces
/// is kept), all charts end inside \f$ [0,1]^2 \f$, and any two charts, and
/// a chart and the sides of the square, are at least
/// `padding_in_texels / texture_resolution` apart.
///
/// With `Packing_method::TIGHT` (the default), every chart is first scaled by
/// \f$ \sqrt{A_{3D} / A_{UV}} \f$ so that all have the same texel density,
/// rotated so that its minimum-area bounding rectangle (rotating calipers on
/// the convex hull of its UVs) is axis-aligned with its longer side
/// horizontal, and the rectangles are packed by a best-fit skyline packer
/// (each step fills the lowest gap with the widest rectangle that fits it),
/// which may turn a rectangle by a quarter turn to fill a gap. A search
/// guided by each trial's packing density, then bisection, finds the largest
/// common scale (to 0.05 percent) at which the packing fits in the square;
/// the padding, fixed in texels, does not scale with the charts. Then the
/// chart shapes are packed (not ours in the paper, nor a rectangle packer):
/// on a grid of at most 512 cells across, each chart in each of its four
/// quarter turns is reduced to the lowest and highest cell it covers in
/// every column, and charts are dropped, largest first, onto the skyline of
/// those already placed where their top ends lowest (plus 5 % of the cells
/// they leave empty below), so that jagged charts nest into each other's
/// dents; bisection finds the largest scale at which that fits (only for
/// 64 charts or fewer: with more, the raster packer alone packs as much in
/// less time). Then the
/// shapes are packed again with their holes (the raster packer, ours): on
/// the same grid, each chart in each of its eight orientations (eighths of
/// a turn; four quarter turns for charts under 400 cells, two for those
/// under 100) becomes the set of cells it touches (its border triangles
/// rasterized, its inside filled by crossing parity), and charts are
/// placed, largest first, where their top ends lowest (then lowest, then
/// leftmost) among the positions where that set grown by the padding meets
/// no cell already taken, so that small charts fill the holes under and
/// inside large ones and long charts may lie along a diagonal; each trial
/// aims at the scale at which the rows used would just fill the square, to
/// 1 percent, in at most six trials, starting 20 % above the rectangles'
/// scale, or from the profile packer's scale if that ran. The best of the three
/// layouts (rectangles, profile, raster) is kept; on a tie, the earlier
/// one. Padding is rounded up to whole cells. With TBB and
/// `number_of_threads` other than 1, the orientations of a chart are
/// profiled or rasterized and searched side by side; the layout is the same
/// for any number of threads.
///
/// With `texels_per_unit` given (`TIGHT` only, not in the paper), the scale
/// is not searched: every chart gets that texel density, and pages are
/// filled one after the other by the raster packer, each with the charts
/// left that fit on it, largest first (the xatlas and UVAtlas "atlas
/// count"). Each chart lies whole in the unit square of its page;
/// `Packing_report::page_of_chart` says which page that is. A chart that
/// does not fit an empty page, or more pages than `max_number_of_pages`,
/// throws `Input_error` naming the chart's size in texels.
///
/// With `Packing_method::GRID` (the paper's packer), chart `i` goes to cell
/// `i` of a `ceil(sqrt(P)) x ceil(sqrt(P))` grid of equal square cells, row by
/// row from the bottom left (the UV origin). Each chart is turned by the
/// rotation that lets it be scaled largest in a square (found exactly over
/// the convex hull: edge directions and the angles where width equals
/// height), scaled to fill its cell less the padding, and centered.
///
/// The result is deterministic: it depends only on the input, in the order of
/// `faces(tm)`. Time is \f$ O(N \log N) \f$ for the \f$ N = 3F \f$ UV corners
/// of the `F` faces plus, for
/// `TIGHT`, \f$ O(P \log P) \f$ per trial rectangle packing (typically under
/// ten) and, per trial profile packing (about ten), the cells the charts
/// cross plus 4 times 512 times the sum of the charts' widths in cells; per
/// raster trial (at most six), per chart and orientation, the rows of the
/// strip below the chart's position times the free runs it crosses there.
/// Memory is \f$ O(N + P) \f$: the corners are copied once, grouped by chart.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeGraph` whose
///         faces are triangles
/// @tparam FacePatchMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
///         an integral value type
/// @tparam UVMap a model of `ReadWritePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type
///         and a 2D point as value type (with `x()`, `y()` and a constructor
///         from two `double`s, e.g. `Kernel::Point_2`)
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param tm a triangle mesh
/// @param face_patch_map the patch id of every face, contiguous in
///        `[0, P)`, as written by `segment_into_disks()`
/// @param uv_map per-corner UVs: `uv_map[h]` is the UV of `target(h)` as seen
///        from `face(h)`; halfedges without a face are neither read nor
///        written. On entry, the charts may have any position, scale and
///        rotation, but every face must have a positive signed UV area
///        (counterclockwise); on return they are packed. Each halfedge must
///        hold its own value (a map that shares storage between halfedges,
///        e.g. one that reads per vertex, would be moved twice).
/// @param np an optional sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{packing_method}
///     \cgalParamDescription{how the charts are placed}
///     \cgalParamType{`Packing_method`}
///     \cgalParamDefault{`Packing_method::TIGHT`}
///   \cgalParamNEnd
///   \cgalParamNBegin{texture_resolution}
///     \cgalParamDescription{side, in texels, of the texture the atlas is made for}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`1024`}
///     \cgalParamExtra{must be at least 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{texture_height}
///     \cgalParamDescription{`TIGHT` only: height, in texels, of a non-square texture; `texture_resolution` is
///       then its width. The UVs still span the unit square (each page's), so that a chart is a similar copy of
///       its parameterization in texels, stretched by `texture_height / texture_resolution` in \f$ v \f$ relative to
///       \f$ u \f$ in UV units}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`texture_resolution`}
///     \cgalParamExtra{must be at least 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{padding_in_texels}
///     \cgalParamDescription{gap kept between the charts' bounding rectangles and along the sides of the square, in texels}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`2`}
///     \cgalParamExtra{must be finite, >= 0 and less than half of `texture_resolution`}
///   \cgalParamNEnd
///   \cgalParamNBegin{texels_per_unit}
///     \cgalParamDescription{`TIGHT` only: texels of the target texture per unit of 3D length, fixed. The charts
///       are then spread over as many pages (textures of `texture_resolution` texels, each the unit square of
///       its own UVs) as they need; 0: the largest density that fits all charts on one page}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`}
///     \cgalParamExtra{must be finite and >= 0}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_number_of_pages}
///     \cgalParamDescription{most pages a fixed `texels_per_unit` may fill; more throws `Input_error`}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`64`}
///     \cgalParamExtra{must be at least 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{maximum number of threads of the `TIGHT` packing (0: TBB's choice; 1: sequential). Without TBB, sequential.}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called as `("packing", trial, 16)` before each trial layout of the `TIGHT`
///       packing; a `false` result stops it with `Cancelled` before any UV is written}
///     \cgalParamType{a callable of `(const std::string&, std::size_t, std::size_t)` returning `bool` or `void`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm` (3D areas of `TIGHT`)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key type and the traits' `Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class, used only to read coordinates: they are converted with `CGAL::to_double()` and all computation runs in `double` whatever the kernel}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @return a `Packing_report`; a mesh without faces gives 0 charts and leaves
///         `uv_map` untouched
///
/// @throws Input_error if a parameter is out of range, a face is not a
///         triangle, a patch id is out of range or a patch has no face, a
///         patch has a zero, negative or non-finite UV area (or, for `TIGHT`,
///         a non-finite 3D area), or the padding leaves no room for all
///         charts, or (with `texels_per_unit`) a chart is larger than a page or
///         the charts need more than `max_number_of_pages` pages. `uv_map` is
///         not written then. A `TIGHT` chart whose 3D area
///         is zero (degenerate faces) or below a millionth of the mean chart
///         area is not an error: it is given the size of a chart of a
///         millionth of the mean chart area.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Packing_report pack_patches(const TriangleMesh& tm,
                            FacePatchMap face_patch_map,
                            UVMap uv_map,
                            const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  internal::Progress progress = internal::Progress::from(np);
  internal::Packing_settings settings = internal::packing_settings(np);
  settings.progress = &progress;
  // The coordinates are read through a chain of the mesh's maps only: one
  // instantiation for any chain of values.
  return internal::pack_checked_patches(tm, internal::checked_patch_map<TriangleMesh>(face_patch_map),
                                        internal::checked_uv_map<TriangleMesh>(uv_map), settings,
                                        internal::forward_mesh_parameters(np, parameters::default_values()));
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PACK_PATCHES_H
