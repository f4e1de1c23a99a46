// Tests of the segmentation into topological disks. Every result is checked
// with test_support::check_disk_partition(), written independently from the
// library (see independent_topology.h).

#include "independent_topology.h"
#include "test_meshes.h"

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Disk_segmentation/internal/Chart_selection/Face_group_moves.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace DS = CGAL::Disk_segmentation;
namespace TS = test_support;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

namespace {

const std::size_t no_id = static_cast<std::size_t>(-1);

std::string data_path(const std::string& name)
{
  return std::string(DISK_SEGMENTATION_TEST_DATA_DIR) + "/" + name;
}

template <typename TM>
TM load(const std::string& name)
{
  TM tm;
  if(!CGAL::IO::read_polygon_mesh(data_path(name), tm))
    throw std::runtime_error("cannot read test mesh " + name);
  return tm;
}

template <typename TM>
TM make(const TS::Soup& soup)
{
  TM tm;
  TS::to_mesh(soup, tm);
  return tm;
}

// Patch ids in face order, the form in which results are compared.
template <typename TM>
struct Patches
{
  typedef typename boost::property_map<TM, CGAL::dynamic_face_property_t<std::size_t> >::const_type Map;
  Map map;
  explicit Patches(const TM& tm) : map(get(CGAL::dynamic_face_property_t<std::size_t>(), tm))
  {
    for(auto f : faces(tm)) put(map, f, no_id);
  }
  std::vector<std::size_t> ids(const TM& tm) const
  {
    std::vector<std::size_t> out;
    for(auto f : faces(tm)) out.push_back(get(map, f));
    return out;
  }
};

template <typename TM>
void expect_disk_partition(const TM& tm, const Patches<TM>& patches, std::size_t expected_count)
{
  const TS::Partition_report report = TS::check_disk_partition(tm, patches.map);
  EXPECT_TRUE(report.ok) << report.problem;
  EXPECT_EQ(report.number_of_patches, expected_count);
}

// The three steps one by one, each result checked.
template <typename TM>
std::vector<std::size_t> segment_step_by_step(const TM& tm, std::size_t n = 10)
{
  Patches<TM> patches(tm);
  const std::size_t cells = DS::voronoi_fps_segmentation(tm, patches.map, DS::parameters::number_of_seeds(n));
  EXPECT_GE(cells, std::min<std::size_t>(n, num_faces(tm)));
  const auto voronoi = TS::patches_as_face_index_sets(tm, patches.map);
  EXPECT_EQ(voronoi.size(), cells);

  const std::size_t refined = DS::refine_to_topological_disks(tm, patches.map);
  expect_disk_partition(tm, patches, refined);
  const auto disks = TS::patches_as_face_index_sets(tm, patches.map);
  EXPECT_TRUE(TS::refines(disks, voronoi)) << "refinement must only split cells";

  const std::size_t merged = DS::merge_disk_regions(tm, patches.map);
  expect_disk_partition(tm, patches, merged);
  EXPECT_LE(merged, refined);
  EXPECT_TRUE(TS::refines(disks, TS::patches_as_face_index_sets(tm, patches.map)))
    << "merging must only unite regions";

  Patches<TM> at_once(tm);
  // smooth_borders(false): the paper's segmentation, which the three steps are.
  EXPECT_EQ(DS::segment_into_disks(tm, at_once.map, DS::parameters::number_of_seeds(n).smooth_borders(false)), merged);
  EXPECT_EQ(at_once.ids(tm), patches.ids(tm)) << "segment_into_disks must equal the three steps";
  // Without the parameter, the borders are smoothed as everywhere else.
  Patches<TM> by_default(tm), smoothed(tm);
  DS::segment_into_disks(tm, by_default.map, DS::parameters::number_of_seeds(n));
  DS::segment_into_disks(tm, smoothed.map, DS::parameters::number_of_seeds(n).smooth_borders(true));
  EXPECT_EQ(by_default.ids(tm), smoothed.ids(tm));
  return patches.ids(tm);
}

struct Generated
{
  const char* name;
  TS::Soup soup;
};

std::vector<Generated> generated_meshes()
{
  return {
    { "sphere", TS::uv_sphere(16, 24) },
    { "torus", TS::torus(40, 16) },
    { "genus3", TS::genus_surface(3, 3) },
    { "cylinder", TS::cylinder(24, 12) },
    { "disk", TS::disk(8, 24) },
    { "grid_with_holes", TS::grid_with_holes(30, 30, 6) },
    { "disconnected", TS::disconnected(5) },
    { "single_triangle", TS::single_triangle() },
    { "thin_strip", TS::thin_strip(300) },
  };
}

const char* shipped_meshes[] = { "elephant.off", "elephant-with-holes.off", "blobby_3cc.off", "knot1.off",
                                 "bones.off", "eight.off", "couplingdown.off" };

} // namespace

// ---------------------------------------------------------------------------
// Every patch is a disk, on generated and shipped meshes, on both mesh types,
// with identical ids on both.

TEST(Segmentation, GeneratedMeshesGiveDisksOnBothMeshTypes)
{
  for(const Generated& g : generated_meshes())
  {
    SCOPED_TRACE(g.name);
    for(std::size_t n : { std::size_t(1), std::size_t(10), std::size_t(60) })
    {
      SCOPED_TRACE(n);
      const std::vector<std::size_t> sm = segment_step_by_step(make<Mesh>(g.soup), n);
      const std::vector<std::size_t> ph = segment_step_by_step(make<Polyhedron>(g.soup), n);
      EXPECT_EQ(sm, ph);
    }
  }
}

