// Self-test of the library-independent atlas checker (independent_atlas.h):
// hand-built meshes and UVs with known defects. Does not use the library.

#include "test_meshes.h"
#include "independent_atlas.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> SM;
typedef CGAL::Polyhedron_3<K> Poly;

using test_support::Atlas_report;
using test_support::Soup;

// patch of soup triangle f
typedef std::function<std::size_t(std::size_t)> Patch_fn;
// UV of soup point p as seen from soup triangle f of patch c
typedef std::function<Point_2(std::size_t f, std::size_t p, std::size_t c)> Uv_fn;

template <class Mesh>
struct Atlas
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;

  Mesh tm;
  std::map<face_descriptor, std::size_t> patch;
  std::map<halfedge_descriptor, Point_2> uv;

  Atlas(const Soup& s, const Patch_fn& patch_of, const Uv_fn& uv_of)
  {
    test_support::to_mesh(s, tm);
    std::map<vertex_descriptor, std::size_t> vi;
    for(vertex_descriptor v : vertices(tm))
      vi.emplace(v, vi.size());
    std::size_t fi = 0;
    for(face_descriptor f : faces(tm))
    {
      const std::size_t c = patch_of(fi);
      patch[f] = c;
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
        uv[h] = uv_of(fi, vi.at(target(h, tm)), c);
      ++fi;
    }
  }

  boost::associative_property_map<std::map<face_descriptor, std::size_t> > patch_map()
  {
    return boost::associative_property_map<std::map<face_descriptor, std::size_t> >(patch);
  }
  boost::associative_property_map<std::map<halfedge_descriptor, Point_2> > uv_map()
  {
    return boost::associative_property_map<std::map<halfedge_descriptor, Point_2> >(uv);
  }
  Atlas_report check(unsigned resolution = 512) { return test_support::check_atlas(tm, patch_map(), uv_map(), resolution); }
};

Patch_fn one_patch()
{
  return [](std::size_t) { return std::size_t(0); };
}

// UV = (a*x + b, a*y + c) of the soup point, optionally overriding points.
Uv_fn affine_uv(const Soup& s, double a, double b, double c, std::map<std::size_t, Point_2> moved = {})
{
  return [&s, a, b, c, moved](std::size_t, std::size_t p, std::size_t) {
    const auto it = moved.find(p);
    const double x = it == moved.end() ? s.points[p][0] : it->second.x();
    const double y = it == moved.end() ? s.points[p][1] : it->second.y();
    return Point_2(a * x + b, a * y + c);
  };
}

std::array<double, 3> centroid(const Soup& s, std::size_t f)
{
  std::array<double, 3> c{{0., 0., 0.}};
  for(std::size_t p : s.triangles[f])
    for(int k = 0; k < 3; ++k)
      c[std::size_t(k)] += s.points[p][std::size_t(k)] / 3.;
  return c;
}

void expect_clean(const Atlas_report& r)
{
  EXPECT_TRUE(r.ok()) << r.summary();
  EXPECT_EQ(r.corners_non_finite, 0u);
  EXPECT_EQ(r.corners_outside_unit_square, 0u);
  EXPECT_EQ(r.flipped, 0u);
  EXPECT_EQ(r.degenerate, 0u);
  EXPECT_EQ(r.charts_with_bad_border, 0u);
  EXPECT_EQ(r.inconsistent_corners, 0u);
  EXPECT_EQ(r.overlapping_chart_pairs, 0u);
  EXPECT_EQ(r.texel_overlaps, 0u);
  EXPECT_EQ(r.same_chart_texel_overlaps, 0u);
  EXPECT_EQ(r.empty_patch_ids, 0u);
}

const double kPi = 3.14159265358979323846;

// ------------------------------------------------------------- valid atlases

template <class Mesh>
void identity_disk_case()
{
  const Soup s = test_support::disk(4, 16);
  Atlas<Mesh> a(s, one_patch(), affine_uv(s, 0.45, 0.5, 0.5));
  for(unsigned R : {512u, 1024u, 7u, 0u})
  {
    const Atlas_report r = a.check(R);
    expect_clean(r);
    EXPECT_EQ(r.number_of_faces, s.triangles.size());
    EXPECT_EQ(r.number_of_charts, 1u);
    EXPECT_EQ(r.number_of_border_segments, 16u);
  }
  const double polygon_area = 0.5 * 16 * std::sin(2. * kPi / 16);
  EXPECT_NEAR(test_support::uv_area_sum(a.tm, a.uv_map()), 0.45 * 0.45 * polygon_area, 1e-12);
  const std::vector<double> scales = test_support::chart_scales(a.tm, a.patch_map(), a.uv_map());
  ASSERT_EQ(scales.size(), 1u);
  EXPECT_NEAR(scales[0], 0.45, 1e-12);
}

