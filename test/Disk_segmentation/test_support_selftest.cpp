// Self-test of the library-independent test support code (test_meshes.h and
// independent_topology.h) against known facts. Does not use the library.

#include "test_meshes.h"
#include "independent_topology.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> SM;
typedef CGAL::Polyhedron_3<K> Poly;

using test_support::Soup;

std::array<double, 3> sub(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
}
std::array<double, 3> cross(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
double dot(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
std::array<double, 3> normal(const Soup& s, std::size_t t)
{
  const auto& tri = s.triangles[t];
  return cross(sub(s.points[tri[1]], s.points[tri[0]]), sub(s.points[tri[2]], s.points[tri[0]]));
}
std::array<double, 3> centroid(const Soup& s, std::size_t t)
{
  std::array<double, 3> c{{0., 0., 0.}};
  for(std::size_t i : s.triangles[t])
    for(int d = 0; d < 3; ++d)
      c[std::size_t(d)] += s.points[i][std::size_t(d)] / 3.;
  return c;
}

// Signed volume enclosed (divergence theorem); > 0 iff normals point outward.
double signed_volume(const Soup& s)
{
  double v = 0.;
  for(const auto& t : s.triangles)
    v += dot(s.points[t[0]], cross(s.points[t[1]], s.points[t[2]])) / 6.;
  return v;
}

// Face property map based on a std::map, usable with any mesh type.
template <class Mesh>
struct Id_map_holder
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  std::map<face_descriptor, std::size_t> ids;
  boost::associative_property_map<std::map<face_descriptor, std::size_t> > map() { return boost::make_assoc_property_map(ids); }
};

// Partition given as a function of the soup triangle index.
template <class Mesh>
test_support::Partition_report check_with(const Soup& s, const std::function<std::size_t(std::size_t)>& id_of,
                                          std::vector<std::vector<std::size_t> >* sets = nullptr)
{
  Mesh m;
  test_support::to_mesh(s, m);
  Id_map_holder<Mesh> h;
  std::size_t i = 0;
  for(auto f : faces(m))
    h.ids[f] = id_of(i++);
  if(sets)
    *sets = test_support::patches_as_face_index_sets(m, h.map());
  return test_support::check_disk_partition(m, h.map());
}

// Runs the partition check on both mesh types and requires identical results.
test_support::Partition_report check_both(const Soup& s, const std::function<std::size_t(std::size_t)>& id_of)
{
  std::vector<std::vector<std::size_t> > sets_sm, sets_poly;
  const test_support::Partition_report a = check_with<SM>(s, id_of, &sets_sm);
  const test_support::Partition_report b = check_with<Poly>(s, id_of, &sets_poly);
  EXPECT_EQ(a.ok, b.ok);
  EXPECT_EQ(a.problem, b.problem);
  EXPECT_EQ(a.number_of_patches, b.number_of_patches);
  EXPECT_EQ(sets_sm, sets_poly);
  return a;
}

struct Expected
{
  std::string name;
  Soup soup;
  long chi;
  std::size_t boundary_loops;
  std::size_t components;
  bool planar; // in z = 0, normals +z; otherwise closed with outward normals (when loops == 0)
};

std::vector<Expected> catalogue()
{
  using namespace test_support;
  return {
    {"uv_sphere(2,3)", uv_sphere(2, 3), 2, 0, 1, false},
    {"uv_sphere(6,10)", uv_sphere(6, 10), 2, 0, 1, false},
    {"torus(4,3)", torus(4, 3), 0, 0, 1, false},
    {"torus(12,8)", torus(12, 8), 0, 0, 1, false},
    {"genus_surface(0,1)", genus_surface(0, 1), 2, 0, 1, false},
    {"genus_surface(1,1)", genus_surface(1, 1), 0, 0, 1, false},
    {"genus_surface(2,3)", genus_surface(2, 3), -2, 0, 1, false},
    {"genus_surface(3,2)", genus_surface(3, 2), -4, 0, 1, false},
    {"cylinder(3,1)", cylinder(3, 1), 0, 2, 1, false},
    {"cylinder(8,3)", cylinder(8, 3), 0, 2, 1, false},
    {"disk(1,3)", disk(1, 3), 1, 1, 1, true},
    {"disk(3,8)", disk(3, 8), 1, 1, 1, true},
    {"grid_with_holes(1,1,0)", grid_with_holes(1, 1, 0), 1, 1, 1, true},
    {"grid_with_holes(5,5,0)", grid_with_holes(5, 5, 0), 1, 1, 1, true},
    {"grid_with_holes(3,3,1)", grid_with_holes(3, 3, 1), 0, 2, 1, true},
    {"grid_with_holes(9,7,3)", grid_with_holes(9, 7, 3), -2, 4, 1, true},
    {"grid_with_holes(9,7,12)", grid_with_holes(9, 7, 12), -11, 13, 1, true},
    {"disconnected(1)", disconnected(1), 2, 0, 1, false},
    {"disconnected(3)", disconnected(3), 4, 0, 3, false},
    {"single_triangle", single_triangle(), 1, 1, 1, true},
    {"thin_strip(1)", thin_strip(1), 1, 1, 1, true},
    {"thin_strip(50)", thin_strip(50), 1, 1, 1, true},
  };
}

template <class Mesh>
void check_mesh_facts(const Expected& e)
{
  SCOPED_TRACE(e.name);
  Mesh m;
  ASSERT_NO_THROW(test_support::to_mesh(e.soup, m));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  EXPECT_EQ(num_vertices(m), e.soup.points.size());
  EXPECT_EQ(num_faces(m), e.soup.triangles.size());
  EXPECT_EQ(CGAL::is_closed(m), e.boundary_loops == 0);

  const long chi_cgal = long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
  EXPECT_EQ(chi_cgal, e.chi);
  EXPECT_EQ(test_support::euler_characteristic_of(m, faces(m)), e.chi);

  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> cycles;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(m, std::back_inserter(cycles));
  EXPECT_EQ(cycles.size(), e.boundary_loops);

  EXPECT_EQ(test_support::is_disk(m, faces(m)), e.chi == 1 && e.boundary_loops == 1 && e.components == 1);
}

} // namespace

