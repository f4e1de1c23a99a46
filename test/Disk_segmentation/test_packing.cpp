// Tests of pack_patches(). Meshes, patch partitions and input UVs are made
// here, and every property of the result is checked with code written here,
// not with the packer's helpers.

#include "test_meshes.h"

#include <CGAL/Disk_segmentation/pack_patches.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <iostream>
#include <limits>
#include <map>
#include <vector>

namespace DS = CGAL::Disk_segmentation;
namespace TS = test_support;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
typedef Mesh::Property_map<face_descriptor, std::size_t> Patch_map;
typedef Mesh::Property_map<halfedge_descriptor, Point_2> UV_map;

namespace {

const double pi = 3.14159265358979323846;

typedef std::array<double, 3> Vec3;

Vec3 sub(const Vec3& a, const Vec3& b) { return {{ a[0] - b[0], a[1] - b[1], a[2] - b[2] }}; }
Vec3 cross3(const Vec3& a, const Vec3& b)
{
  return {{ a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] }};
}
double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm3(const Vec3& a) { return std::sqrt(dot3(a, a)); }

Vec3 point3(const Mesh& m, Mesh::Vertex_index v)
{
  const K::Point_3& p = m.point(v);
  return {{ p.x(), p.y(), p.z() }};
}

double signed_area(const Point_2& a, const Point_2& b, const Point_2& c)
{
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
}

// A test case: a mesh, a partition into patches and per-corner UVs that are,
// per patch, a planar projection moved by an arbitrary similarity.
struct Case
{
  Mesh mesh;
  Patch_map patch;
  UV_map uv;
  std::size_t number_of_patches = 0;
  bool isometric_uv = false;  // input UVs are similar to the (planar) 3D patches
};

void init_maps(Case& c)
{
  c.patch = c.mesh.add_property_map<face_descriptor, std::size_t>("f:patch", 0).first;
  c.uv = c.mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
}

Vec3 centroid(const Mesh& m, face_descriptor f)
{
  Vec3 c = {{ 0., 0., 0. }};
  for(auto v : CGAL::vertices_around_face(m.halfedge(f), m))
  {
    const Vec3 p = point3(m, v);
    for(std::size_t i = 0; i < 3; ++i) c[i] += p[i] / 3.;
  }
  return c;
}

// UVs of every patch: projection onto the plane orthogonal to the patch's
// mean normal (kept counterclockwise), then an arbitrary similarity of the
// patch's own.
void make_projected_uvs(Case& c)
{
  std::vector<Vec3> normal(c.number_of_patches, Vec3{{ 0., 0., 0. }});
  for(face_descriptor f : faces(c.mesh))
  {
    const halfedge_descriptor h = c.mesh.halfedge(f);
    const Vec3 a = point3(c.mesh, c.mesh.source(h));
    const Vec3 b = point3(c.mesh, c.mesh.target(h));
    const Vec3 d = point3(c.mesh, c.mesh.target(c.mesh.next(h)));
    const Vec3 n = cross3(sub(b, a), sub(d, a));
    for(std::size_t i = 0; i < 3; ++i) normal[c.patch[f]][i] += n[i];
  }
  for(face_descriptor f : faces(c.mesh))
  {
    const std::size_t p = c.patch[f];
    Vec3 n = normal[p];
    const double ln = norm3(n);
    for(double& x : n) x /= ln;
    // e1, e2, n right-handed: a counterclockwise face seen from n stays so.
    const Vec3 helper = std::abs(n[0]) < 0.9 ? Vec3{{ 1., 0., 0. }} : Vec3{{ 0., 1., 0. }};
    Vec3 e1 = cross3(helper, n);
    const double l1 = norm3(e1);
    for(double& x : e1) x /= l1;
    const Vec3 e2 = cross3(n, e1);

    const double angle = 0.7 * double(p) + 0.3;
    const double scale = 0.5 + 0.37 * double(p % 7);
    const double tx = 1.3 * double(p) - 5., ty = 3. - 0.7 * double(p);
    for(halfedge_descriptor h : CGAL::halfedges_around_face(c.mesh.halfedge(f), c.mesh))
    {
      const Vec3 q = point3(c.mesh, c.mesh.target(h));
      const double x = dot3(q, e1), y = dot3(q, e2);
      c.uv[h] = Point_2(scale * (std::cos(angle) * x - std::sin(angle) * y) + tx,
                        scale * (std::sin(angle) * x + std::cos(angle) * y) + ty);
    }
  }
}

// Planar grid cut into blocks of varied widths and heights.
Case grid_case(const std::vector<int>& x_cuts, const std::vector<int>& y_cuts)
{
  Case c;
  TS::to_mesh(TS::grid_with_holes(x_cuts.back(), y_cuts.back(), 0), c.mesh);
  init_maps(c);
  const std::size_t columns = x_cuts.size() - 1;
  for(face_descriptor f : faces(c.mesh))
  {
    const Vec3 g = centroid(c.mesh, f);
    const std::size_t i = std::size_t(std::upper_bound(x_cuts.begin(), x_cuts.end(), g[0]) - x_cuts.begin()) - 1;
    const std::size_t j = std::size_t(std::upper_bound(y_cuts.begin(), y_cuts.end(), g[1]) - y_cuts.begin()) - 1;
    c.patch[f] = j * columns + i;
  }
  c.number_of_patches = columns * (y_cuts.size() - 1);
  c.isometric_uv = true;
  make_projected_uvs(c);
  return c;
}

Case varied_grid_case()
{
  return grid_case({ 0, 1, 3, 6, 10, 15, 21, 28, 36 }, { 0, 2, 3, 7, 8, 13, 14, 20 });
}

// Planar disk cut into sectors of the inner rings and thinner sectors of the outer ones.
Case disk_case()
{
  Case c;
  TS::to_mesh(TS::disk(8, 24), c.mesh);
  init_maps(c);
  for(face_descriptor f : faces(c.mesh))
  {
    const Vec3 g = centroid(c.mesh, f);
    const double r = std::sqrt(g[0] * g[0] + g[1] * g[1]);
    double a = std::atan2(g[1], g[0]);
    if(a < 0.) a += 2. * pi;
    if(r < 0.5)
      c.patch[f] = std::size_t(a / (2. * pi) * 3.);
    else
      c.patch[f] = 3 + std::size_t(a / (2. * pi) * 8.);
  }
  c.number_of_patches = 11;
  c.isometric_uv = true;
  make_projected_uvs(c);
  return c;
}

