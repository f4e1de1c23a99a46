// Property tests of uv_atlas() on randomized meshes. Every random choice comes
// from a std::mt19937 seeded from a fixed list, so each run tests the same
// meshes and parameters; a failure message names the seed and the choices.
//
// The meshes are random variations of the generators of test_meshes.h:
// random genus (genus_surface), vertex jitter, 1-to-3 splits of random faces,
// holes made by deleting the stars of random interior vertices, and extra
// translated components. The results are checked only with the independent
// checkers: every chart a topological disk (check_disk_partition) and a valid
// atlas without overlap (check_atlas), and no invalid chart in the report.
// Also: thousands of tiny components, isolated vertices and duplicated
// vertices (same coordinates, different indices).

#include "atlas_fixture.h"
#include "independent_atlas.h"
#include "independent_topology.h"
#include "test_meshes.h"

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace DS = CGAL::Disk_segmentation;
namespace TS = test_support;
using test_support::Atlas;
using test_support::expect_valid_atlas;
using test_support::make_atlas;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Face_index, std::size_t> Patch_map;
typedef Mesh::Property_map<Mesh::Halfedge_index, K::Point_2> UV_map;

namespace {

const std::uint32_t seeds[] = { 1u,     2u,     3u,      5u,      8u,         13u,        21u,
                                34u,    55u,    89u,     144u,    233u,       377u,       610u,
                                987u,   1597u,  2584u,   4181u,   20250101u,  4294967295u };


int uniform_int(std::mt19937& rng, int lo, int hi) // in [lo, hi]
{
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

double uniform_real(std::mt19937& rng, double lo, double hi)
{
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Drops the points no triangle uses, keeping the order of the others.
TS::Soup compact(const TS::Soup& s)
{
  std::vector<std::size_t> new_index(s.points.size(), std::size_t(-1));
  TS::Soup out;
  for(const auto& t : s.triangles)
    for(std::size_t v : t)
      if(new_index[v] == std::size_t(-1))
        new_index[v] = 0; // mark used
  for(std::size_t v = 0; v < s.points.size(); ++v)
    if(new_index[v] != std::size_t(-1))
    {
      new_index[v] = out.points.size();
      out.points.push_back(s.points[v]);
    }
  for(const auto& t : s.triangles)
    out.triangles.push_back({{ new_index[t[0]], new_index[t[1]], new_index[t[2]] }});
  return out;
}

// Shortest edge length at each vertex (infinity for an unused point).
std::vector<double> shortest_edge_at(const TS::Soup& s)
{
  std::vector<double> len(s.points.size(), std::numeric_limits<double>::infinity());
  for(const auto& t : s.triangles)
    for(int k = 0; k < 3; ++k)
    {
      const auto& a = s.points[t[std::size_t(k)]];
      const auto& b = s.points[t[std::size_t((k + 1) % 3)]];
      const double d = std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                 (a[2] - b[2]) * (a[2] - b[2]));
      len[t[std::size_t(k)]] = std::min(len[t[std::size_t(k)]], d);
      len[t[std::size_t((k + 1) % 3)]] = std::min(len[t[std::size_t((k + 1) % 3)]], d);
    }
  return len;
}

// Moves every point by a random vector of length < `amount` times its
// shortest edge (amount < 0.5 keeps every triangle non-degenerate).
void jitter(TS::Soup& s, std::mt19937& rng, double amount)
{
  const std::vector<double> len = shortest_edge_at(s);
  for(std::size_t v = 0; v < s.points.size(); ++v)
  {
    if(!std::isfinite(len[v]))
      continue;
    for(int c = 0; c < 3; ++c)
      s.points[v][std::size_t(c)] += uniform_real(rng, -1., 1.) * amount * len[v] / std::sqrt(3.);
  }
}

// Splits each face with probability `p` into three around a point near its
// centroid (barycentric weights in [0.2, 0.6], normalized).
void split_random_faces(TS::Soup& s, std::mt19937& rng, double p)
{
  std::vector<std::array<std::size_t, 3> > triangles;
  for(const auto& t : s.triangles)
  {
    if(uniform_real(rng, 0., 1.) >= p)
    {
      triangles.push_back(t);
      continue;
    }
    double w[3] = { uniform_real(rng, 0.2, 0.6), uniform_real(rng, 0.2, 0.6), uniform_real(rng, 0.2, 0.6) };
    const double sum = w[0] + w[1] + w[2];
    std::array<double, 3> c = {{ 0., 0., 0. }};
    for(int k = 0; k < 3; ++k)
      for(int d = 0; d < 3; ++d)
        c[std::size_t(d)] += w[k] / sum * s.points[t[std::size_t(k)]][std::size_t(d)];
    const std::size_t m = s.points.size();
    s.points.push_back(c);
    triangles.push_back({{ t[0], t[1], m }});
    triangles.push_back({{ t[1], t[2], m }});
    triangles.push_back({{ t[2], t[0], m }});
  }
  s.triangles.swap(triangles);
}

// Deletes the stars of up to `holes` random vertices such that each chosen
// vertex and all its neighbours are interior and no two chosen vertices are
// within 3 edges of each other: each neighbour then loses one contiguous
// wedge of its fan, so the result stays manifold, with one new border loop
// per hole. The soup is compacted afterwards.
void punch_holes(TS::Soup& s, std::mt19937& rng, int holes)
{
  const std::size_t nv = s.points.size();
  std::vector<std::set<std::size_t> > neighbours(nv);
  std::map<std::pair<std::size_t, std::size_t>, int> edge_count;
  for(const auto& t : s.triangles)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
      neighbours[a].insert(b);
      neighbours[b].insert(a);
      ++edge_count[std::make_pair(std::min(a, b), std::max(a, b))];
    }
  std::vector<char> on_border(nv, 0);
  for(const auto& e : edge_count)
    if(e.second == 1)
      on_border[e.first.first] = on_border[e.first.second] = 1;

  std::vector<char> blocked(nv, 0), chosen(nv, 0);
  std::vector<std::size_t> order(nv);
  for(std::size_t v = 0; v < nv; ++v)
    order[v] = v;
  std::shuffle(order.begin(), order.end(), rng);
  int made = 0;
  for(std::size_t v : order)
  {
    if(made >= holes)
      break;
    if(blocked[v] || on_border[v] || neighbours[v].size() < 3)
      continue;
    bool ok = true;
    for(std::size_t u : neighbours[v])
      ok = ok && !on_border[u];
    if(!ok)
      continue;
    chosen[v] = 1;
    ++made;
    // Block everything within distance 3.
    std::set<std::size_t> ring = { v };
    for(int d = 0; d < 3; ++d)
    {
      std::set<std::size_t> next = ring;
      for(std::size_t a : ring)
        next.insert(neighbours[a].begin(), neighbours[a].end());
      ring.swap(next);
    }
    for(std::size_t a : ring)
      blocked[a] = 1;
  }
  std::vector<std::array<std::size_t, 3> > kept;
  for(const auto& t : s.triangles)
    if(!chosen[t[0]] && !chosen[t[1]] && !chosen[t[2]])
      kept.push_back(t);
  s.triangles.swap(kept);
  s = compact(s);
}

void bounding_box(const TS::Soup& s, std::array<double, 3>& lo, std::array<double, 3>& hi)
{
  lo = hi = s.points.front();
  for(const auto& p : s.points)
    for(std::size_t d = 0; d < 3; ++d)
    {
      lo[d] = std::min(lo[d], p[d]);
      hi[d] = std::max(hi[d], p[d]);
    }
}

// Appends `part` to the right of `s` (along x), with a gap.
void append_beside(TS::Soup& s, const TS::Soup& part)
{
  if(s.points.empty())
  {
    s = part;
    return;
  }
  std::array<double, 3> lo, hi, plo, phi;
  bounding_box(s, lo, hi);
  bounding_box(part, plo, phi);
  const std::size_t offset = s.points.size();
  const double dx = hi[0] + 0.5 - plo[0];
  for(const auto& p : part.points)
    s.points.push_back({{ p[0] + dx, p[1], p[2] }});
  for(const auto& t : part.triangles)
    s.triangles.push_back({{ t[0] + offset, t[1] + offset, t[2] + offset }});
}

// One random base surface: a sphere, a torus or a genus-g surface.
TS::Soup random_base(std::mt19937& rng, std::string& what)
{
  std::ostringstream name;
  TS::Soup s;
  switch(uniform_int(rng, 0, 2))
  {
  case 0:
  {
    const int lat = uniform_int(rng, 4, 24), lon = uniform_int(rng, 5, 32);
    name << "uv_sphere(" << lat << "," << lon << ")";
    s = TS::uv_sphere(lat, lon);
    break;
  }
  case 1:
  {
    const int major = uniform_int(rng, 6, 48), minor = uniform_int(rng, 4, 16);
    name << "torus(" << major << "," << minor << ")";
    s = TS::torus(major, minor);
    break;
  }
  default:
  {
    const int g = uniform_int(rng, 0, 4), r = uniform_int(rng, 1, 4);
    name << "genus_surface(" << g << "," << r << ")";
    s = TS::genus_surface(g, r);
    break;
  }
  }
  what = name.str();
  return s;
}

struct Random_case
{
  TS::Soup soup;
  std::string description;
  int n, k;
  double threshold;
  DS::Parameterization_method method;
};

Random_case make_random_case(std::uint32_t seed)
{
  std::mt19937 rng(seed);
  Random_case c;
  std::ostringstream d;
  d << "seed " << seed << ":";
  const int components = uniform_int(rng, 1, 3);
  for(int i = 0; i < components; ++i)
  {
    std::string what;
    TS::Soup part = random_base(rng, what);
    d << " [" << what;
    if(uniform_int(rng, 0, 1) == 1)
    {
      const double p = uniform_real(rng, 0.05, 0.5);
      split_random_faces(part, rng, p);
      d << " split p=" << p;
    }
    if(uniform_int(rng, 0, 2) != 0)
    {
      const int holes = uniform_int(rng, 1, 6);
      TS::Soup punched = part;
      punch_holes(punched, rng, holes);
      // Guard: keep the holes only if the generator above kept the promise.
      if(!punched.triangles.empty() && CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(punched.triangles))
      {
        part = punched;
        d << " holes<=" << holes;
      }
      else
        d << " (holes rejected)";
    }
    const double amount = uniform_real(rng, 0., 0.3);
    jitter(part, rng, amount);
    d << " jitter=" << amount << "]";
    append_beside(c.soup, part);
  }
  c.n = uniform_int(rng, 1, 40);
  c.k = uniform_int(rng, 2, 8);
  c.threshold = uniform_real(rng, 0., 2.);
  c.method = TS::all_parameterization_methods[uniform_int(rng, 0, 4)];
  d << " n=" << c.n << " k=" << c.k << " threshold=" << c.threshold << " method=" << DS::to_string(c.method)
    << " (" << c.soup.points.size() << " points, " << c.soup.triangles.size() << " triangles)";
  c.description = d.str();
  return c;
}



// Faces of each connected component (through shared vertices), as face
// indices; component of each face.
std::vector<std::size_t> face_components(const Mesh& tm, std::size_t& count)
{
  TS::topo_detail::Union_find uf(tm.number_of_vertices());
  for(Mesh::Face_index f : faces(tm))
  {
    const Mesh::Halfedge_index h = halfedge(f, tm);
    uf.unite(std::size_t(target(h, tm)), std::size_t(source(h, tm)));
    uf.unite(std::size_t(target(h, tm)), std::size_t(target(next(h, tm), tm)));
  }
  std::map<std::size_t, std::size_t> id;
  std::vector<std::size_t> result;
  for(Mesh::Face_index f : faces(tm))
    result.push_back(id.emplace(uf.find(std::size_t(target(halfedge(f, tm), tm))), id.size()).first->second);
  count = id.size();
  return result;
}

// Every chart lies inside one connected component (so each component has
// its own charts).
void expect_charts_within_components(const Mesh& tm, const Atlas& a)
{
  std::size_t count = 0;
  const std::vector<std::size_t> component = face_components(tm, count);
  std::map<std::size_t, std::size_t> component_of_chart;
  std::size_t fi = 0, bad = 0;
  for(Mesh::Face_index f : faces(tm))
  {
    auto it = component_of_chart.emplace(a.patch[f], component[fi]).first;
    if(it->second != component[fi])
      ++bad;
    ++fi;
  }
  EXPECT_EQ(bad, 0u) << "faces whose chart spans several components";
  EXPECT_GE(a.report.number_of_charts, count);
}

} // namespace