TEST(AtlasChecker, IdentityDiskIsOkSurfaceMesh) { identity_disk_case<SM>(); }
TEST(AtlasChecker, IdentityDiskIsOkPolyhedron) { identity_disk_case<Poly>(); }

// Closed sphere cut at the equator into two hemispheres, each projected to
// the plane (the southern one mirrored to keep the orientation).
TEST(AtlasChecker, SphereHemispheresAreOk)
{
  const Soup s = test_support::uv_sphere(4, 8);
  auto patch_of = [&s](std::size_t f) { return centroid(s, f)[2] > 0. ? std::size_t(0) : std::size_t(1); };
  auto uv_of = [&s](std::size_t, std::size_t p, std::size_t c) {
    const double x = s.points[p][0], y = s.points[p][1];
    return c == 0 ? Point_2(0.25 + 0.2 * x, 0.5 + 0.2 * y) : Point_2(0.75 - 0.2 * x, 0.5 + 0.2 * y);
  };
  Atlas<SM> a(s, patch_of, uv_of);
  const Atlas_report r = a.check(1024);
  expect_clean(r);
  EXPECT_EQ(r.number_of_charts, 2u);
  EXPECT_EQ(r.number_of_border_segments, 16u);
}

// 4 x 2 grid, left half (x < 2) chart 0, right half chart 1; UV = (x, y) / 8
// for chart 0 and (x / 8 + shift, y / 8) for chart 1.
Atlas<SM> two_charts(const Soup& s, double shift, double scale1 = 1. / 8, double dx1 = 0., double dy1 = 0.)
{
  auto patch_of = [&s](std::size_t f) { return centroid(s, f)[0] < 2. ? std::size_t(0) : std::size_t(1); };
  auto uv_of = [&s, shift, scale1, dx1, dy1](std::size_t, std::size_t p, std::size_t c) {
    const double x = s.points[p][0], y = s.points[p][1];
    if(c == 0)
      return Point_2(x / 8, y / 8);
    return Point_2((x - 2.) * scale1 + 0.25 + shift + dx1, y * scale1 + dy1);
  };
  return Atlas<SM>(s, patch_of, uv_of);
}

TEST(AtlasChecker, TwoSeparatedChartsAreOk)
{
  const Soup s = test_support::grid_with_holes(4, 2, 0);
  Atlas<SM> a = two_charts(s, 0.25);
  const Atlas_report r = a.check();
  expect_clean(r);
  EXPECT_EQ(r.number_of_charts, 2u);
  EXPECT_EQ(r.number_of_border_segments, 16u); // 8 per 2x2 square
  const std::vector<double> scales = test_support::chart_scales(a.tm, a.patch_map(), a.uv_map());
  ASSERT_EQ(scales.size(), 2u);
  EXPECT_NEAR(scales[0], 0.125, 1e-12);
  EXPECT_NEAR(scales[1], 0.125, 1e-12);
}

// Abutting charts share a border line exactly; at R = 6 texel centres lie
// exactly on that line (u = 1.5/6 = 0.25) and on interior diagonals: the fill
// rule must count each centre once.
TEST(AtlasChecker, AbuttingChartsAreOk)
{
  const Soup s = test_support::grid_with_holes(4, 2, 0);
  Atlas<SM> a = two_charts(s, 0.);
  for(unsigned R : {6u, 8u, 512u, 1024u})
  {
    const Atlas_report r = a.check(R);
    expect_clean(r);
  }
}

// ------------------------------------------------------------- defects