// Sphere cut into latitude bands and longitude sectors (curved patches).
Case sphere_case()
{
  Case c;
  TS::to_mesh(TS::uv_sphere(12, 24), c.mesh);
  init_maps(c);
  for(face_descriptor f : faces(c.mesh))
  {
    const Vec3 g = centroid(c.mesh, f);
    const double theta = std::acos(g[2] / norm3(g));
    double phi = std::atan2(g[1], g[0]);
    if(phi < 0.) phi += 2. * pi;
    const std::size_t band = std::min<std::size_t>(3, std::size_t(theta / pi * 4.));
    const std::size_t sector = std::min<std::size_t>(5, std::size_t(phi / (2. * pi) * 6.));
    c.patch[f] = band * 6 + sector;
  }
  c.number_of_patches = 24;
  make_projected_uvs(c);
  return c;
}

// Torus cut into three bands around the tube and sectors of varied widths
// around the axis: many curved charts of varied sizes.
Case torus_case()
{
  Case c;
  TS::to_mesh(TS::torus(60, 18), c.mesh);
  init_maps(c);
  const std::vector<double> cuts = { 0, 2, 5, 6, 10, 13, 14, 17, 22, 23, 26, 30, 31, 35, 40, 41, 45, 47, 52, 56, 60 };
  for(face_descriptor f : faces(c.mesh))
  {
    const Vec3 g = centroid(c.mesh, f);
    double phi = std::atan2(g[1], g[0]);
    if(phi < 0.) phi += 2. * pi;
    double theta = std::atan2(g[2], std::sqrt(g[0] * g[0] + g[1] * g[1]) - 1.);
    if(theta < 0.) theta += 2. * pi;
    const double slot = phi / (2. * pi) * 60.;
    const std::size_t sector = std::size_t(std::upper_bound(cuts.begin(), cuts.end(), slot) - cuts.begin()) - 1;
    const std::size_t band = std::min<std::size_t>(2, std::size_t(theta / (2. * pi) * 3.));
    c.patch[f] = band * (cuts.size() - 1) + sector;
  }
  c.number_of_patches = 3 * (cuts.size() - 1);
  make_projected_uvs(c);
  return c;
}

// Every face its own chart.
Case single_face_case(int nx, int ny)
{
  Case c;
  TS::to_mesh(TS::grid_with_holes(nx, ny, 0), c.mesh);
  init_maps(c);
  std::size_t i = 0;
  for(face_descriptor f : faces(c.mesh))
    c.patch[f] = i++;
  c.number_of_patches = i;
  c.isometric_uv = true;
  make_projected_uvs(c);
  return c;
}

// A flat "C": the ring between radii 0.55 and 1 less a 40-degree gap at +x,
// and, unless `with_square` is false, a 0.6 x 0.6 square apart from it
// (patch 1). The square fits inside the C's hollow (its diagonal, 0.85, is
// less than the hollow's diameter, 1.1) but not through the gap, nor in the
// corners of the C's bounding square.
Case c_and_square_case(bool with_square)
{
  TS::Soup soup;
  const int around = 48, across = 4;
  const double gap = 20. * pi / 180.;
  for(int i = 0; i <= around; ++i)
    for(int k = 0; k <= across; ++k)
    {
      const double phi = gap + (2. * pi - 2. * gap) * double(i) / around;
      const double radius = 0.55 + 0.45 * double(k) / across;
      TS::soup_detail::add_point(soup, radius * std::cos(phi), radius * std::sin(phi), 0.);
    }
  const auto ring = [](int i, int k) { return std::size_t(i * (across + 1) + k); };
  // e_phi x e_rho = -e_z: quads go (i, k), (i, k + 1), (i + 1, k + 1), (i + 1, k) for +z.
  for(int i = 0; i < around; ++i)
    for(int k = 0; k < across; ++k)
      TS::soup_detail::add_quad(soup, ring(i, k), ring(i, k + 1), ring(i + 1, k + 1), ring(i + 1, k));
  if(with_square)
  {
    const std::size_t first = soup.points.size();
    for(int j = 0; j <= 3; ++j)
      for(int i = 0; i <= 3; ++i)
        TS::soup_detail::add_point(soup, 5. + 0.2 * i, 0.2 * j, 0.);
    for(int j = 0; j < 3; ++j)
      for(int i = 0; i < 3; ++i)
        TS::soup_detail::add_quad(soup, first + std::size_t(j * 4 + i), first + std::size_t(j * 4 + i + 1),
                     first + std::size_t((j + 1) * 4 + i + 1), first + std::size_t((j + 1) * 4 + i));
  }
  Case c;
  TS::to_mesh(soup, c.mesh);
  init_maps(c);
  for(face_descriptor f : faces(c.mesh))
    c.patch[f] = centroid(c.mesh, f)[0] > 3. ? 1 : 0;
  c.number_of_patches = with_square ? 2 : 1;
  c.isometric_uv = true;
  make_projected_uvs(c);
  return c;
}

std::vector<Point_2> snapshot(const Case& c)
{
  std::vector<Point_2> uv(c.mesh.number_of_halfedges(), Point_2(0, 0));
  for(face_descriptor f : faces(c.mesh))
    for(halfedge_descriptor h : CGAL::halfedges_around_face(c.mesh.halfedge(f), c.mesh))
      uv[h.idx()] = c.uv[h];
  return uv;
}

struct Box
{
  double xmin = std::numeric_limits<double>::max(), ymin = std::numeric_limits<double>::max();
  double xmax = -std::numeric_limits<double>::max(), ymax = -std::numeric_limits<double>::max();
};

// Distance from p to the segment [a, b].
double point_segment_distance(const Point_2& p, const Point_2& a, const Point_2& b)
{
  const double dx = b.x() - a.x(), dy = b.y() - a.y(), l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / l2 : 0.;
  t = std::max(0., std::min(1., t));
  return std::hypot(p.x() - (a.x() + t * dx), p.y() - (a.y() + t * dy));
}