TEST(RandomMeshes, RandomSurfacesAndParametersGiveValidAtlases)
{
  std::size_t with_holes = 0, with_several_components = 0;
  std::set<DS::Parameterization_method> methods;
  for(std::uint32_t seed : seeds)
  {
    const Random_case c = make_random_case(seed);
    SCOPED_TRACE(c.description);
    if(std::getenv("DISK_SEGMENTATION_TEST_VERBOSE") != nullptr)
      std::cout << c.description << std::endl;
    with_holes += (c.description.find("holes<=") != std::string::npos) ? 1 : 0;
    with_several_components += (c.description.find("] [") != std::string::npos) ? 1 : 0;
    methods.insert(c.method);
    Mesh tm;
    ASSERT_NO_THROW(TS::to_mesh(c.soup, tm));
    Atlas a;
    ASSERT_NO_THROW(a = make_atlas(tm, DS::parameters::number_of_seeds(std::size_t(c.n))
                                          .number_of_subsamples(std::size_t(c.k))
                                          .merge_threshold(c.threshold)
                                          .parameterization_method(c.method)));
    expect_valid_atlas(tm, a, 512);
    expect_charts_within_components(tm, a);
  }
  // The seeds must keep exercising what this test is about.
  EXPECT_GE(with_holes, 5u);
  EXPECT_GE(with_several_components, 5u);
  EXPECT_EQ(methods.size(), 5u);
}