TEST(AtlasChecker, MirroredTriangleIsFlipped)
{
  const Soup s = test_support::single_triangle();
  Atlas<SM> a(s, one_patch(), [&s](std::size_t, std::size_t p, std::size_t) {
    return Point_2(0.1 + 0.8 * s.points[p][1], 0.1 + 0.8 * s.points[p][0]); // swap x and y
  });
  const Atlas_report r = a.check();
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.flipped, 1u) << r.summary();
  EXPECT_EQ(r.degenerate, 0u);
  EXPECT_EQ(r.charts_with_bad_border, 0u); // a clockwise triangle is still a simple curve
  EXPECT_EQ(r.texel_overlaps, 0u);
  EXPECT_EQ(r.same_chart_texel_overlaps, 0u);
  EXPECT_LT(test_support::uv_area_sum(a.tm, a.uv_map()), 0.);
}

// 4 x 4 grid, UV = (x, y) / 8 + 1/4 (exact in binary); interior point (2, 2)
// (index 12) moved to (3.5, 2): exactly two of its six triangles turn
// clockwise, and they fold over their neighbours.
TEST(AtlasChecker, MovedInteriorVertexFlipsTwoTriangles)
{
  const Soup s = test_support::grid_with_holes(4, 4, 0);
  Atlas<SM> a(s, one_patch(), affine_uv(s, 0.125, 0.25, 0.25, {{12, Point_2(3.5, 2.)}}));
  const Atlas_report r = a.check();
  EXPECT_EQ(r.flipped, 2u) << r.summary();
  EXPECT_EQ(r.degenerate, 0u);
  EXPECT_EQ(r.charts_with_bad_border, 0u);
  EXPECT_EQ(r.inconsistent_corners, 0u);
  EXPECT_EQ(r.texel_overlaps, 0u);
  EXPECT_GT(r.same_chart_texel_overlaps, 0u);
  EXPECT_FALSE(r.ok());
}

// Same grid, point (2, 2) moved onto the segment (2,1)-(3,2): exactly one
// triangle becomes collinear in UV (exactly, thanks to the binary scale).
TEST(AtlasChecker, DegenerateTriangleIsCounted)
{
  const Soup s = test_support::grid_with_holes(4, 4, 0);
  Atlas<SM> a(s, one_patch(), affine_uv(s, 0.125, 0.25, 0.25, {{12, Point_2(2.5, 1.5)}}));
  const Atlas_report r = a.check();
  EXPECT_EQ(r.degenerate, 1u) << r.summary();
  EXPECT_EQ(r.flipped, 0u);
  EXPECT_EQ(r.charts_with_bad_border, 0u);
  EXPECT_EQ(r.texel_overlaps, 0u);
  EXPECT_EQ(r.same_chart_texel_overlaps, 0u);
  EXPECT_FALSE(r.ok());
}

TEST(AtlasChecker, NearlyDegenerateTriangleIsCounted)
{
  // Not exactly collinear, but |det| far below 1e-12 * mean |det|.
  const Soup s = test_support::grid_with_holes(4, 4, 0);
  Atlas<SM> a(s, one_patch(), affine_uv(s, 0.125, 0.25, 0.25, {{12, Point_2(2.5 - 1e-14, 1.5)}}));
  const Atlas_report r = a.check();
  EXPECT_EQ(r.degenerate, 1u) << r.summary();
}

TEST(AtlasChecker, CollinearSingleTriangle)
{
  const Soup s = test_support::single_triangle();
  Atlas<SM> a(s, one_patch(), [](std::size_t, std::size_t p, std::size_t) {
    return Point_2(0.1 + 0.4 * double(p), 0.1 + 0.4 * double(p)); // (0.1,0.1), (0.5,0.5), (0.9,0.9)
  });
  const Atlas_report r = a.check();
  EXPECT_EQ(r.degenerate, 1u) << r.summary();
  EXPECT_EQ(r.flipped, 0u);
  EXPECT_EQ(r.charts_with_bad_border, 1u); // the border folds back onto itself
}

// Corner (4, 4) (index 24) of the 4 x 4 grid folded over the left side:
// the border crosses itself.
TEST(AtlasChecker, FoldedCornerMakesBorderSelfIntersect)
{
  const Soup s = test_support::grid_with_holes(4, 4, 0);
  Atlas<SM> a(s, one_patch(), affine_uv(s, 0.125, 0.25, 0.25, {{24, Point_2(-1., 2.)}}));
  const Atlas_report r = a.check();
  EXPECT_EQ(r.charts_with_bad_border, 1u) << r.summary();
  ASSERT_EQ(r.bad_border_charts.size(), 1u);
  EXPECT_EQ(r.bad_border_charts[0], 0u);
  EXPECT_EQ(r.corners_outside_unit_square, 0u);
  EXPECT_FALSE(r.ok());
}