TEST(Segmentation, ShippedMeshesGiveDisksOnBothMeshTypes)
{
  for(const char* name : shipped_meshes)
  {
    SCOPED_TRACE(name);
    const std::vector<std::size_t> sm = segment_step_by_step(load<Mesh>(name));
    const std::vector<std::size_t> ph = segment_step_by_step(load<Polyhedron>(name));
    EXPECT_EQ(sm, ph);
  }
}

TEST(Segmentation, HighGenusNeedsRefinementAndGetsDisks)
{
  // A closed genus-3 surface cannot be covered by one cell: with a single
  // seed the cell is the whole surface, which refinement must split.
  const Mesh tm = make<Mesh>(TS::genus_surface(3, 2));
  Patches<Mesh> patches(tm);
  ASSERT_EQ(DS::voronoi_fps_segmentation(tm, patches.map, DS::parameters::number_of_seeds(1)), 1u);
  EXPECT_FALSE(TS::check_disk_partition(tm, patches.map).ok);
  const std::size_t refined = DS::refine_to_topological_disks(tm, patches.map, DS::parameters::number_of_subsamples(2));
  EXPECT_GE(refined, 2u);
  expect_disk_partition(tm, patches, refined);
}

TEST(Segmentation, RefinementTerminatesOnEveryMeshWithSmallestSubsampling)
{
  // k = 2 recurses deepest; the whole mesh as one region is the worst start.
  for(const Generated& g : generated_meshes())
  {
    SCOPED_TRACE(g.name);
    const Mesh tm = make<Mesh>(g.soup);
    Patches<Mesh> patches(tm);
    for(auto f : faces(tm)) put(patches.map, f, 7);
    const std::size_t refined = DS::refine_to_topological_disks(tm, patches.map, DS::parameters::number_of_subsamples(2));
    expect_disk_partition(tm, patches, refined);
  }
}

// ---------------------------------------------------------------------------
// Properties of each step

TEST(Segmentation, RefinementLeavesDiskRegionsUntouched)
{
  for(const char* name : { "elephant.off", "knot1.off", "couplingdown.off" })
  {
    SCOPED_TRACE(name);
    const Mesh tm = load<Mesh>(name);
    Patches<Mesh> patches(tm);
    DS::voronoi_fps_segmentation(tm, patches.map, DS::parameters::number_of_seeds(10));
    const auto cells = TS::patches_as_face_index_sets(tm, patches.map);

    std::vector<std::vector<std::size_t> > disk_cells;
    std::size_t non_disk_cells = 0;
    std::vector<Mesh::Face_index> all_faces(faces(tm).begin(), faces(tm).end());
    for(const auto& cell : cells)
    {
      std::vector<Mesh::Face_index> fs;
      for(std::size_t i : cell) fs.push_back(all_faces[i]);
      if(TS::is_disk(tm, fs)) disk_cells.push_back(cell);
      else ++non_disk_cells;
    }
    EXPECT_GT(non_disk_cells, 0u) << "the test needs a mesh with some non-disk cell";

    DS::refine_to_topological_disks(tm, patches.map);
    const auto refined = TS::patches_as_face_index_sets(tm, patches.map);
    const std::set<std::vector<std::size_t> > refined_set(refined.begin(), refined.end());
    for(const auto& cell : disk_cells)
      EXPECT_EQ(refined_set.count(cell), 1u) << "a disk cell was changed";
  }
}

TEST(Segmentation, HigherThresholdStopsEarlierOnTheSameMergeSequence)
{
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "couplingdown.off" })
  {
    SCOPED_TRACE(name);
    const Mesh tm = load<Mesh>(name);
    Patches<Mesh> refined(tm);
    DS::voronoi_fps_segmentation(tm, refined.map, DS::parameters::number_of_seeds(30));
    DS::refine_to_topological_disks(tm, refined.map);
    const std::vector<std::size_t> start = refined.ids(tm);

    std::vector<std::vector<std::size_t> > previous;
    std::size_t previous_count = std::numeric_limits<std::size_t>::max();
    for(double eps : { 3.0, 1.2, DS::regular_polygon_threshold(5), 0.5, 0.2, 0.0 })
    {
      SCOPED_TRACE(eps);
      Patches<Mesh> patches(tm);
      std::size_t i = 0;
      for(auto f : faces(tm)) put(patches.map, f, start[i++]);
      const std::size_t count = DS::merge_disk_regions(tm, patches.map, DS::parameters::merge_threshold(eps));
      expect_disk_partition(tm, patches, count);
      EXPECT_LE(count, previous_count) << "a lower threshold gave more patches";
      const auto current = TS::patches_as_face_index_sets(tm, patches.map);
      if(!previous.empty())
        EXPECT_TRUE(TS::refines(previous, current)) << "the higher-threshold run is not a prefix";
      previous = current;
      previous_count = count;
    }
  }
}

