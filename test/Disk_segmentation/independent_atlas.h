// Test support: an independent checker of texture atlases (per-corner UVs on a
// triangle mesh partitioned into charts), and a minimal OBJ reader.
//
// This file is deliberately independent of the Disk_segmentation library: it
// must not include any <CGAL/Disk_segmentation/...> header.
//
// Data being checked
//   * a triangle mesh tm (any CGAL FaceListGraph with a vertex_point map,
//     e.g. Surface_mesh<Epick::Point_3> or Polyhedron_3<Epick>);
//   * patch: face -> std::size_t, ids expected to be contiguous 0..P-1;
//   * uv: halfedge -> Point_2, uv[h] = UV of target(h) as seen from face(h).
//
// Everything is first copied into an Atlas_soup (per face: 3 corners in the
// order halfedge(f), next, next-next; corner k is the target of the k-th
// halfedge; "edge k" of a face is that halfedge, from corner (k+2)%3 to
// corner k). All checks then run on the soup, so OBJ files can be checked
// the same way (check_obj_atlas).
//
// Definitions (those of the manual's Quality Metrics section and of
// Atlas_quality in atlas_quality.h, restated here for the checker)
//   corners_non_finite          corners (face, k) with a NaN/inf coordinate.
//   corners_outside_unit_square finite corners outside [-1e-9, 1+1e-9]^2.
//   flipped                     faces whose UV corners, in face order, make a
//                               clockwise turn (exact orientation predicate).
//   degenerate                  faces whose UV corners are exactly collinear,
//                               or with |det J| <= 1e-12 * mean |det J|, where
//                               det J = signed UV area / 3D area and the mean
//                               runs over faces with finite UVs and non-zero 3D
//                               area. A face may be both flipped and degenerate.
//   Faces with a non-finite UV corner take part in no geometric test below
//   (only in corners_non_finite); faces with zero 3D area are counted in
//   faces_zero_3d_area (informational) instead of in `degenerate`.
//   inconsistent_corners        for every edge whose two faces are in the same
//                               chart, each endpoint whose UVs differ (exact
//                               comparison) in the two faces counts one (an
//                               edge counts 0, 1 or 2).
//   charts_with_bad_border      border segment of a chart = edge of a chart
//                               face whose other side has no face or a face of
//                               another chart, taken in UV from the face's own
//                               corners. The chart is bad unless: all border
//                               UVs are finite; segments chain (by exact UV
//                               equality of end -> start) into exactly one
//                               closed loop of >= 3 segments, each UV point
//                               being the start of one segment and the end of
//                               one; consecutive segments do not fold back
//                               onto each other; non-consecutive segments do
//                               not intersect at all (not even touch). A chart
//                               without border (closed) is bad, an annulus is
//                               bad, a pinched border is bad.
//   overlapping_chart_pairs     unordered pairs {A, B} of charts whose UV
//                               regions (bounded by their border loops)
//                               share interior points. Found, for charts with
//                               overlapping bounding boxes, by: a border
//                               segment of A properly crossing one of B (the
//                               interiors cross at one point); or a border
//                               vertex of A strictly inside B (winding number
//                               != 0 and not on B's border); or a border
//                               segment of A, cut at the vertices of B lying
//                               on it, having an open piece whose exact
//                               midpoint is strictly inside B (chords and
//                               collinear runs through B); or the exact
//                               centroid of A's largest non-degenerate UV
//                               triangle strictly inside B (identical
//                               charts); and the same with A and B swapped.
//                               For simple borders and unfolded charts this
//                               is exact (touching charts are not counted).
//                               "Inside B" is only tested when B's border is
//                               finite and closed (every UV point starts as
//                               many segments as end there), so an annulus
//                               chart's hole is correctly outside it.
//   texel_overlaps              texel centres ((i+0.5)/R, (j+0.5)/R), i, j in
//                               [0, R), covered by triangles of two or more
//                               different charts.
//   same_chart_texel_overlaps   texel centres covered twice by one chart
//                               (a fold, or flipped triangles).
//   Coverage uses a top-left-style fill rule: a centre strictly inside a
//   triangle is covered, one exactly on an edge only by the triangle on one
//   fixed side of that edge, so that two triangles sharing an edge (in the
//   same chart, or two abutting charts) never both cover it. Non-finite and
//   exactly collinear UV triangles cover nothing; flipped triangles cover
//   their area like the others.
//   empty_patch_ids             ids in [0, max id] that no face carries.
//
// ok() is true iff every counter listed above is zero (the informational
// fields number_of_*, faces_zero_3d_area are not part of it).
//
// Predicates: CGAL Epick orientation (exact) on the double UVs; Epeck only
// for the constructed midpoints and centroids above; a Shewchuk-style static
// filter with exact fallback in the rasterizer. No test depends on a
// tolerance except corners_outside_unit_square and `degenerate`.
//
// Cost: O(F log F) for the mesh copy, border chaining with std::map, a
// uniform grid over all border segments for the segment-pair tests (pairs
// are tested once, in the lowest grid cell their bounding boxes share), a
// sweep over chart bounding boxes plus per-chart y-buckets for the
// point-in-chart tests, and per-row spans (binary search of each edge's
// switch point, exact) for the texel counts. 100k faces / 1000 charts /
// R = 1024: about 0.25 s at -O1. Pathological input (all charts stacked on
// each other) is quadratic in the number of charts: a few seconds for 1000.