// The same corner put exactly on the left side (not at a vertex): the border
// touches itself (a T-junction), which is not simple either.
TEST(AtlasChecker, BorderTouchingItselfIsBad)
{
  const Soup s = test_support::grid_with_holes(4, 4, 0);
  Atlas<SM> a(s, one_patch(), affine_uv(s, 0.125, 0.25, 0.25, {{24, Point_2(0., 2.5)}}));
  const Atlas_report r = a.check();
  EXPECT_EQ(r.charts_with_bad_border, 1u) << r.summary();
}

// ... and exactly on the left-side vertex (0, 2): two border vertices share a
// UV (pinch).
TEST(AtlasChecker, PinchedBorderIsBad)
{
  const Soup s = test_support::grid_with_holes(4, 4, 0);
  Atlas<SM> a(s, one_patch(), affine_uv(s, 0.125, 0.25, 0.25, {{24, Point_2(0., 2.)}}));
  const Atlas_report r = a.check();
  EXPECT_EQ(r.charts_with_bad_border, 1u) << r.summary();
}

TEST(AtlasChecker, AnnulusChartIsBad)
{
  const Soup s = test_support::grid_with_holes(3, 3, 1);
  Atlas<SM> a(s, one_patch(), affine_uv(s, 0.25, 0.1, 0.1));
  const Atlas_report r = a.check();
  EXPECT_EQ(r.charts_with_bad_border, 1u) << r.summary();
  EXPECT_EQ(r.flipped, 0u);
  EXPECT_EQ(r.overlapping_chart_pairs, 0u);
  EXPECT_EQ(r.texel_overlaps + r.same_chart_texel_overlaps, 0u);
}

TEST(AtlasChecker, ClosedChartIsBad)
{
  const Soup s = test_support::uv_sphere(4, 8);
  Atlas<SM> a(s, one_patch(), [&s](std::size_t, std::size_t p, std::size_t) {
    return Point_2(0.5 + 0.4 * s.points[p][0], 0.5 + 0.4 * s.points[p][1]);
  });
  const Atlas_report r = a.check();
  EXPECT_EQ(r.charts_with_bad_border, 1u) << r.summary();
  EXPECT_EQ(r.number_of_border_segments, 0u);
}

TEST(AtlasChecker, TranslatedChartsOverlap)
{
  const Soup s = test_support::grid_with_holes(4, 2, 0);
  Atlas<SM> a = two_charts(s, -0.125); // chart 1 covers u in [0.125, 0.375], chart 0 [0, 0.25]
  const Atlas_report r = a.check();
  EXPECT_EQ(r.overlapping_chart_pairs, 1u) << r.summary();
  ASSERT_EQ(r.overlapping_pairs.size(), 1u);
  EXPECT_EQ(r.overlapping_pairs[0], std::make_pair(std::size_t(0), std::size_t(1)));
  EXPECT_GT(r.texel_overlaps, 0u);
  EXPECT_EQ(r.same_chart_texel_overlaps, 0u);
  EXPECT_EQ(r.charts_with_bad_border, 0u);
  EXPECT_EQ(r.inconsistent_corners, 0u);
  EXPECT_EQ(r.flipped, 0u);
  EXPECT_FALSE(r.ok());
  // overlap of 1/8 x 1/4 in UV = 1/32 of the square: about 1/32 of the texels
  const Atlas_report r64 = a.check(64);
  EXPECT_NEAR(double(r64.texel_overlaps), 64. * 64. / 32., 64.);
}

TEST(AtlasChecker, IdenticalChartsOverlap)
{
  // borders coincide: no crossing, no vertex strictly inside; the interior
  // probe must catch it
  const Soup s = test_support::grid_with_holes(4, 2, 0);
  Atlas<SM> a = two_charts(s, -0.25);
  const Atlas_report r = a.check();
  EXPECT_EQ(r.overlapping_chart_pairs, 1u) << r.summary();
  EXPECT_GT(r.texel_overlaps, 0u);
}