TEST(TestMeshes, SoupsAreValidOrientedManifolds)
{
  for(const Expected& e : catalogue())
  {
    SCOPED_TRACE(e.name);
    const Soup& s = e.soup;
    ASSERT_FALSE(s.triangles.empty());
    EXPECT_TRUE(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(s.triangles));
    std::vector<char> used(s.points.size(), 0);
    for(const auto& t : s.triangles)
      for(std::size_t i : t)
      {
        ASSERT_LT(i, s.points.size());
        used[i] = 1;
      }
    EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "isolated points";
    for(std::size_t t = 0; t < s.triangles.size(); ++t)
    {
      const auto n = normal(s, t);
      ASSERT_GT(std::sqrt(dot(n, n)), 1e-9) << "degenerate triangle " << t;
      if(e.planar)
      {
        EXPECT_EQ(s.points[s.triangles[t][0]][2], 0.);
        EXPECT_GT(n[2], 0.) << "triangle " << t << " not facing +z";
      }
    }
    if(!e.planar && e.boundary_loops == 0)
    {
      EXPECT_GT(signed_volume(s), 0.) << "normals not outward";
    }
  }
}

TEST(TestMeshes, OutwardNormalsLocally)
{
  // Sphere and cylinder: each normal points away from the centre / axis.
  const Soup sphere = test_support::uv_sphere(7, 9);
  for(std::size_t t = 0; t < sphere.triangles.size(); ++t)
    EXPECT_GT(dot(normal(sphere, t), centroid(sphere, t)), 0.);
  const Soup tube = test_support::cylinder(7, 4);
  for(std::size_t t = 0; t < tube.triangles.size(); ++t)
  {
    auto c = centroid(tube, t);
    c[2] = 0.;
    EXPECT_GT(dot(normal(tube, t), c), 0.);
  }
  // Torus: away from the core circle.
  const Soup ring = test_support::torus(10, 7);
  for(std::size_t t = 0; t < ring.triangles.size(); ++t)
  {
    const auto c = centroid(ring, t);
    const double rho = std::sqrt(c[0] * c[0] + c[1] * c[1]);
    const std::array<double, 3> core{{c[0] / rho, c[1] / rho, 0.}};
    EXPECT_GT(dot(normal(ring, t), sub(c, core)), 0.);
  }
}