TEST(Segmentation, MergingNeverGluesAlongTwoArcs)
{
  // Two half-tubes share two separate lines: their union is an annulus, so
  // they must stay apart whatever the threshold.
  const Mesh tm = make<Mesh>(TS::cylinder(24, 6));
  Patches<Mesh> patches(tm);
  for(auto f : faces(tm))
  {
    const auto c = CGAL::centroid(tm.point(target(halfedge(f, tm), tm)),
                                  tm.point(target(next(halfedge(f, tm), tm), tm)),
                                  tm.point(source(halfedge(f, tm), tm)));
    put(patches.map, f, c.y() > 0 ? 0 : 1);
  }
  ASSERT_TRUE(TS::check_disk_partition(tm, patches.map).ok);
  EXPECT_EQ(DS::merge_disk_regions(tm, patches.map, DS::parameters::merge_threshold(0.)), 2u);
  expect_disk_partition(tm, patches, 2);
}

TEST(Segmentation, MergingSingleFacesOfADiskRebuildsLargeDisks)
{
  const Mesh tm = make<Mesh>(TS::disk(6, 16));
  Patches<Mesh> patches(tm);
  std::size_t i = 0;
  for(auto f : faces(tm)) put(patches.map, f, i++);
  const std::size_t count = DS::merge_disk_regions(tm, patches.map, DS::parameters::merge_threshold(0.));
  expect_disk_partition(tm, patches, count);
  EXPECT_LT(count, num_faces(tm) / 10);
}

TEST(Segmentation, EveryComponentGetsASeed)
{
  const Mesh tm = make<Mesh>(TS::disconnected(5));
  Patches<Mesh> patches(tm);
  std::vector<Mesh::Face_index> seeds;
  const std::size_t cells = DS::voronoi_fps_segmentation(
    tm, patches.map, DS::parameters::number_of_seeds(2).seeds_output_iterator(std::back_inserter(seeds)));
  EXPECT_EQ(cells, 5u);
  ASSERT_EQ(seeds.size(), 5u);
  // Each seed lies in its own cell and cells never span components, so the
  // five cells are exactly the five components.
  for(std::size_t i = 0; i < seeds.size(); ++i)
    EXPECT_EQ(get(patches.map, seeds[i]), i);
  const auto cells_faces = TS::patches_as_face_index_sets(tm, patches.map);
  std::set<std::size_t> sizes;
  for(const auto& c : cells_faces) sizes.insert(c.size());
  const TS::Soup sphere = TS::uv_sphere(4, 8), torus = TS::torus(8, 6);
  EXPECT_EQ(sizes, (std::set<std::size_t>{ sphere.triangles.size(), torus.triangles.size() }));
}

TEST(Segmentation, SeedsAreDistinctFacesOwningTheirCells)
{
  const Mesh tm = load<Mesh>("elephant.off");
  Patches<Mesh> patches(tm);
  std::vector<Mesh::Face_index> seeds;
  const std::size_t cells = DS::voronoi_fps_segmentation(
    tm, patches.map, DS::parameters::number_of_seeds(40).seeds_output_iterator(std::back_inserter(seeds)));
  ASSERT_EQ(cells, 40u);
  ASSERT_EQ(seeds.size(), 40u);
  EXPECT_EQ(std::set<Mesh::Face_index>(seeds.begin(), seeds.end()).size(), 40u);
  for(std::size_t i = 0; i < seeds.size(); ++i)
    EXPECT_EQ(get(patches.map, seeds[i]), i);
  // Voronoi cells of a connected mesh are edge-connected: a flood fill
  // through edges from the seed reaches the whole cell.
  std::vector<std::size_t> reached(cells, 0), size(cells, 0);
  for(auto f : faces(tm)) ++size[get(patches.map, f)];
  for(std::size_t i = 0; i < seeds.size(); ++i)
  {
    std::set<Mesh::Face_index> seen{ seeds[i] };
    std::vector<Mesh::Face_index> stack{ seeds[i] };
    while(!stack.empty())
    {
      const Mesh::Face_index f = stack.back();
      stack.pop_back();
      for(Mesh::Face_index g : CGAL::faces_around_face(tm.halfedge(f), tm))
        if(g != Mesh::null_face() && get(patches.map, g) == i && seen.insert(g).second)
          stack.push_back(g);
    }
    EXPECT_EQ(seen.size(), size[i]) << "cell " << i << " is not edge-connected";
  }
}

TEST(Segmentation, FirstSeedAndRandomSeedParameters)
{
  const Mesh tm = load<Mesh>("elephant.off");
  const Mesh::Face_index chosen(1234);
  std::vector<Mesh::Face_index> seeds;
  Patches<Mesh> patches(tm);
  DS::voronoi_fps_segmentation(tm, patches.map,
    DS::parameters::testing::first_seed(chosen).number_of_seeds(5).seeds_output_iterator(std::back_inserter(seeds)));
  ASSERT_FALSE(seeds.empty());
  EXPECT_EQ(seeds.front(), chosen);

  auto run_random = [&](unsigned int s)
  {
    std::vector<Mesh::Face_index> out;
    Patches<Mesh> p(tm);
    DS::voronoi_fps_segmentation(tm, p.map,
      DS::parameters::random_seed(s).number_of_seeds(5).seeds_output_iterator(std::back_inserter(out)));
    return out;
  };
  EXPECT_EQ(run_random(3), run_random(3));
  std::set<Mesh::Face_index> firsts;
  for(unsigned int s = 0; s < 8; ++s) firsts.insert(run_random(s).front());
  EXPECT_GT(firsts.size(), 1u) << "random_seed has no effect";
}