TEST(RandomMeshes, GenerationIsDeterministic)
{
  const Random_case a = make_random_case(seeds[3]), b = make_random_case(seeds[3]);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.soup.points, b.soup.points);
  EXPECT_EQ(a.soup.triangles, b.soup.triangles);
}

namespace {

// A regular-ish tetrahedron with outward normals, vertices at `c` + offsets.
void add_tetrahedron(TS::Soup& s, double x, double y, double z)
{
  const std::size_t o = s.points.size();
  s.points.push_back({{ x, y, z }});
  s.points.push_back({{ x + 1., y, z }});
  s.points.push_back({{ x, y + 1., z }});
  s.points.push_back({{ x, y, z + 1. }});
  s.triangles.push_back({{ o + 0, o + 2, o + 1 }});
  s.triangles.push_back({{ o + 0, o + 1, o + 3 }});
  s.triangles.push_back({{ o + 0, o + 3, o + 2 }});
  s.triangles.push_back({{ o + 1, o + 2, o + 3 }});
}

} // namespace

TEST(RandomMeshes, ThousandsOfTetrahedraEachGetTheirOwnCharts)
{
  TS::Soup s;
  for(int i = 0; i < 3000; ++i)
    add_tetrahedron(s, 2. * (i % 60), 2. * (i / 60), 0.);
  Mesh tm;
  TS::to_mesh(s, tm);
  Atlas a;
  ASSERT_NO_THROW(a = make_atlas(tm, DS::parameters::number_of_seeds(5)));
  expect_valid_atlas(tm, a, 1024);
  expect_charts_within_components(tm, a);
  EXPECT_GE(a.report.number_of_charts, 2u * 3000u) << "a closed tetrahedron needs two disks at least";
}