TEST(TestMeshes, Sizes)
{
  using namespace test_support;
  EXPECT_EQ(uv_sphere(5, 7).points.size(), 2u + 4u * 7u);
  EXPECT_EQ(uv_sphere(5, 7).triangles.size(), 2u * 7u * 4u);
  EXPECT_EQ(torus(6, 5).triangles.size(), 60u);
  EXPECT_EQ(cylinder(6, 2).triangles.size(), 24u);
  EXPECT_EQ(disk(3, 8).triangles.size(), 8u * 5u);
  EXPECT_EQ(grid_with_holes(9, 7, 3).triangles.size(), 2u * (63u - 3u));
  EXPECT_EQ(thin_strip(40).triangles.size(), 80u);
  EXPECT_EQ(single_triangle().triangles.size(), 1u);
  EXPECT_EQ(disconnected(4).triangles.size(), 2u * 48u + 2u * 96u);
  for(int g = 0; g <= 4; ++g)
    for(int r = 1; r <= 4; ++r)
      EXPECT_EQ(genus_surface(g, r).triangles.size(), std::size_t(r * r * (36 * g + 28)));
  EXPECT_EQ(genus_surface(3, 3).triangles.size(), 1224u);
  // Determinism
  const Soup a = genus_surface(2, 2), b = genus_surface(2, 2);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  // Bad arguments
  EXPECT_THROW(uv_sphere(1, 5), std::invalid_argument);
  EXPECT_THROW(grid_with_holes(3, 3, 2), std::invalid_argument);
  EXPECT_THROW(thin_strip(0), std::invalid_argument);
}

TEST(TestMeshes, GenusSurfaceIsConnectedWithRequestedGenus)
{
  for(int g = 0; g <= 4; ++g)
  {
    SM m;
    test_support::to_mesh(test_support::genus_surface(g, 2), m);
    EXPECT_TRUE(CGAL::is_closed(m));
    auto fcc = m.add_property_map<SM::Face_index, std::size_t>("f:cc", 0).first;
    EXPECT_EQ(CGAL::Polygon_mesh_processing::connected_components(m, fcc), 1u);
    EXPECT_EQ(long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m)), 2 - 2 * g);
  }
}

TEST(TestMeshes, ConnectedComponents)
{
  for(const Expected& e : catalogue())
  {
    SCOPED_TRACE(e.name);
    SM m;
    test_support::to_mesh(e.soup, m);
    auto fcc = m.add_property_map<SM::Face_index, std::size_t>("f:cc", 0).first;
    EXPECT_EQ(CGAL::Polygon_mesh_processing::connected_components(m, fcc), e.components);
  }
}

TEST(TestMeshes, MeshFactsSurfaceMesh)
{
  for(const Expected& e : catalogue())
    check_mesh_facts<SM>(e);
}

TEST(TestMeshes, MeshFactsPolyhedron)
{
  for(const Expected& e : catalogue())
    check_mesh_facts<Poly>(e);
}

// Explicit check (independent of the one inside to_mesh) that vertex i is
// point i and face i is triangle i, for both mesh types.
template <class Mesh>
void check_order(const Soup& s)
{
  Mesh m;
  test_support::to_mesh(s, m);
  std::map<typename boost::graph_traits<Mesh>::vertex_descriptor, std::size_t> vi;
  std::size_t i = 0;
  for(auto v : vertices(m))
  {
    const Point_3& p = get(CGAL::vertex_point, m, v);
    ASSERT_EQ(p, Point_3(s.points[i][0], s.points[i][1], s.points[i][2]));
    vi[v] = i++;
  }
  std::size_t fi = 0;
  for(auto f : faces(m))
  {
    std::vector<std::size_t> c;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
      c.push_back(vi[v]);
    ASSERT_EQ(c.size(), 3u);
    // same cyclic order: rotate so that the smallest index comes first
    std::array<std::size_t, 3> t = s.triangles[fi++];
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    ASSERT_EQ(c, std::vector<std::size_t>(t.begin(), t.end()));
  }
}

TEST(TestMeshes, ToMeshPreservesOrder)
{
  for(const Expected& e : catalogue())
  {
    SCOPED_TRACE(e.name);
    check_order<SM>(e.soup);
    check_order<Poly>(e.soup);
  }
  // Converting into a non-empty mesh first clears it.
  SM m;
  test_support::to_mesh(test_support::torus(5, 4), m);
  test_support::to_mesh(test_support::single_triangle(), m);
  EXPECT_EQ(num_faces(m), 1u);
  EXPECT_EQ(num_vertices(m), 3u);
  check_order<SM>(test_support::single_triangle());
}