#ifndef DISK_SEGMENTATION_TEST_SUPPORT_INDEPENDENT_ATLAS_H
#define DISK_SEGMENTATION_TEST_SUPPORT_INDEPENDENT_ATLAS_H

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace test_support {

constexpr std::size_t atlas_npos = std::size_t(-1);

struct Atlas_report
{
  std::size_t corners_non_finite = 0, corners_outside_unit_square = 0;
  std::size_t flipped = 0, degenerate = 0;
  std::size_t charts_with_bad_border = 0;
  std::size_t inconsistent_corners = 0;
  std::size_t overlapping_chart_pairs = 0;
  std::size_t texel_overlaps = 0;
  std::size_t same_chart_texel_overlaps = 0;
  std::size_t empty_patch_ids = 0;

  // Informational (not part of ok()).
  std::size_t number_of_faces = 0;
  std::size_t number_of_charts = 0;          // max patch id + 1 (0 without faces)
  std::size_t number_of_border_segments = 0;
  std::size_t faces_zero_3d_area = 0;
  unsigned resolution = 0;                   // texel resolution used (0: texel test skipped)
  std::vector<std::size_t> bad_border_charts;                            // sorted ids
  std::vector<std::pair<std::size_t, std::size_t> > overlapping_pairs;  // sorted, first < second

  bool ok() const
  {
    return corners_non_finite == 0 && corners_outside_unit_square == 0 && flipped == 0 && degenerate == 0 &&
           charts_with_bad_border == 0 && inconsistent_corners == 0 && overlapping_chart_pairs == 0 &&
           texel_overlaps == 0 && same_chart_texel_overlaps == 0 && empty_patch_ids == 0;
  }

  std::string summary() const
  {
    std::ostringstream s;
    s << (ok() ? "atlas OK" : "atlas NOT ok") << ": faces=" << number_of_faces << " charts=" << number_of_charts
      << " border_segments=" << number_of_border_segments << " | corners_non_finite=" << corners_non_finite
      << " corners_outside_unit_square=" << corners_outside_unit_square << " flipped=" << flipped
      << " degenerate=" << degenerate << " charts_with_bad_border=" << charts_with_bad_border;
    if(!bad_border_charts.empty())
    {
      s << " [";
      for(std::size_t i = 0; i < bad_border_charts.size() && i < 10; ++i)
        s << (i ? " " : "") << bad_border_charts[i];
      s << (bad_border_charts.size() > 10 ? " ...]" : "]");
    }
    s << " inconsistent_corners=" << inconsistent_corners << " overlapping_chart_pairs=" << overlapping_chart_pairs;
    if(!overlapping_pairs.empty())
    {
      s << " [";
      for(std::size_t i = 0; i < overlapping_pairs.size() && i < 10; ++i)
        s << (i ? " " : "") << "(" << overlapping_pairs[i].first << "," << overlapping_pairs[i].second << ")";
      s << (overlapping_pairs.size() > 10 ? " ...]" : "]");
    }
    s << " texel_overlaps=" << texel_overlaps << " same_chart_texel_overlaps=" << same_chart_texel_overlaps
      << " (R=" << resolution << ") empty_patch_ids=" << empty_patch_ids;
    if(faces_zero_3d_area != 0)
      s << " faces_zero_3d_area=" << faces_zero_3d_area;
    return s.str();
  }
};

// Flat copy of an atlas. For face f and corner k (0..2):
//   xyz[f][k], uv[f][k], vertex[f][k]: 3D point, UV and vertex id of corner k;
//   across[f][k]: the face on the other side of edge k (from corner (k+2)%3
//   to corner k), or atlas_npos on a mesh border.
struct Atlas_soup
{
  std::vector<std::array<std::array<double, 3>, 3> > xyz;
  std::vector<std::array<std::array<double, 2>, 3> > uv;
  std::vector<std::array<std::size_t, 3> > vertex;
  std::vector<std::size_t> patch;
  std::vector<std::array<std::size_t, 3> > across;

  std::size_t size() const { return patch.size(); }
};

namespace atlas_detail {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 P2;
typedef K::Segment_2 S2;
typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef std::array<double, 2> UV;
typedef std::pair<double, double> Key;

inline bool finite(const UV& p) { return std::isfinite(p[0]) && std::isfinite(p[1]); }
inline P2 pt(const UV& p) { return P2(p[0], p[1]); }
inline Key key(const UV& p) { return Key(p[0], p[1]); }
inline bool same_uv(const UV& a, const UV& b) { return a[0] == b[0] && a[1] == b[1]; }

inline CGAL::Orientation orient(const UV& a, const UV& b, const UV& c) { return CGAL::orientation(pt(a), pt(b), pt(c)); }

// Same result as orient(), faster: a floating-point evaluation with a static
// error bound (Shewchuk's first orient2d stage, written from its published
// error analysis), falling back to the exact predicate when the sign is not
// certain or when underflow could have hidden it.
inline CGAL::Orientation orient_fast(const UV& a, const UV& b, const UV& c)
{
  const double left = (a[0] - c[0]) * (b[1] - c[1]);
  const double right = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = left - right;
  const double tiny = 1e-280;
  if(std::abs(left) > tiny && std::abs(right) > tiny)
  {
    if((left > 0.) != (right > 0.)) // opposite signs: the difference cannot change sign
      return left > 0. ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
    const double eps = std::ldexp(1., -53);
    const double bound = (3. + 16. * eps) * eps * (std::abs(left) + std::abs(right));
    if(det > bound)
      return CGAL::LEFT_TURN;
    if(-det > bound)
      return CGAL::RIGHT_TURN;
  }
  return orient(a, b, c);
}

// Twice the signed area (inexact; used for magnitudes only).
inline double cross2(const UV& a, const UV& b, const UV& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

inline double area3(const std::array<std::array<double, 3>, 3>& p)
{
  const double ux = p[1][0] - p[0][0], uy = p[1][1] - p[0][1], uz = p[1][2] - p[0][2];
  const double vx = p[2][0] - p[0][0], vy = p[2][1] - p[0][1], vz = p[2][2] - p[0][2];
  const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
  return 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
}

inline bool face_finite(const Atlas_soup& s, std::size_t f)
{
  return finite(s.uv[f][0]) && finite(s.uv[f][1]) && finite(s.uv[f][2]);
}

struct Seg
{
  UV a, b;
  std::size_t chart;
  double xmin, xmax, ymin, ymax;
  std::uint32_t cx0, cx1, cy0, cy1; // grid cell range
};

inline Seg make_seg(const UV& a, const UV& b, std::size_t chart)
{
  Seg s;
  s.a = a;
  s.b = b;
  s.chart = chart;
  s.xmin = std::min(a[0], b[0]);
  s.xmax = std::max(a[0], b[0]);
  s.ymin = std::min(a[1], b[1]);
  s.ymax = std::max(a[1], b[1]);
  s.cx0 = s.cx1 = s.cy0 = s.cy1 = 0;
  return s;
}

inline bool boxes_meet(const Seg& s, const Seg& t)
{
  return s.xmin <= t.xmax && t.xmin <= s.xmax && s.ymin <= t.ymax && t.ymin <= s.ymax;
}

// Interiors cross at a single point (no endpoint on the other segment).
inline bool proper_cross(const Seg& s, const Seg& t)
{
  const CGAL::Orientation o1 = orient(s.a, s.b, t.a), o2 = orient(s.a, s.b, t.b);
  if(o1 == CGAL::COLLINEAR || o2 == CGAL::COLLINEAR || o1 == o2)
    return false;
  const CGAL::Orientation o3 = orient(t.a, t.b, s.a), o4 = orient(t.a, t.b, s.b);
  return o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR && o3 != o4;
}

// Monotone map of a coordinate to a cell index in [0, n).
struct Axis
{
  double lo = 0., scale = 0.;
  std::size_t n = 1;

  Axis() {}
  Axis(double lo_, double hi_, std::size_t n_) : lo(lo_), scale(0.), n(n_)
  {
    if(hi_ > lo_ && std::isfinite(hi_ - lo_))
      scale = double(n_) / (hi_ - lo_);
  }

  std::size_t operator()(double x) const
  {
    const double v = std::floor((x - lo) * scale);
    if(!(v > 0.))
      return 0;
    if(v >= double(n - 1))
      return n - 1;
    return std::size_t(v);
  }
};

// A chart's border, closed, for point-in-chart queries.
struct Chart_polygon
{
  std::size_t begin = 0, end = 0; // segment range
  double xmin = 0., xmax = -1., ymin = 0., ymax = -1.;
  Axis rows;
  std::vector<std::size_t> row_begin; // CSR over rows
  std::vector<std::size_t> row_segs;
};

inline void build_polygon(const std::vector<Seg>& segs, std::size_t begin, std::size_t end, Chart_polygon& poly)
{
  poly.begin = begin;
  poly.end = end;
  poly.xmin = poly.ymin = std::numeric_limits<double>::infinity();
  poly.xmax = poly.ymax = -std::numeric_limits<double>::infinity();
  for(std::size_t i = begin; i < end; ++i)
  {
    poly.xmin = std::min(poly.xmin, segs[i].xmin);
    poly.xmax = std::max(poly.xmax, segs[i].xmax);
    poly.ymin = std::min(poly.ymin, segs[i].ymin);
    poly.ymax = std::max(poly.ymax, segs[i].ymax);
  }
  const std::size_t n = end - begin;
  const std::size_t rows = std::max<std::size_t>(1, std::min<std::size_t>(n, std::size_t(2. * std::sqrt(double(n))) + 1));
  poly.rows = Axis(poly.ymin, poly.ymax, rows);
  poly.row_begin.assign(rows + 1, 0);
  for(std::size_t i = begin; i < end; ++i)
    for(std::size_t r = poly.rows(segs[i].ymin), r1 = poly.rows(segs[i].ymax); r <= r1; ++r)
      ++poly.row_begin[r + 1];
  for(std::size_t r = 0; r < rows; ++r)
    poly.row_begin[r + 1] += poly.row_begin[r];
  poly.row_segs.assign(poly.row_begin[rows], 0);
  std::vector<std::size_t> fill(poly.row_begin.begin(), poly.row_begin.end() - 1);
  for(std::size_t i = begin; i < end; ++i)
    for(std::size_t r = poly.rows(segs[i].ymin), r1 = poly.rows(segs[i].ymax); r <= r1; ++r)
      poly.row_segs[fill[r]++] = i;
}

// Winding number of the closed border around p is non-zero, and p is on no
// border segment.
inline bool strictly_inside(const std::vector<Seg>& segs, const Chart_polygon& poly, const UV& p)
{
  if(p[0] < poly.xmin || p[0] > poly.xmax || p[1] < poly.ymin || p[1] > poly.ymax)
    return false;
  const std::size_t r = poly.rows(p[1]);
  long winding = 0;
  for(std::size_t k = poly.row_begin[r]; k < poly.row_begin[r + 1]; ++k)
  {
    const Seg& s = segs[poly.row_segs[k]];
    if(p[1] < s.ymin || p[1] > s.ymax)
      continue;
    const CGAL::Orientation o = orient(s.a, s.b, p);
    if(o == CGAL::COLLINEAR && p[0] >= s.xmin && p[0] <= s.xmax)
      return false; // on the border
    if(s.a[1] <= p[1])
    {
      if(s.b[1] > p[1] && o == CGAL::LEFT_TURN)
        ++winding;
    }
    else if(s.b[1] <= p[1] && o == CGAL::RIGHT_TURN)
      --winding;
  }
  return winding != 0;
}

inline EK::Point_2 ept(const UV& p) { return EK::Point_2(p[0], p[1]); }

// Same as strictly_inside() for a point with exact (rational) coordinates.
inline bool strictly_inside_exact(const std::vector<Seg>& segs, const Chart_polygon& poly, const EK::Point_2& p)
{
  // rounding to nearest is monotone, so these double filters never reject a
  // point or a segment that the exact comparison would keep
  const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
  if(px < poly.xmin || px > poly.xmax || py < poly.ymin || py > poly.ymax)
    return false;
  const std::size_t r = poly.rows(py);
  long winding = 0;
  for(std::size_t k = poly.row_begin[r]; k < poly.row_begin[r + 1]; ++k)
  {
    const Seg& s = segs[poly.row_segs[k]];
    if(py < s.ymin || py > s.ymax)
      continue;
    const EK::Point_2 a = ept(s.a), b = ept(s.b);
    const CGAL::Orientation o = CGAL::orientation(a, b, p);
    if(o == CGAL::COLLINEAR)
    {
      if(CGAL::collinear_are_ordered_along_line(a, p, b))
        return false; // on the border
      continue;
    }
    if(!(p.y() < a.y()))
    {
      if(p.y() < b.y() && o == CGAL::LEFT_TURN)
        ++winding;
    }
    else if(!(p.y() < b.y()) && o == CGAL::RIGHT_TURN)
      --winding;
  }
  return winding != 0;
}

// Fill rule for a centre exactly on the edge a -> b of a counter-clockwise
// triangle: covered iff the edge goes down, or goes right horizontally. For
// the reversed edge b -> a (the neighbour across it) the answer is the
// opposite, so exactly one of two triangles sharing an edge covers it.
inline bool owns_edge(const UV& a, const UV& b) { return b[1] < a[1] || (b[1] == a[1] && b[0] > a[0]); }

// p is covered by the closed-with-fill-rule half-plane left of s -> t.
inline bool edge_in(const UV& s, const UV& t, const UV& p)
{
  const CGAL::Orientation o = orient_fast(s, t, p);
  return o == CGAL::LEFT_TURN || (o == CGAL::COLLINEAR && owns_edge(s, t));
}

// p is covered by the counter-clockwise triangle a, b, c.
inline bool covers(const UV& a, const UV& b, const UV& c, const UV& p)
{
  return edge_in(a, b, p) && edge_in(b, c, p) && edge_in(c, a, p);
}

} // namespace atlas_detail

// Runs every check on a flat atlas. `resolution` 0 skips the texel counts.
inline Atlas_report check_atlas_soup(const Atlas_soup& s, unsigned resolution = 512)
{
  using namespace atlas_detail;
  Atlas_report rep;
  const std::size_t F = s.size();
  if(s.xyz.size() != F || s.uv.size() != F || s.vertex.size() != F || s.across.size() != F)
    throw std::invalid_argument("check_atlas_soup: arrays of different sizes");
  rep.number_of_faces = F;
  rep.resolution = resolution;

  // ---- charts
  std::size_t P = 0;
  for(std::size_t f = 0; f < F; ++f)
  {
    if(s.patch[f] == atlas_npos)
      throw std::invalid_argument("check_atlas_soup: patch id -1");
    P = std::max(P, s.patch[f] + 1);
  }
  rep.number_of_charts = P;
  std::vector<std::size_t> chart_first(P + 1, 0); // CSR of faces by chart
  for(std::size_t f = 0; f < F; ++f)
    ++chart_first[s.patch[f] + 1];
  for(std::size_t c = 0; c < P; ++c)
  {
    if(chart_first[c + 1] == 0)
      ++rep.empty_patch_ids;
    chart_first[c + 1] += chart_first[c];
  }
  std::vector<std::size_t> faces_by_chart(F);
  {
    std::vector<std::size_t> fill(chart_first.begin(), chart_first.end() - 1);
    for(std::size_t f = 0; f < F; ++f)
      faces_by_chart[fill[s.patch[f]]++] = f;
  }

  // ---- corners
  const double tol = 1e-9;
  std::vector<char> fin(F, 0);
  for(std::size_t f = 0; f < F; ++f)
  {
    for(int k = 0; k < 3; ++k)
    {
      const UV& u = s.uv[f][k];
      if(!finite(u))
        ++rep.corners_non_finite;
      else if(u[0] < -tol || u[0] > 1. + tol || u[1] < -tol || u[1] > 1. + tol)
        ++rep.corners_outside_unit_square;
    }
    fin[f] = face_finite(s, f) ? 1 : 0;
  }

  // ---- flipped / degenerate
  std::vector<CGAL::Orientation> turn(F, CGAL::COLLINEAR);
  {
    std::vector<double> det(F, std::numeric_limits<double>::quiet_NaN());
    double sum = 0.;
    std::size_t n = 0;
    for(std::size_t f = 0; f < F; ++f)
    {
      if(!fin[f])
        continue;
      turn[f] = orient(s.uv[f][0], s.uv[f][1], s.uv[f][2]);
      if(turn[f] == CGAL::RIGHT_TURN)
        ++rep.flipped;
      const double a3 = area3(s.xyz[f]);
      if(!(a3 > 0.) || !std::isfinite(a3))
      {
        ++rep.faces_zero_3d_area;
        continue;
      }
      det[f] = 0.5 * cross2(s.uv[f][0], s.uv[f][1], s.uv[f][2]) / a3;
      if(std::isfinite(det[f]))
      {
        sum += std::abs(det[f]);
        ++n;
      }
    }
    const double mean = n ? sum / double(n) : 0.;
    for(std::size_t f = 0; f < F; ++f)
    {
      if(!fin[f] || std::isnan(det[f]))
        continue;
      if(turn[f] == CGAL::COLLINEAR || std::abs(det[f]) <= 1e-12 * mean)
        ++rep.degenerate;
    }
  }

  // ---- continuity inside charts
  for(std::size_t f = 0; f < F; ++f)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t g = s.across[f][k];
      if(g == atlas_npos || g <= f || g >= F || s.patch[g] != s.patch[f])
        continue;
      const int k0 = (k + 2) % 3;
      for(int e = 0; e < 2; ++e)
      {
        const int kf = e ? k : k0;
        const std::size_t v = s.vertex[f][kf];
        for(int j = 0; j < 3; ++j)
          if(s.vertex[g][j] == v)
          {
            const UV& a = s.uv[f][kf];
            const UV& b = s.uv[g][j];
            // two non-finite corners are not counted again (corners_non_finite has them)
            if(!same_uv(a, b) && (finite(a) || finite(b)))
              ++rep.inconsistent_corners;
            break;
          }
      }
    }

  // ---- border segments, grouped by chart
  std::vector<char> bad(P, 0), finite_border(P, 1), closed(P, 0);
  std::vector<Seg> segs;
  std::vector<std::size_t> seg_first(P + 1, 0);
  for(std::size_t c = 0; c < P; ++c)
  {
    seg_first[c] = segs.size();
    for(std::size_t i = chart_first[c]; i < chart_first[c + 1]; ++i)
    {
      const std::size_t f = faces_by_chart[i];
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t g = s.across[f][k];
        if(g != atlas_npos && g < F && s.patch[g] == c)
          continue;
        ++rep.number_of_border_segments;
        const UV& a = s.uv[f][(k + 2) % 3];
        const UV& b = s.uv[f][k];
        if(!finite(a) || !finite(b))
          finite_border[c] = 0;
        else
          segs.push_back(make_seg(a, b, c));
      }
    }
    if(!finite_border[c])
      segs.resize(seg_first[c]); // drop the chart's segments: no geometry on it
  }
  seg_first[P] = segs.size();

  // ---- chaining into one loop; segments of good charts are put in loop order
  std::vector<char> chained(P, 0);
  for(std::size_t c = 0; c < P; ++c)
  {
    if(chart_first[c] == chart_first[c + 1])
      continue; // empty id, counted elsewhere
    const std::size_t b0 = seg_first[c], b1 = seg_first[c + 1], n = b1 - b0;
    if(finite_border[c] && n > 0)
    {
      // closed 1-cycle: every UV point starts as many segments as end there
      std::vector<Key> st, en;
      st.reserve(n);
      en.reserve(n);
      for(std::size_t i = b0; i < b1; ++i)
      {
        st.push_back(key(segs[i].a));
        en.push_back(key(segs[i].b));
      }
      std::sort(st.begin(), st.end());
      std::sort(en.begin(), en.end());
      closed[c] = (st == en) ? 1 : 0;
    }
    if(!finite_border[c] || n < 3)
    {
      bad[c] = 1;
      continue;
    }
    std::map<Key, std::size_t> start_at;
    bool good = true;
    for(std::size_t i = b0; i < b1 && good; ++i)
      good = start_at.emplace(key(segs[i].a), i).second;
    if(good)
    {
      std::set<Key> ends;
      for(std::size_t i = b0; i < b1 && good; ++i)
        good = ends.insert(key(segs[i].b)).second && start_at.count(key(segs[i].b)) == 1;
    }
    if(good)
    {
      std::vector<Seg> loop;
      loop.reserve(n);
      std::size_t cur = b0;
      do
      {
        loop.push_back(segs[cur]);
        cur = start_at.find(key(segs[cur].b))->second;
      } while(cur != b0 && loop.size() <= n);
      good = (loop.size() == n && cur == b0);
      if(good)
        std::copy(loop.begin(), loop.end(), segs.begin() + std::ptrdiff_t(b0));
    }
    if(good)
    {
      // consecutive segments must not fold back onto each other
      for(std::size_t i = 0; i < n && good; ++i)
      {
        const Seg& s0 = segs[b0 + i];
        const Seg& s1 = segs[b0 + (i + 1) % n];
        if(orient(s0.a, s0.b, s1.b) == CGAL::COLLINEAR &&
           !CGAL::collinear_are_ordered_along_line(pt(s0.a), pt(s0.b), pt(s1.b)))
          good = false;
      }
    }
    chained[c] = good ? 1 : 0;
    if(!good)
      bad[c] = 1;
  }

  // ---- segment pairs on a uniform grid
  std::set<std::pair<std::size_t, std::size_t> > overlapping;
  if(!segs.empty())
  {
    double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
    for(const Seg& q : segs)
    {
      xmin = std::min(xmin, q.xmin);
      xmax = std::max(xmax, q.xmax);
      ymin = std::min(ymin, q.ymin);
      ymax = std::max(ymax, q.ymax);
    }
    const std::size_t G =
      std::max<std::size_t>(1, std::min<std::size_t>(2048, std::size_t(std::ceil(std::sqrt(double(segs.size()))))));
    const Axis ax(xmin, xmax, G), ay(ymin, ymax, G);
    std::vector<std::size_t> cell_first(G * G + 1, 0);
    for(Seg& q : segs)
    {
      q.cx0 = std::uint32_t(ax(q.xmin));
      q.cx1 = std::uint32_t(ax(q.xmax));
      q.cy0 = std::uint32_t(ay(q.ymin));
      q.cy1 = std::uint32_t(ay(q.ymax));
      for(std::size_t y = q.cy0; y <= q.cy1; ++y)
        for(std::size_t x = q.cx0; x <= q.cx1; ++x)
          ++cell_first[y * G + x + 1];
    }
    for(std::size_t i = 0; i < G * G; ++i)
      cell_first[i + 1] += cell_first[i];
    std::vector<std::size_t> cell_segs(cell_first[G * G]);
    {
      std::vector<std::size_t> fill(cell_first.begin(), cell_first.end() - 1);
      for(std::size_t i = 0; i < segs.size(); ++i)
      {
        const Seg& q = segs[i];
        for(std::size_t y = q.cy0; y <= q.cy1; ++y)
          for(std::size_t x = q.cx0; x <= q.cx1; ++x)
            cell_segs[fill[y * G + x]++] = i;
      }
    }
    for(std::size_t y = 0; y < G; ++y)
      for(std::size_t x = 0; x < G; ++x)
      {
        const std::size_t cell = y * G + x;
        for(std::size_t ii = cell_first[cell]; ii < cell_first[cell + 1]; ++ii)
          for(std::size_t jj = ii + 1; jj < cell_first[cell + 1]; ++jj)
          {
            const std::size_t i = cell_segs[ii], j = cell_segs[jj];
            const Seg& A = segs[i];
            const Seg& B = segs[j];
            if(std::max(A.cx0, B.cx0) != x || std::max(A.cy0, B.cy0) != y) // tested in another cell
              continue;
            if(!boxes_meet(A, B))
              continue;
            if(A.chart == B.chart)
            {
              const std::size_t c = A.chart;
              if(bad[c] || !chained[c])
                continue;
              const std::size_t n = seg_first[c + 1] - seg_first[c];
              const std::size_t d = i > j ? i - j : j - i;
              if(d == 1 || d == n - 1)
                continue; // consecutive: checked for fold-back already
              if(CGAL::do_intersect(S2(pt(A.a), pt(A.b)), S2(pt(B.a), pt(B.b))))
                bad[c] = 1;
            }
            else
            {
              const std::pair<std::size_t, std::size_t> pr(std::min(A.chart, B.chart), std::max(A.chart, B.chart));
              if(overlapping.count(pr) == 0 && proper_cross(A, B))
                overlapping.insert(pr);
            }
          }
      }
  }

  // ---- containment: probes of one chart strictly inside another
  {
    std::vector<Chart_polygon> poly(P);
    std::vector<char> has_poly(P, 0);
    std::vector<std::size_t> with_segs;
    for(std::size_t c = 0; c < P; ++c)
      if(seg_first[c + 1] > seg_first[c])
      {
        build_polygon(segs, seg_first[c], seg_first[c + 1], poly[c]);
        has_poly[c] = closed[c];
        with_segs.push_back(c);
      }
    // interior probe: exact centroid of the largest non-degenerate UV triangle
    std::vector<char> has_probe(P, 0);
    std::vector<EK::Point_2> probe(P);
    for(std::size_t c = 0; c < P; ++c)
    {
      double best = 0.;
      std::size_t best_face = atlas_npos;
      for(std::size_t i = chart_first[c]; i < chart_first[c + 1]; ++i)
      {
        const std::size_t f = faces_by_chart[i];
        if(!fin[f] || turn[f] == CGAL::COLLINEAR)
          continue;
        const double a = std::abs(cross2(s.uv[f][0], s.uv[f][1], s.uv[f][2]));
        if(best_face == atlas_npos || a > best)
        {
          best = a;
          best_face = f;
        }
      }
      if(best_face != atlas_npos)
      {
        has_probe[c] = 1;
        probe[c] = CGAL::centroid(ept(s.uv[best_face][0]), ept(s.uv[best_face][1]), ept(s.uv[best_face][2]));
      }
    }
    // probes of chart a strictly inside chart b: the interior probe, then the
    // border vertices (in doubles, exact predicates)
    auto points_inside = [&](std::size_t a, std::size_t b) -> bool {
      if(!has_poly[b])
        return false;
      const Chart_polygon& pb = poly[b];
      if(has_probe[a] && strictly_inside_exact(segs, pb, probe[a]))
        return true;
      for(std::size_t i = seg_first[a]; i < seg_first[a + 1]; ++i)
        if(strictly_inside(segs, pb, segs[i].a))
          return true;
      return false;
    };
    // border segments of chart a cut at the vertices of chart b that lie on
    // them: the exact midpoint of an open piece strictly inside b. With no
    // proper crossing, each open piece is wholly inside b, outside b or on
    // b's border, so this finds chords and collinear runs of a through b.
    std::vector<UV> cut;
    auto pieces_inside = [&](std::size_t a, std::size_t b) -> bool {
      if(!has_poly[b])
        return false;
      const Chart_polygon& pb = poly[b];
      for(std::size_t i = seg_first[a]; i < seg_first[a + 1]; ++i)
      {
        const Seg& q = segs[i];
        if(q.xmax < pb.xmin || q.xmin > pb.xmax || q.ymax < pb.ymin || q.ymin > pb.ymax)
          continue;
        cut.clear();
        cut.push_back(q.a);
        cut.push_back(q.b);
        const std::size_t r0 = pb.rows(std::max(q.ymin, pb.ymin)), r1 = pb.rows(std::min(q.ymax, pb.ymax));
        for(std::size_t r = r0; r <= r1; ++r)
          for(std::size_t k = pb.row_begin[r]; k < pb.row_begin[r + 1]; ++k)
          {
            const UV& v = segs[pb.row_segs[k]].a; // every vertex of a closed border starts a segment
            if(v[0] < q.xmin || v[0] > q.xmax || v[1] < q.ymin || v[1] > q.ymax)
              continue;
            if(orient(q.a, q.b, v) == CGAL::COLLINEAR &&
               CGAL::collinear_are_strictly_ordered_along_line(pt(q.a), pt(v), pt(q.b)))
              cut.push_back(v);
          }
        std::sort(cut.begin(), cut.end()); // lexicographic = monotone along the segment
        cut.erase(std::unique(cut.begin(), cut.end()), cut.end());
        for(std::size_t k = 0; k + 1 < cut.size(); ++k)
          if(strictly_inside_exact(segs, pb, CGAL::midpoint(ept(cut[k]), ept(cut[k + 1]))))
            return true;
      }
      return false;
    };
    std::sort(with_segs.begin(), with_segs.end(),
              [&](std::size_t a, std::size_t b) { return poly[a].xmin < poly[b].xmin; });
    for(std::size_t i = 0; i < with_segs.size(); ++i)
    {
      const std::size_t a = with_segs[i];
      for(std::size_t j = i + 1; j < with_segs.size() && poly[with_segs[j]].xmin <= poly[a].xmax; ++j)
      {
        const std::size_t b = with_segs[j];
        if(poly[b].ymin > poly[a].ymax || poly[a].ymin > poly[b].ymax)
          continue;
        const std::pair<std::size_t, std::size_t> pr(std::min(a, b), std::max(a, b));
        if(overlapping.count(pr))
          continue;
        if(points_inside(a, b) || points_inside(b, a) || pieces_inside(a, b) || pieces_inside(b, a))
          overlapping.insert(pr);
      }
    }
  }
  rep.overlapping_chart_pairs = overlapping.size();
  rep.overlapping_pairs.assign(overlapping.begin(), overlapping.end());
  for(std::size_t c = 0; c < P; ++c)
    if(bad[c])
      rep.bad_border_charts.push_back(c);
  rep.charts_with_bad_border = rep.bad_border_charts.size();

  // ---- texels, chart after chart
  if(resolution > 0)
  {
    const std::size_t R = resolution;
    const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> last(R * R, none);
    std::vector<unsigned char> flags(R * R, 0);
    auto first_index = [&](double lo) -> std::size_t { // smallest i with (i+0.5)/R >= lo, roughly
      const double v = std::floor(lo * double(R) - 0.5) - 1.;
      if(!(v > 0.))
        return 0;
      if(v >= double(R))
        return R;
      return std::size_t(v);
    };
    auto last_index = [&](double hi) -> std::size_t { // one past the largest i with (i+0.5)/R <= hi, roughly
      const double v = std::ceil(hi * double(R) - 0.5) + 2.;
      if(!(v > 0.))
        return 0;
      if(v >= double(R))
        return R;
      return std::size_t(v);
    };
    auto center = [&](std::size_t i) { return (double(i) + 0.5) / double(R); };
    for(std::size_t c = 0; c < P; ++c)
      for(std::size_t i = chart_first[c]; i < chart_first[c + 1]; ++i)
      {
        const std::size_t f = faces_by_chart[i];
        if(!fin[f] || turn[f] == CGAL::COLLINEAR)
          continue;
        const UV& a = s.uv[f][0];
        const UV& b = turn[f] == CGAL::LEFT_TURN ? s.uv[f][1] : s.uv[f][2];
        const UV& d = turn[f] == CGAL::LEFT_TURN ? s.uv[f][2] : s.uv[f][1];
        const std::size_t x0 = first_index(std::min({a[0], b[0], d[0]}));
        const std::size_t x1 = last_index(std::max({a[0], b[0], d[0]}));
        const std::size_t y0 = first_index(std::min({a[1], b[1], d[1]}));
        const std::size_t y1 = last_index(std::max({a[1], b[1], d[1]}));
        const UV* corner[3] = {&a, &b, &d};
        for(std::size_t y = y0; y < y1; ++y)
        {
          const double py = center(y);
          std::size_t L = x0, Rx = x1; // covered texels of this row: [L, Rx)
          if(x1 - x0 <= 16)
          {
            // narrow: test every centre (the covered ones are contiguous)
            while(L < Rx && !covers(a, b, d, UV{{center(L), py}}))
              ++L;
            std::size_t e = L;
            while(e < Rx && covers(a, b, d, UV{{center(e), py}}))
              ++e;
            Rx = e;
          }
          else
          {
            // wide: along the row each edge test is monotone (true on a
            // half-line, or constant for a horizontal edge); binary search
            // each edge's exact switch index
            for(int k = 0; k < 3 && L < Rx; ++k)
            {
              const UV& e0 = *corner[k];
              const UV& e1 = *corner[(k + 1) % 3];
              if(e0[1] == e1[1])
              {
                if(!edge_in(e0, e1, UV{{center(x0), py}}))
                  Rx = L;
                continue;
              }
              const bool increasing = e1[1] < e0[1]; // edge goes down: interior towards +x
              std::size_t lo = x0, hi = x1;          // first index where edge_in == increasing
              while(lo < hi)
              {
                const std::size_t mid = lo + (hi - lo) / 2;
                if(edge_in(e0, e1, UV{{center(mid), py}}) == increasing)
                  hi = mid;
                else
                  lo = mid + 1;
              }
              if(increasing)
                L = std::max(L, lo);
              else
                Rx = std::min(Rx, lo);
            }
          }
          for(std::size_t x = L; x < Rx; ++x)
          {
            const std::size_t t = y * R + x;
            if(last[t] == std::uint32_t(c))
              flags[t] |= 2;
            else
            {
              if(last[t] != none)
                flags[t] |= 1;
              last[t] = std::uint32_t(c);
            }
          }
        }
      }
    for(unsigned char fl : flags)
    {
      if(fl & 1)
        ++rep.texel_overlaps;
      if(fl & 2)
        ++rep.same_chart_texel_overlaps;
    }
  }
  return rep;
}