TEST(RandomMeshes, VeryHighGenusGivesValidAtlases)
{
  // Genus 60 with 10 seeds: most Voronoi cells hold several handles, so the
  // recursive refinement does nearly all the work.
  const int genus = 60;
  Mesh tm;
  TS::to_mesh(TS::genus_surface(genus, 1), tm);
  ASSERT_EQ(TS::euler_characteristic_of(tm, faces(tm)), 2 - 2 * genus);
  Atlas a;
  ASSERT_NO_THROW(a = make_atlas(tm, DS::parameters::default_values()));
  expect_valid_atlas(tm, a, 2048);
}

TEST(RandomMeshes, ThousandsOfSeparateTrianglesEachGetOneChart)
{
  TS::Soup s;
  for(int i = 0; i < 3000; ++i)
  {
    const std::size_t o = s.points.size();
    const double x = 2. * (i % 60), y = 2. * (i / 60);
    s.points.push_back({{ x, y, 0. }});
    s.points.push_back({{ x + 1., y, 0. }});
    s.points.push_back({{ x, y + 1., 0.5 * (i % 3) }});
    s.triangles.push_back({{ o, o + 1, o + 2 }});
  }
  Mesh tm;
  TS::to_mesh(s, tm);
  Atlas a;
  ASSERT_NO_THROW(a = make_atlas(tm, DS::parameters::default_values()));
  expect_valid_atlas(tm, a, 1024);
  expect_charts_within_components(tm, a);
  EXPECT_EQ(a.report.number_of_charts, 3000u);
}