TEST(TestMeshes, ToMeshRejectsBadSoup)
{
  Soup s = test_support::disk(2, 6);
  std::swap(s.triangles[0][1], s.triangles[0][2]); // inconsistent orientation
  SM m;
  EXPECT_THROW(test_support::to_mesh(s, m), std::runtime_error);
}

// ---------------------------------------------------------------------------
// Checker

TEST(Checker, WholeClosedSurfacesAreNotDisks)
{
  using namespace test_support;
  for(const Soup& s : {uv_sphere(6, 10), torus(8, 6), genus_surface(3, 1), cylinder(8, 2)})
  {
    const auto r = check_both(s, [](std::size_t) { return std::size_t(0); });
    EXPECT_FALSE(r.ok);
    EXPECT_EQ(r.number_of_patches, 1u);
    EXPECT_FALSE(r.problem.empty());
  }
  SM m;
  to_mesh(uv_sphere(6, 10), m);
  EXPECT_FALSE(is_disk(m, faces(m)));
  EXPECT_EQ(euler_characteristic_of(m, faces(m)), 2);
}

TEST(Checker, OnePatchDisks)
{
  using namespace test_support;
  for(const Soup& s : {disk(3, 8), single_triangle(), thin_strip(30), grid_with_holes(6, 4, 0)})
  {
    const auto r = check_both(s, [](std::size_t) { return std::size_t(0); });
    EXPECT_TRUE(r.ok) << r.problem;
    EXPECT_EQ(r.number_of_patches, 1u);
    EXPECT_TRUE(r.problem.empty());
  }
  // Grid with holes and cylinder: not disks.
  for(const Soup& s : {grid_with_holes(5, 5, 1), cylinder(6, 2)})
  {
    const auto r = check_both(s, [](std::size_t) { return std::size_t(0); });
    EXPECT_FALSE(r.ok);
  }
}

TEST(Checker, Hemispheres)
{
  const Soup s = test_support::uv_sphere(8, 12);
  const auto r = check_both(s, [&](std::size_t t) { return centroid(s, t)[2] > 0. ? std::size_t(0) : std::size_t(1); });
  EXPECT_TRUE(r.ok) << r.problem;
  EXPECT_EQ(r.number_of_patches, 2u);

  // Each hemisphere on its own with is_disk / euler_characteristic_of.
  Poly m;
  test_support::to_mesh(s, m);
  std::vector<boost::graph_traits<Poly>::face_descriptor> north, south;
  std::size_t t = 0;
  for(auto f : faces(m))
    (centroid(s, t++)[2] > 0. ? north : south).push_back(f);
  EXPECT_TRUE(test_support::is_disk(m, north));
  EXPECT_TRUE(test_support::is_disk(m, south));
  EXPECT_EQ(test_support::euler_characteristic_of(m, north), 1);
  // duplicates in the face range are ignored
  std::vector<boost::graph_traits<Poly>::face_descriptor> twice = north;
  twice.insert(twice.end(), north.begin(), north.end());
  EXPECT_TRUE(test_support::is_disk(m, twice));
  EXPECT_EQ(test_support::euler_characteristic_of(m, twice), 1);
}

TEST(Checker, LunesAndBands)
{
  const double pi = 3.14159265358979323846;
  const Soup s = test_support::uv_sphere(6, 12);
  // Four lunes from pole to pole: all share both poles, each is a disk.
  auto lune = [&](std::size_t t) {
    const auto c = centroid(s, t);
    double a = std::atan2(c[1], c[0]);
    if(a < 0.)
      a += 2. * pi;
    return std::size_t(a / (pi / 2.));
  };
  auto r = check_both(s, lune);
  EXPECT_TRUE(r.ok) << r.problem;
  EXPECT_EQ(r.number_of_patches, 4u);

  // Three latitude bands: caps are disks, the middle band is an annulus.
  auto band = [&](std::size_t t) {
    const double z = centroid(s, t)[2];
    return z > 0.5 ? std::size_t(0) : (z < -0.5 ? std::size_t(2) : std::size_t(1));
  };
  r = check_both(s, band);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.problem.find("patch 1"), std::string::npos) << r.problem;
  EXPECT_EQ(r.number_of_patches, 3u);

  // Every triangle its own patch.
  r = check_both(s, [](std::size_t t) { return t; });
  EXPECT_TRUE(r.ok) << r.problem;
  EXPECT_EQ(r.number_of_patches, s.triangles.size());

  // Cylinder cut in two halves along its length: two disks.
  const Soup tube = test_support::cylinder(8, 3);
  r = check_both(tube, [&](std::size_t t) { return centroid(tube, t)[1] > 0. ? std::size_t(0) : std::size_t(1); });
  EXPECT_TRUE(r.ok) << r.problem;
}