// The smallest distance between two sets of counterclockwise triangles: 0
// if a corner of one lies in a triangle of the other or two edges cross,
// else the smallest distance from a corner to an edge of the other set.
double chart_distance(const std::vector<std::array<Point_2, 3> >& s, const std::vector<std::array<Point_2, 3> >& t)
{
  double d = std::numeric_limits<double>::max();
  for(const auto& a : s)
    for(const auto& b : t)
      for(int i = 0; i < 3; ++i)
      {
        const Point_2 &p0 = a[i], &p1 = a[(i + 1) % 3], &q0 = b[i], &q1 = b[(i + 1) % 3];
        if(CGAL::do_intersect(K::Segment_2(p0, p1), K::Segment_2(q0, q1)))
          return 0.;
        bool inside_b = true, inside_a = true;
        for(int j = 0; j < 3; ++j)
        {
          inside_b = inside_b && signed_area(b[j], b[(j + 1) % 3], p0) > 0;
          inside_a = inside_a && signed_area(a[j], a[(j + 1) % 3], q0) > 0;
        }
        if(inside_a || inside_b)
          return 0.;
        for(int j = 0; j < 3; ++j)
        {
          d = std::min(d, point_segment_distance(p0, b[j], b[(j + 1) % 3]));
          d = std::min(d, point_segment_distance(q0, a[j], a[(j + 1) % 3]));
        }
      }
  return d;
}

// Checks everything pack_patches promises, from the input and output UVs.
// `aspect`: the texture's height over its width. Charts are checked in
// texel-proportional coordinates (u, aspect v), where each must be a similar
// copy of its input and the page is [0, 1] x [0, aspect].
void check_packing(const Case& c, const std::vector<Point_2>& before, const DS::Packing_report& report,
                   DS::Packing_method method, double resolution, double padding_in_texels, double aspect = 1.)
{
  auto page_uv = [&](halfedge_descriptor h) { return Point_2(c.uv[h].x(), aspect * c.uv[h].y()); };
  const Mesh& m = c.mesh;
  const std::size_t P = c.number_of_patches;
  ASSERT_EQ(report.number_of_charts, P);
  const double pad = padding_in_texels / resolution;
  const double eps = 1e-9;

  std::vector<std::vector<halfedge_descriptor> > corners(P);
  std::vector<double> uv_area(P, 0.), area3(P, 0.);
  std::vector<Box> box(P);
  double total_uv_area = 0.;
  for(face_descriptor f : faces(m))
  {
    const std::size_t p = c.patch[f];
    std::vector<Point_2> q;
    std::vector<Vec3> x;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
    {
      const Point_2& u = page_uv(h);
      ASSERT_TRUE(std::isfinite(u.x()) && std::isfinite(u.y()));
      ASSERT_GE(u.x(), 0.); ASSERT_LE(u.x(), 1.);
      ASSERT_GE(u.y(), 0.); ASSERT_LE(u.y(), aspect * (1. + 1e-12));
      q.push_back(u);
      x.push_back(point3(m, m.target(h)));
      corners[p].push_back(h);
      box[p].xmin = std::min(box[p].xmin, u.x()); box[p].xmax = std::max(box[p].xmax, u.x());
      box[p].ymin = std::min(box[p].ymin, u.y()); box[p].ymax = std::max(box[p].ymax, u.y());
    }
    const double a = signed_area(q[0], q[1], q[2]);
    EXPECT_GT(a, 0.) << "face lost its counterclockwise orientation";
    uv_area[p] += a;
    total_uv_area += a;
    area3[p] += 0.5 * norm3(cross3(sub(x[1], x[0]), sub(x[2], x[0])));
  }
  // Each chart's page comes from the report; every page is a unit square of
  // its own, used by some chart, and covered at most once.
  ASSERT_EQ(report.page_of_chart.size(), P);
  ASSERT_GE(report.number_of_pages, 1u);
  std::vector<double> page_area(report.number_of_pages, 0.);
  for(std::size_t p = 0; p < P; ++p)
  {
    ASSERT_LT(report.page_of_chart[p], report.number_of_pages);
    page_area[report.page_of_chart[p]] += uv_area[p];
  }
  ASSERT_EQ(report.page_efficiency.size(), report.number_of_pages);
  for(std::size_t k = 0; k < report.number_of_pages; ++k)
  {
    EXPECT_GT(page_area[k], 0.) << "page " << k << " holds no chart";
    EXPECT_LE(page_area[k], aspect);
    EXPECT_NEAR(report.page_efficiency[k], page_area[k] / aspect, 1e-9);
  }
  const double pages = double(report.number_of_pages);
  EXPECT_NEAR(report.efficiency, total_uv_area / aspect / pages, 1e-9 * std::max(1., total_uv_area));
  EXPECT_GT(report.efficiency, 0.);
  EXPECT_LE(report.efficiency, 1.);

  // One direct similarity per chart: z' = a z + b with complex a. A
  // reflection would need conj(z), so a small residual of this fit means
  // scale, rotation and translation only, and all distance ratios equal |a|.
  std::vector<double> chart_scale(P);
  for(std::size_t p = 0; p < P; ++p)
  {
    ASSERT_FALSE(corners[p].empty());
    const std::size_t h0 = corners[p][0].idx();
    std::size_t far = h0;
    for(halfedge_descriptor h : corners[p])
      if(CGAL::squared_distance(before[h.idx()], before[h0]) > CGAL::squared_distance(before[far], before[h0]))
        far = h.idx();
    const std::complex<double> z0(before[h0].x(), before[h0].y()), z1(before[far].x(), before[far].y());
    const halfedge_descriptor g0 = corners[p][0];
    halfedge_descriptor g1 = g0;
    for(halfedge_descriptor h : corners[p]) if(h.idx() == far) g1 = h;
    const std::complex<double> w0(page_uv(g0).x(), page_uv(g0).y()), w1(page_uv(g1).x(), page_uv(g1).y());
    const std::complex<double> a = (w1 - w0) / (z1 - z0);
    const std::complex<double> b = w0 - a * z0;
    const double size = std::abs(w1 - w0);
    for(halfedge_descriptor h : corners[p])
    {
      const std::complex<double> z(before[h.idx()].x(), before[h.idx()].y());
      const std::complex<double> w(page_uv(h).x(), page_uv(h).y());
      ASSERT_LT(std::abs(a * z + b - w), 1e-9 * std::max(size, 1e-3)) << "chart " << p << " is not a similar copy";
    }
    chart_scale[p] = std::sqrt(uv_area[p] / area3[p]);

    // Planar charts given isometric UVs: every edge has the same UV / 3D ratio.
    if(c.isometric_uv)
      for(halfedge_descriptor h : corners[p])
      {
        const halfedge_descriptor n = m.next(h);
        const double l3 = norm3(sub(point3(m, m.target(n)), point3(m, m.target(h))));
        const double luv = std::sqrt(CGAL::squared_distance(page_uv(n), page_uv(h)));
        ASSERT_NEAR(luv / l3, chart_scale[p], 1e-7 * chart_scale[p]);
      }
  }

  // Bounding boxes inside the square with the padding; charts pairwise at
  // least the padding apart. The tight packer may nest a chart into
  // another's box, so where boxes come closer than the padding the charts
  // themselves are measured: no corner of one inside a triangle of the
  // other, and every edge of one at least the padding from every edge of
  // the other.
  std::vector<std::vector<std::array<Point_2, 3> > > triangles(P);
  for(face_descriptor f : faces(m))
  {
    std::array<Point_2, 3> t;
    int i = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
      t[i++] = page_uv(h);
    triangles[c.patch[f]].push_back(t);
  }
  for(std::size_t p = 0; p < P; ++p)
  {
    EXPECT_GE(box[p].xmin, pad - eps); EXPECT_GE(box[p].ymin, pad - eps);
    EXPECT_LE(box[p].xmax, 1. - pad + eps); EXPECT_LE(box[p].ymax, aspect - pad + eps);
    for(std::size_t q = p + 1; q < P; ++q)
    {
      if(report.page_of_chart[p] != report.page_of_chart[q])
        continue;
      const double gap_x = std::max(box[q].xmin - box[p].xmax, box[p].xmin - box[q].xmax);
      const double gap_y = std::max(box[q].ymin - box[p].ymax, box[p].ymin - box[q].ymax);
      if(std::max(gap_x, gap_y) >= pad - eps)
        continue;
      ASSERT_GE(chart_distance(triangles[p], triangles[q]), pad - eps)
        << "charts " << p << " and " << q << " are too close";
    }
  }

  if(method == DS::Packing_method::TIGHT)
  {
    const double lo = *std::min_element(chart_scale.begin(), chart_scale.end());
    const double hi = *std::max_element(chart_scale.begin(), chart_scale.end());
    EXPECT_LE(hi, 1.01 * lo) << "texel density differs between charts";
    for(double s : chart_scale)
      EXPECT_NEAR(s * resolution, report.texels_per_unit, 1e-6 * report.texels_per_unit);
  }
  else
  {
    EXPECT_EQ(report.texels_per_unit, 0.);
  }
}