// Copies a triangle mesh with its patch and per-corner UV maps into a soup.
// Throws std::invalid_argument on a non-triangular face.
template <class Mesh, class PatchMap, class UVMap>
Atlas_soup atlas_soup_from_mesh(const Mesh& tm, PatchMap patch, UVMap uv)
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  std::map<vertex_descriptor, std::size_t> vindex;
  for(vertex_descriptor v : vertices(tm))
    vindex.emplace(v, vindex.size());
  std::map<face_descriptor, std::size_t> findex;
  for(face_descriptor f : faces(tm))
    findex.emplace(f, findex.size());

  Atlas_soup s;
  const std::size_t F = findex.size();
  s.xyz.resize(F);
  s.uv.resize(F);
  s.vertex.resize(F);
  s.patch.resize(F);
  s.across.resize(F);
  for(face_descriptor f : faces(tm))
  {
    const std::size_t i = findex.at(f);
    const halfedge_descriptor h0 = halfedge(f, tm);
    halfedge_descriptor h = h0;
    for(int k = 0; k < 3; ++k)
    {
      const vertex_descriptor t = target(h, tm);
      s.vertex[i][k] = vindex.at(t);
      const auto p = get(CGAL::vertex_point, tm, t);
      s.xyz[i][k] = {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
      const auto q = get(uv, h);
      s.uv[i][k] = {{CGAL::to_double(q.x()), CGAL::to_double(q.y())}};
      const face_descriptor g = face(opposite(h, tm), tm);
      s.across[i][k] = (g == GT::null_face()) ? atlas_npos : findex.at(g);
      h = next(h, tm);
    }
    if(h != h0)
      throw std::invalid_argument("atlas_soup_from_mesh: the mesh has a non-triangular face");
    s.patch[i] = std::size_t(get(patch, f));
  }
  return s;
}

