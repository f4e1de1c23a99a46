// Tests of atlas_quality() on hand-built atlases. Every expected value is
// derived by hand in the comments (the definitions are those of
// Atlas_quality in atlas_quality.h); none is computed with the library's internals.
//
// Conventions used below (test_meshes.h):
//  * grid_with_holes(nx, ny, 0): point (i, j) has index j*(nx+1) + i; square
//    (i, j) is split into faces 2q = (i,j),(i+1,j),(i+1,j+1) and
//    2q+1 = (i,j),(i+1,j+1),(i,j+1), q = j*nx + i. Every face has 3D area 1/2.
//  * cylinder(n, H): radius 1, z in [0, 1]; point (i, h) has index h*n + i;
//    quad (i, h) (i = 0..n-1) gives faces 2q = (i,h),(i+1,h),(i+1,h+1) and
//    2q+1 = (i,h),(i+1,h+1),(i,h+1), q = h*n + i, column n meaning column 0.
//  * disk(R, n): unit disk, centre 0, outer ring a regular n-gon of radius 1.
// UV maps are per corner: uv[h] is the UV of target(h) seen from face(h).

#include "test_meshes.h"

#include <CGAL/Disk_segmentation/atlas_quality.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace {

namespace DS = CGAL::Disk_segmentation;
namespace TS = test_support;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Face_index, std::size_t> Patch_map;
typedef Mesh::Property_map<Mesh::Halfedge_index, Point_2> UV_map;

const double pi = 3.14159265358979323846;
// Tolerance of values that are exact up to a few roundings.
const double tol = 1e-12;

// A mesh made from a soup (face i = triangle i, vertex i = point i), with a
// per-corner UV map and a patch map (all faces in chart 0 to start with).
struct Atlas
{
  TS::Soup soup;
  Mesh mesh;
  UV_map uv;
  Patch_map patch;

  explicit Atlas(const TS::Soup& s) : soup(s)
  {
    TS::to_mesh(soup, mesh);
    uv = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv", Point_2(0, 0)).first;
    patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  }
  Atlas(const Atlas&) = delete;
  Atlas& operator=(const Atlas&) = delete;

  std::size_t number_of_faces() const { return soup.triangles.size(); }

  // uv_of(face index, vertex index) -> UV of that vertex as seen from that face.
  template <typename UV_of>
  void set_uv(const UV_of& uv_of)
  {
    for(Mesh::Face_index f : mesh.faces())
      for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
        uv[h] = uv_of(std::size_t(f.idx()), std::size_t(mesh.target(h).idx()));
  }

  // UV = (sx * x + ox, sy * y + oy) for every corner.
  void set_linear_uv(double sx, double sy, double ox = 0, double oy = 0)
  {
    set_uv([&](std::size_t, std::size_t v) {
      return Point_2(sx * soup.points[v][0] + ox, sy * soup.points[v][1] + oy);
    });
  }

  template <typename Chart_of>
  void set_patches(const Chart_of& chart_of)
  {
    for(Mesh::Face_index f : mesh.faces())
      patch[f] = chart_of(std::size_t(f.idx()));
  }

  DS::Atlas_quality quality() const { return DS::atlas_quality(mesh, patch, uv); }
  template <typename NamedParameters>
  DS::Atlas_quality quality(const NamedParameters& np) const { return DS::atlas_quality(mesh, patch, uv, np); }
};

// Every distortion at its ideal value (0 for the differences, 1 for the
// ratios, 2 for the benchmark's symmetric Dirichlet).
void expect_no_distortion(const DS::Atlas_quality& q)
{
  EXPECT_NEAR(q.angle_distortion.mean, 0, tol);
  EXPECT_NEAR(q.angle_distortion.percentile_95, 0, tol);
  EXPECT_NEAR(q.angle_distortion.max, 0, tol);
  EXPECT_NEAR(q.area_distortion.mean, 0, tol);
  EXPECT_NEAR(q.area_distortion.percentile_95, 0, tol);
  EXPECT_NEAR(q.area_distortion.max, 0, tol);
  EXPECT_NEAR(q.atlas_area_distortion.mean, 0, tol);
  EXPECT_NEAR(q.atlas_area_distortion.max, 0, tol);
  EXPECT_NEAR(q.conformal_ratio, 1, tol);
  EXPECT_NEAR(q.symmetric_dirichlet, 1, tol);
  EXPECT_NEAR(q.benchmark_area_distortion, 0, tol);
  EXPECT_NEAR(q.benchmark_angle_distortion, 0, tol);
  EXPECT_NEAR(q.benchmark_symmetric_dirichlet, 2, tol);
  EXPECT_NEAR(q.benchmark_atlas_area_distortion, 0, tol);
  EXPECT_NEAR(q.benchmark_atlas_symmetric_dirichlet, 2, tol);
}

// ---------------------------------------------------------------------------
// Identity maps of planar meshes.