// Two unit squares (one triangle pair each) as charts: chart 0 at
// [0, 1/4]^2, chart 1 the same square moved up by 3/16. The borders never
// cross properly (they meet at T-junctions and run along the same lines), no
// vertex lies strictly inside the other chart and neither interior probe
// does: only the cut-segment midpoints see the overlap.
TEST(AtlasChecker, OverlapWithoutCrossingsOrInnerVertices)
{
  const Soup s = test_support::grid_with_holes(2, 1, 0);
  auto patch_of = [&s](std::size_t f) { return centroid(s, f)[0] < 1. ? std::size_t(0) : std::size_t(1); };
  for(double dv : {3. / 16, 1. / 4})
  {
    Atlas<SM> a(s, patch_of, [&s, dv](std::size_t, std::size_t p, std::size_t c) {
      const double x = s.points[p][0], y = s.points[p][1];
      return c == 0 ? Point_2(x / 4, y / 4) : Point_2((x - 1.) / 4, y / 4 + dv);
    });
    const Atlas_report r = a.check();
    if(dv < 0.25)
    {
      EXPECT_EQ(r.overlapping_chart_pairs, 1u) << r.summary();
      EXPECT_GT(r.texel_overlaps, 0u);
    }
    else
      expect_clean(r); // stacked exactly on top of each other: touching only
    EXPECT_EQ(r.charts_with_bad_border, 0u);
  }
}

TEST(AtlasChecker, ContainedChartOverlaps)
{
  const Soup s = test_support::grid_with_holes(4, 2, 0);
  // chart 1 shrunk to [0.1, 0.1625] x [0.05, 0.1125], inside chart 0 = [0, 0.25]^2
  Atlas<SM> a = two_charts(s, 0., 1. / 32, 0.1 - 0.25, 0.05);
  const Atlas_report r = a.check();
  EXPECT_EQ(r.overlapping_chart_pairs, 1u) << r.summary();
  EXPECT_GT(r.texel_overlaps, 0u);
  EXPECT_EQ(r.charts_with_bad_border, 0u);
}

// An annulus chart (bad border: two loops) and a triangle chart: inside the
// hole they do not overlap (the winding numbers of the two loops cancel), on
// the ring they do.
TEST(AtlasChecker, ChartInsideAnnulusHole)
{
  Soup s = test_support::grid_with_holes(3, 3, 1); // hole = square [1,2]^2
  const std::size_t ring_faces = s.triangles.size();
  test_support::soup_detail::append(s, test_support::single_triangle(), 10., 0., 0.);
  for(double offset : {1.25, 0.25})
  {
    Atlas<SM> a(s, [ring_faces](std::size_t f) { return std::size_t(f < ring_faces ? 0 : 1); },
                [&s, offset](std::size_t, std::size_t p, std::size_t c) {
                  const double x = s.points[p][0], y = s.points[p][1];
                  if(c == 0)
                    return Point_2(x / 4, y / 4);
                  return Point_2((x - 10.) / 8 + offset / 4, y / 8 + offset / 4);
                });
    const Atlas_report r = a.check();
    EXPECT_EQ(r.charts_with_bad_border, 1u) << r.summary();
    EXPECT_EQ(r.flipped, 0u);
    if(offset > 1.)
    {
      EXPECT_EQ(r.overlapping_chart_pairs, 0u) << r.summary();
      EXPECT_EQ(r.texel_overlaps, 0u);
    }
    else
    {
      EXPECT_EQ(r.overlapping_chart_pairs, 1u) << r.summary();
      EXPECT_GT(r.texel_overlaps, 0u);
    }
  }
}

TEST(AtlasChecker, InconsistentCornerInsideChart)
{
  // Triangle 10 = (1,1),(2,1),(2,2) gives point 12 = (2,2) another UV; its two
  // interior edges through that point each disagree once.
  const Soup s = test_support::grid_with_holes(4, 4, 0);
  ASSERT_EQ(s.triangles[10][2], 12u);
  Atlas<SM> a(s, one_patch(), [&s](std::size_t f, std::size_t p, std::size_t) {
    const double dx = (f == 10 && p == 12) ? 1. / 64 : 0.;
    return Point_2(s.points[p][0] / 8 + 0.25 + dx, s.points[p][1] / 8 + 0.25);
  });
  const Atlas_report r = a.check();
  EXPECT_EQ(r.inconsistent_corners, 2u) << r.summary();
  EXPECT_FALSE(r.ok());
}