template <class Mesh, class PatchMap, class UVMap>
Atlas_report check_atlas(const Mesh& tm, PatchMap patch, UVMap uv, unsigned resolution = 512)
{
  return check_atlas_soup(atlas_soup_from_mesh(tm, patch, uv), resolution);
}

// Sum over faces of the signed UV triangle areas (corners in face order).
template <class Mesh, class UVMap>
double uv_area_sum(const Mesh& tm, UVMap uv)
{
  double sum = 0.;
  for(auto f : faces(tm))
  {
    const auto h0 = halfedge(f, tm);
    const auto h1 = next(h0, tm);
    const auto h2 = next(h1, tm);
    const auto a = get(uv, h0);
    const auto b = get(uv, h1);
    const auto c = get(uv, h2);
    const atlas_detail::UV ua{{CGAL::to_double(a.x()), CGAL::to_double(a.y())}};
    const atlas_detail::UV ub{{CGAL::to_double(b.x()), CGAL::to_double(b.y())}};
    const atlas_detail::UV uc{{CGAL::to_double(c.x()), CGAL::to_double(c.y())}};
    sum += 0.5 * atlas_detail::cross2(ua, ub, uc);
  }
  return sum;
}

// Per chart id c in [0, max id]: sqrt(|sum of signed UV areas| / 3D area) of
// the chart's faces; NaN for an id without faces or with zero 3D area.
template <class Mesh, class PatchMap, class UVMap>
std::vector<double> chart_scales(const Mesh& tm, PatchMap patch, UVMap uv)
{
  const Atlas_soup s = atlas_soup_from_mesh(tm, patch, uv);
  std::size_t P = 0;
  for(std::size_t c : s.patch)
    P = std::max(P, c + 1);
  std::vector<double> uv_area(P, 0.), area(P, 0.);
  for(std::size_t f = 0; f < s.size(); ++f)
  {
    uv_area[s.patch[f]] += 0.5 * atlas_detail::cross2(s.uv[f][0], s.uv[f][1], s.uv[f][2]);
    area[s.patch[f]] += atlas_detail::area3(s.xyz[f]);
  }
  std::vector<double> scale(P, std::numeric_limits<double>::quiet_NaN());
  for(std::size_t c = 0; c < P; ++c)
    if(area[c] > 0.)
      scale[c] = std::sqrt(std::abs(uv_area[c]) / area[c]);
  return scale;
}