// Grid 4x4 with one hole (square (1,1)): 15 unit squares, F = 30. UV = (x, y)/4
// maps [0,4]^2 onto [0,1]^2, a similarity: s1 = s2 = 1/4 on every face, so
// s1/s2 = 1 and, after scaling the chart's UV area (15/16) to its 3D area
// (15), s1 s2 = 1: every distortion is ideal. One chart, no seam (each
// vertex has one UV), packing = UV area = 15 * (1/4)^2 = 15/16. All UVs are
// dyadic, so texel centres on shared edges are exactly on them and belong to
// no triangle: no overlap at the default resolution.
TEST(QualityIdentity, GridWithHole)
{
  Atlas a(TS::grid_with_holes(4, 4, 1));
  ASSERT_EQ(a.number_of_faces(), 30u);
  a.set_linear_uv(0.25, 0.25);
  const DS::Atlas_quality q = a.quality();
  EXPECT_FALSE(q.failed) << q.failure_reason;
  EXPECT_EQ(q.number_of_faces, 30u);
  EXPECT_EQ(q.flipped_faces, 0u);
  EXPECT_EQ(q.degenerate_faces, 0u);
  EXPECT_EQ(q.zero_area_faces, 0u);
  EXPECT_EQ(q.flipped_percent, 0.);
  EXPECT_EQ(q.degenerate_percent, 0.);
  expect_no_distortion(q);
  EXPECT_EQ(q.number_of_charts, 1u);
  EXPECT_EQ(q.smallest_chart_faces, 30u);
  EXPECT_EQ(q.single_face_charts, 0u);
  EXPECT_EQ(q.seam_length, 0.);
  EXPECT_EQ(q.cut_length, 0.);
  EXPECT_NEAR(q.packing_efficiency, 15. / 16., tol);
  EXPECT_EQ(q.texel_overlaps, 0u);
}

// Disk with 4 rings of 16: F = 16 * (2*4 - 1) = 112. UV = ((x+1)/2, (y+1)/2)
// maps [-1,1]^2 onto [0,1]^2 (a similarity, s1 = s2 = 1/2). The mesh is the
// regular 16-gon of radius 1, area 16 * (1/2) sin(2 pi/16) = 8 sin(pi/8), so
// packing = (1/4) * 8 sin(pi/8) = 2 sin(pi/8) = 0.76536686...
TEST(QualityIdentity, Disk)
{
  Atlas a(TS::disk(4, 16));
  ASSERT_EQ(a.number_of_faces(), 112u);
  a.set_linear_uv(0.5, 0.5, 0.5, 0.5);
  const DS::Atlas_quality q = a.quality(DS::parameters::texture_resolution(0u));
  EXPECT_FALSE(q.failed) << q.failure_reason;
  EXPECT_EQ(q.number_of_faces, 112u);
  EXPECT_EQ(q.flipped_faces, 0u);
  EXPECT_EQ(q.degenerate_faces, 0u);
  expect_no_distortion(q);
  EXPECT_EQ(q.number_of_charts, 1u);
  EXPECT_EQ(q.smallest_chart_faces, 112u);
  EXPECT_EQ(q.single_face_charts, 0u);
  EXPECT_EQ(q.seam_length, 0.);
  EXPECT_EQ(q.cut_length, 0.);
  EXPECT_NEAR(q.packing_efficiency, 2 * std::sin(pi / 8), tol);
}

// Same atlas, overlaps counted at the default resolution (1024): the 112
// triangles tile the 16-gon without overlap, so no texel centre may be
// counted twice, not even the ones that lie (up to rounding) on the shared
// radial edges at 45 degrees, which pass through texel centres i == j.
TEST(QualityIdentity, DiskHasNoTexelOverlap)
{
  Atlas a(TS::disk(4, 16));
  a.set_linear_uv(0.5, 0.5, 0.5, 0.5);
  EXPECT_EQ(a.quality().texel_overlaps, 0u);
}

// ---------------------------------------------------------------------------
// Uniform scales.

// UV = k (x, y) on disk(3, 10), one chart: s1 = s2 = k, and the chart
// normalization (3D area / UV area = 1/k^2) brings s1 s2 back to 1, so the
// chart-normalized metrics are ideal for any k; with one chart the atlas
// normalization is the same, so the atlas-normalized ones are ideal too.
// Packing = k^2 * area(10-gon) = k^2 * 5 sin(2 pi/10).
TEST(QualityScale, OneChartIsScaleFree)
{
  for(double k : { 1e-6, 0.25, 3., 1e6 })
  {
    SCOPED_TRACE("k = " + std::to_string(k));
    Atlas a(TS::disk(3, 10));
    a.set_linear_uv(k, k);
    const DS::Atlas_quality q = a.quality(DS::parameters::texture_resolution(0u));
    EXPECT_FALSE(q.failed) << q.failure_reason;
    EXPECT_EQ(q.flipped_faces, 0u);
    EXPECT_EQ(q.degenerate_faces, 0u);
    expect_no_distortion(q);
    EXPECT_NEAR(q.packing_efficiency / (k * k), 5 * std::sin(2 * pi / 10), tol);
    EXPECT_EQ(q.texel_overlaps, 0u);  // resolution 0: not computed
  }
}