TEST(RandomMeshes, IsolatedVerticesAreIgnored)
{
  Mesh tm;
  TS::to_mesh(TS::torus(16, 8), tm);
  // Isolated vertices: one far away, one at the same place as a mesh vertex,
  // one inside the torus.
  tm.add_vertex(K::Point_3(10., 10., 10.));
  const K::Point_3 first = tm.point(*vertices(tm).begin()); // a copy: add_vertex may reallocate
  tm.add_vertex(first);
  tm.add_vertex(K::Point_3(1., 0., 0.));
  for(DS::Parameterization_method method : TS::all_parameterization_methods)
  {
    SCOPED_TRACE(DS::to_string(method));
    Mesh copy = tm;
    Atlas a;
    ASSERT_NO_THROW(a = make_atlas(copy, DS::parameters::parameterization_method(method)));
    expect_valid_atlas(copy, a, 512);
  }
}

namespace {

// No chart may have failed on a CGAL assertion: this build keeps them on,
// but where they are off (release builds), the same input runs past them.
void expect_no_assertion_failure(const Atlas& a)
{
  for(const DS::Chart_report& r : a.report.parameterization.charts)
    EXPECT_EQ(r.problem.find("assertion"), std::string::npos) << "chart " << r.patch << ": " << r.problem;
}

// Every method gives a valid atlas of `s`, no chart across two components,
// and no chart failed on a CGAL assertion.
void expect_every_method_gives_a_valid_atlas(const TS::Soup& s)
{
  for(DS::Parameterization_method method : TS::all_parameterization_methods)
  {
    SCOPED_TRACE(DS::to_string(method));
    Mesh tm;
    TS::to_mesh(s, tm);
    Atlas a;
    ASSERT_NO_THROW(a = make_atlas(tm, DS::parameters::parameterization_method(method)));
    expect_valid_atlas(tm, a, 512);
    expect_charts_within_components(tm, a);
    expect_no_assertion_failure(a);
  }
}

} // namespace

TEST(RandomMeshes, DuplicatedVerticesAreDistinctVertices)
{
  // A 6 x 6 grid cut along x = 3: the points on the cut are duplicated
  // (same coordinates, different indices), giving two components whose
  // borders coincide in 3D. Plus two coincident copies of a sphere.
  TS::Soup grid = TS::grid_with_holes(6, 6, 0);
  std::map<std::size_t, std::size_t> twin;
  for(auto& t : grid.triangles)
  {
    const double cx = (grid.points[t[0]][0] + grid.points[t[1]][0] + grid.points[t[2]][0]) / 3.;
    if(cx < 3.)
      continue;
    for(std::size_t& v : t)
      if(grid.points[v][0] == 3.)
      {
        auto it = twin.find(v);
        if(it == twin.end())
        {
          it = twin.emplace(v, grid.points.size()).first;
          grid.points.push_back(grid.points[v]);
        }
        v = it->second;
      }
  }
  ASSERT_EQ(twin.size(), 7u);
  TS::Soup s = grid;
  const TS::Soup sphere = TS::uv_sphere(8, 12);
  TS::soup_detail::append(s, sphere, 10., 0., 0.);
  TS::soup_detail::append(s, sphere, 10., 0., 0.);
  expect_every_method_gives_a_valid_atlas(s);
}