// ---------------------------------------------------------------- OBJ

// Triangles only: polygons with more than 3 corners are split into a fan
// (0, i, i+1). Indices are 0-based; face_vt[f] is {atlas_npos x3} for a face
// given without texture coordinates. face_group[f] is the text after the
// last 'g' or 'o' line before the face (trimmed; "" before any).
struct Obj_data
{
  std::vector<std::array<double, 3> > v;
  std::vector<std::array<double, 2> > vt;
  std::vector<std::array<std::size_t, 3> > face_v, face_vt;
  std::vector<std::string> face_group;
};

namespace atlas_detail {

inline std::string trim(const std::string& s)
{
  const char* ws = " \t\r\n\f\v";
  const std::size_t b = s.find_first_not_of(ws);
  if(b == std::string::npos)
    return std::string();
  const std::size_t e = s.find_last_not_of(ws);
  return s.substr(b, e - b + 1);
}

inline bool parse_double(const std::string& tok, double& x)
{
  if(tok.empty())
    return false;
  char* end = nullptr;
  x = std::strtod(tok.c_str(), &end);
  return end == tok.c_str() + tok.size();
}

// OBJ index (1-based, or negative = relative to `count` items read so far)
// to 0-based. Forward positive references are range-checked later.
inline bool parse_index(const std::string& tok, std::size_t count, std::size_t& out)
{
  if(tok.empty())
    return false;
  char* end = nullptr;
  const long long i = std::strtoll(tok.c_str(), &end, 10);
  if(end != tok.c_str() + tok.size() || i == 0)
    return false;
  if(i > 0)
  {
    out = std::size_t(i - 1);
    return true;
  }
  if(std::size_t(-i) > count)
    return false;
  out = count - std::size_t(-i);
  return true;
}

} // namespace atlas_detail