TEST(AtlasChecker, OutsideUnitSquareIsCounted)
{
  const Soup s = test_support::single_triangle();
  auto with_corner1 = [&s](double u1) {
    return Atlas<SM>(s, one_patch(), [u1](std::size_t, std::size_t p, std::size_t) {
      return p == 0 ? Point_2(0., 0.) : p == 1 ? Point_2(u1, 0.) : Point_2(0., 1.);
    });
  };
  {
    Atlas<SM> a = with_corner1(1. + 1e-10); // within tolerance
    expect_clean(a.check());
  }
  {
    Atlas<SM> a = with_corner1(1. + 1e-8);
    const Atlas_report r = a.check();
    EXPECT_EQ(r.corners_outside_unit_square, 1u) << r.summary();
    EXPECT_FALSE(r.ok());
  }
  {
    Atlas<SM> a(s, one_patch(), [&s](std::size_t, std::size_t p, std::size_t) {
      return Point_2(s.points[p][0] - 0.5, s.points[p][1]); // (-0.5,0) (0.5,0) (-0.5,1)
    });
    const Atlas_report r = a.check();
    EXPECT_EQ(r.corners_outside_unit_square, 2u) << r.summary();
    EXPECT_EQ(r.flipped, 0u);
  }
}

TEST(AtlasChecker, NonFiniteIsCounted)
{
  const Soup s = test_support::single_triangle();
  for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    Atlas<SM> a(s, one_patch(), [bad](std::size_t, std::size_t p, std::size_t) {
      return p == 0 ? Point_2(0.1, 0.1) : p == 1 ? Point_2(0.9, bad) : Point_2(0.1, 0.9);
    });
    const Atlas_report r = a.check();
    EXPECT_EQ(r.corners_non_finite, 1u) << r.summary();
    EXPECT_EQ(r.corners_outside_unit_square, 0u);
    EXPECT_EQ(r.flipped, 0u);
    EXPECT_EQ(r.degenerate, 0u);
    EXPECT_EQ(r.charts_with_bad_border, 1u);
    EXPECT_EQ(r.texel_overlaps, 0u);
    EXPECT_FALSE(r.ok());
  }
  // a NaN in a larger mesh: corners of that vertex, no crash, other counts sane
  const Soup g = test_support::grid_with_holes(4, 4, 0);
  Atlas<SM> a(g, one_patch(), affine_uv(g, 0.125, 0.25, 0.25, {{12, Point_2(std::nan(""), 2.)}}));
  const Atlas_report r = a.check();
  EXPECT_EQ(r.corners_non_finite, 6u) << r.summary(); // valence of the interior point
  EXPECT_EQ(r.inconsistent_corners, 0u);
  EXPECT_EQ(r.charts_with_bad_border, 0u);
  EXPECT_EQ(r.flipped, 0u);
}

TEST(AtlasChecker, EmptyPatchIdIsCounted)
{
  const Soup s = test_support::disk(2, 8);
  Atlas<SM> a(s, [](std::size_t) { return std::size_t(1); }, affine_uv(s, 0.4, 0.5, 0.5));
  const Atlas_report r = a.check();
  EXPECT_EQ(r.empty_patch_ids, 1u) << r.summary();
  EXPECT_EQ(r.number_of_charts, 2u);
  EXPECT_EQ(r.charts_with_bad_border, 0u);
  EXPECT_FALSE(r.ok());
}

// ------------------------------------------------------------- OBJ

std::string temp_path(const std::string& name)
{
  return std::string(::testing::TempDir()) + name;
}