TEST(Segmentation, DeterministicAcrossRuns)
{
  const Mesh tm = load<Mesh>("knot1.off");
  std::vector<std::vector<std::size_t> > runs;
  for(int r = 0; r < 3; ++r)
  {
    Patches<Mesh> patches(tm);
    DS::segment_into_disks(tm, patches.map, DS::parameters::number_of_seeds(25));
    runs.push_back(patches.ids(tm));
  }
  EXPECT_EQ(runs[0], runs[1]);
  EXPECT_EQ(runs[0], runs[2]);
}

// ---------------------------------------------------------------------------
// Named parameters

namespace {

// Doubles every coordinate: an exact scaling, so every distance and area
// scales exactly and the segmentation must not change.
struct Doubled_point_map
{
  typedef Mesh::Vertex_index key_type;
  typedef K::Point_3 value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;
  const Mesh* mesh;
  friend value_type get(const Doubled_point_map& m, key_type v)
  {
    const K::Point_3& p = m.mesh->point(v);
    return K::Point_3(2 * p.x(), 2 * p.y(), 2 * p.z());
  }
};

} // namespace

TEST(Parameters, ChainInAnyOrderWithCGALParameters)
{
  const Mesh tm = load<Mesh>("elephant.off");
  Patches<Mesh> a(tm), b(tm), c(tm), d(tm);
  DS::segment_into_disks(tm, a.map, DS::parameters::number_of_seeds(20).merge_threshold(0.5).number_of_subsamples(3));
  DS::segment_into_disks(tm, b.map,
    DS::parameters::vertex_point_map(tm.points()).merge_threshold(0.5).geom_traits(K()).number_of_subsamples(3).number_of_seeds(20));
  DS::segment_into_disks(tm, c.map,
    DS::parameters::number_of_subsamples(3).vertex_point_map(Doubled_point_map{ &tm }).number_of_seeds(20).merge_threshold(0.5));
  DS::segment_into_disks(tm, d.map);
  EXPECT_EQ(a.ids(tm), b.ids(tm));
  EXPECT_EQ(a.ids(tm), c.ids(tm)) << "an exact scaling changed the segmentation";
  EXPECT_NE(a.ids(tm), d.ids(tm)) << "the parameters had no effect";
}

TEST(Parameters, NumberOfSeedsIsClampedToTheNumberOfFaces)
{
  const Mesh tm = make<Mesh>(TS::single_triangle());
  Patches<Mesh> patches(tm);
  EXPECT_EQ(DS::voronoi_fps_segmentation(tm, patches.map, DS::parameters::number_of_seeds(10)), 1u);
  const Mesh strip = make<Mesh>(TS::thin_strip(5));
  Patches<Mesh> p2(strip);
  EXPECT_EQ(DS::voronoi_fps_segmentation(strip, p2.map, DS::parameters::number_of_seeds(1000)), 10u);
  expect_disk_partition(strip, p2, 10);
}

TEST(Parameters, RegularPolygonThreshold)
{
  // eps_N = side / sqrt(area) of a regular N-gon; eps_4 = 1 for a square.
  EXPECT_NEAR(DS::regular_polygon_threshold(4), 1.0, 1e-12);
  EXPECT_NEAR(DS::regular_polygon_threshold(5), 0.7624, 1e-4);
  const double side = 1.0, area_triangle = std::sqrt(3.) / 4.;
  EXPECT_NEAR(DS::regular_polygon_threshold(3), side / std::sqrt(area_triangle), 1e-12);
  // Fewer than 3 sides is no polygon, in release builds too (NDEBUG or not).
  for(int n : { 2, 0, -1 })
    EXPECT_THROW(DS::regular_polygon_threshold(n), DS::Input_error) << n;
  EXPECT_THROW(DS::regular_polygon_threshold(2u), DS::Input_error);
}

// ---------------------------------------------------------------------------
// Public topology queries against the independent checker

TEST(Topology, QueriesAgreeWithIndependentChecker)
{
  const Mesh tm = load<Mesh>("elephant.off");
  Patches<Mesh> patches(tm);
  const std::size_t n = DS::voronoi_fps_segmentation(tm, patches.map, DS::parameters::number_of_seeds(30));
  std::vector<std::vector<Mesh::Face_index> > cells(n);
  for(auto f : faces(tm)) cells[get(patches.map, f)].push_back(f);
  std::size_t disks = 0;
  for(const auto& c : cells)
  {
    EXPECT_EQ(DS::euler_characteristic(c, tm), TS::euler_characteristic_of(tm, c));
    EXPECT_EQ(DS::is_topological_disk(c, tm), TS::is_disk(tm, c));
    disks += TS::is_disk(tm, c);
  }
  EXPECT_GT(disks, 0u);
  EXPECT_LT(disks, n);

  EXPECT_EQ(DS::euler_characteristic(faces(tm), tm), -4);
  EXPECT_FALSE(DS::is_topological_disk(faces(tm), tm));

  // Two triangles touching at a vertex: chi = 1, but not a disk.
  const Mesh sphere = make<Mesh>(TS::uv_sphere(6, 8));
  std::vector<Mesh::Face_index> pinched;
  const Mesh::Vertex_index pole(0);
  std::vector<Mesh::Face_index> around(CGAL::faces_around_target(sphere.halfedge(pole), sphere).begin(),
                                       CGAL::faces_around_target(sphere.halfedge(pole), sphere).end());
  pinched.push_back(around[0]);
  pinched.push_back(around[around.size() / 2]);
  EXPECT_EQ(DS::euler_characteristic(pinched, sphere), 1);
  EXPECT_FALSE(DS::is_topological_disk(pinched, sphere));
  EXPECT_FALSE(TS::is_disk(sphere, pinched));
}