// Two charts of equal 3D area with different scales: grid_with_holes(2, 1, 0),
// chart 0 = square [0,1]^2 (faces 0, 1), chart 1 = square [1,2]x[0,1]
// (faces 2, 3). Chart 0: UV = a (x, y) with a = 1/4; chart 1:
// UV = b (x - 1, y) + (1/2, 0) with b = 1/2.
//
// Chart-normalized: each chart is a similarity, so everything is ideal.
// Atlas-normalized: total 3D area 2, total UV area a^2 + b^2 = 5/16, one
// scale k^2 = 2 / (a^2 + b^2) = 32/5 for both charts. Per face
// s1 s2 k^2 = a^2 k^2 = 2/5 on chart 0 and b^2 k^2 = 8/5 on chart 1, with
// equal 3D weights (1 each):
//   atlas area distortion mean = (|log(2/5)| + |log(8/5)|) / 2
//                              = (log(5/2) + log(8/5)) / 2 = log(4)/2 = log 2,
//   max = log(5/2); the 95th percentile is reached in the larger value:
//   sorted (log(8/5), weight 1), (log(5/2), weight 1), 1/2 < 0.95 <= 1 -> log(5/2).
//   benchmark atlas area = ((2/5 + 5/2 - 2) + (8/5 + 5/8 - 2)) / 2
//                        = (9/10 + 9/40) / 2 = 9/16,
//   benchmark atlas symmetric Dirichlet, s1 = s2 = sqrt(x): (2x + 2/x)/2 = x + 1/x:
//                        ((2/5 + 5/2) + (8/5 + 5/8)) / 2 = (29/10 + 89/40) / 2 = 41/16.
// The shared edge x = 1 (length 1) is seen at u = 1/4 from chart 0 and at
// u = 1/2 from chart 1: seam_length = 1, cut_length = 1/sqrt(2).
// Packing = a^2 + b^2 = 5/16. UV squares [0,1/4]^2 and [1/2,1]x[0,1/2]: no overlap.
TEST(QualityScale, TwoChartsWithDifferentScales)
{
  Atlas a(TS::grid_with_holes(2, 1, 0));
  ASSERT_EQ(a.number_of_faces(), 4u);
  a.set_patches([](std::size_t f) { return f / 2; });
  a.set_uv([&](std::size_t f, std::size_t v) {
    const double x = a.soup.points[v][0], y = a.soup.points[v][1];
    return f < 2 ? Point_2(0.25 * x, 0.25 * y) : Point_2(0.5 * (x - 1) + 0.5, 0.5 * y);
  });
  const DS::Atlas_quality q = a.quality();
  EXPECT_FALSE(q.failed) << q.failure_reason;
  EXPECT_EQ(q.flipped_faces, 0u);
  EXPECT_EQ(q.degenerate_faces, 0u);

  // Chart-normalized: ideal.
  EXPECT_NEAR(q.angle_distortion.mean, 0, tol);
  EXPECT_NEAR(q.area_distortion.mean, 0, tol);
  EXPECT_NEAR(q.area_distortion.max, 0, tol);
  EXPECT_NEAR(q.conformal_ratio, 1, tol);
  EXPECT_NEAR(q.symmetric_dirichlet, 1, tol);
  EXPECT_NEAR(q.benchmark_area_distortion, 0, tol);
  EXPECT_NEAR(q.benchmark_symmetric_dirichlet, 2, tol);

  // Atlas-normalized: exposes the uneven texel density.
  EXPECT_NEAR(q.atlas_area_distortion.mean, std::log(2.), tol);
  EXPECT_NEAR(q.atlas_area_distortion.max, std::log(2.5), tol);
  EXPECT_NEAR(q.atlas_area_distortion.percentile_95, std::log(2.5), tol);
  EXPECT_NEAR(q.benchmark_atlas_area_distortion, 9. / 16., tol);
  EXPECT_NEAR(q.benchmark_atlas_symmetric_dirichlet, 41. / 16., tol);

  EXPECT_EQ(q.number_of_charts, 2u);
  EXPECT_EQ(q.smallest_chart_faces, 2u);
  EXPECT_EQ(q.single_face_charts, 0u);
  EXPECT_NEAR(q.seam_length, 1, tol);
  EXPECT_NEAR(q.cut_length, 1 / std::sqrt(2.), tol);
  EXPECT_NEAR(q.packing_efficiency, 5. / 16., tol);
  EXPECT_EQ(q.texel_overlaps, 0u);
}