DS::Packing_report pack_and_check(Case& c, DS::Packing_method method, unsigned resolution = 1024,
                                  double padding = 2., double texels_per_unit = 0.)
{
  const std::vector<Point_2> before = snapshot(c);
  for(face_descriptor f : faces(c.mesh))
  {
    std::vector<Point_2> q;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(c.mesh.halfedge(f), c.mesh))
      q.push_back(c.uv[h]);
    EXPECT_GT(signed_area(q[0], q[1], q[2]), 0.) << "test input is not counterclockwise";
  }
  const DS::Packing_report report =
    DS::pack_patches(c.mesh, c.patch, c.uv,
                     DS::parameters::packing_method(method).texture_resolution(resolution).padding_in_texels(padding)
                       .texels_per_unit(texels_per_unit));
  check_packing(c, before, report, method, double(resolution), padding);
  return report;
}

const char* name(DS::Packing_method m) { return m == DS::Packing_method::TIGHT ? "TIGHT" : "GRID"; }

} // namespace

TEST(Packing, VariedGridBothMethods)
{
  double efficiency[2];
  int k = 0;
  for(DS::Packing_method method : { DS::Packing_method::TIGHT, DS::Packing_method::GRID })
  {
    Case c = varied_grid_case();
    const DS::Packing_report r = pack_and_check(c, method);
    std::cout << "[ varied grid, " << c.number_of_patches << " charts ] " << name(method)
              << " efficiency " << r.efficiency << std::endl;
    efficiency[k++] = r.efficiency;
  }
  EXPECT_GE(efficiency[0], efficiency[1]);
}

TEST(Packing, DiskAndSphereBothMethods)
{
  for(DS::Packing_method method : { DS::Packing_method::TIGHT, DS::Packing_method::GRID })
  {
    Case d = disk_case();
    const DS::Packing_report rd = pack_and_check(d, method);
    Case s = sphere_case();
    const DS::Packing_report rs = pack_and_check(s, method, 512, 3.5);
    std::cout << "[ disk, 11 charts ] " << name(method) << " efficiency " << rd.efficiency << std::endl;
    std::cout << "[ sphere, 24 charts ] " << name(method) << " efficiency " << rs.efficiency << std::endl;
  }
}

TEST(Packing, ManySmallChartsTightBeatsGrid)
{
  double efficiency[2];
  int k = 0;
  for(DS::Packing_method method : { DS::Packing_method::TIGHT, DS::Packing_method::GRID })
  {
    // 3 x 3 blocks of varied size next to a field of single squares.
    std::vector<int> cuts;
    for(int x = 0; x <= 12; ++x) cuts.push_back(x);
    cuts.push_back(17);
    cuts.push_back(25);
    cuts.push_back(36);
    Case c = grid_case(cuts, cuts);
    const DS::Packing_report r = pack_and_check(c, method, 2048, 1.);
    std::cout << "[ mixed grid, " << c.number_of_patches << " charts ] " << name(method)
              << " efficiency " << r.efficiency << std::endl;
    efficiency[k++] = r.efficiency;
  }
  EXPECT_GT(efficiency[0], efficiency[1]);
}

TEST(Packing, TorusBothMethods)
{
  double efficiency[2];
  int k = 0;
  for(DS::Packing_method method : { DS::Packing_method::TIGHT, DS::Packing_method::GRID })
  {
    Case c = torus_case();
    const DS::Packing_report r = pack_and_check(c, method, 4096, 2.);
    std::cout << "[ torus, " << c.number_of_patches << " charts ] " << name(method)
              << " efficiency " << r.efficiency << std::endl;
    efficiency[k++] = r.efficiency;
  }
  EXPECT_GE(efficiency[0], efficiency[1]);
}

