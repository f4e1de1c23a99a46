// Per-chart distortion of an atlas, computed for the tests apart from the
// library's Triangle_distortion.h: through the metric tensors of each
// triangle (first fundamental forms of the 3D triangle and of its UV image)
// rather than through the Jacobian's singular values.

#ifndef DISK_SEGMENTATION_TEST_INDEPENDENT_DISTORTION_H
#define DISK_SEGMENTATION_TEST_INDEPENDENT_DISTORTION_H

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace test_support {

struct Chart_measure
{
  double area_3d = 0, area_uv = 0;
  double angle_mean = 0;  // area-weighted mean |log(s1/s2)|
  double area_mean = 0;   // area-weighted mean |log(s1 s2)|, chart scaled to its 3D area
  double max_stretch = 1; // largest s1/s2
  double min_scale = 1, max_scale = 1;  // extremes of s1 s2, chart scaled to its 3D area
  std::vector<double> stretches;        // s1/s2 of every measured triangle, sorted
  double hull_area_uv = 0;              // area of the convex hull of the chart's UVs
  // UV area over the area of its convex hull (1 for a flat layout).
  double convexity() const { return hull_area_uv > 0 ? area_uv / hull_area_uv : 1; }
  // The value with 95% of the triangles at or below it (nearest rank).
  double stretch_p95() const
  {
    if(stretches.empty())
      return 1;
    std::size_t rank = 0;
    while(100 * (rank + 1) < 95 * stretches.size())
      ++rank;
    return stretches[rank];
  }
};

// Area of the convex hull of points, by gift wrapping (the library uses a
// monotone chain): from the lowest-leftmost point, each next hull vertex is
// the point with every other point on its left, the farthest on ties.
inline double convex_hull_area(std::vector<std::array<double, 2> > points)
{
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if(points.size() < 3)
    return 0;
  auto cross = [](const std::array<double, 2>& o, const std::array<double, 2>& a, const std::array<double, 2>& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  auto dist2 = [](const std::array<double, 2>& a, const std::array<double, 2>& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
  };
  std::size_t start = 0;
  for(std::size_t i = 1; i < points.size(); ++i)
    if(points[i][1] < points[start][1] || (points[i][1] == points[start][1] && points[i][0] < points[start][0]))
      start = i;
  std::vector<std::array<double, 2> > hull;
  std::size_t current = start;
  do
  {
    hull.push_back(points[current]);
    std::size_t next = current == 0 ? 1 : 0;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const double turn = cross(points[current], points[next], points[i]);
      if(turn < 0 || (turn == 0 && dist2(points[current], points[i]) > dist2(points[current], points[next])))
        next = i;
    }
    current = next;
  } while(current != start && hull.size() <= points.size());
  double twice = 0;
  for(std::size_t i = 0; i < hull.size(); ++i)
    twice += hull[i][0] * hull[(i + 1) % hull.size()][1] - hull[(i + 1) % hull.size()][0] * hull[i][1];
  return std::abs(twice) / 2;
}

// For a triangle with 3D edges a, b and UV edges p, q from corner 0, the
// metric tensors are G = [a.a a.b; a.b b.b] and H = [p.p p.q; p.q q.q];
// the eigenvalues of G^-1 H are s1^2 and s2^2, so det H / det G = (s1 s2)^2
// and trace(G^-1 H) = s1^2 + s2^2.
template <class Mesh, class PatchMap, class UVMap>
std::map<std::size_t, Chart_measure> measure_charts(const Mesh& tm, PatchMap patch, UVMap uv)
{
  struct Face_values { std::size_t chart; double area_3d, area_uv, stretch; };
  std::vector<Face_values> values;
  std::map<std::size_t, Chart_measure> charts;
  std::map<std::size_t, std::vector<std::array<double, 2> > > chart_uvs;
  for(auto f : faces(tm))
  {
    std::array<std::array<double, 3>, 3> p;
    std::array<std::array<double, 2>, 3> u;
    int i = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
    {
      const auto& x = tm.point(target(h, tm));
      p[i] = {{ x.x(), x.y(), x.z() }};
      u[i] = {{ get(uv, h).x(), get(uv, h).y() }};
      chart_uvs[static_cast<std::size_t>(get(patch, f))].push_back(u[i]);
      ++i;
    }
    double a[3], b[3];
    for(int k = 0; k < 3; ++k) { a[k] = p[1][k] - p[0][k]; b[k] = p[2][k] - p[0][k]; }
    const double pq[2] = { u[1][0] - u[0][0], u[1][1] - u[0][1] };
    const double qq[2] = { u[2][0] - u[0][0], u[2][1] - u[0][1] };
    const double g11 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2], g12 = a[0] * b[0] + a[1] * b[1] + a[2] * b[2],
                 g22 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    const double h11 = pq[0] * pq[0] + pq[1] * pq[1], h12 = pq[0] * qq[0] + pq[1] * qq[1],
                 h22 = qq[0] * qq[0] + qq[1] * qq[1];
    const double det_g = g11 * g22 - g12 * g12, det_h = h11 * h22 - h12 * h12;
    if(!(det_g > 0))
      continue;  // zero 3D area: no distortion to measure
    const double trace = (g22 * h11 - 2 * g12 * h12 + g11 * h22) / det_g;
    const double d = det_h / det_g;
    const double disc = std::sqrt((std::max)(0., trace * trace - 4 * d));
    const double s1_sq = (trace + disc) / 2, s2_sq = (std::max)(0., (trace - disc) / 2);
    Face_values v;
    v.chart = static_cast<std::size_t>(get(patch, f));
    v.area_3d = std::sqrt(det_g) / 2;
    v.area_uv = std::sqrt((std::max)(0., det_h)) / 2;
    v.stretch = s2_sq > 0 ? std::sqrt(s1_sq / s2_sq) : HUGE_VAL;
    values.push_back(v);
    charts[v.chart].area_3d += v.area_3d;
    charts[v.chart].area_uv += v.area_uv;
  }
  std::map<std::size_t, bool> first;
  for(const Face_values& v : values)
  {
    Chart_measure& c = charts[v.chart];
    const double scale = (v.area_uv / v.area_3d) * (c.area_3d / c.area_uv);
    c.angle_mean += v.area_3d * std::log(v.stretch) / c.area_3d;
    c.area_mean += v.area_3d * std::abs(std::log(scale)) / c.area_3d;
    const bool is_first = first.emplace(v.chart, true).second;
    c.max_stretch = is_first ? v.stretch : (std::max)(c.max_stretch, v.stretch);
    c.stretches.push_back(v.stretch);
    c.min_scale = is_first ? scale : (std::min)(c.min_scale, scale);
    c.max_scale = is_first ? scale : (std::max)(c.max_scale, scale);
  }
  for(auto& entry : charts)
  {
    std::sort(entry.second.stretches.begin(), entry.second.stretches.end());
    entry.second.hull_area_uv = convex_hull_area(chart_uvs[entry.first]);
  }
  return charts;
}

} // namespace test_support

#endif // DISK_SEGMENTATION_TEST_INDEPENDENT_DISTORTION_H