// ---------------------------------------------------------------------------
// A known stretch: UV = (2x, y) on a planar mesh, J = diag(2, 1) in any
// orthonormal frame of the plane z = 0 up to rotations, so s1 = 2, s2 = 1 on
// every face:
//   angle = |log(2/1)| = log 2 (mean = 95th percentile = max, uniform),
//   conformal ratio = 2, benchmark angle = 2 + 1/2 - 2 = 1/2;
//   chart normalization: UV area = 2 * 3D area, scale by 1/sqrt(2):
//   c1 = sqrt(2), c2 = 1/sqrt(2), c1 c2 = 1 -> area distortion 0 (log and
//   benchmark); symmetric Dirichlet = (2 + 1/2 + 1/2 + 2)/4 = 5/4, benchmark 5/2.
//   One chart: atlas-normalized = chart-normalized.
void expect_stretch_2_1(const DS::Atlas_quality& q)
{
  EXPECT_FALSE(q.failed) << q.failure_reason;
  EXPECT_EQ(q.flipped_faces, 0u);
  EXPECT_EQ(q.degenerate_faces, 0u);
  EXPECT_NEAR(q.angle_distortion.mean, std::log(2.), tol);
  EXPECT_NEAR(q.angle_distortion.percentile_95, std::log(2.), tol);
  EXPECT_NEAR(q.angle_distortion.max, std::log(2.), tol);
  EXPECT_NEAR(q.conformal_ratio, 2, tol);
  EXPECT_NEAR(q.benchmark_angle_distortion, 0.5, tol);
  EXPECT_NEAR(q.area_distortion.mean, 0, tol);
  EXPECT_NEAR(q.area_distortion.percentile_95, 0, tol);
  EXPECT_NEAR(q.area_distortion.max, 0, tol);
  EXPECT_NEAR(q.atlas_area_distortion.mean, 0, tol);
  EXPECT_NEAR(q.benchmark_area_distortion, 0, tol);
  EXPECT_NEAR(q.benchmark_atlas_area_distortion, 0, tol);
  EXPECT_NEAR(q.symmetric_dirichlet, 1.25, tol);
  EXPECT_NEAR(q.benchmark_symmetric_dirichlet, 2.5, tol);
  EXPECT_NEAR(q.benchmark_atlas_symmetric_dirichlet, 2.5, tol);
}

// Grid 3x2 (F = 12, 3D area 6): UV area = 2 * 6 = 12 (the map leaves [0,1]^2;
// packing is still the plain sum of UV areas).
TEST(QualityStretch, GridTwoToOne)
{
  Atlas a(TS::grid_with_holes(3, 2, 0));
  a.set_linear_uv(2, 1);
  const DS::Atlas_quality q = a.quality();
  expect_stretch_2_1(q);
  EXPECT_EQ(q.seam_length, 0.);
  EXPECT_NEAR(q.packing_efficiency, 12, tol);
}

// The disk's triangles have edges in every direction, so the frame of each
// face (first edge along its local x axis) is rotated differently; the
// singular values must not depend on it. Disk(3, 12): 12-gon of area
// 6 sin(2 pi/12) = 3; UV = (x/2 + 1/2, y/4 + 1/2) is the same stretch
// (ratio 2) scaled by 1/4: packing = 3 * (1/2)(1/4) = 3/8.
TEST(QualityStretch, DiskTwoToOneInEveryFrame)
{
  Atlas a(TS::disk(3, 12));
  a.set_linear_uv(0.5, 0.25, 0.5, 0.5);
  const DS::Atlas_quality q = a.quality();
  expect_stretch_2_1(q);
  EXPECT_NEAR(q.packing_efficiency, 3. / 8., tol);
  EXPECT_EQ(q.texel_overlaps, 0u);
}

// ---------------------------------------------------------------------------
// Cylinder cut along the vertical line at angle 0 and unrolled into one
// chart. cylinder(12, 3): the faceted surface is 12 planar rectangles of
// width w = 2 sin(pi/12) (the chord) and height 1, so the total 3D area is
// A = 12 w = 24 sin(pi/12) = 6.2116570824...; unrolling the column i at
// u = i w (faces of the last quad see vertex column 0 at u = 12 w, the faces
// of quad 0 at u = 0) and v = z is an isometry on every face: no distortion.
// Seam edges: the 3 vertical edges of column 0, each of length 1/3:
// seam_length = 1 = the height; cut_length = 1 / sqrt(24 sin(pi/12)) = 0.40123...
// The other vertical edges and all the diagonals see equal UVs: no seam.
// Packing = the UV area = the 3D area = 24 sin(pi/12).
const int cyl_n = 12, cyl_h = 3;

// Column of vertex v as seen from face f (n or 0 for the cut column).
int cylinder_column(std::size_t f, std::size_t v)
{
  const int column = int(v % cyl_n);
  const int quad_column = int((f / 2) % cyl_n);
  return (column == 0 && quad_column == cyl_n - 1) ? cyl_n : column;
}

TEST(QualityCylinder, OneVerticalCut)
{
  Atlas a(TS::cylinder(cyl_n, cyl_h));
  ASSERT_EQ(a.number_of_faces(), std::size_t(2 * cyl_n * cyl_h));
  const double w = 2 * std::sin(pi / cyl_n);
  a.set_uv([&](std::size_t f, std::size_t v) {
    return Point_2(cylinder_column(f, v) * w, a.soup.points[v][2]);
  });
  const DS::Atlas_quality q = a.quality();
  EXPECT_FALSE(q.failed) << q.failure_reason;
  EXPECT_EQ(q.flipped_faces, 0u);
  EXPECT_EQ(q.degenerate_faces, 0u);
  expect_no_distortion(q);
  EXPECT_EQ(q.number_of_charts, 1u);
  EXPECT_EQ(q.smallest_chart_faces, 72u);
  const double area = 24 * std::sin(pi / 12);
  EXPECT_NEAR(q.seam_length, 1, tol);
  EXPECT_NEAR(q.cut_length, 1 / std::sqrt(area), tol);
  EXPECT_NEAR(q.packing_efficiency, area, tol);
  EXPECT_EQ(q.texel_overlaps, 0u);
}