// ---------------------------------------------------------------------------
// Bad input: a clear Input_error, and the patch map left untouched

namespace {

template <typename F>
std::string error_of(F&& f)
{
  try { f(); }
  catch(const DS::Input_error& e) { return e.what(); }
  return std::string();
}

template <typename TM>
void expect_untouched(const TM& tm, const Patches<TM>& patches)
{
  for(auto f : faces(tm)) ASSERT_EQ(get(patches.map, f), no_id);
}

} // namespace

TEST(Errors, EmptyMesh)
{
  const Mesh tm;
  Patches<Mesh> p(tm);
  EXPECT_NE(error_of([&] { DS::segment_into_disks(tm, p.map); }).find("no face"), std::string::npos);
  EXPECT_NE(error_of([&] { DS::voronoi_fps_segmentation(tm, p.map); }).find("no face"), std::string::npos);
}

TEST(Errors, NonTriangleFace)
{
  Mesh tm;
  const auto a = tm.add_vertex(K::Point_3(0, 0, 0)), b = tm.add_vertex(K::Point_3(1, 0, 0)),
             c = tm.add_vertex(K::Point_3(1, 1, 0)), d = tm.add_vertex(K::Point_3(0, 1, 0)),
             e = tm.add_vertex(K::Point_3(2, 0, 0));
  tm.add_face(b, e, c);
  tm.add_face(a, b, c, d);
  Patches<Mesh> p(tm);
  const std::string message = error_of([&] { DS::segment_into_disks(tm, p.map); });
  EXPECT_NE(message.find("more than three vertices"), std::string::npos) << message;
  expect_untouched(tm, p);
}

TEST(Segmentation, PinchedVertexIsCutNotRejected)
{
  // Two triangles sharing only vertex 0: each is its own disk.
  Mesh tm;
  const auto o = tm.add_vertex(K::Point_3(0, 0, 0));
  const auto a = tm.add_vertex(K::Point_3(1, 0, 0)), b = tm.add_vertex(K::Point_3(1, 1, 0));
  const auto c = tm.add_vertex(K::Point_3(-1, 0, 0)), d = tm.add_vertex(K::Point_3(-1, -1, 0));
  ASSERT_NE(tm.add_face(o, a, b), Mesh::null_face());
  ASSERT_NE(tm.add_face(o, c, d), Mesh::null_face());
  Patches<Mesh> p(tm);
  EXPECT_EQ(DS::segment_into_disks(tm, p.map, DS::parameters::number_of_seeds(1)), 2u);
  const TS::Partition_report r = TS::check_disk_partition(tm, p.map);
  EXPECT_TRUE(r.ok) << r.problem;
  EXPECT_EQ(r.number_of_patches, 2u);
}

TEST(Segmentation, NoRegionHoldsTwoFansOfAPinchedVertex)
{
  // A band around a cylinder, cut along one generator except at its bottom
  // vertex, which both ends share: the band is edge-connected and pinched
  // there (two fans). The package cuts the mesh at that vertex internally,
  // where the whole band would be one disk; no region may keep both fans.
  const int around = 24, rows = 3;
  Mesh tm;
  std::vector<std::vector<Mesh::Vertex_index> > v(around + 1, std::vector<Mesh::Vertex_index>(rows + 1));
  for(int k = 0; k <= around; ++k)
    for(int r = 0; r <= rows; ++r)
    {
      const double angle = 2 * TS::soup_detail::pi() * k / around;
      v[k][r] = (k == around && r == 0) ? v[0][0]
                                        : tm.add_vertex(K::Point_3(std::cos(angle), std::sin(angle), 0.5 * r));
    }
  for(int k = 0; k < around; ++k)
    for(int r = 0; r < rows; ++r)
    {
      ASSERT_NE(tm.add_face(v[k][r], v[k + 1][r], v[k + 1][r + 1]), Mesh::null_face());
      ASSERT_NE(tm.add_face(v[k][r], v[k + 1][r + 1], v[k][r + 1]), Mesh::null_face());
    }
  // The whole band is not a disk for the independent checker.
  Patches<Mesh> whole(tm);
  for(Mesh::Face_index f : tm.faces()) put(whole.map, f, 0);
  ASSERT_FALSE(TS::check_disk_partition(tm, whole.map).ok);

  Patches<Mesh> p(tm);
  EXPECT_GE(DS::segment_into_disks(tm, p.map, DS::parameters::number_of_seeds(1)), 2u);
  const TS::Partition_report r = TS::check_disk_partition(tm, p.map);
  EXPECT_TRUE(r.ok) << r.problem;

  // Merging single faces as long as unions stay disks must stop short of
  // the whole band.
  Patches<Mesh> q(tm);
  std::size_t id = 0;
  for(Mesh::Face_index f : tm.faces()) put(q.map, f, id++);
  EXPECT_GE(DS::merge_disk_regions(tm, q.map, DS::parameters::merge_threshold(0.)), 2u);
  const TS::Partition_report rq = TS::check_disk_partition(tm, q.map);
  EXPECT_TRUE(rq.ok) << rq.problem;
}