inline bool read_obj(const std::string& path, Obj_data& out, std::string& error)
{
  using namespace atlas_detail;
  out = Obj_data();
  error.clear();
  std::ifstream in(path.c_str(), std::ios::binary);
  if(!in)
  {
    error = "read_obj: cannot open '" + path + "'";
    return false;
  }
  std::string line, group;
  std::size_t line_no = 0;
  auto fail = [&](const std::string& what) {
    error = "read_obj: " + path + ":" + std::to_string(line_no) + ": " + what;
    out = Obj_data();
    return false;
  };
  while(std::getline(in, line))
  {
    ++line_no;
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos)
      line.erase(hash);
    std::istringstream ls(line);
    std::string tag;
    if(!(ls >> tag))
      continue;
    if(tag == "v")
    {
      std::array<double, 3> p{{0., 0., 0.}};
      std::string tok;
      for(int k = 0; k < 3; ++k)
        if(!(ls >> tok) || !parse_double(tok, p[std::size_t(k)]))
          return fail("bad vertex line");
      out.v.push_back(p);
    }
    else if(tag == "vt")
    {
      std::array<double, 2> p{{0., 0.}};
      std::string tok;
      if(!(ls >> tok) || !parse_double(tok, p[0]))
        return fail("bad texture coordinate line");
      if(ls >> tok && !parse_double(tok, p[1]))
        return fail("bad texture coordinate line");
      out.vt.push_back(p);
    }
    else if(tag == "f")
    {
      std::vector<std::size_t> fv, ft;
      std::size_t with_vt = 0;
      std::string tok;
      while(ls >> tok)
      {
        std::vector<std::string> parts;
        std::size_t b = 0;
        for(;;)
        {
          const std::size_t e = tok.find('/', b);
          parts.push_back(tok.substr(b, e == std::string::npos ? std::string::npos : e - b));
          if(e == std::string::npos)
            break;
          b = e + 1;
        }
        if(parts.size() > 3)
          return fail("bad face corner '" + tok + "'");
        std::size_t vi = 0, ti = atlas_npos;
        if(!parse_index(parts[0], out.v.size(), vi))
          return fail("bad vertex index in '" + tok + "'");
        if(parts.size() >= 2 && !parts[1].empty())
        {
          if(!parse_index(parts[1], out.vt.size(), ti))
            return fail("bad texture index in '" + tok + "'");
          ++with_vt;
        }
        fv.push_back(vi);
        ft.push_back(ti);
      }
      if(fv.size() < 3)
        return fail("face with fewer than 3 corners");
      if(with_vt != 0 && with_vt != fv.size())
        return fail("face with texture coordinates on some corners only");
      for(std::size_t i = 1; i + 1 < fv.size(); ++i)
      {
        out.face_v.push_back(std::array<std::size_t, 3>{{fv[0], fv[i], fv[i + 1]}});
        out.face_vt.push_back(std::array<std::size_t, 3>{{ft[0], ft[i], ft[i + 1]}});
        out.face_group.push_back(group);
      }
    }
    else if(tag == "g" || tag == "o")
    {
      std::string rest;
      std::getline(ls, rest);
      group = trim(rest);
    }
    // anything else (vn, vp, s, usemtl, mtllib, l, ...) is ignored
  }
  line_no = 0;
  for(std::size_t f = 0; f < out.face_v.size(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      if(out.face_v[f][std::size_t(k)] >= out.v.size())
        return fail("vertex index out of range in triangle " + std::to_string(f));
      const std::size_t t = out.face_vt[f][std::size_t(k)];
      if(t != atlas_npos && t >= out.vt.size())
        return fail("texture index out of range in triangle " + std::to_string(f));
    }
  return true;
}