// The same unrolling stretched along u by 2 (UV = (2 i w, z)): on every 3D
// face J = diag(2, 1) in the frame (around, up), the same values as the
// planar stretch; the seams are unchanged (seam_length = 1).
TEST(QualityCylinder, UnrolledAndStretched)
{
  Atlas a(TS::cylinder(cyl_n, cyl_h));
  const double w = 2 * std::sin(pi / cyl_n);
  a.set_uv([&](std::size_t f, std::size_t v) {
    return Point_2(2 * cylinder_column(f, v) * w, a.soup.points[v][2]);
  });
  const DS::Atlas_quality q = a.quality(DS::parameters::texture_resolution(0u));
  expect_stretch_2_1(q);
  EXPECT_NEAR(q.seam_length, 1, tol);
  EXPECT_NEAR(q.cut_length, 1 / std::sqrt(24 * std::sin(pi / 12)), tol);
}

// ---------------------------------------------------------------------------
// Flipped and degenerate faces, on grid_with_holes(4, 4, 0) (F = 32) with
// UV = (x, y)/4. Face 0 is (0,0),(1,0),(1,1) = vertices 0, 1, 6.

// Face 0 with the UVs of its corners at vertices 1 and 6 swapped: UV
// triangle (0,0), (1/4,1/4), (1/4,0), clockwise -> det J < 0, flipped.
// In grid units J maps (1,0) -> (1,1) and (1,1) -> (1,0), so
// J = [1 0; 1 -1], J^T J = [2 -1; -1 1], s^2 = (3 +- sqrt 5)/2: s1/s2 =
// (3 + sqrt 5)/2 = 2.618: had the face been measured, the angle mean would be
// log(2.618)/31.5... > 0 and the max log(2.618) = 0.962. It must be skipped:
// the 31 other faces are similarities, angle distortion 0, conformal 1.
// flipped_percent = 100/32 = 3.125.
// Seams: edge 1-6 (length 1) is seen by face 3 as (1/4,0)-(1/4,1/4) and by
// face 0 swapped; edge 0-6 (length sqrt 2) disagrees with face 1 at vertex 6;
// edge 0-1 is on the border. seam_length = 1 + sqrt 2, cut = (1 + sqrt 2)/4.
void flip_face_0(Atlas& a)
{
  a.set_uv([&](std::size_t f, std::size_t v) {
    std::size_t w = v;
    if(f == 0 && v == 1) w = 6;
    else if(f == 0 && v == 6) w = 1;
    return Point_2(0.25 * a.soup.points[w][0], 0.25 * a.soup.points[w][1]);
  });
}

TEST(QualityFlipped, OneMirroredFace)
{
  Atlas a(TS::grid_with_holes(4, 4, 0));
  ASSERT_EQ(a.number_of_faces(), 32u);
  flip_face_0(a);
  const DS::Atlas_quality q = a.quality();
  EXPECT_FALSE(q.failed) << q.failure_reason;
  EXPECT_EQ(q.flipped_faces, 1u);
  EXPECT_DOUBLE_EQ(q.flipped_percent, 100. / 32.);
  EXPECT_EQ(q.degenerate_faces, 0u);
  EXPECT_EQ(q.degenerate_percent, 0.);
  EXPECT_NEAR(q.angle_distortion.mean, 0, tol);
  EXPECT_NEAR(q.angle_distortion.max, 0, tol);
  EXPECT_NEAR(q.conformal_ratio, 1, tol);
  EXPECT_NEAR(q.benchmark_angle_distortion, 0, tol);
  EXPECT_NEAR(q.seam_length, 1 + std::sqrt(2.), tol);
  EXPECT_NEAR(q.cut_length, (1 + std::sqrt(2.)) / 4, tol);
}

// The flipped face covers exactly the UV triangle it covered before the swap,
// so the chart still covers [0,1]^2: its UV area is 1 = 32 triangles of area
// 1/32 ("sum of UV triangle areas"), equal to 3D area 16 times 1/16. The
// chart normalization is then 16 and every measured face has s1 s2 = 1:
// area distortion 0, packing efficiency 1. (Counting the flipped triangle's
// area as negative would give a UV area of 30/32, a normalization of
// 16 * 32/30 and an area distortion of log(16/15) = 0.0645 on every face.)
TEST(QualityFlipped, FlippedFaceAreaCountsInNormalizationAndPacking)
{
  Atlas a(TS::grid_with_holes(4, 4, 0));
  flip_face_0(a);
  const DS::Atlas_quality q = a.quality();
  EXPECT_NEAR(q.area_distortion.mean, 0, tol);
  EXPECT_NEAR(q.area_distortion.max, 0, tol);
  EXPECT_NEAR(q.atlas_area_distortion.mean, 0, tol);
  EXPECT_NEAR(q.benchmark_area_distortion, 0, tol);
  EXPECT_NEAR(q.symmetric_dirichlet, 1, tol);
  EXPECT_NEAR(q.packing_efficiency, 1, tol);
}