namespace {

struct Scaled_components
{
  TS::Soup soup;
  std::vector<double> face_scale;  // scale of each triangle's component
};

// Components of `scales.size()` sizes, all near the origin: a bumpy 3 x 3
// grid (18 triangles) and a small closed sphere in turn, the k-th multiplied
// by scales[k]. Positions relative to one another are meaningless at such
// ratios; the shape of each component is not.
Scaled_components components_of_scales(const std::vector<double>& scales)
{
  TS::Soup grid = TS::grid_with_holes(3, 3, 0);
  for(auto& p : grid.points)
    p[2] = 0.1 * double((int(p[0]) * int(p[1])) % 3);
  const TS::Soup sphere = TS::uv_sphere(4, 6);
  Scaled_components c;
  for(std::size_t k = 0; k < scales.size(); ++k)
  {
    TS::Soup part = (k % 2 == 0) ? grid : sphere;
    for(auto& p : part.points)
      for(double& x : p)
        x *= scales[k];
    TS::soup_detail::append(c.soup, part, 0., 0., 0.);
    c.face_scale.resize(c.soup.triangles.size(), scales[k]);
  }
  return c;
}

// expect_valid_atlas(), but with the 3D coordinates of each face divided by
// its component's scale. The checker calls a face degenerate when its
// UV-to-3D area ratio is under 1e-12 of the mean over all faces: with
// components 1e300 apart in 3D area, every atlas would fail that. All other
// checks read only the UVs, which are left as they are.
void expect_valid_atlas_per_component(const Mesh& tm, const Atlas& a, const std::vector<double>& face_scale)
{
  const TS::Partition_report partition = TS::check_disk_partition(tm, a.patch);
  EXPECT_TRUE(partition.ok) << partition.problem;
  EXPECT_EQ(partition.number_of_patches, a.report.number_of_charts);
  TS::Atlas_soup soup = TS::atlas_soup_from_mesh(tm, a.patch, a.uv);
  ASSERT_EQ(soup.size(), face_scale.size());
  for(std::size_t f = 0; f < soup.size(); ++f)
    for(auto& p : soup.xyz[f])
      for(double& x : p)
        x /= face_scale[f];
  const TS::Atlas_report atlas = TS::check_atlas_soup(soup, 512);
  EXPECT_TRUE(atlas.ok()) << atlas.summary();
  EXPECT_EQ(atlas.faces_zero_3d_area, 0u);
  EXPECT_EQ(a.report.parameterization.number_of_invalid_charts, 0u);
}

} // namespace

TEST(RandomMeshes, ComponentsOfWildlyDifferentScalesGiveValidAtlases)
{
  // One frame for the whole mesh once collapsed the small copy of the first
  // case to a point (shared center), on which LSCM wrote out of bounds, and
  // underflowed the lengths and areas of the 1e-150 one (shared scale).
  const std::vector<std::vector<double> > cases = {
    { 1e20, 1e-20 },
    { 1e-30, 1., 1e30 },
    { 1e-150, 1e-30, 1., 1e30, 1e150 } };
  for(const std::vector<double>& scales : cases)
  {
    const Scaled_components c = components_of_scales(scales);
    for(DS::Parameterization_method method : TS::all_parameterization_methods)
      for(DS::Packing_method packer : { DS::Packing_method::TIGHT, DS::Packing_method::GRID })
      {
        std::ostringstream what;
        what << scales.size() << " components, " << DS::to_string(method)
             << (packer == DS::Packing_method::TIGHT ? ", tight" : ", grid");
        SCOPED_TRACE(what.str());
        Mesh tm;
        TS::to_mesh(c.soup, tm);
        Atlas a;
        // Unbounded: the check below counts single-triangle charts, which the
        // bound makes on purpose for methods that pin the border on a circle.
        ASSERT_NO_THROW(a = make_atlas(tm, DS::parameters::parameterization_method(method).packing_method(packer)
                                             .distortion_bound(DS::Distortion_bound::unbounded())));
        expect_valid_atlas_per_component(tm, a, c.face_scale);
        expect_charts_within_components(tm, a);
        expect_no_assertion_failure(a);
        // A component whose shape was lost to rounding would only have
        // charts that fail every method, split down to single triangles.
        for(const DS::Chart_report& r : a.report.parameterization.charts)
          EXPECT_GT(r.faces, 1u) << "chart " << r.patch << ": " << r.problem;

        // Without the fallback, charts may stay invalid, but nothing may crash.
        Mesh raw;
        TS::to_mesh(c.soup, raw);
        try
        {
          make_atlas(raw, DS::parameters::parameterization_method(method).packing_method(packer).use_fallback(false));
        }
        catch(const DS::Input_error&)
        {
          // Packing refuses invalid charts (e.g. of zero UV area).
        }
      }
  }
}