// Chart id per OBJ triangle: distinct face_group strings numbered in order of
// first appearance.
inline std::vector<std::size_t> obj_patches_from_groups(const Obj_data& obj)
{
  std::map<std::string, std::size_t> id;
  std::vector<std::size_t> patch(obj.face_group.size());
  for(std::size_t f = 0; f < obj.face_group.size(); ++f)
    patch[f] = id.emplace(obj.face_group[f], id.size()).first->second;
  return patch;
}

// Chart id per OBJ triangle: faces joined across every edge on which both
// faces give the same UV values (exact comparison, not vt indices) to both
// endpoints, i.e. across every edge that is not a seam (a cut in the sense
// of Atlas_quality::cut_length); ids in order of first face. Corners without vt join nothing.
inline std::vector<std::size_t> obj_patches_from_uv_connectivity(const Obj_data& obj)
{
  const std::size_t F = obj.face_v.size();
  std::vector<std::size_t> parent(F);
  for(std::size_t f = 0; f < F; ++f)
    parent[f] = f;
  auto find = [&](std::size_t x) {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  typedef std::pair<std::pair<std::size_t, std::size_t>, std::array<double, 4> > Edge_uv;
  std::map<Edge_uv, std::size_t> edge; // undirected edge + UVs at its (sorted) endpoints -> first face
  for(std::size_t f = 0; f < F; ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      std::size_t a = obj.face_v[f][(k + 2) % 3], b = obj.face_v[f][k];
      std::size_t ta = obj.face_vt[f][(k + 2) % 3], tb = obj.face_vt[f][k];
      if(ta == atlas_npos || tb == atlas_npos || ta >= obj.vt.size() || tb >= obj.vt.size())
        continue;
      if(b < a)
      {
        std::swap(a, b);
        std::swap(ta, tb);
      }
      const Edge_uv e(std::make_pair(a, b),
                      std::array<double, 4>{{obj.vt[ta][0], obj.vt[ta][1], obj.vt[tb][0], obj.vt[tb][1]}});
      const auto ins = edge.emplace(e, f);
      if(!ins.second)
      {
        const std::size_t x = find(f), y = find(ins.first->second);
        if(x != y)
          parent[std::max(x, y)] = std::min(x, y);
      }
    }
  std::map<std::size_t, std::size_t> id;
  std::vector<std::size_t> patch(F);
  for(std::size_t f = 0; f < F; ++f)
    patch[f] = id.emplace(find(f), id.size()).first->second;
  return patch;
}

// Builds the soup of an OBJ atlas. Fails (returns false) if a triangle has no
// texture coordinates, repeats a vertex, or if a directed edge is used twice
// (non-manifold or inconsistently oriented mesh).
inline bool atlas_soup_from_obj(const Obj_data& obj, const std::vector<std::size_t>& face_patch, Atlas_soup& s,
                                std::string& error)
{
  const std::size_t F = obj.face_v.size();
  s = Atlas_soup();
  error.clear();
  if(face_patch.size() != F || obj.face_vt.size() != F)
  {
    error = "atlas_soup_from_obj: one patch id per triangle expected";
    return false;
  }
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> directed;
  for(std::size_t f = 0; f < F; ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t a = obj.face_v[f][(k + 2) % 3], b = obj.face_v[f][k];
      if(a == b)
      {
        error = "atlas_soup_from_obj: triangle " + std::to_string(f) + " repeats a vertex";
        return false;
      }
      if(obj.face_vt[f][k] == atlas_npos)
      {
        error = "atlas_soup_from_obj: triangle " + std::to_string(f) + " has no texture coordinates";
        return false;
      }
      if(!directed.emplace(std::make_pair(a, b), f).second)
      {
        error = "atlas_soup_from_obj: edge (" + std::to_string(a) + ", " + std::to_string(b) +
                ") used twice in the same direction";
        return false;
      }
    }
  s.xyz.resize(F);
  s.uv.resize(F);
  s.vertex = obj.face_v;
  s.patch = face_patch;
  s.across.resize(F);
  for(std::size_t f = 0; f < F; ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      s.xyz[f][k] = obj.v[obj.face_v[f][k]];
      s.uv[f][k] = obj.vt[obj.face_vt[f][k]];
      const auto it = directed.find(std::make_pair(obj.face_v[f][k], obj.face_v[f][(k + 2) % 3]));
      s.across[f][k] = (it == directed.end()) ? atlas_npos : it->second;
    }
  return true;
}

inline bool check_obj_atlas(const Obj_data& obj, const std::vector<std::size_t>& face_patch, Atlas_report& report,
                            std::string& error, unsigned resolution = 512)
{
  Atlas_soup s;
  if(!atlas_soup_from_obj(obj, face_patch, s, error))
    return false;
  report = check_atlas_soup(s, resolution);
  return true;
}

} // namespace test_support

#endif // DISK_SEGMENTATION_TEST_SUPPORT_INDEPENDENT_ATLAS_H
