// The tool's polygon triangulation (disk_uv --triangulate): every polygon
// gives n - 2 triangles over its own corners, in its orientation; a simple
// polygon is covered exactly (areas add up, no triangle outside it) without
// a fan; self-crossing and degenerate polygons end in a fan, not a hang.
// Checked with shoelace areas and point-in-polygon tests written here.

#include <CGAL/Disk_segmentation/IO/internal/Polygon_triangulation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

typedef CGAL::Epick::Point_3 Point;
typedef std::vector<std::vector<std::size_t> > Triangles;

struct Planar_polygon
{
  std::vector<double> x, y;  // in the polygon's own plane
  std::vector<Point> points; // placed in 3D
  std::vector<std::size_t> corners;
};

double shoelace_area(const std::vector<double>& x, const std::vector<double>& y, const std::vector<std::size_t>& ids)
{
  double twice = 0;
  for(std::size_t i = 0; i < ids.size(); ++i)
  {
    const std::size_t a = ids[i], b = ids[(i + 1) % ids.size()];
    twice += x[a] * y[b] - x[b] * y[a];
  }
  return twice / 2;
}

bool inside(const Planar_polygon& p, double px, double py)
{
  bool in = false;
  const std::size_t n = p.x.size();
  for(std::size_t i = 0, j = n - 1; i < n; j = i++)
    if((p.y[i] > py) != (p.y[j] > py) &&
       px < (p.x[j] - p.x[i]) * (py - p.y[i]) / (p.y[j] - p.y[i]) + p.x[i])
      in = !in;
  return in;
}

// Places plane coordinates (x, y) in 3D on a tilted plane through `origin`.
Planar_polygon place(const std::vector<double>& x, const std::vector<double>& y, double tilt, double origin)
{
  Planar_polygon p;
  p.x = x;
  p.y = y;
  const double c = std::cos(tilt), s = std::sin(tilt);
  for(std::size_t i = 0; i < x.size(); ++i)
  {
    p.points.emplace_back(origin + x[i], origin + c * y[i], origin + s * y[i]);
    p.corners.push_back(i);
  }
  return p;
}

// Every triangle made of the polygon's corners, positive area in the plane
// (the polygon is counterclockwise there), areas adding up to the polygon's,
// and each triangle's centroid inside the polygon.
void expect_exact_cover(const Planar_polygon& p, const Triangles& triangles)
{
  ASSERT_EQ(triangles.size(), p.corners.size() - 2);
  double total = 0;
  for(const auto& t : triangles)
  {
    ASSERT_EQ(t.size(), 3u);
    const double area = shoelace_area(p.x, p.y, t);
    EXPECT_GT(area, 0) << "a triangle is flipped or flat";
    total += area;
    EXPECT_TRUE(inside(p, (p.x[t[0]] + p.x[t[1]] + p.x[t[2]]) / 3, (p.y[t[0]] + p.y[t[1]] + p.y[t[2]]) / 3))
      << "a triangle lies outside the polygon";
  }
  EXPECT_NEAR(total, shoelace_area(p.x, p.y, p.corners), 1e-9 * std::abs(total));
}

} // namespace

TEST(PolygonTriangulation, LShapedHexagonWithoutFan)
{
  const Planar_polygon p = place({ 0, 2, 2, 1, 1, 0 }, { 0, 0, 1, 1, 2, 2 }, 0.3, 5);
  bool used_fan = true;
  const Triangles t = CGAL::Disk_segmentation::IO::internal::triangulate_polygon(p.points, p.corners, used_fan);
  EXPECT_FALSE(used_fan);
  expect_exact_cover(p, t);
}

TEST(PolygonTriangulation, RandomStarShapedPolygonsAreCoveredExactly)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> radius(0.2, 1.0), tilt(-1.5, 1.5);
  for(int trial = 0; trial < 200; ++trial)
  {
    const std::size_t n = 4 + trial % 60;
    std::vector<double> x, y;
    for(std::size_t i = 0; i < n; ++i)
    {
      const double angle = 2 * M_PI * (i + 0.5 * radius(random) - 0.1) / n, r = radius(random);
      x.push_back(r * std::cos(angle));
      y.push_back(r * std::sin(angle));
    }
    const Planar_polygon p = place(x, y, tilt(random), trial * 1e3);
    SCOPED_TRACE("trial " + std::to_string(trial));
    bool used_fan = true;
    const Triangles t = CGAL::Disk_segmentation::IO::internal::triangulate_polygon(p.points, p.corners, used_fan);
    EXPECT_FALSE(used_fan);
    expect_exact_cover(p, t);
  }
}

TEST(PolygonTriangulation, ClockwisePolygonKeepsItsOrientation)
{
  // The L-hexagon listed clockwise: every triangle is clockwise too.
  const Planar_polygon p = place({ 0, 0, 1, 1, 2, 2 }, { 0, 2, 2, 1, 1, 0 }, 0, 0);
  bool used_fan = true;
  const Triangles t = CGAL::Disk_segmentation::IO::internal::triangulate_polygon(p.points, p.corners, used_fan);
  EXPECT_FALSE(used_fan);
  ASSERT_EQ(t.size(), 4u);
  for(const auto& triangle : t)
    EXPECT_LT(shoelace_area(p.x, p.y, triangle), 0);
}

TEST(PolygonTriangulation, SelfCrossingAndDegeneratePolygonsEndInAFan)
{
  // The polygon that made CGAL's constrained triangulation run for
  // minutes: 120 corners going around 8 points in random order.
  std::mt19937 random(1);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Point> points;
  for(int i = 0; i < 8; ++i)
    points.emplace_back(unit(random), unit(random), 0.01 * unit(random));
  std::vector<std::size_t> crossing;
  for(int i = 0; i < 120; ++i)
    crossing.push_back(std::size_t(random() % 8));
  bool used_fan = false;
  Triangles t = CGAL::Disk_segmentation::IO::internal::triangulate_polygon(points, crossing, used_fan);
  EXPECT_EQ(t.size(), 118u);
  for(const auto& triangle : t)
    for(std::size_t v : triangle)
      EXPECT_LT(v, points.size());

  // All corners on one line: no area, a fan.
  std::vector<Point> line;
  for(int i = 0; i < 6; ++i)
    line.emplace_back(i, 2 * i, 3 * i);
  t = CGAL::Disk_segmentation::IO::internal::triangulate_polygon(line, { 0, 1, 2, 3, 4, 5 }, used_fan);
  EXPECT_EQ(t.size(), 4u);
  EXPECT_TRUE(used_fan);

  // Too many corners for ear clipping: a fan, with the right count.
  std::vector<Point> circle;
  std::vector<std::size_t> all;
  for(std::size_t i = 0; i < CGAL::Disk_segmentation::IO::internal::max_ear_clipped_corners + 1; ++i)
  {
    const double a = 2 * M_PI * double(i) / double(CGAL::Disk_segmentation::IO::internal::max_ear_clipped_corners + 1);
    circle.emplace_back(std::cos(a), std::sin(a), 0);
    all.push_back(i);
  }
  t = CGAL::Disk_segmentation::IO::internal::triangulate_polygon(circle, all, used_fan);
  EXPECT_EQ(t.size(), all.size() - 2);
  EXPECT_TRUE(used_fan);
}