// Face 0 with its corner at vertex 1 moved to (1/8, 1/8), the midpoint of the
// UVs of vertices 0 and 6: UV triangle (0,0), (1/8,1/8), (1/4,1/4) on a line,
// det J = 0 exactly (dyadic values) -> degenerate, not flipped.
// It is skipped: angle distortion 0 on the 31 other faces. Chart UV area =
// 31/32 (face 0 has none), 3D area 16: per face s1 s2 = 1/16 is normalized
// by 16 * 32/31, giving s1 s2 = 32/31 -> area distortion log(32/31) on each
// of the 31 faces (mean, max), packing = 31/32. Seams: edge 1-6 only
// (face 3 sees vertex 1 at (1/4, 0)), length 1; edge 0-6 keeps its UVs.
TEST(QualityDegenerate, OneCollapsedFace)
{
  Atlas a(TS::grid_with_holes(4, 4, 0));
  a.set_uv([&](std::size_t f, std::size_t v) {
    if(f == 0 && v == 1)
      return Point_2(0.125, 0.125);
    return Point_2(0.25 * a.soup.points[v][0], 0.25 * a.soup.points[v][1]);
  });
  const DS::Atlas_quality q = a.quality();
  EXPECT_FALSE(q.failed) << q.failure_reason;
  EXPECT_EQ(q.degenerate_faces, 1u);
  EXPECT_DOUBLE_EQ(q.degenerate_percent, 100. / 32.);
  EXPECT_EQ(q.flipped_faces, 0u);
  EXPECT_EQ(q.zero_area_faces, 0u);
  EXPECT_NEAR(q.angle_distortion.mean, 0, tol);
  EXPECT_NEAR(q.angle_distortion.max, 0, tol);
  EXPECT_NEAR(q.conformal_ratio, 1, tol);
  EXPECT_NEAR(q.area_distortion.mean, std::log(32. / 31.), tol);
  EXPECT_NEAR(q.area_distortion.max, std::log(32. / 31.), tol);
  EXPECT_NEAR(q.packing_efficiency, 31. / 32., tol);
  EXPECT_NEAR(q.seam_length, 1, tol);
  EXPECT_NEAR(q.cut_length, 0.25, tol);
}

// ---------------------------------------------------------------------------
// Texel overlaps on grid_with_holes(2, 1, 0): chart 0 = faces 0, 1 (square
// [0,1]^2), chart 1 = faces 2, 3 (square [1,2]x[0,1]), each mapped to a
// square of side 1/2: chart 0 at [0,1/2]^2, chart 1 at offset (ox, oy).
// Inside one chart, texel centres on the square's diagonal lie on the edge
// shared by its two triangles and belong to neither.
void place_two_squares(Atlas& a, double ox, double oy)
{
  a.set_patches([](std::size_t f) { return f / 2; });
  a.set_uv([&a, ox, oy](std::size_t f, std::size_t v) {
    const double x = a.soup.points[v][0], y = a.soup.points[v][1];
    return f < 2 ? Point_2(0.5 * x, 0.5 * y) : Point_2(0.5 * (x - 1) + ox, 0.5 * y + oy);
  });
}

std::size_t overlaps(const Atlas& a, unsigned int resolution)
{
  return a.quality(DS::parameters::texture_resolution(resolution)).texel_overlaps;
}

// Resolution 8, centres ((i + 1/2)/8, (j + 1/2)/8). Chart 0 covers the
// centres with i, j in 0..3 and i != j (12). Chart 1 on top of it (offset 0):
// the same 12 -> 12 overlaps. At the default resolution 1024: i, j in 0..511,
// i != j -> 512^2 - 512 = 261632.
TEST(QualityTexelOverlap, ChartsOnTopOfEachOther)
{
  Atlas a(TS::grid_with_holes(2, 1, 0));
  place_two_squares(a, 0, 0);
  EXPECT_EQ(overlaps(a, 8), 12u);
  EXPECT_EQ(a.quality().texel_overlaps, 261632u);
}

// Chart 1 at [1/4,3/4]^2: it covers i, j in 2..5, i != j (its diagonal is
// also y = x). Common centres: i, j in {2, 3}, i != j -> 2.
TEST(QualityTexelOverlap, ChartsOverlappingByAQuarter)
{
  Atlas a(TS::grid_with_holes(2, 1, 0));
  place_two_squares(a, 0.25, 0.25);
  EXPECT_EQ(overlaps(a, 8), 2u);
}

// Chart 1 at [1/16, 9/16]x[0,1/2]: (i + 1/2)/8 in (1/16, 9/16) -> i in 1..4,
// j in 0..3; its diagonal y = x - 1/16 meets no centre (i - j = 1/2).
// Common with chart 0 (i, j in 0..3, i != j): i in 1..3, j in 0..3, i != j
// -> 12 - 3 = 9.
TEST(QualityTexelOverlap, ChartsShiftedByHalfATexel)
{
  Atlas a(TS::grid_with_holes(2, 1, 0));
  place_two_squares(a, 1. / 16., 0);
  EXPECT_EQ(overlaps(a, 8), 9u);
}