TEST(AtlasChecker, ReadObjHandWritten)
{
  const std::string path = temp_path("atlas_checker_hand.obj");
  {
    std::ofstream out(path.c_str());
    out << "# hand written\r\n"
           "mtllib none.mtl\n"
           "o thing\n"
           "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
           "vt 0.1 0.1\nvt 0.4 0.1\nvt 0.4 0.4\nvt 0.1 0.4\n"
           "vt 0.6 0.1\nvt 0.9 0.1 0\nvt 0.9 0.4\nvt 0.6 0.4\n"
           "vn 0 0 1\n"
           "g chart_a\n"
           "s off\n"
           "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
           "g   chart_b  \n"
           "f 2/5/1 5/6/1 6/7/1   # comment\n"
           "f -5/-4 -1/-2 -4/-1\n";
  }
  test_support::Obj_data obj;
  std::string error;
  ASSERT_TRUE(test_support::read_obj(path, obj, error)) << error;
  ASSERT_EQ(obj.v.size(), 6u);
  ASSERT_EQ(obj.vt.size(), 8u);
  ASSERT_EQ(obj.face_v.size(), 4u);
  ASSERT_EQ(obj.face_vt.size(), 4u);
  ASSERT_EQ(obj.face_group.size(), 4u);
  EXPECT_EQ(obj.v[5][0], 2.);
  EXPECT_EQ(obj.v[5][1], 1.);
  EXPECT_EQ(obj.vt[5][0], 0.9);
  EXPECT_EQ(obj.vt[5][1], 0.1);
  const std::array<std::size_t, 3> f0{{0, 1, 2}}, f1{{0, 2, 3}}, f2{{1, 4, 5}}, f3{{1, 5, 2}};
  const std::array<std::size_t, 3> t0{{0, 1, 2}}, t1{{0, 2, 3}}, t2{{4, 5, 6}}, t3{{4, 6, 7}};
  EXPECT_EQ(obj.face_v[0], f0);
  EXPECT_EQ(obj.face_v[1], f1);
  EXPECT_EQ(obj.face_v[2], f2);
  EXPECT_EQ(obj.face_v[3], f3);
  EXPECT_EQ(obj.face_vt[0], t0);
  EXPECT_EQ(obj.face_vt[1], t1);
  EXPECT_EQ(obj.face_vt[2], t2);
  EXPECT_EQ(obj.face_vt[3], t3);
  EXPECT_EQ(obj.face_group[0], "chart_a");
  EXPECT_EQ(obj.face_group[1], "chart_a");
  EXPECT_EQ(obj.face_group[2], "chart_b");
  EXPECT_EQ(obj.face_group[3], "chart_b");

  const std::vector<std::size_t> expected{0, 0, 1, 1};
  EXPECT_EQ(test_support::obj_patches_from_groups(obj), expected);
  EXPECT_EQ(test_support::obj_patches_from_uv_connectivity(obj), expected);
  Atlas_report r;
  ASSERT_TRUE(test_support::check_obj_atlas(obj, expected, r, error)) << error;
  expect_clean(r);
  EXPECT_EQ(r.number_of_border_segments, 8u);
  // one chart for everything: the shared edge then disagrees on both endpoints
  ASSERT_TRUE(test_support::check_obj_atlas(obj, std::vector<std::size_t>(4, 0), r, error)) << error;
  EXPECT_EQ(r.inconsistent_corners, 2u) << r.summary();
  EXPECT_EQ(r.charts_with_bad_border, 1u);
  std::remove(path.c_str());
}