TEST(Checker, TwoFacesTouchingAtAVertexOnly)
{
  // Fan of 4 triangles around the centre; triangles 0 and 2 share only the centre.
  const Soup s = test_support::disk(1, 4);
  const auto r = check_both(s, [](std::size_t t) { return t == 0 || t == 2 ? std::size_t(0) : (t == 1 ? std::size_t(1) : std::size_t(2)); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.problem.find("not edge-connected"), std::string::npos) << r.problem;
  EXPECT_NE(r.problem.find("patch 0"), std::string::npos) << r.problem;
}

TEST(Checker, PinchedVertexInEdgeConnectedPatch)
{
  // 4x4 grid; interior vertex (2,2). Square (i,j) gives triangles 2q, 2q+1,
  // q = 4j + i. Triangle 20 (square (2,2), angles 0..45 deg around the
  // vertex) and triangle 11 (square (1,1), angles 180..225 deg) are removed
  // from patch 0, which then has two fans at (2,2) but stays edge-connected.
  const Soup s = test_support::grid_with_holes(4, 4, 0);
  ASSERT_EQ(s.triangles[20], (std::array<std::size_t, 3>{{12, 13, 18}}));
  ASSERT_EQ(s.triangles[11], (std::array<std::size_t, 3>{{6, 12, 11}}));
  auto r = check_both(s, [](std::size_t t) { return t == 20 ? std::size_t(1) : (t == 11 ? std::size_t(2) : 0); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.problem.find("pinched vertex 12"), std::string::npos) << r.problem;

  // Removing the whole fan instead: patch 0 is an annulus (Euler char. 0).
  const std::set<std::size_t> fan{20, 21, 11, 10, 13, 18};
  for(std::size_t t : fan)
  {
    const auto& tri = s.triangles[t];
    ASSERT_TRUE(tri[0] == 12 || tri[1] == 12 || tri[2] == 12);
  }
  r = check_both(s, [&](std::size_t t) { return fan.count(t) ? std::size_t(1) : std::size_t(0); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.problem.find("Euler"), std::string::npos) << r.problem;
  // ... while the fan alone is a disk.
  r = check_both(s, [&](std::size_t t) { return fan.count(t) ? std::size_t(0) : std::size_t(1); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.problem.find("patch 1"), std::string::npos) << r.problem;
}

TEST(Checker, TorusMinusOneFace)
{
  const Soup s = test_support::torus(8, 6);
  const auto r = check_both(s, [](std::size_t t) { return t == 5 ? std::size_t(1) : std::size_t(0); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.problem.find("patch 0"), std::string::npos) << r.problem;
  EXPECT_NE(r.problem.find("= -1 instead of 1"), std::string::npos) << r.problem;
}

TEST(Checker, IdsMustBeContiguousAndPresent)
{
  const Soup s = test_support::uv_sphere(8, 12);
  auto hemi = [&](std::size_t t) { return centroid(s, t)[2] > 0. ? std::size_t(0) : std::size_t(1); };
  // {0, 2}
  auto r = check_both(s, [&](std::size_t t) { return 2 * hemi(t); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.problem.find("contiguous"), std::string::npos) << r.problem;
  EXPECT_EQ(r.number_of_patches, 2u);
  // {1, 2}: 0 missing
  r = check_both(s, [&](std::size_t t) { return 1 + hemi(t); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.problem.find("contiguous"), std::string::npos) << r.problem;
  // a face without id
  r = check_both(s, [&](std::size_t t) { return t == 17 ? std::size_t(-1) : hemi(t); });
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.problem.find("face 17 has no patch id"), std::string::npos) << r.problem;
}

TEST(Checker, SurfaceMeshPropertyMap)
{
  SM m;
  const Soup s = test_support::uv_sphere(8, 12);
  test_support::to_mesh(s, m);
  auto pid = m.add_property_map<SM::Face_index, std::size_t>("f:patch", 0).first;
  for(auto f : faces(m))
    pid[f] = centroid(s, std::size_t(f))[2] > 0. ? 0 : 1;
  const auto r = test_support::check_disk_partition(m, pid);
  EXPECT_TRUE(r.ok) << r.problem;
  EXPECT_EQ(r.number_of_patches, 2u);
  // int-valued map works too
  auto ipid = m.add_property_map<SM::Face_index, int>("f:ipatch", 0).first;
  for(auto f : faces(m))
    ipid[f] = int(pid[f]);
  EXPECT_TRUE(test_support::check_disk_partition(m, ipid).ok);
}

TEST(Checker, EmptyMesh)
{
  SM m;
  auto pid = m.add_property_map<SM::Face_index, std::size_t>("f:patch", 0).first;
  const auto r = test_support::check_disk_partition(m, pid);
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.number_of_patches, 0u);
  std::vector<SM::Face_index> none;
  EXPECT_FALSE(test_support::is_disk(m, none));
  EXPECT_EQ(test_support::euler_characteristic_of(m, none), 0);
}

TEST(Checker, FaceIndexSetsAndRefinement)
{
  const Soup s = test_support::uv_sphere(6, 8);
  std::vector<std::vector<std::size_t> > hemis, hemis_relabelled, singles, whole, singles_poly;
  auto hemi = [&](std::size_t t) { return centroid(s, t)[2] > 0. ? std::size_t(0) : std::size_t(1); };
  check_with<SM>(s, hemi, &hemis);
  check_with<Poly>(s, [&](std::size_t t) { return 1 - hemi(t); }, &hemis_relabelled);
  check_with<SM>(s, [](std::size_t t) { return t; }, &singles);
  check_with<Poly>(s, [&](std::size_t t) { return s.triangles.size() - 1 - t; }, &singles_poly);
  check_with<SM>(s, [](std::size_t) { return std::size_t(0); }, &whole);

  ASSERT_EQ(hemis.size(), 2u);
  EXPECT_EQ(hemis, hemis_relabelled);
  EXPECT_EQ(singles, singles_poly);
  EXPECT_EQ(singles.size(), s.triangles.size());
  EXPECT_EQ(whole.size(), 1u);
  EXPECT_EQ(whole[0].size(), s.triangles.size());
  EXPECT_TRUE(std::is_sorted(hemis.begin(), hemis.end()));
  for(const auto& p : hemis)
    EXPECT_TRUE(std::is_sorted(p.begin(), p.end()));
  EXPECT_EQ(hemis[0][0], 0u); // the north cap contains triangle 0

  EXPECT_TRUE(test_support::refines(singles, hemis));
  EXPECT_TRUE(test_support::refines(hemis, whole));
  EXPECT_TRUE(test_support::refines(singles, whole));
  EXPECT_TRUE(test_support::refines(hemis, hemis));
  EXPECT_FALSE(test_support::refines(hemis, singles));
  EXPECT_FALSE(test_support::refines(whole, hemis));
  // a face missing from the coarse partition
  std::vector<std::vector<std::size_t> > partial = hemis;
  partial[1].pop_back();
  EXPECT_FALSE(test_support::refines(hemis, partial));
  EXPECT_TRUE(test_support::refines(partial, hemis));
}

TEST(Checker, HundredThousandFaceGrid)
{
  // 250 x 200 grid = 100000 triangles, one patch per row of squares.
  const Soup s = test_support::grid_with_holes(250, 200, 0);
  ASSERT_EQ(s.triangles.size(), 100000u);
  SM m;
  test_support::to_mesh(s, m);
  auto pid = m.add_property_map<SM::Face_index, std::size_t>("f:patch", 0).first;
  for(auto f : faces(m))
    pid[f] = std::size_t(f) / 500;
  const auto r = test_support::check_disk_partition(m, pid);
  EXPECT_TRUE(r.ok) << r.problem;
  EXPECT_EQ(r.number_of_patches, 200u);

  // Single patch of 100k faces.
  for(auto f : faces(m))
    pid[f] = 0;
  EXPECT_TRUE(test_support::check_disk_partition(m, pid).ok);
}