// Chart 1 mirrored onto chart 0: UV = (1/2 - (x - 1)/2, y/2), so both its
// faces are flipped (clockwise UV triangles), and its diagonal (1,0)-(2,1)
// lands on the anti-diagonal x + y = 1/2: centres with i + j = 3. Chart 1
// covers i, j in 0..3 with i + j != 3 (12), chart 0 those with i != j (12);
// no centre has both i = j and i + j = 3, so the common ones are
// 16 - 4 - 4 = 8. Overlaps are counted whatever the winding.
TEST(QualityTexelOverlap, MirroredChartOnTop)
{
  Atlas a(TS::grid_with_holes(2, 1, 0));
  a.set_patches([](std::size_t f) { return f / 2; });
  a.set_uv([&a](std::size_t f, std::size_t v) {
    const double x = a.soup.points[v][0], y = a.soup.points[v][1];
    return f < 2 ? Point_2(0.5 * x, 0.5 * y) : Point_2(0.5 - 0.5 * (x - 1), 0.5 * y);
  });
  const DS::Atlas_quality q = a.quality(DS::parameters::texture_resolution(8u));
  EXPECT_EQ(q.flipped_faces, 2u);
  EXPECT_DOUBLE_EQ(q.flipped_percent, 50.);
  EXPECT_EQ(q.texel_overlaps, 8u);
}

// Chart 1 at [1/2,1]x[0,1/2], beside chart 0: no common centre, at any
// resolution.
TEST(QualityTexelOverlap, SeparatedCharts)
{
  Atlas a(TS::grid_with_holes(2, 1, 0));
  place_two_squares(a, 0.5, 0);
  EXPECT_EQ(overlaps(a, 8), 0u);
  EXPECT_EQ(overlaps(a, 1024), 0u);
  EXPECT_EQ(overlaps(a, 1000), 0u);
}

// Resolution 0: overlaps are not computed (0), even when charts overlap.
TEST(QualityTexelOverlap, ResolutionZeroSkipsTheCount)
{
  Atlas a(TS::grid_with_holes(2, 1, 0));
  place_two_squares(a, 0, 0);
  EXPECT_EQ(overlaps(a, 0), 0u);
}

// All four faces mapped to the same large triangle (-1,-1), (L,-1), (-1,L)
// with L = 1e19 (finite, beyond the range of a 64-bit integer in texels):
// it contains [0,1]^2, so each of the 4 x 4 texel centres is covered four
// times and counted once: 16 overlaps. (Texel indices must be clamped to
// the grid before any conversion to an integer.)
TEST(QualityTexelOverlap, HugeTrianglesCoveringTheTexture)
{
  Atlas a(TS::grid_with_holes(2, 1, 0));
  const double L = 1e19;
  a.set_uv([&](std::size_t f, std::size_t v) {
    // Corner k of face f (soup order) gets the k-th UV corner.
    const auto& t = a.soup.triangles[f];
    if(v == t[0]) return Point_2(-1, -1);
    if(v == t[1]) return Point_2(L, -1);
    return Point_2(-1, L);
  });
  EXPECT_EQ(overlaps(a, 4), 16u);
}

// ---------------------------------------------------------------------------
// Failure: a non-finite UV is reported, not thrown.
TEST(QualityFailure, NonFiniteUv)
{
  for(double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity() })
  {
    SCOPED_TRACE("bad = " + std::to_string(bad));
    Atlas a(TS::disk(2, 8));
    a.set_uv([&](std::size_t f, std::size_t v) {
      const double x = a.soup.points[v][0], y = a.soup.points[v][1];
      return (f == 5 && v == a.soup.triangles[5][1]) ? Point_2(x, bad) : Point_2(x, y);
    });
    DS::Atlas_quality q;
    EXPECT_NO_THROW(q = a.quality());
    EXPECT_TRUE(q.failed);
    EXPECT_FALSE(q.failure_reason.empty());
  }
}

// A finite atlas does not fail and has no reason.
TEST(QualityFailure, FiniteUvDoesNotFail)
{
  Atlas a(TS::disk(2, 8));
  a.set_linear_uv(1, 1);
  const DS::Atlas_quality q = a.quality();
  EXPECT_FALSE(q.failed);
  EXPECT_TRUE(q.failure_reason.empty());
}

// ---------------------------------------------------------------------------
// Chart counts on grid_with_holes(3, 2, 0) (F = 12) with identity UVs (no
// seam whatever the partition: chart borders with agreeing UVs are no cuts).

// Charts {0..5}, {6..9}, {10}, {11}: 4 charts, the smallest has 1 face, 2 of
// them have one face.
TEST(QualityCharts, MixedSizes)
{
  Atlas a(TS::grid_with_holes(3, 2, 0));
  a.set_linear_uv(1. / 3., 1. / 3.);
  a.set_patches([](std::size_t f) -> std::size_t { return f < 6 ? 0 : f < 10 ? 1 : f == 10 ? 2 : 3; });
  const DS::Atlas_quality q = a.quality();
  EXPECT_EQ(q.number_of_faces, 12u);
  EXPECT_EQ(q.number_of_charts, 4u);
  EXPECT_EQ(q.smallest_chart_faces, 1u);
  EXPECT_EQ(q.single_face_charts, 2u);
  EXPECT_EQ(q.seam_length, 0.);
  EXPECT_EQ(q.cut_length, 0.);
  expect_no_distortion(q);
}