TEST(AtlasChecker, ReadObjErrors)
{
  test_support::Obj_data obj;
  std::string error;
  EXPECT_FALSE(test_support::read_obj(temp_path("atlas_checker_missing_file.obj"), obj, error));
  EXPECT_FALSE(error.empty());

  auto read_text = [&](const std::string& text) {
    const std::string path = temp_path("atlas_checker_err.obj");
    {
      std::ofstream out(path.c_str());
      out << text;
    }
    const bool ok = test_support::read_obj(path, obj, error);
    std::remove(path.c_str());
    return ok;
  };
  EXPECT_FALSE(read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"));
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
  EXPECT_FALSE(read_text("v 0 0 0\nv 1 0 0\nf 1 2\n"));
  EXPECT_FALSE(read_text("v 0 0\n"));
  EXPECT_NE(error.find(":1:"), std::string::npos) << error;
  EXPECT_FALSE(read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3\n"));
  EXPECT_FALSE(read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"));
  EXPECT_FALSE(read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 -2 -1\n"));
  // no texture coordinates: readable, but not an atlas
  ASSERT_TRUE(read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n")) << error;
  ASSERT_EQ(obj.face_vt.size(), 1u);
  EXPECT_EQ(obj.face_vt[0][0], test_support::atlas_npos);
  Atlas_report r;
  EXPECT_FALSE(test_support::check_obj_atlas(obj, std::vector<std::size_t>(1, 0), r, error));
}

// Writes the two-chart grid atlas as OBJ (one vt per corner, groups per chart),
// reads it back and checks that both paths give the same report.
TEST(AtlasChecker, ReadObjRoundTrip)
{
  const Soup s = test_support::grid_with_holes(4, 2, 0);
  for(double shift : {0.25, -0.125})
  {
    Atlas<SM> a = two_charts(s, shift);
    const std::string path = temp_path("atlas_checker_round_trip.obj");
    std::vector<std::array<double, 2> > written_vt;
    {
      std::ofstream out(path.c_str());
      out.precision(17);
      for(auto v : vertices(a.tm))
      {
        const Point_3& p = a.tm.point(v);
        out << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
      }
      for(auto f : faces(a.tm))
      {
        out << "g chart" << a.patch.at(f) << "\nf";
        for(auto h : CGAL::halfedges_around_face(halfedge(f, a.tm), a.tm))
        {
          const Point_2& q = a.uv.at(h);
          written_vt.push_back(std::array<double, 2>{{q.x(), q.y()}});
          out << " " << (std::size_t(target(h, a.tm)) + 1) << "/" << written_vt.size();
        }
        out << "\n";
      }
      for(const auto& t : written_vt)
        out << "vt " << t[0] << " " << t[1] << "\n";
    }
    test_support::Obj_data obj;
    std::string error;
    ASSERT_TRUE(test_support::read_obj(path, obj, error)) << error;
    std::remove(path.c_str());
    ASSERT_EQ(obj.v.size(), num_vertices(a.tm));
    ASSERT_EQ(obj.face_v.size(), num_faces(a.tm));
    ASSERT_EQ(obj.vt.size(), written_vt.size());
    for(std::size_t i = 0; i < written_vt.size(); ++i)
      EXPECT_EQ(obj.vt[i], written_vt[i]);
    std::size_t fi = 0;
    for(auto f : faces(a.tm))
    {
      EXPECT_EQ(obj.face_group[fi], "chart" + std::to_string(a.patch.at(f)));
      std::size_t k = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, a.tm), a.tm))
      {
        EXPECT_EQ(obj.face_v[fi][k], std::size_t(target(h, a.tm)));
        ++k;
      }
      ++fi;
    }
    const std::vector<std::size_t> by_group = test_support::obj_patches_from_groups(obj);
    Atlas_report from_obj;
    ASSERT_TRUE(test_support::check_obj_atlas(obj, by_group, from_obj, error)) << error;
    const Atlas_report from_mesh = a.check();
    EXPECT_EQ(from_obj.summary(), from_mesh.summary());
    EXPECT_EQ(from_obj.ok(), shift > 0.);
    // every corner has its own vt index, but equal UV values still join the
    // faces of a chart (and only of a chart: the charts are not continuous)
    EXPECT_EQ(test_support::obj_patches_from_uv_connectivity(obj), by_group);
  }
}

// ------------------------------------------------------------- scale

// 100k triangles in 1000 separated charts (blocks of 10 x 5 squares) packed
// in [0,1]^2; must be clean and fast.
TEST(AtlasChecker, LargeAtlasWithThousandCharts)
{
  const int nx = 200, ny = 250, bw = 10, bh = 5;
  const Soup s = test_support::grid_with_holes(nx, ny, 0);
  const double gap = 0.5, span = std::max(nx + gap * (nx / bw), ny + gap * (ny / bh)) + 1.;
  auto block = [&](double x, double y) {
    return std::make_pair(std::min(int(x) / bw, nx / bw - 1), std::min(int(y) / bh, ny / bh - 1));
  };
  auto patch_of = [&](std::size_t f) {
    const std::array<double, 3> c = centroid(s, f);
    const auto b = block(c[0], c[1]);
    return std::size_t(b.second * (nx / bw) + b.first);
  };
  auto uv_of = [&](std::size_t, std::size_t p, std::size_t c) {
    const double bx = double(c % std::size_t(nx / bw)), by = double(c / std::size_t(nx / bw));
    return Point_2((s.points[p][0] + gap * bx + 0.5) / span, (s.points[p][1] + gap * by + 0.5) / span);
  };
  Atlas<SM> a(s, patch_of, uv_of);
  const Atlas_report r = a.check(1024);
  expect_clean(r);
  EXPECT_EQ(r.number_of_charts, 1000u);
}

} // namespace