TEST(Packing, SingleFaceChartsAndZeroPadding)
{
  for(DS::Packing_method method : { DS::Packing_method::TIGHT, DS::Packing_method::GRID })
  {
    Case c = single_face_case(7, 5);
    pack_and_check(c, method, 256, 0.);
    Case one = single_face_case(1, 1);
    pack_and_check(one, method, 64, 4.);
  }
}

TEST(Packing, OneLongChartIsPackedAtLeastAlongTheSquareWidth)
{
  Case c = grid_case({ 0, 6 }, { 0, 2 });
  const DS::Packing_report r = pack_and_check(c, DS::Packing_method::TIGHT, 1000, 10.);
  // A 6 x 2 rectangle laid horizontally fills the width less the padding;
  // turned by an eighth of a turn it needs only (6 + 2) / sqrt(2) of it,
  // which is the best any rotation can do.
  EXPECT_GE(r.efficiency, (0.98 * 0.98) / 3. - 1e-9);
  EXPECT_LE(r.efficiency, 12. * std::pow(0.98 * std::sqrt(2.) / 8., 2) + 1e-9);
}

TEST(Packing, SmallChartGoesIntoTheHollowOfALargeOne)
{
  // Around the C, the square would need a box 2.6 long instead of 2: at
  // most 2 / 2.6 = 0.77 of the texel density of the C alone. Inside the
  // hollow it costs (almost) nothing.
  Case alone = c_and_square_case(false);
  const DS::Packing_report ra = pack_and_check(alone, DS::Packing_method::TIGHT, 1024, 2.);
  Case both = c_and_square_case(true);
  const DS::Packing_report rb = pack_and_check(both, DS::Packing_method::TIGHT, 1024, 2.);
  std::cout << "[ C alone ] texels per unit " << ra.texels_per_unit << ", [ C and square ] " << rb.texels_per_unit
            << std::endl;
  EXPECT_GE(rb.texels_per_unit, 0.95 * ra.texels_per_unit);
}

TEST(Packing, DefaultIsTightAndDeterministic)
{
  Case a = sphere_case(), b = sphere_case();
  const DS::Packing_report ra = DS::pack_patches(a.mesh, a.patch, a.uv);
  const DS::Packing_report rb =
    DS::pack_patches(b.mesh, b.patch, b.uv, DS::parameters::packing_method(DS::Packing_method::TIGHT));
  EXPECT_EQ(ra.efficiency, rb.efficiency);
  EXPECT_GT(ra.texels_per_unit, 0.);
  for(face_descriptor f : faces(a.mesh))
    for(halfedge_descriptor h : CGAL::halfedges_around_face(a.mesh.halfedge(f), a.mesh))
      ASSERT_EQ(a.uv[h], b.uv[h]);
}

TEST(Packing, SameLayoutForAnyNumberOfThreads)
{
  // Few charts (the profile search, then the raster one) and many (the
  // raster search alone); each chart's turns are searched side by side.
  std::vector<int> cuts;
  for(int x = 0; x <= 12; ++x) cuts.push_back(x);
  cuts.push_back(17);
  cuts.push_back(25);
  Case cases[] = { sphere_case(), torus_case(), c_and_square_case(true), grid_case(cuts, cuts) };
  for(Case& c : cases)
  {
    SCOPED_TRACE(std::to_string(c.number_of_patches) + " charts");
    const std::vector<Point_2> before = snapshot(c);
    std::vector<std::vector<Point_2>> layouts;
    for(unsigned int threads : { 1u, 2u, 4u, 0u })
    {
      for(face_descriptor f : faces(c.mesh))
        for(halfedge_descriptor h : CGAL::halfedges_around_face(c.mesh.halfedge(f), c.mesh))
          c.uv[h] = before[h.idx()];
      DS::pack_patches(c.mesh, c.patch, c.uv, DS::parameters::number_of_threads(threads));
      layouts.push_back(snapshot(c));
    }
    for(std::size_t k = 1; k < layouts.size(); ++k)
      EXPECT_TRUE(layouts[k] == layouts[0]) << "layout " << k << " differs from the sequential one";
  }
}

TEST(Packing, PolyhedronGivesTheSameAtlas)
{
  for(DS::Packing_method method : { DS::Packing_method::TIGHT, DS::Packing_method::GRID })
  {
    Case c = disk_case();
    Polyhedron poly;
    TS::to_mesh(TS::disk(8, 24), poly);
    typedef boost::graph_traits<Polyhedron>::face_descriptor pface;
    typedef boost::graph_traits<Polyhedron>::halfedge_descriptor phalfedge;
    std::map<pface, std::size_t> patch_storage;
    std::map<phalfedge, Point_2> uv_storage;
    // Faces and vertices come in the same order in both meshes; match corners by target vertex index.
    std::map<boost::graph_traits<Polyhedron>::vertex_descriptor, std::size_t> vindex;
    for(auto v : vertices(poly)) vindex.emplace(v, vindex.size());
    auto fp = faces(poly).begin();
    for(face_descriptor f : faces(c.mesh))
    {
      patch_storage[*fp] = c.patch[f];
      for(phalfedge ph : CGAL::halfedges_around_face(halfedge(*fp, poly), poly))
        for(halfedge_descriptor h : CGAL::halfedges_around_face(c.mesh.halfedge(f), c.mesh))
          if(std::size_t(c.mesh.target(h).idx()) == vindex[target(ph, poly)])
            uv_storage[ph] = c.uv[h];
      ++fp;
    }
    const auto np = DS::parameters::packing_method(method);
    const DS::Packing_report rm = DS::pack_patches(c.mesh, c.patch, c.uv, np);
    const DS::Packing_report rp = DS::pack_patches(poly, boost::make_assoc_property_map(patch_storage),
                                                   boost::make_assoc_property_map(uv_storage), np);
    EXPECT_EQ(rm.number_of_charts, rp.number_of_charts);
    EXPECT_NEAR(rm.efficiency, rp.efficiency, 1e-12);
    fp = faces(poly).begin();
    for(face_descriptor f : faces(c.mesh))
    {
      for(phalfedge ph : CGAL::halfedges_around_face(halfedge(*fp, poly), poly))
        for(halfedge_descriptor h : CGAL::halfedges_around_face(c.mesh.halfedge(f), c.mesh))
          if(std::size_t(c.mesh.target(h).idx()) == vindex[target(ph, poly)])
          {
            EXPECT_NEAR(uv_storage[ph].x(), c.uv[h].x(), 1e-12);
            EXPECT_NEAR(uv_storage[ph].y(), c.uv[h].y(), 1e-12);
          }
      ++fp;
    }
  }
}