// One chart per square: 6 charts of 2 faces.
TEST(QualityCharts, OneChartPerSquare)
{
  Atlas a(TS::grid_with_holes(3, 2, 0));
  a.set_linear_uv(1. / 3., 1. / 3.);
  a.set_patches([](std::size_t f) { return f / 2; });
  const DS::Atlas_quality q = a.quality();
  EXPECT_EQ(q.number_of_charts, 6u);
  EXPECT_EQ(q.smallest_chart_faces, 2u);
  EXPECT_EQ(q.single_face_charts, 0u);
}

// One chart per face: 12 single-face charts.
TEST(QualityCharts, OneChartPerFace)
{
  Atlas a(TS::grid_with_holes(3, 2, 0));
  a.set_linear_uv(1. / 3., 1. / 3.);
  a.set_patches([](std::size_t f) { return f; });
  const DS::Atlas_quality q = a.quality();
  EXPECT_EQ(q.number_of_charts, 12u);
  EXPECT_EQ(q.smallest_chart_faces, 1u);
  EXPECT_EQ(q.single_face_charts, 12u);
}

// ---------------------------------------------------------------------------
// Scale invariance: the cylinder with a non-uniform unrolling (so that the
// distortions are not trivially 0) measured with its own points and with
// points scaled by s = 2^20 or 2^-20 through vertex_point_map. Distortions
// and cut_length are scale free; seam_length scales by s (it is 1 at s = 1:
// the 3 vertical edges of the cut).
TEST(QualityScaleInvariance, VertexPointMapScaledByPowersOfTwo)
{
  Atlas a(TS::cylinder(cyl_n, cyl_h));
  const double w = 2 * std::sin(pi / cyl_n);
  a.set_uv([&](std::size_t f, std::size_t v) {
    const double c = cylinder_column(f, v), z = a.soup.points[v][2];
    return Point_2(c * w * (1 + 0.25 * z), z + 0.1 * c * w * z);
  });
  const DS::Atlas_quality q = a.quality(DS::parameters::texture_resolution(0u));
  ASSERT_FALSE(q.failed) << q.failure_reason;
  EXPECT_EQ(q.flipped_faces, 0u);
  EXPECT_GT(q.angle_distortion.mean, 0.01);
  EXPECT_GT(q.area_distortion.mean, 0.01);
  EXPECT_NEAR(q.seam_length, 1, tol);

  for(double s : { std::ldexp(1., 20), std::ldexp(1., -20) })
  {
    SCOPED_TRACE("s = " + std::to_string(s));
    auto scaled = a.mesh.add_property_map<Mesh::Vertex_index, K::Point_3>("v:scaled", K::Point_3(0, 0, 0)).first;
    for(Mesh::Vertex_index v : a.mesh.vertices())
    {
      const K::Point_3& p = a.mesh.point(v);
      scaled[v] = K::Point_3(s * p.x(), s * p.y(), s * p.z());
    }
    const DS::Atlas_quality r =
      a.quality(DS::parameters::vertex_point_map(scaled).texture_resolution(0u));
    a.mesh.remove_property_map(scaled);
    ASSERT_FALSE(r.failed) << r.failure_reason;
    EXPECT_EQ(r.flipped_faces, q.flipped_faces);
    EXPECT_EQ(r.degenerate_faces, q.degenerate_faces);
    EXPECT_DOUBLE_EQ(r.angle_distortion.mean, q.angle_distortion.mean);
    EXPECT_DOUBLE_EQ(r.angle_distortion.percentile_95, q.angle_distortion.percentile_95);
    EXPECT_DOUBLE_EQ(r.angle_distortion.max, q.angle_distortion.max);
    EXPECT_DOUBLE_EQ(r.area_distortion.mean, q.area_distortion.mean);
    EXPECT_DOUBLE_EQ(r.area_distortion.max, q.area_distortion.max);
    EXPECT_DOUBLE_EQ(r.atlas_area_distortion.mean, q.atlas_area_distortion.mean);
    EXPECT_DOUBLE_EQ(r.conformal_ratio, q.conformal_ratio);
    EXPECT_DOUBLE_EQ(r.symmetric_dirichlet, q.symmetric_dirichlet);
    EXPECT_DOUBLE_EQ(r.benchmark_area_distortion, q.benchmark_area_distortion);
    EXPECT_DOUBLE_EQ(r.benchmark_angle_distortion, q.benchmark_angle_distortion);
    EXPECT_DOUBLE_EQ(r.cut_length, q.cut_length);
    EXPECT_NEAR(r.cut_length, 1 / std::sqrt(24 * std::sin(pi / 12)), tol);
    EXPECT_DOUBLE_EQ(r.seam_length, s * q.seam_length);
    EXPECT_NEAR(r.seam_length / s, 1, tol);
    EXPECT_DOUBLE_EQ(r.packing_efficiency, q.packing_efficiency);
  }
}

} // namespace