TEST(RandomMeshes, ComponentCollapsedToAPointGivesAValidAtlas)
{
  // A grid and a copy of it whose vertices all lie at one point: no method
  // can flatten the copy's charts (LSCM once wrote out of bounds on them),
  // the fallback must still give a valid atlas.
  TS::Soup s = components_of_scales({ 1. }).soup;
  TS::Soup point = s;
  for(auto& p : point.points)
    p = {{ 1., 1., 1. }};
  TS::soup_detail::append(s, point, 0., 0., 0.);
  expect_every_method_gives_a_valid_atlas(s);
}

namespace {

// n triangles around an apex at `height` over a unit circle; with `closed`,
// a second fan around the circle's center closes it (two vertices of
// valence n).
TS::Soup cone(std::size_t n, double height, bool closed)
{
  TS::Soup s;
  s.points.push_back({{ 0., 0., height }});
  for(std::size_t i = 0; i < n; ++i)
  {
    const double a = 2. * TS::soup_detail::pi() * double(i) / double(n);
    s.points.push_back({{ std::cos(a), std::sin(a), 0. }});
  }
  for(std::size_t i = 0; i < n; ++i)
    s.triangles.push_back({{ 0, 1 + i, 1 + (i + 1) % n }});
  if(closed)
  {
    s.points.push_back({{ 0., 0., 0. }});
    for(std::size_t i = 0; i < n; ++i)
      s.triangles.push_back({{ n + 1, 1 + (i + 1) % n, 1 + i }});
  }
  return s;
}

} // namespace

// Slivers around a vertex of high valence: each border arc, the smoothing
// and the packers' footprints once walked every face around it.
TEST(RandomMeshes, AVertexOfHighValenceGivesAValidAtlas)
{
  for(const auto& c : { std::make_pair(std::size_t(20000), false), std::make_pair(std::size_t(3000), true) })
  {
    SCOPED_TRACE("valence " + std::to_string(c.first) + (c.second ? ", closed cone" : ", open cone"));
    Mesh tm;
    TS::to_mesh(cone(c.first, 0.3, c.second), tm);
    Atlas a;
    ASSERT_NO_THROW(a = make_atlas(tm, DS::parameters::default_values()));
    expect_valid_atlas(tm, a, 1024);
  }
}

// Small parts beside a large one: each small chart's place was searched
// from the bottom rows, filled by the large one, again.
TEST(RandomMeshes, ThousandsOfTinyComponentsBesideALargeOneGiveAValidAtlas)
{
  TS::Soup s = TS::torus(120, 40, 100., 30.);
  for(int i = 0; i < 2000; ++i)
    add_tetrahedron(s, 150. + 2. * (i % 40), 2. * (i / 40), 0.);
  Mesh tm;
  TS::to_mesh(s, tm);
  Atlas a;
  ASSERT_NO_THROW(a = make_atlas(tm, DS::parameters::default_values()));
  expect_valid_atlas(tm, a, 1024);
  expect_charts_within_components(tm, a);
  EXPECT_GE(a.report.number_of_charts, 2u * 2000u + 1u);
}