TEST(Packing, EmptyMeshGivesNoChart)
{
  Mesh m;
  auto patch = m.add_property_map<face_descriptor, std::size_t>("f:patch", 0).first;
  auto uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
  const DS::Packing_report r = DS::pack_patches(m, patch, uv);
  EXPECT_EQ(r.number_of_charts, 0u);
  EXPECT_EQ(r.efficiency, 0.);
}

TEST(Packing, BadParametersThrow)
{
  Case c = disk_case();
  const std::vector<Point_2> before = snapshot(c);
  auto unchanged = [&]()
  {
    for(face_descriptor f : faces(c.mesh))
      for(halfedge_descriptor h : CGAL::halfedges_around_face(c.mesh.halfedge(f), c.mesh))
        if(c.uv[h] != before[h.idx()]) return false;
    return true;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv, DS::parameters::texture_resolution(0u)), DS::Input_error);
  EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv, DS::parameters::texture_resolution(-5)), DS::Input_error);
  EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv, DS::parameters::padding_in_texels(-1.)), DS::Input_error);
  EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv, DS::parameters::padding_in_texels(nan)), DS::Input_error);
  EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv, DS::parameters::padding_in_texels(inf)), DS::Input_error);
  EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv, DS::parameters::number_of_threads(-1)), DS::Input_error);
  EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv,
                                DS::parameters::texture_resolution(64u).padding_in_texels(32.)),
               DS::Input_error);
  EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv,
                                DS::parameters::packing_method(static_cast<DS::Packing_method>(7))),
               DS::Input_error);
  try
  {
    DS::pack_patches(c.mesh, c.patch, c.uv, DS::parameters::padding_in_texels(-1.));
  }
  catch(const DS::Input_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("padding_in_texels"), std::string::npos);
  }
  try
  {
    DS::pack_patches(c.mesh, c.patch, c.uv, DS::parameters::texture_resolution(0u));
  }
  catch(const DS::Input_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("texture_resolution"), std::string::npos);
  }
  EXPECT_TRUE(unchanged());
}

// Cuts of a grid into 144 unit squares and larger blocks.
static std::vector<int> mixed_grid_cuts()
{
  std::vector<int> cuts;
  for(int x = 0; x <= 12; ++x) cuts.push_back(x);
  cuts.push_back(17);
  cuts.push_back(25);
  cuts.push_back(36);
  return cuts;
}

TEST(Packing, FixedTexelDensitySpreadsTheChartsOverPages)
{
  const std::vector<int> cuts = mixed_grid_cuts();
  Case fit = grid_case(cuts, cuts);
  const DS::Packing_report one_page = pack_and_check(fit, DS::Packing_method::TIGHT, 512, 2.);
  EXPECT_EQ(one_page.number_of_pages, 1u);

  // Twice the density of the one-page fit: four times the area, so at least
  // as many pages as the area needs (charts never cover a page whole).
  Case paged = grid_case(cuts, cuts);
  const double density = 2. * one_page.texels_per_unit;
  const DS::Packing_report r = pack_and_check(paged, DS::Packing_method::TIGHT, 512, 2., density);
  EXPECT_NEAR(r.texels_per_unit, density, 1e-9 * density);
  const double area_in_pages = 4. * one_page.efficiency;
  EXPECT_GE(double(r.number_of_pages), std::ceil(area_in_pages - 1e-9));
  EXPECT_GT(r.number_of_pages, 1u);
  std::cout << "[ mixed grid, " << paged.number_of_patches << " charts ] one page " << one_page.efficiency
            << " at " << one_page.texels_per_unit << " texels per unit; at twice that " << r.number_of_pages
            << " pages, mean " << r.efficiency << std::endl;

  // Half the density: one page, a quarter of the area.
  Case sparse = grid_case(cuts, cuts);
  const DS::Packing_report half =
    pack_and_check(sparse, DS::Packing_method::TIGHT, 512, 2., 0.5 * one_page.texels_per_unit);
  EXPECT_EQ(half.number_of_pages, 1u);
  EXPECT_NEAR(half.efficiency, 0.25 * one_page.efficiency, 1e-9);

  // The same pages and UVs on any number of threads.
  Case again = grid_case(cuts, cuts);
  const DS::Packing_report sequential = DS::pack_patches(
    again.mesh, again.patch, again.uv,
    DS::parameters::texture_resolution(512u).padding_in_texels(2.).texels_per_unit(density).number_of_threads(1u));
  EXPECT_EQ(sequential.page_of_chart, r.page_of_chart);
  EXPECT_TRUE(snapshot(again) == snapshot(paged));
}

// The pages as they were made before a page skipped the charts it cannot
// hold: each page tries every chart left, largest first.
std::vector<std::size_t> pages_trying_every_chart(const Case& c, double texels_per_unit,
                                                  std::vector<DS::internal::Profile_placement>& placement)
{
  namespace I = CGAL::Disk_segmentation::internal;
  const auto np = DS::parameters::texture_resolution(512u).padding_in_texels(2.).texels_per_unit(texels_per_unit)
                    .number_of_threads(1u);
  const I::Packing_settings s = I::packing_settings(np);
  I::Chart_set<Mesh> charts;
  I::collect_charts(c.mesh, c.patch, c.uv, true, np, charts);
  I::frame_charts(s.method, 1u, charts);
  std::vector<double> density(charts.size());
  for(std::size_t p = 0; p < charts.size(); ++p)
    density[p] = std::sqrt(charts.surface_area[p] / charts.uv_area[p]);
  const I::Shape_input shapes(charts, density);
  const double scale = s.texels_per_unit / (s.resolution * charts.length_scale);
  const std::size_t columns = I::shape_columns(s);
  I::Raster_packer packer(columns, I::shape_pad_cells(s, columns), I::shape_rows(s, columns));
  std::vector<std::size_t> left = I::largest_first(shapes.charts), page_of_chart(charts.size(), 0), still_left;
  placement.assign(charts.size(), I::Profile_placement());
  for(std::size_t page = 0; !left.empty(); ++page)
  {
    packer.start_page();
    still_left.clear();
    for(std::size_t i : left)
    {
      std::size_t need = 0;
      if(packer.place_on_page(shapes.charts[i], scale, placement[i], need))
        page_of_chart[i] = page;
      else
        still_left.push_back(i);
    }
    if(still_left.size() == left.size())
      break;
    left.swap(still_left);
  }
  return page_of_chart;
}