TEST(Errors, NonFiniteCoordinate)
{
  for(double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    Mesh tm = make<Mesh>(TS::uv_sphere(6, 8));
    tm.point(Mesh::Vertex_index(3)) = K::Point_3(bad, 0, 0);
    Patches<Mesh> p(tm);
    const std::string message = error_of([&] { DS::segment_into_disks(tm, p.map); });
    EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
    expect_untouched(tm, p);
  }
}

TEST(Errors, ParametersOutOfRange)
{
  const Mesh tm = make<Mesh>(TS::uv_sphere(6, 8));
  Patches<Mesh> p(tm);
  EXPECT_NE(error_of([&] { DS::segment_into_disks(tm, p.map, DS::parameters::number_of_seeds(0)); })
              .find("number_of_seeds"), std::string::npos);
  for(std::size_t k : { std::size_t(0), std::size_t(1) })
    EXPECT_NE(error_of([&] { DS::refine_to_topological_disks(tm, p.map, DS::parameters::number_of_subsamples(k)); })
                .find("number_of_subsamples"), std::string::npos);
  // Negative counts are named, not wrapped around to huge ones.
  EXPECT_NE(error_of([&] { DS::voronoi_fps_segmentation(tm, p.map, DS::parameters::number_of_seeds(-3)); })
              .find("number_of_seeds must not be negative"), std::string::npos);
  EXPECT_NE(error_of([&] { DS::segment_into_disks(tm, p.map, DS::parameters::number_of_seeds(-3)); })
              .find("number_of_seeds must not be negative"), std::string::npos);
  EXPECT_NE(error_of([&] { DS::refine_to_topological_disks(tm, p.map, DS::parameters::number_of_subsamples(-2)); })
              .find("number_of_subsamples must not be negative"), std::string::npos);
  for(double eps : { -0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
    EXPECT_NE(error_of([&] { DS::segment_into_disks(tm, p.map, DS::parameters::merge_threshold(eps)); })
                .find("merge_threshold"), std::string::npos);
  expect_untouched(tm, p);

  const Mesh other = make<Mesh>(TS::uv_sphere(6, 8));
  Mesh::Face_index foreign(static_cast<Mesh::size_type>(num_faces(other) + 5));
  EXPECT_NE(error_of([&] { DS::voronoi_fps_segmentation(tm, p.map, DS::parameters::testing::first_seed(foreign)); })
              .find("first_seed"), std::string::npos);
}

TEST(Segmentation, PatchFacesListsEveryFaceOnceUnderItsId)
{
  const Mesh tm = make<Mesh>(TS::uv_sphere(8, 12));
  Patches<Mesh> p(tm);
  const std::size_t count = DS::segment_into_disks(tm, p.map, DS::parameters::number_of_seeds(6));
  const auto lists = DS::patch_faces(tm, p.map);
  ASSERT_EQ(lists.size(), count);
  // Every face in exactly one list, the one of its id, in faces(tm) order.
  std::vector<std::size_t> seen(num_faces(tm), 0);
  for(std::size_t id = 0; id < lists.size(); ++id)
  {
    EXPECT_FALSE(lists[id].empty()) << id;
    for(std::size_t k = 0; k < lists[id].size(); ++k)
    {
      const Mesh::Face_index f = lists[id][k];
      EXPECT_EQ(get(p.map, f), id);
      ++seen[f.idx()];
      if(k > 0)
        EXPECT_LT(lists[id][k - 1].idx(), f.idx());
    }
  }
  for(std::size_t f = 0; f < seen.size(); ++f)
    EXPECT_EQ(seen[f], 1u) << f;

  // A gap in the ids gives an empty list; a negative id is an error.
  std::map<Mesh::Face_index, int> ids;
  for(auto f : faces(tm))
    ids[f] = 2;
  const auto gap = DS::patch_faces(tm, boost::make_assoc_property_map(ids));
  ASSERT_EQ(gap.size(), 3u);
  EXPECT_TRUE(gap[0].empty() && gap[1].empty());
  EXPECT_EQ(gap[2].size(), num_faces(tm));
  ids[*faces(tm).begin()] = -1;
  EXPECT_NE(error_of([&] { DS::patch_faces(tm, boost::make_assoc_property_map(ids)); }).find("negative patch id"),
            std::string::npos);
}

TEST(Segmentation, SurfaceMeshWithGarbageIsHandled)
{
  // Faces removed without collect_garbage() stay in the Surface_mesh as
  // garbage; the package skips them, so the result equals the one on a
  // copy without garbage and with the same face and vertex orders
  // (copy_face_graph; collect_garbage() may reorder them), face for face.
  Mesh tm = make<Mesh>(TS::uv_sphere(10, 16));
  std::size_t k = 0;
  for(Mesh::Face_index f : tm.faces())
    if(k++ % 9 == 4)
      CGAL::Euler::remove_face(tm.halfedge(f), tm);
  ASSERT_TRUE(tm.has_garbage());
  Mesh compact;
  CGAL::copy_face_graph(tm, compact);
  ASSERT_FALSE(compact.has_garbage());
  // num_faces() of a Surface_mesh counts removed faces too; faces() skips them.
  ASSERT_EQ(compact.number_of_faces(), tm.number_of_faces());

  Patches<Mesh> p(tm), q(compact);
  const std::size_t n = DS::segment_into_disks(tm, p.map, DS::parameters::number_of_seeds(5));
  EXPECT_EQ(DS::segment_into_disks(compact, q.map, DS::parameters::number_of_seeds(5)), n);
  EXPECT_EQ(p.ids(tm), q.ids(compact));
  const TS::Partition_report r = TS::check_disk_partition(tm, p.map);
  EXPECT_TRUE(r.ok) << r.problem;
}

TEST(Errors, MergeRefusesRegionsThatAreNotDisks)
{
  const Mesh tm = make<Mesh>(TS::torus(20, 8));
  Patches<Mesh> p(tm);
  for(auto f : faces(tm)) put(p.map, f, 3);
  const std::string message = error_of([&] { DS::merge_disk_regions(tm, p.map); });
  EXPECT_NE(message.find("not a topological disk"), std::string::npos) << message;
  for(auto f : faces(tm)) EXPECT_EQ(get(p.map, f), 3u);
}

namespace {

// A random group of faces: grown from a random face through edges (a small
// polygon), or, one time in five, two faces anywhere (a part that is no disk).
std::vector<std::size_t> random_group(const Mesh& tm, std::mt19937& rng, const std::vector<char>& taken)
{
  const std::size_t n = num_faces(tm);
  std::uniform_int_distribution<std::size_t> any(0, n - 1);
  std::vector<std::size_t> group;
  std::size_t seed = any(rng);
  for(int tries = 0; taken[seed] && tries < 100; ++tries)
    seed = any(rng);
  if(taken[seed])
    return group;
  group.push_back(seed);
  if(rng() % 5 == 0)
  {
    const std::size_t other = any(rng);
    if(!taken[other] && other != seed)
      group.push_back(other);
    return group;
  }
  const std::size_t size = 1 + rng() % 7;
  for(std::size_t k = 0; k < group.size() && group.size() < size; ++k)
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(tm.halfedge(Mesh::Face_index(Mesh::size_type(group[k]))), tm))
    {
      const Mesh::Face_index g = tm.face(tm.opposite(h));
      if(g != Mesh::null_face() && !taken[std::size_t(g)] &&
         std::find(group.begin(), group.end(), std::size_t(g)) == group.end() && group.size() < size && rng() % 2)
        group.push_back(std::size_t(g));
    }
  return group;
}

} // namespace

// Face_group_mover decides each move by local tests; the independent
// checker decides it by testing every patch whole: the first patch, in
// order of the group's faces in it (then of patch id), where the group can
// go with every patch staying a disk (or emptying), or none.
TEST(Segmentation, FaceGroupsMoveWholeExactlyWhenEveryPatchStaysADisk)
{
  namespace DSI = CGAL::Disk_segmentation::internal;
  const std::pair<const char*, TS::Soup> meshes[] = {
    { "torus", TS::torus(24, 10) },
    { "grid with holes", TS::grid_with_holes(18, 14, 3) },
    { "disk with a center of valence 60", TS::disk(6, 60) },
  };
  std::size_t moved = 0, left = 0;
  for(const auto& named : meshes)
    for(std::uint32_t seed : { 1u, 2u, 3u })
    {
      SCOPED_TRACE(std::string(named.first) + ", seed " + std::to_string(seed));
      std::mt19937 rng(seed);
      const Mesh tm = make<Mesh>(named.second);
      Patches<Mesh> p(tm);
      DS::segment_into_disks(tm, p.map, DS::parameters::number_of_seeds(8 + rng() % 30).merge_threshold(2.));
      ASSERT_TRUE(TS::check_disk_partition(tm, p.map).ok);

      DSI::Indexed_triangle_mesh m;
      std::vector<Mesh::Face_index> handles;
      DSI::build_indexed_triangle_mesh(tm, DS::parameters::default_values(), m, handles);
      std::vector<std::size_t> indexed(num_faces(tm));
      std::vector<DSI::Index> labels(num_faces(tm));
      for(DSI::Index i = 0; i < handles.size(); ++i)
      {
        indexed[std::size_t(handles[i])] = i;
        labels[i] = DSI::Index(get(p.map, handles[i]));
      }
      DSI::Face_group_mover mover(m, labels);
      std::vector<char> taken(num_faces(tm), 0);
      for(int g = 0; g < 120; ++g)
      {
        const std::vector<std::size_t> group = random_group(tm, rng, taken);
        if(group.empty())
          continue;
        for(std::size_t f : group)
          taken[f] = 1;
        // The independent decision, on the mesh's faces.
        std::vector<std::size_t> before(num_faces(tm));
        for(std::size_t f = 0; f < before.size(); ++f)
          before[f] = labels[indexed[f]];
        std::map<std::size_t, long> count;
        for(std::size_t f : group)
          ++count[before[f]];
        std::vector<std::pair<long, std::size_t> > order;
        for(const auto& c : count)
          order.emplace_back(-c.second, c.first);
        std::sort(order.begin(), order.end());
        std::vector<std::size_t> expected = before;
        bool whole = order.size() == 1;
        for(std::size_t i = 0; i < order.size() && !whole; ++i)
        {
          std::vector<std::size_t> after = before;
          for(std::size_t f : group)
            after[f] = order[i].second;
          bool disks = true;
          for(const auto& c : count)
          {
            std::vector<Mesh::Face_index> faces;
            for(std::size_t f = 0; f < after.size(); ++f)
              if(after[f] == c.first)
                faces.push_back(Mesh::Face_index(Mesh::size_type(f)));
            disks = disks && (faces.empty() || TS::is_disk(tm, faces));
          }
          if(disks)
          {
            expected = after;
            whole = true;
          }
        }
        if(order.size() > 1)
          ++(whole ? moved : left);
        std::vector<DSI::Index> group_indexed;
        for(std::size_t f : group)
          group_indexed.push_back(DSI::Index(indexed[f]));
        EXPECT_EQ(mover.keep_whole(group_indexed, std::size_t(-1)), whole) << "group " << g;
        for(std::size_t f = 0; f < expected.size(); ++f)
          ASSERT_EQ(labels[indexed[f]], expected[f]) << "group " << g << ", face " << f;
      }
    }
  // Both outcomes were seen, so that the test tests something.
  EXPECT_GT(moved, 20u);
  EXPECT_GT(left, 20u);
}

namespace {

// The share of the length of the mesh's sharp edges (normals of the two
// faces more than `degrees` apart) that lies between two patches.
double sharp_edge_share_on_borders(const Mesh& tm, const Patches<Mesh>& patches, double degrees)
{
  auto normal = [&](Mesh::Face_index f) {
    const auto h = tm.halfedge(f);
    const K::Point_3 &a = tm.point(tm.source(h)), &b = tm.point(tm.target(h)), &c = tm.point(tm.target(tm.next(h)));
    const K::Vector_3 n = CGAL::cross_product(b - a, c - a);
    return n / std::sqrt(n.squared_length());
  };
  const double cos_limit = std::cos(degrees * 3.14159265358979323846 / 180.);
  double sharp = 0, on_borders = 0;
  for(Mesh::Edge_index e : tm.edges())
  {
    if(tm.is_border(e))
      continue;
    const Mesh::Face_index f = tm.face(tm.halfedge(e, 0)), g = tm.face(tm.halfedge(e, 1));
    if(normal(f) * normal(g) >= cos_limit)
      continue;
    const double length = std::sqrt(CGAL::squared_distance(tm.point(tm.vertex(e, 0)), tm.point(tm.vertex(e, 1))));
    sharp += length;
    if(get(patches.map, f) != get(patches.map, g))
      on_borders += length;
  }
  return sharp > 0 ? on_borders / sharp : 0.;
}

} // namespace

TEST(Segmentation, ACreasePenaltyPutsSharpEdgesOnPatchBorders)
{
  // couplingdown is a machined part: flat and cylindrical faces meeting at
  // sharp edges. Distances that grow across bent edges make the Voronoi
  // cells, and so the patches, end at those edges.
  const Mesh tm = load<Mesh>("couplingdown.off");
  Patches<Mesh> plain(tm), creased(tm);
  DS::segment_into_disks(tm, plain.map, DS::parameters::crease_penalty(0.));
  const std::size_t n = DS::segment_into_disks(tm, creased.map, DS::parameters::crease_penalty(10.));
  expect_disk_partition(tm, creased, n);
  const double plain_share = sharp_edge_share_on_borders(tm, plain, 60.);
  const double creased_share = sharp_edge_share_on_borders(tm, creased, 60.);
  std::cout << "sharp edge length on borders: " << plain_share << " without, " << creased_share << " with the penalty, "
            << n << " patches" << std::endl;
  EXPECT_GT(creased_share, plain_share + 0.2);

  // The same patches on a Polyhedron_3, and 10 is the default.
  const Polyhedron ph = load<Polyhedron>("couplingdown.off");
  Patches<Polyhedron> on_polyhedron(ph), zero(ph), by_default(ph);
  DS::segment_into_disks(ph, on_polyhedron.map, DS::parameters::crease_penalty(10.));
  EXPECT_EQ(on_polyhedron.ids(ph), creased.ids(tm));
  DS::segment_into_disks(ph, by_default.map);
  EXPECT_EQ(by_default.ids(ph), creased.ids(tm));
  DS::segment_into_disks(ph, zero.map, DS::parameters::crease_penalty(0.));
  EXPECT_EQ(zero.ids(ph), plain.ids(tm));

  // A penalty that is not a finite number >= 0 is refused, naming it, and
  // the map is left as it was.
  for(double bad : { -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    const std::vector<std::size_t> before = creased.ids(tm);
    try
    {
      DS::segment_into_disks(tm, creased.map, DS::parameters::crease_penalty(bad));
      ADD_FAILURE() << "crease_penalty " << bad << " was accepted";
    }
    catch(const DS::Input_error& e)
    {
      EXPECT_NE(std::string(e.what()).find("crease_penalty"), std::string::npos) << e.what();
    }
    EXPECT_EQ(creased.ids(tm), before);
  }
}