TEST(Packing, PagesSkipOnlyTheChartsThatCannotFit)
{
  // 144 equal squares (one class of footprints) and larger blocks.
  const std::vector<int> cuts = mixed_grid_cuts();
  Case fit = grid_case(cuts, cuts);
  const DS::Packing_report one_page = pack_and_check(fit, DS::Packing_method::TIGHT, 512, 2.);
  for(double times : { 1.5, 2., 3. })
  {
    Case paged = grid_case(cuts, cuts);
    const double density = times * one_page.texels_per_unit;
    std::vector<DS::internal::Profile_placement> expected;
    const std::vector<std::size_t> expected_pages = pages_trying_every_chart(paged, density, expected);
    const DS::Packing_report r = DS::pack_patches(
      paged.mesh, paged.patch, paged.uv,
      DS::parameters::texture_resolution(512u).padding_in_texels(2.).texels_per_unit(density).number_of_threads(1u));
    EXPECT_GT(r.number_of_pages, 1u);
    EXPECT_EQ(r.page_of_chart, expected_pages) << "at " << times << " times the one-page density";
    // The same places (the layout on any number of threads).
    namespace I = CGAL::Disk_segmentation::internal;
    const auto np = DS::parameters::texture_resolution(512u).padding_in_texels(2.).texels_per_unit(density);
    I::Chart_set<Mesh> charts;
    Case fresh = grid_case(cuts, cuts);
    I::collect_charts(fresh.mesh, fresh.patch, fresh.uv, true, np, charts);
    I::frame_charts(DS::Packing_method::TIGHT, 1u, charts);
    double global_scale = 0.;
    std::vector<std::size_t> pages;
    const std::vector<I::Chart_similarity> layout = I::tight_layout(charts, I::packing_settings(np), global_scale, pages);
    std::vector<double> density_of(charts.size());
    for(std::size_t p = 0; p < charts.size(); ++p)
      density_of[p] = std::sqrt(charts.surface_area[p] / charts.uv_area[p]);
    const std::vector<I::Chart_similarity> oracle = I::shape_similarities(charts, expected, density_of, global_scale);
    ASSERT_EQ(layout.size(), oracle.size());
    for(std::size_t p = 0; p < layout.size(); ++p)
      EXPECT_TRUE(layout[p].scale == oracle[p].scale && layout[p].tx == oracle[p].tx && layout[p].ty == oracle[p].ty)
        << "chart " << p;
    std::cout << "[ " << paged.number_of_patches << " charts at " << times << " times the one-page density ] "
              << r.number_of_pages << " pages, as when each page tried every chart left" << std::endl;
  }
}

TEST(Packing, NonSquareTexturesKeepTheTexelsSquare)
{
  std::vector<int> cuts;
  for(int x = 0; x <= 12; ++x) cuts.push_back(x);
  cuts.push_back(17);
  cuts.push_back(25);
  Case square = grid_case(cuts, cuts);
  const std::vector<Point_2> square_before = snapshot(square);
  const DS::Packing_report r_square = DS::pack_patches(
    square.mesh, square.patch, square.uv, DS::parameters::texture_resolution(512u).padding_in_texels(2.));
  check_packing(square, square_before, r_square, DS::Packing_method::TIGHT, 512., 2.);
  for(unsigned int height : { 128u, 2048u })
  {
    SCOPED_TRACE("512 x " + std::to_string(height));
    Case c = grid_case(cuts, cuts);
    const std::vector<Point_2> before = snapshot(c);
    const DS::Packing_report r = DS::pack_patches(
      c.mesh, c.patch, c.uv, DS::parameters::texture_resolution(512u).texture_height(height).padding_in_texels(2.));
    check_packing(c, before, r, DS::Packing_method::TIGHT, 512., 2., double(height) / 512.);
    std::cout << "[ mixed grid, " << c.number_of_patches << " charts ] 512 x " << height << ": " << r.efficiency
              << " of the page at " << r.texels_per_unit << " texels per unit (512 x 512: " << r_square.efficiency
              << " at " << r_square.texels_per_unit << ")" << std::endl;
    // A page of 4 times (a quarter of) the square's area holds the charts
    // at about twice (half) the square's density.
    const double expected = r_square.texels_per_unit * std::sqrt(double(height) / 512.);
    EXPECT_GT(r.texels_per_unit, 0.75 * expected);
    EXPECT_LT(r.texels_per_unit, 1.25 * expected);

    // Pages at a fixed density on the same texture.
    Case paged = grid_case(cuts, cuts);
    const std::vector<Point_2> paged_before = snapshot(paged);
    const DS::Packing_report rp = DS::pack_patches(
      paged.mesh, paged.patch, paged.uv,
      DS::parameters::texture_resolution(512u).texture_height(height).padding_in_texels(2.)
        .texels_per_unit(1.5 * r.texels_per_unit));
    check_packing(paged, paged_before, rp, DS::Packing_method::TIGHT, 512., 2., double(height) / 512.);
    EXPECT_GE(rp.number_of_pages, 2u);
  }
  Case grid = grid_case(cuts, cuts);
  EXPECT_THROW(DS::pack_patches(grid.mesh, grid.patch, grid.uv,
                                DS::parameters::packing_method(DS::Packing_method::GRID).texture_resolution(512u)
                                  .texture_height(256u)),
               DS::Input_error);
  EXPECT_THROW(DS::pack_patches(grid.mesh, grid.patch, grid.uv,
                                DS::parameters::texture_resolution(512u).texture_height(0u)),
               DS::Input_error);
  // The padding is checked against the shorter side.
  EXPECT_THROW(DS::pack_patches(grid.mesh, grid.patch, grid.uv,
                                DS::parameters::texture_resolution(512u).texture_height(8u).padding_in_texels(4.)),
               DS::Input_error);
}

TEST(Packing, FixedTexelDensityThatCannotBePackedThrowsAndWritesNothing)
{
  Case c = disk_case();
  const std::vector<Point_2> before = snapshot(c);
  auto message_of = [&](const auto& np) {
    try
    {
      DS::pack_patches(c.mesh, c.patch, c.uv, np);
    }
    catch(const DS::Input_error& e)
    {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  Case fresh = disk_case();
  const double fit_density = DS::pack_patches(fresh.mesh, fresh.patch, fresh.uv).texels_per_unit;
  // Far above the fit: the largest chart alone is larger than a page.
  std::string m = message_of(DS::parameters::texels_per_unit(1e3 * fit_density).max_number_of_pages(1000000u));
  EXPECT_NE(m.find("does not fit a page"), std::string::npos) << m;
  EXPECT_NE(m.find("texels_per_unit"), std::string::npos) << m;
  // More pages than allowed.
  m = message_of(DS::parameters::texels_per_unit(3. * fit_density).max_number_of_pages(2u));
  EXPECT_NE(m.find("max_number_of_pages"), std::string::npos) << m;
  m = message_of(DS::parameters::texels_per_unit(-1.));
  EXPECT_NE(m.find("texels_per_unit"), std::string::npos) << m;
  m = message_of(DS::parameters::texels_per_unit(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_NE(m.find("texels_per_unit"), std::string::npos) << m;
  m = message_of(DS::parameters::texels_per_unit(fit_density).packing_method(DS::Packing_method::GRID));
  EXPECT_NE(m.find("TIGHT"), std::string::npos) << m;
  m = message_of(DS::parameters::texels_per_unit(fit_density).max_number_of_pages(0u));
  EXPECT_NE(m.find("max_number_of_pages"), std::string::npos) << m;
  // So low that rounding would collapse the charts' triangles (in doubles,
  // next to the padding's offsets): refused, not packed into a broken atlas.
  for(double tiny : { 1e-18, 1e-300 })
  {
    m = message_of(DS::parameters::texels_per_unit(tiny * fit_density));
    EXPECT_NE(m.find("degenerate or flipped in the packed UVs"), std::string::npos) << m;
    EXPECT_NE(m.find("raise texels_per_unit"), std::string::npos) << m;
  }
  EXPECT_TRUE(snapshot(c) == before) << "a packing that threw moved the UVs";
}

TEST(Packing, ChartsBelowATexelAreCountedAndKeepTheirOrientation)
{
  Case fresh = disk_case();
  const double fit_density = DS::pack_patches(fresh.mesh, fresh.patch, fresh.uv).texels_per_unit;
  Case fit_case = disk_case();
  const DS::Packing_report fit = pack_and_check(fit_case, DS::Packing_method::TIGHT, 1024, 2., fit_density);
  EXPECT_EQ(fit.number_of_charts_below_a_texel, 0u);
  // A millionth of the fit: every chart far below a texel, yet every
  // triangle still positive in doubles.
  Case tiny = disk_case();
  const std::vector<Point_2> before = snapshot(tiny);
  const DS::Packing_report r = DS::pack_patches(tiny.mesh, tiny.patch, tiny.uv,
                                                DS::parameters::texels_per_unit(1e-6 * fit_density));
  EXPECT_EQ(r.number_of_charts_below_a_texel, r.number_of_charts);
  for(auto f : faces(tiny.mesh))
  {
    std::vector<Point_2> t;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tiny.mesh), tiny.mesh))
      t.push_back(tiny.uv[h]);
    EXPECT_GT(signed_area(t[0], t[1], t[2]), 0.);
  }
  EXPECT_FALSE(snapshot(tiny) == before);
}

TEST(Packing, NonTriangleFaceThrows)
{
  Mesh m;
  const auto a = m.add_vertex(K::Point_3(0, 0, 0)), b = m.add_vertex(K::Point_3(1, 0, 0));
  const auto d = m.add_vertex(K::Point_3(1, 1, 0)), e = m.add_vertex(K::Point_3(0, 1, 0));
  const face_descriptor f = m.add_face(a, b, d, e);
  ASSERT_NE(f, Mesh::null_face());
  auto patch = m.add_property_map<face_descriptor, std::size_t>("f:patch", 0).first;
  auto uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(0, 0)).first;
  for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(f), m))
    uv[h] = Point_2(m.point(m.target(h)).x(), m.point(m.target(h)).y());
  EXPECT_THROW(DS::pack_patches(m, patch, uv), DS::Input_error);
}

TEST(Packing, PaddingTooLargeForTheChartsThrows)
{
  // 800 single-triangle charts cannot be 1 texel apart on a 16 x 16 texture.
  for(DS::Packing_method method : { DS::Packing_method::TIGHT, DS::Packing_method::GRID })
  {
    Case c = single_face_case(20, 20);
    EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv,
                                  DS::parameters::packing_method(method).texture_resolution(16u).padding_in_texels(1.)),
                 DS::Input_error);
  }
}

TEST(Packing, DegeneratePatchesThrow)
{
  for(DS::Packing_method method : { DS::Packing_method::TIGHT, DS::Packing_method::GRID })
  {
    const auto np = DS::parameters::packing_method(method);
    {
      // Patch 4 collapsed to a point.
      Case c = disk_case();
      for(face_descriptor f : faces(c.mesh))
        if(c.patch[f] == 4)
          for(halfedge_descriptor h : CGAL::halfedges_around_face(c.mesh.halfedge(f), c.mesh))
            c.uv[h] = Point_2(1, 2);
      try
      {
        DS::pack_patches(c.mesh, c.patch, c.uv, np);
        ADD_FAILURE() << "no exception";
      }
      catch(const DS::Input_error& e)
      {
        EXPECT_NE(std::string(e.what()).find("patch #4"), std::string::npos) << e.what();
      }
    }
    {
      // A NaN UV in patch 2.
      Case c = disk_case();
      for(face_descriptor f : faces(c.mesh))
        if(c.patch[f] == 2)
        {
          c.uv[c.mesh.halfedge(f)] = Point_2(std::numeric_limits<double>::quiet_NaN(), 0.);
          break;
        }
      try
      {
        DS::pack_patches(c.mesh, c.patch, c.uv, np);
        ADD_FAILURE() << "no exception";
      }
      catch(const DS::Input_error& e)
      {
        EXPECT_NE(std::string(e.what()).find("patch #2"), std::string::npos) << e.what();
      }
    }
    {
      // Ids not contiguous: no face in patch 11, one face in patch 12.
      Case c = disk_case();
      c.patch[*faces(c.mesh).begin()] = 12;
      EXPECT_THROW(DS::pack_patches(c.mesh, c.patch, c.uv, np), DS::Input_error);
    }
  }
}
