// Tests of the complete atlas: parameterization of every chart, fallbacks,
// packing and the files disk_uv writes. Atlases are checked with
// test_support::check_atlas() (independent_atlas.h), written independently
// from the library.

#include "atlas_fixture.h"
#include "independent_atlas.h"
#include "independent_distortion.h"
#include "independent_topology.h"
#include "test_meshes.h"

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Disk_segmentation/IO/Atlas_options.h>
#include <CGAL/Disk_segmentation/IO/read_triangle_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_sparse_matrix.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <stdexcept>
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

std::string data_path(const std::string& name)
{
  return std::string(DISK_SEGMENTATION_TEST_DATA_DIR) + "/" + name;
}

Mesh load(const std::string& name)
{
  Mesh tm;
  if(!CGAL::IO::read_polygon_mesh(data_path(name), tm))
    throw std::runtime_error("cannot read test mesh " + name);
  return tm;
}

Mesh make(const TS::Soup& soup)
{
  Mesh tm;
  TS::to_mesh(soup, tm);
  return tm;
}




// A fan of triangles around a border vertex whose 3D angles add up to about
// 740 degrees: the surface is embedded (zig-zag pleats), but any map that
// keeps angles must wrap the fan around twice in the plane.
TS::Soup pleated_fan()
{
  TS::Soup s;
  s.points.push_back({{ 0., 0., 0. }});
  const int n = 8;
  for(int i = 0; i <= n; ++i)
  {
    const double angle = 3.14159265358979323846 * i / n;
    s.points.push_back({{ std::cos(angle), std::sin(angle), (i % 2 == 0) ? 1. : -1. }});
  }
  for(int i = 0; i < n; ++i)
    s.triangles.push_back({{ 0, std::size_t(i + 1), std::size_t(i + 2) }});
  return s;
}

} // namespace

TEST(Atlas, EveryMethodGivesAValidAtlasOnShippedMeshes)
{
  // Under AddressSanitizer (6x slower) each mesh gets two of the five
  // methods, in turn, so that every method still runs on some meshes; the
  // release pass runs all of them on every mesh.
#if defined(__SANITIZE_ADDRESS__)
  const std::size_t methods_per_mesh = 2;
#else
  const std::size_t methods_per_mesh = std::size(TS::all_parameterization_methods);
#endif
  std::size_t turn = 0;
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "blobby_3cc.off", "knot1.off",
                           "bones.off", "eight.off", "couplingdown.off" })
  {
    for(std::size_t k = 0; k < methods_per_mesh; ++k, ++turn)
    {
      const DS::Parameterization_method method =
        TS::all_parameterization_methods[turn % std::size(TS::all_parameterization_methods)];
      SCOPED_TRACE(std::string(name) + " " + DS::to_string(method));
      Mesh tm = load(name);
      const Atlas a = make_atlas(tm, DS::parameters::parameterization_method(method));
      expect_valid_atlas(tm, a);
      EXPECT_GT(a.report.packing.efficiency, 0.2);
    }
  }
}

TEST(Atlas, GeneratedMeshesGiveValidAtlases)
{
  const std::vector<std::pair<const char*, TS::Soup> > meshes = {
    { "sphere", TS::uv_sphere(16, 24) }, { "torus", TS::torus(40, 16) }, { "genus3", TS::genus_surface(3, 3) },
    { "cylinder", TS::cylinder(24, 12) }, { "disk", TS::disk(8, 24) }, { "holes", TS::grid_with_holes(30, 30, 6) },
    { "disconnected", TS::disconnected(5) }, { "triangle", TS::single_triangle() }, { "strip", TS::thin_strip(300) },
    { "pleated_fan", pleated_fan() } };
  for(const auto& g : meshes)
  {
    SCOPED_TRACE(g.first);
    Mesh tm = make(g.second);
    expect_valid_atlas(tm, make_atlas(tm, DS::parameters::default_values()));
  }
}

TEST(Atlas, FallbackRepairsAChartThatTheRequestedMethodFlips)
{
  Mesh tm = make(pleated_fan());
  // One patch: the whole fan, a topological disk.
  Patch_map patch = tm.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  UV_map uv = tm.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;

  const DS::Parameterization_report without =
    DS::parameterize_patches(tm, patch, uv, DS::parameters::parameterization_method(DS::Parameterization_method::LSCM)
                                              .use_fallback(false));
  ASSERT_EQ(without.charts.size(), 1u);
  EXPECT_FALSE(without.charts[0].valid);
  EXPECT_EQ(without.number_of_invalid_charts, 1u);
  // The independent checker sees the overlap too (the chart wraps over itself).
  DS::pack_patches(tm, patch, uv);
  EXPECT_FALSE(TS::check_atlas(tm, patch, uv, 512).ok()) << "LSCM no longer fails here: the test is void";

  const DS::Parameterization_report with =
    DS::parameterize_patches(tm, patch, uv, DS::parameters::parameterization_method(DS::Parameterization_method::LSCM)
                                              .distortion_bound(DS::Distortion_bound::unbounded()));
  ASSERT_EQ(with.charts.size(), 1u);
  EXPECT_TRUE(with.charts[0].valid);
  EXPECT_TRUE(with.charts[0].fallback);
  EXPECT_EQ(with.charts[0].used, DS::Parameterization_method::MEAN_VALUE);
  EXPECT_FALSE(with.charts[0].problem.empty());
  EXPECT_EQ(with.number_of_fallbacks, 1u);
  DS::pack_patches(tm, patch, uv);
  const TS::Atlas_report atlas = TS::check_atlas(tm, patch, uv, 512);
  EXPECT_TRUE(atlas.ok()) << atlas.summary();
}

TEST(Atlas, UnderABoundAChartWithAnInvalidMapIsReplacedNotRedone)
{
  // ARAP's start on the pleated fan wraps around itself: without a bound the
  // chart is redone from another start and kept whole; under a bound so
  // loose that the redone chart would meet it, it is split instead.
  Mesh tm = make(pleated_fan());
  Patch_map patch = tm.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  UV_map uv = tm.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
  const double loose = 1e9;
  DS::Distortion_bound b;
  b.max_angle_distortion = b.max_area_distortion = b.max_stretch = b.max_area_scale = b.max_stretch_p95 = loose;

  const DS::Parameterization_report unbounded =
    DS::parameterize_patches(tm, patch, uv, DS::parameters::distortion_bound(DS::Distortion_bound::unbounded()));
  ASSERT_EQ(unbounded.charts.size(), 1u);
  EXPECT_TRUE(unbounded.charts[0].valid);
  const TS::Chart_measure whole = TS::measure_charts(tm, patch, uv).begin()->second;
  ASSERT_TRUE(whole.angle_mean < loose && whole.area_mean < loose && whole.max_stretch < loose &&
              whole.max_scale < loose && whole.min_scale * loose > 1)
    << "the redone chart would not meet the loose bound: the test is void";

  for(auto& f : tm.faces())
    put(patch, f, 0);
  const DS::Parameterization_report bounded =
    DS::parameterize_patches(tm, patch, uv, DS::parameters::distortion_bound(b));
  EXPECT_GT(bounded.charts.size(), 1u);
  EXPECT_EQ(bounded.number_of_fallbacks, 0u);
  for(const DS::Chart_report& r : bounded.charts)
    EXPECT_TRUE(r.valid);
  DS::pack_patches(tm, patch, uv);
  const TS::Atlas_report atlas = TS::check_atlas(tm, patch, uv, 512);
  EXPECT_TRUE(atlas.ok()) << atlas.summary();
}

// Whether every chart meets `b`, measured with independent code.
::testing::AssertionResult charts_meet(const Mesh& tm, const Atlas& a, const DS::Distortion_bound& b)
{
  // Room for the rounding of two different formulas.
  const double slack = 1 + 1e-9;
  const std::map<std::size_t, TS::Chart_measure> charts = TS::measure_charts(tm, a.patch, a.uv);
  double mesh_area = 0;
  for(const auto& entry : charts)
    mesh_area += entry.second.area_3d;
  for(const auto& entry : charts)
  {
    const TS::Chart_measure& c = entry.second;
    if(!(c.angle_mean <= b.max_angle_distortion * slack) || !(c.area_mean <= b.max_area_distortion * slack) ||
       !(c.max_stretch <= b.max_stretch * slack) || !(c.max_scale <= b.max_area_scale * slack) ||
       !(c.min_scale * b.max_area_scale * slack >= 1) || !(c.stretch_p95() <= b.max_stretch_p95 * slack))
      return ::testing::AssertionFailure()
             << "chart " << entry.first << ": mean |log s1/s2| " << c.angle_mean << ", mean |log s1 s2| "
             << c.area_mean << ", s1/s2 up to " << c.max_stretch << ", s1 s2 in [" << c.min_scale << ", "
             << c.max_scale << "], p95 s1/s2 " << c.stretch_p95();
    // The full convexity bound holds from a share of the mesh's area on,
    // a fraction of it below; a little rounding room around that share.
    const bool large = c.area_3d >= DS::Distortion_bound::convexity_area_fraction * mesh_area * (1 + 1e-6);
    const double least_convexity =
      large ? b.min_convexity : DS::Distortion_bound::small_chart_convexity_ratio * b.min_convexity;
    if(!(c.convexity() * (1 + 1e-6) >= least_convexity))
      return ::testing::AssertionFailure() << "chart " << entry.first << " of " << c.area_3d / mesh_area
                                           << " of the mesh's area fills " << c.convexity()
                                           << " of its UV convex hull";
  }
  return ::testing::AssertionSuccess();
}

DS::Distortion_bound make_bound(double angle, double area, double stretch, double scale,
                               double p95 = std::numeric_limits<double>::infinity(), double convexity = 0)
{
  DS::Distortion_bound b;
  b.min_convexity = convexity;
  b.max_stretch_p95 = p95;
  b.max_angle_distortion = angle;
  b.max_area_distortion = area;
  b.max_stretch = stretch;
  b.max_area_scale = scale;
  return b;
}

TEST(Atlas, EveryChartMeetsTheDistortionBoundItIsGiven)
{
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<DS::Distortion_bound> bounds = {
    DS::Distortion_bound(),              // the defaults
    make_bound(0.03, inf, inf, inf),     // angles only, tight
    make_bound(inf, 0.03, inf, inf),     // areas only, tight
    make_bound(inf, inf, 1.5, 1.5),      // the per-triangle tails only
    make_bound(inf, inf, inf, inf, 1.05),  // the 95th percentile of s1/s2 only
    make_bound(inf, inf, inf, inf, inf, 0.9),  // the convexity only
    make_bound(0.3, 0.4, 4., 4.) };      // loose
  std::vector<bool> paper_breaks(bounds.size(), false);
  for(const char* name : { "elephant.off", "knot1.off", "bones.off" })
  {
    Mesh paper_mesh = load(name);
    const Atlas paper = make_atlas(paper_mesh, DS::parameters::distortion_bound(DS::Distortion_bound::unbounded()));
    expect_valid_atlas(paper_mesh, paper);
    for(std::size_t i = 0; i < bounds.size(); ++i)
    {
      SCOPED_TRACE(std::string(name) + ", bound " + std::to_string(i));
      Mesh tm = load(name);
      const Atlas bounded = make_atlas(tm, DS::parameters::distortion_bound(bounds[i]));
      expect_valid_atlas(tm, bounded);
      EXPECT_TRUE(charts_meet(tm, bounded, bounds[i]));
      // Where the paper's charts break the bound, it did some work.
      if(!charts_meet(paper_mesh, paper, bounds[i]))
        paper_breaks[i] = true;
    }
  }
  // Every bound is broken by the paper's charts of some mesh, so this test
  // fails if a bound is ignored.
  for(std::size_t i = 0; i < bounds.size(); ++i)
    EXPECT_TRUE(paper_breaks[i]) << "bound " << i << " is too loose to test anything";
}

TEST(Atlas, WithoutTheFallbackTheBoundMergesAndReroutesStillWork)
{
  // use_fallback(false) only keeps invalid charts: a chart over the bound is
  // still split, and charts are still merged and their borders rerouted.
  const double inf = std::numeric_limits<double>::infinity();
  const DS::Distortion_bound tight = make_bound(0.03, inf, inf, inf);
  for(const char* name : { "elephant.off", "knot1.off" })
  {
    SCOPED_TRACE(name);
    Mesh paper_mesh = load(name);
    const Atlas paper = make_atlas(paper_mesh, DS::parameters::distortion_bound(DS::Distortion_bound::unbounded())
                                                 .use_fallback(false));
    ASSERT_FALSE(charts_meet(paper_mesh, paper, tight)) << "the bound is too loose to test anything";

    Mesh tm = load(name);
    const Atlas bounded = make_atlas(tm, DS::parameters::distortion_bound(tight).use_fallback(false));
    ASSERT_EQ(bounded.report.parameterization.number_of_invalid_charts, 0u);
    expect_valid_atlas(tm, bounded);
    EXPECT_TRUE(charts_meet(tm, bounded, tight));

    // Merging and rerouting change the charts whether the fallback is on or off.
    Mesh plain_mesh = load(name);
    const Atlas plain = make_atlas(plain_mesh, DS::parameters::distortion_bound(tight).use_fallback(false)
                                                 .merge_charts(false).straighten_borders(false));
    EXPECT_LT(bounded.report.number_of_charts, plain.report.number_of_charts) << "no merge happened";
  }
}

TEST(Atlas, MergingAcceptedChartsLeavesFewerChartsWithinTheBound)
{
  std::size_t fewer = 0;
  for(const char* name : { "elephant.off", "bones.off", "knot1.off" })
  {
    SCOPED_TRACE(name);
    Mesh separate_mesh = load(name), merged_mesh = load(name);
    const Atlas separate = make_atlas(separate_mesh, DS::parameters::merge_charts(false));
    const Atlas merged = make_atlas(merged_mesh, DS::parameters::default_values());
    expect_valid_atlas(merged_mesh, merged);
    EXPECT_TRUE(charts_meet(merged_mesh, merged, DS::Distortion_bound()));
    EXPECT_LE(merged.report.number_of_charts, separate.report.number_of_charts);
    fewer += merged.report.number_of_charts < separate.report.number_of_charts ? 1 : 0;
  }
  EXPECT_GT(fewer, 0u) << "no chart was merged on any mesh: the test is void";
}

// The stages see one chain type for any chain of values: two chains that
// differ in the parameters given, their order and their value types give the
// stages the same type, and so one instantiation of the pipeline.
TEST(Atlas, ChainsOfValuesGiveTheStagesOneParameterType)
{
  Mesh m;
  const auto a = DS::parameters::number_of_seeds(12).max_stretch(4.).texture_resolution(512u);
  const auto b = DS::parameters::padding_in_texels(3).merge_threshold(0.5f).number_of_seeds(std::size_t(7))
                   .smooth_borders(false).texels_per_unit(100.).max_number_of_charts(20u);
  const auto settings_a = DS::internal::segmentation_settings(a);
  const auto settings_b = DS::internal::segmentation_settings(b);
  const auto stages_a = DS::internal::stage_parameters(a, settings_a);
  const auto stages_b = DS::internal::stage_parameters(b, settings_b);
  static_assert(std::is_same<decltype(stages_a), decltype(stages_b)>::value, "a value changed the stages' type");
  // The values themselves are carried, in the settings.
  EXPECT_EQ(settings_a.number_of_seeds, 12u);
  EXPECT_EQ(settings_b.number_of_seeds, 7u);
  EXPECT_FALSE(settings_b.smooth_borders);
  EXPECT_TRUE(settings_a.smooth_borders);
  EXPECT_DOUBLE_EQ(settings_b.merge_threshold, double(0.5f));
  // A map is kept, and changes the type (so it is read as given).
  const auto vpm = get(CGAL::vertex_point, m);
  const auto with_map = DS::internal::stage_parameters(a.vertex_point_map(vpm), settings_a);
  static_assert(!std::is_same<decltype(stages_a), decltype(with_map)>::value, "the point map was dropped");
}

TEST(Atlas, AChartBudgetIsMetWithValidDisksOrReportedAsUnmet)
{
  Mesh free_mesh = load("elephant.off");
  const Atlas free = make_atlas(free_mesh, DS::parameters::number_of_threads(2u));
  const std::size_t bound_charts = free.report.number_of_charts;
  ASSERT_GT(bound_charts, 8u) << "too few charts under the bound to test a budget";
  EXPECT_EQ(free.report.parameterization.charts_before_budget, 0u);

  // A budget the bound already meets changes nothing.
  Mesh roomy_mesh = load("elephant.off");
  const Atlas roomy = make_atlas(roomy_mesh, DS::parameters::max_number_of_charts(bound_charts).number_of_threads(2u));
  std::size_t moved = 0;
  for(Mesh::Halfedge_index h : free_mesh.halfedges())
    if(!free_mesh.is_border(h) && free.uv[h] != roomy.uv[h])
      ++moved;
  EXPECT_EQ(moved, 0u);

  // Half the charts: merged past the bound into disks with valid maps, the same on 1 and 2 threads.
  const std::size_t budget = bound_charts / 2;
  Mesh one_mesh = load("elephant.off"), two_mesh = load("elephant.off");
  const Atlas one = make_atlas(one_mesh, DS::parameters::max_number_of_charts(budget).number_of_threads(1u));
  const Atlas two = make_atlas(two_mesh, DS::parameters::max_number_of_charts(budget).number_of_threads(2u));
  expect_valid_atlas(two_mesh, two);
  EXPECT_EQ(two.report.number_of_charts, budget);
  EXPECT_TRUE(two.report.parameterization.chart_budget_met);
  EXPECT_EQ(two.report.parameterization.charts_before_budget, bound_charts);
  EXPECT_FALSE(charts_meet(two_mesh, two, DS::Distortion_bound())) << "the budget did not need to pass the bound";
  moved = 0;
  for(Mesh::Halfedge_index h : one_mesh.halfedges())
    if(!one_mesh.is_border(h) && one.uv[h] != two.uv[h])
      ++moved;
  EXPECT_EQ(moved, 0u);

  // One chart cannot hold a closed surface: the budget is reported unmet, the atlas stays valid.
  Mesh tight_mesh = load("elephant.off");
  const Atlas tight =
    make_atlas(tight_mesh, DS::parameters::max_number_of_charts(std::size_t(1)).number_of_threads(2u));
  expect_valid_atlas(tight_mesh, tight);
  EXPECT_GT(tight.report.number_of_charts, 1u);
  EXPECT_LT(tight.report.number_of_charts, budget);
  EXPECT_FALSE(tight.report.parameterization.chart_budget_met);

  Mesh tm = load("elephant.off");
  EXPECT_THROW(make_atlas(tm, DS::parameters::max_number_of_charts(std::size_t(0)).number_of_threads(2u)),
               DS::Input_error);
}

namespace {

typedef Mesh::Property_map<Mesh::Face_index, std::int64_t> Face_value_map;

// uv_atlas() with a polygon and a material per face: one chain type for the tests below.
Atlas atlas_with_groups(Mesh& tm, Face_value_map polygon, Face_value_map material, unsigned threads)
{
  return make_atlas(tm, DS::parameters::face_polygon_map(polygon).face_material_map(material).number_of_threads(threads));
}

} // namespace

TEST(Atlas, NoChartSpansTwoMaterials)
{
  // Two materials in a 3D checkerboard of cells a third of the elephant
  // wide: many pieces, and vertices where they alternate around.
  Mesh tm = load("elephant.off");
  Face_value_map polygon = tm.add_property_map<Mesh::Face_index, std::int64_t>("f:polygon", 0).first;
  Face_value_map material = tm.add_property_map<Mesh::Face_index, std::int64_t>("f:material", 0).first;
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(tm);
  std::set<std::int64_t> used;
  for(Mesh::Face_index f : tm.faces())
  {
    polygon[f] = std::int64_t(f);
    K::Point_3 c = CGAL::centroid(tm.point(tm.source(tm.halfedge(f))), tm.point(tm.target(tm.halfedge(f))),
                                  tm.point(tm.target(tm.next(tm.halfedge(f)))));
    std::int64_t cell = 0;
    for(int i = 0; i < 3; ++i)
      cell += std::int64_t(3 * (c[i] - box.min(i)) / (box.max(i) - box.min(i) + 1e-9));
    material[f] = cell % 2;
    used.insert(material[f]);
  }
  ASSERT_EQ(used.size(), 2u);
  const Atlas a = atlas_with_groups(tm, polygon, material, 2u);
  expect_valid_atlas(tm, a);
  std::map<std::size_t, std::set<std::int64_t> > materials_of_chart;
  for(Mesh::Face_index f : tm.faces())
    materials_of_chart[a.patch[f]].insert(material[f]);
  std::size_t spanning = 0;
  for(const auto& chart : materials_of_chart)
    spanning += chart.second.size() > 1 ? 1 : 0;
  EXPECT_EQ(spanning, 0u);
  EXPECT_EQ(a.report.polygons_moved_whole + a.report.polygons_left_across_charts, 0u);
}

TEST(Atlas, PolygonsSplitByChartsAreMovedWholeIntoOne)
{
  // A torus of quads, each two triangles (faces 2q and 2q + 1).
  const TS::Soup soup = TS::torus(32, 12);
  std::size_t cut[2] = { 0, 0 };
  DS::Atlas_report reports[2];
  for(int keep = 0; keep < 2; ++keep)
  {
    Mesh tm = make(soup);
    Face_value_map polygon = tm.add_property_map<Mesh::Face_index, std::int64_t>("f:polygon", 0).first;
    Face_value_map material = tm.add_property_map<Mesh::Face_index, std::int64_t>("f:material", 0).first;
    for(Mesh::Face_index f : tm.faces())
      polygon[f] = keep ? std::int64_t(f) / 2 : std::int64_t(f);
    const Atlas a = atlas_with_groups(tm, polygon, material, 2u);
    expect_valid_atlas(tm, a);
    reports[keep] = a.report;
    std::map<std::int64_t, std::set<std::size_t> > charts_of_quad;
    for(Mesh::Face_index f : tm.faces())
      charts_of_quad[std::int64_t(f) / 2].insert(a.patch[f]);
    for(const auto& quad : charts_of_quad)
      cut[keep] += quad.second.size() > 1 ? 1 : 0;
  }
  EXPECT_GT(cut[0], 0u) << "no quad is cut without polygons: the test is void";
  EXPECT_GT(reports[1].polygons_moved_whole, 0u);
  EXPECT_EQ(cut[1], reports[1].polygons_left_across_charts);
  EXPECT_LT(cut[1], cut[0]);
  EXPECT_EQ(reports[0].polygons_moved_whole, 0u);
}

TEST(Atlas, SeveralMeshesKeepTheirOwnChartsInOneValidAtlas)
{
  const char* names[] = { "elephant.off", "knot1.off", "eight.off" };
  std::vector<Mesh> meshes;
  for(const char* name : names)
    meshes.push_back(load(name));
  std::vector<const Mesh*> pointers;
  std::vector<UV_map> uvs;
  std::vector<Patch_map> patches;
  for(Mesh& m : meshes)
  {
    pointers.push_back(&m);
    uvs.push_back(m.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:multi_uv", K::Point_2(7, 7)).first);
    patches.push_back(m.add_property_map<Mesh::Face_index, std::size_t>("f:multi_patch", 7).first);
  }

  // Mismatched maps: refused, nothing written.
  std::vector<UV_map> too_few(uvs.begin(), uvs.end() - 1);
  EXPECT_THROW(DS::uv_atlas_of_meshes(pointers, too_few, patches), DS::Input_error);
  EXPECT_EQ(patches[0][*meshes[0].faces().begin()], 7u);

  const DS::Multi_mesh_atlas_report report = DS::uv_atlas_of_meshes(pointers, uvs, patches);
  ASSERT_EQ(report.meshes.size(), 3u);
  ASSERT_EQ(report.first_chart.size(), 4u);

  // Each mesh's charts are those it gets alone, numbered after the charts of the meshes before it.
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    SCOPED_TRACE(names[i]);
    Mesh alone_mesh = load(names[i]);
    const Atlas alone = make_atlas(alone_mesh, DS::parameters::default_values());
    EXPECT_EQ(report.first_chart[i + 1] - report.first_chart[i], alone.report.number_of_charts);
    std::size_t different = 0;
    for(Mesh::Face_index f : meshes[i].faces())
      different += patches[i][f] != report.first_chart[i] + alone.patch[f] ? 1 : 0;
    EXPECT_EQ(different, 0u);
  }

  // One atlas: the meshes side by side in one mesh, checked as a whole (no overlap across meshes).
  Mesh all;
  Patch_map all_patch = all.add_property_map<Mesh::Face_index, std::size_t>("f:all_patch", 0).first;
  UV_map all_uv = all.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:all_uv").first;
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    std::vector<std::pair<Mesh::Halfedge_index, Mesh::Halfedge_index> > halfedges;
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > faces;
    CGAL::copy_face_graph(meshes[i], all,
                          CGAL::parameters::halfedge_to_halfedge_output_iterator(std::back_inserter(halfedges))
                            .face_to_face_output_iterator(std::back_inserter(faces)));
    for(const auto& f : faces)
      all_patch[f.second] = patches[i][f.first];
    for(const auto& h : halfedges)
      if(!meshes[i].is_border(h.first))
        all_uv[h.second] = uvs[i][h.first];
  }
  const TS::Partition_report partition = TS::check_disk_partition(all, all_patch);
  EXPECT_TRUE(partition.ok) << partition.problem;
  EXPECT_EQ(partition.number_of_patches, report.first_chart.back());
  const TS::Atlas_report atlas = TS::check_atlas(all, all_patch, all_uv, 1024);
  EXPECT_TRUE(atlas.ok()) << atlas.summary();
}

TEST(Atlas, TheBoundParametersOverrideTheBoundAndAreChecked)
{
  Mesh tm = load("knot1.off");
  const double inf = std::numeric_limits<double>::infinity();
  // Individual parameters win over distortion_bound(): all infinite (and
  // no convexity bound) give the paper's charts.
  Mesh paper_mesh = tm;
  const Atlas paper = make_atlas(paper_mesh, DS::parameters::distortion_bound(DS::Distortion_bound::unbounded()));
  const Atlas overridden = make_atlas(tm, DS::parameters::distortion_bound(DS::Distortion_bound())
                                            .max_angle_distortion(inf).max_area_distortion(inf)
                                            .max_stretch(inf).max_area_scale(inf).max_stretch_p95(inf)
                                            .min_convexity(0.));
  EXPECT_EQ(overridden.report.number_of_charts, paper.report.number_of_charts);
  EXPECT_THROW(make_atlas(tm, DS::parameters::max_angle_distortion(0.)), DS::Input_error);
  EXPECT_THROW(make_atlas(tm, DS::parameters::max_area_distortion(-1.)), DS::Input_error);
  EXPECT_THROW(make_atlas(tm, DS::parameters::max_stretch(1.)), DS::Input_error);
  EXPECT_THROW(make_atlas(tm, DS::parameters::max_area_scale(std::nan(""))), DS::Input_error);
  EXPECT_THROW(make_atlas(tm, DS::parameters::max_stretch_p95(1.)), DS::Input_error);
  EXPECT_THROW(make_atlas(tm, DS::parameters::min_convexity(1.)), DS::Input_error);
  EXPECT_THROW(make_atlas(tm, DS::parameters::min_convexity(-0.1)), DS::Input_error);
  EXPECT_THROW(make_atlas(tm, DS::parameters::min_convexity(std::nan(""))), DS::Input_error);
  EXPECT_THROW(DS::check_uv_atlas_parameters(DS::parameters::max_stretch(0.5)), DS::Input_error);
}

// Length of the edges between faces of different patches, and the faces
// with two edges on one other patch (the saw teeth), counted apart from the
// library.
struct Border_measure
{
  double length = 0;
  std::size_t teeth = 0;
};

Border_measure measure_borders(const Mesh& tm, Patch_map patch)
{
  Border_measure b;
  for(Mesh::Face_index f : tm.faces())
  {
    std::map<std::size_t, int> edges_on;
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(tm.halfedge(f), tm))
    {
      const Mesh::Face_index g = tm.face(tm.opposite(h));
      if(g == Mesh::null_face() || patch[g] == patch[f])
        continue;
      ++edges_on[patch[g]];
      b.length += 0.5 * std::sqrt(CGAL::squared_distance(tm.point(tm.source(h)), tm.point(tm.target(h))));
    }
    for(const auto& e : edges_on)
      b.teeth += (e.second == 2) ? 1 : 0;
  }
  return b;
}

TEST(Atlas, SmoothedBordersAreShorterWithFewerTeethAndStayDisks)
{
  for(const char* name : { "elephant.off", "bones.off", "knot1.off" })
  {
    SCOPED_TRACE(name);
    Mesh tm = load(name);
    Patch_map rough = tm.add_property_map<Mesh::Face_index, std::size_t>("f:rough", 0).first;
    Patch_map smooth = tm.add_property_map<Mesh::Face_index, std::size_t>("f:smooth", 0).first;
    // No merging: the refined regions themselves, with and without smoothing.
    const auto np = DS::parameters::number_of_seeds(30).merge_threshold(1e9);
    const std::size_t rough_count = DS::segment_into_disks(tm, rough, np.smooth_borders(false));
    const std::size_t smooth_count = DS::segment_into_disks(tm, smooth, np.smooth_borders(true));
    EXPECT_EQ(smooth_count, rough_count) << "smoothing moves faces, it neither adds nor removes regions";
    const TS::Partition_report partition = TS::check_disk_partition(tm, smooth);
    EXPECT_TRUE(partition.ok) << partition.problem;
    const Border_measure before = measure_borders(tm, rough), after = measure_borders(tm, smooth);
    ASSERT_GT(before.teeth, 0u) << "nothing to smooth: the test is void";
    EXPECT_LT(after.length, before.length);
    EXPECT_LT(after.teeth, before.teeth);
  }
}

// Length of the edges between regions a and b of an indexed mesh, summed
// over the faces of a (each such edge has exactly one face in a).
double shared_length(const DS::internal::Indexed_triangle_mesh& m, const std::vector<DS::internal::Index>& labels,
                     DS::internal::Index a, DS::internal::Index b)
{
  double length = 0.;
  for(DS::internal::Index f = 0; f < m.number_of_faces(); ++f)
    for(int e = 0; e < 3; ++e)
    {
      const DS::internal::Index g = m.neighbors[f][e];
      if(labels[f] == a && g != DS::internal::no_index && labels[g] == b)
        length += DS::internal::Indexed_triangle_mesh::distance(m.points[m.corners[f][e]],
                                                                 m.points[m.corners[f][(e + 1) % 3]]);
    }
  return length;
}

TEST(Atlas, ReroutedBorderArcsAreShorterAndTheRegionsStayDisks)
{
  for(const char* name : { "elephant.off", "knot1.off" })
  {
    SCOPED_TRACE(name);
    Mesh tm = load(name);
    Patch_map patch = tm.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
    // The refined regions with their saw teeth: borders to straighten.
    const std::size_t regions =
      DS::segment_into_disks(tm, patch, DS::parameters::number_of_seeds(30).merge_threshold(1e9));
    DS::internal::Indexed_triangle_mesh m;
    std::vector<Mesh::Face_index> face_handles;
    DS::internal::build_indexed_triangle_mesh(tm, DS::parameters::default_values(), m, face_handles);
    std::vector<DS::internal::Index> labels(m.number_of_faces());
    std::vector<std::size_t> size(regions, 0);
    for(DS::internal::Index f = 0; f < m.number_of_faces(); ++f)
    {
      labels[f] = static_cast<DS::internal::Index>(patch[face_handles[f]]);
      ++size[labels[f]];
    }
    const Border_measure before = measure_borders(tm, patch);

    DS::internal::Border_router router(m);
    router.assign(labels, regions);
    DS::internal::Region_topology topology(m);
    std::vector<char> locked(m.number_of_faces(), 0);
    const double least_gain = 0.02;
    std::size_t rerouted = 0;
    for(const DS::internal::Border_arc& arc : router.arcs(labels))
    {
      ASSERT_GE(arc.vertices.size(), 2u);
      double arc_length = 0.;
      for(std::size_t i = 0; i + 1 < arc.vertices.size(); ++i)
        arc_length += DS::internal::Indexed_triangle_mesh::distance(m.points[arc.vertices[i]],
                                                                     m.points[arc.vertices[i + 1]]);
      const std::vector<DS::internal::Index> old = labels;
      const double shared_before = shared_length(m, labels, arc.a, arc.b);
      ASSERT_GE(shared_before, arc_length * (1. - 1e-9)) << "an arc runs along the border of its two regions";
      DS::internal::Arc_change change;
      if(!router.reroute(labels, size, locked, topology, arc, least_gain, change))
      {
        ASSERT_EQ(labels, old) << "a refused reroute changes nothing";
        continue;
      }
      ++rerouted;
      std::size_t moved = 0;
      for(DS::internal::Index f = 0; f < m.number_of_faces(); ++f)
        if(labels[f] != old[f])
        {
          ++moved;
          ASSERT_TRUE((old[f] == arc.a && labels[f] == arc.b) || (old[f] == arc.b && labels[f] == arc.a))
            << "only the arc's two regions trade faces";
        }
      EXPECT_EQ(moved, change.old_labels.size());
      EXPECT_LE(shared_length(m, labels, arc.a, arc.b), shared_before - least_gain * arc_length + 1e-12);
      for(const auto& f : change.old_labels)
        locked[f.first] = 1;
    }
    ASSERT_GT(rerouted, 0u) << "nothing was rerouted: the test is void";
    for(DS::internal::Index f = 0; f < m.number_of_faces(); ++f)
      patch[face_handles[f]] = labels[f];
    const TS::Partition_report partition = TS::check_disk_partition(tm, patch);
    EXPECT_TRUE(partition.ok) << partition.problem;
    std::set<std::size_t> ids;
    for(Mesh::Face_index f : tm.faces())
      ids.insert(patch[f]);
    EXPECT_EQ(ids.size(), regions) << "no region disappears";
    EXPECT_LT(measure_borders(tm, patch).length, before.length);
  }
}

TEST(Atlas, ChartsAreMergeTreeNodesOrPiecesOfOneLeaf)
{
  Mesh tm = load("elephant.off");
  DS::Merge_tree tree;
  Patch_map patch = tm.add_property_map<Mesh::Face_index, std::size_t>("f:p", 0).first;
  const std::size_t patches = DS::segment_into_disks(tm, patch, DS::parameters::merge_tree(&tree));
  ASSERT_EQ(tree.face_leaves.size(), tm.number_of_faces());
  ASSERT_EQ(tree.number_of_leaves, tree.merges.size() + patches);
  // Every node's faces, by union of its leaves; every node is a disk.
  std::vector<std::vector<std::size_t> > node_faces(tree.number_of_nodes());
  for(std::size_t f = 0; f < tree.face_leaves.size(); ++f)
    node_faces.at(tree.face_leaves[f]).push_back(f);
  for(std::size_t i = 0; i < tree.merges.size(); ++i)
  {
    std::vector<std::size_t>& faces = node_faces[tree.number_of_leaves + i];
    for(std::size_t child : tree.merges[i])
    {
      ASSERT_LT(child, tree.number_of_leaves + i);
      faces.insert(faces.end(), node_faces[child].begin(), node_faces[child].end());
    }
    std::sort(faces.begin(), faces.end());
  }
  std::vector<Mesh::Face_index> handles(tm.faces().begin(), tm.faces().end());
  for(std::size_t n = 0; n < tree.number_of_nodes(); ++n)
  {
    std::vector<Mesh::Face_index> fs;
    for(std::size_t f : node_faces[n]) fs.push_back(handles[f]);
    EXPECT_TRUE(TS::is_disk(tm, fs)) << "node " << n;
  }
  // Charts chosen top-down: each is a node, or lies inside one leaf.
  UV_map uv = tm.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
  // Without the merging of accepted charts, which may join pieces of two
  // leaves, and the straightening of their borders, which trades faces
  // between charts.
  const DS::Parameterization_report report = DS::parameterize_patches(
    tm, patch, uv, DS::parameters::merge_tree(&tree).merge_charts(false).straighten_borders(false));
  EXPECT_GT(report.charts.size(), patches);
  std::vector<std::vector<std::size_t> > sorted_nodes = node_faces;
  std::sort(sorted_nodes.begin(), sorted_nodes.end());
  for(const std::vector<std::size_t>& chart : TS::patches_as_face_index_sets(tm, patch))
  {
    bool in_one_leaf = true;
    for(std::size_t f : chart)
      in_one_leaf = in_one_leaf && tree.face_leaves[f] == tree.face_leaves[chart.front()];
    EXPECT_TRUE(in_one_leaf || std::binary_search(sorted_nodes.begin(), sorted_nodes.end(), chart))
      << "a chart of " << chart.size() << " faces is neither a node nor inside a leaf";
  }
  // A tree that does not match the patches is refused.
  DS::Merge_tree wrong = tree;
  wrong.face_leaves.pop_back();
  EXPECT_THROW(DS::parameterize_patches(tm, patch, uv, DS::parameters::merge_tree(&wrong)), DS::Input_error);
}

TEST(Atlas, PatchesAboveTheSizeCapAreSplitBeforeParameterization)
{
  const DS::Distortion_bound no_distortion_split = DS::Distortion_bound::unbounded();
  Mesh tm = load("elephant.off");
  Mesh capped_mesh = tm, capped_no_fallback_mesh = tm;
  const std::size_t cap = 400;
  const Atlas uncapped = make_atlas(tm, DS::parameters::distortion_bound(no_distortion_split));
  const Atlas capped = make_atlas(capped_mesh,
                                  DS::parameters::distortion_bound(no_distortion_split).max_chart_faces(cap));
  const Atlas capped_no_fallback = make_atlas(
    capped_no_fallback_mesh,
    DS::parameters::distortion_bound(no_distortion_split).max_chart_faces(cap).use_fallback(false));
  expect_valid_atlas(capped_mesh, capped);
  expect_valid_atlas(capped_no_fallback_mesh, capped_no_fallback);
  ASSERT_GT(capped.report.parameterization.number_of_split_patches, 0u) << "elephant's charts exceed 400 faces";
  // The cap holds with or without the fallback, counted from the patch map.
  for(const Atlas* a : { &capped, &capped_no_fallback })
  {
    std::vector<std::size_t> faces_per_patch(a->report.number_of_charts, 0);
    for(Mesh::Face_index f : tm.faces())
      ++faces_per_patch.at(a->patch[f]);
    EXPECT_LE(*std::max_element(faces_per_patch.begin(), faces_per_patch.end()), cap);
  }
  // The pieces come from the same segmentation.
  EXPECT_TRUE(TS::refines(TS::patches_as_face_index_sets(capped_mesh, capped.patch),
                          TS::patches_as_face_index_sets(tm, uncapped.patch)));
  EXPECT_THROW(make_atlas(capped_mesh, DS::parameters::max_chart_faces(std::size_t(0))), DS::Input_error);
}

TEST(Atlas, SelfIntersectingSurfaceGivesAValidAtlas)
{
  // A spindle torus (minor radius above the major one): the tube passes
  // through itself around the axis. The method only uses intrinsic
  // distances and per-chart flattening, so the crossing does not matter.
  const int n_major = 48, n_minor = 24;
  TS::Soup soup = TS::torus(n_major, n_minor);
  const double R = 0.6, r = 1.0;
  for(std::size_t k = 0; k < soup.points.size(); ++k)
  {
    const double u = 2 * TS::soup_detail::pi() * double(k / n_minor) / n_major, v = 2 * TS::soup_detail::pi() * double(k % n_minor) / n_minor;
    const double rho = R + r * std::cos(v);
    soup.points[k] = {{ rho * std::cos(u), rho * std::sin(u), r * std::sin(v) }};
  }
  Mesh tm = make(soup);
  ASSERT_TRUE(CGAL::Polygon_mesh_processing::does_self_intersect(tm)) << "the test mesh must cross itself";
  for(DS::Parameterization_method method : TS::all_parameterization_methods)
  {
    Mesh copy = tm;
    const Atlas a = make_atlas(copy, DS::parameters::parameterization_method(method));
    expect_valid_atlas(copy, a);
  }
}

namespace {

// Patch ids renumbered in the order of first appearance over the faces, so
// that two partitions compare equal whatever their numbering.
std::vector<std::size_t> partition_of(const Mesh& tm, const Patch_map& patch)
{
  std::map<std::size_t, std::size_t> renumbered;
  std::vector<std::size_t> out;
  for(Mesh::Face_index f : tm.faces())
    out.push_back(renumbered.emplace(patch[f], renumbered.size()).first->second);
  return out;
}

} // namespace

TEST(Atlas, SegmentingThenParameterizingGivesTheChartsOfUvAtlas)
{
  // couplingdown is a machined part whose patches are split under the bound:
  // the splits must use the distance the caller gives parameterize_patches(),
  // as uv_atlas() uses one distance for both steps.
  for(double penalty : { 0., DS::default_crease_penalty, 3. })
  {
    SCOPED_TRACE("crease_penalty " + std::to_string(penalty));
    Mesh tm = load("couplingdown.off");
    Mesh copy = tm;
    const Atlas at_once = make_atlas(tm, DS::parameters::crease_penalty(penalty));

    Patch_map patch = copy.add_property_map<Mesh::Face_index, std::size_t>("f:steps", 0).first;
    UV_map uv = copy.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:steps", K::Point_2(0, 0)).first;
    DS::Merge_tree tree;
    DS::segment_into_disks(copy, patch, DS::parameters::crease_penalty(penalty).merge_tree(&tree));
    const DS::Parameterization_report steps =
      DS::parameterize_patches(copy, patch, uv, DS::parameters::crease_penalty(penalty).merge_tree(&tree));
    EXPECT_GT(steps.number_of_split_patches, 0u) << "no split: the distance of the splits is not tested";
    EXPECT_EQ(partition_of(copy, patch), partition_of(tm, at_once.patch));
  }
}

TEST(Atlas, SameResultForAnyNumberOfThreads)
{
  Mesh tm = load("elephant.off");
  Mesh copy = tm;
  const Atlas one = make_atlas(tm, DS::parameters::number_of_threads(1u));
  const Atlas two = make_atlas(copy, DS::parameters::number_of_threads(2u));
  std::size_t differences = 0;
  for(Mesh::Halfedge_index h : tm.halfedges())
    if(!tm.is_border(h) && (one.uv[h] != two.uv[h]))
      ++differences;
  EXPECT_EQ(differences, 0u);
  // The same charts tried, too.
  EXPECT_EQ(one.report.parameterization.solved_faces, two.report.parameterization.solved_faces);
  EXPECT_EQ(one.report.parameterization.number_of_solves, two.report.parameterization.number_of_solves);
}

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;

// A parameterizer of the user's, as SMP's concept Parameterizer_3 asks:
// SMP's discrete authalic map (a method the package has no name for),
// counting its calls, the faces it solved and the most calls running at
// once, in counters its copies share.
struct Counted_authalic_parameterizer
{
  typedef DS::Chart_mesh Triangle_mesh;
  std::shared_ptr<std::atomic<std::size_t> > calls = std::make_shared<std::atomic<std::size_t> >(0);
  std::shared_ptr<std::atomic<std::size_t> > faces = std::make_shared<std::atomic<std::size_t> >(0);
  std::shared_ptr<std::atomic<int> > running = std::make_shared<std::atomic<int> >(0);
  std::shared_ptr<std::atomic<int> > most_running = std::make_shared<std::atomic<int> >(0);

  template <typename VertexUVMap, typename VertexIndexMap, typename VertexParameterizedMap>
  SMP::Error_code parameterize(DS::Chart_mesh& mesh, DS::Chart_mesh::Halfedge_index border, VertexUVMap uv,
                               VertexIndexMap index, VertexParameterizedMap parameterized)
  {
    ++*calls;
    *faces += mesh.number_of_faces();
    const int now = ++*running;
    for(int most = most_running->load(); now > most && !most_running->compare_exchange_weak(most, now);)
    {}
    struct Leave
    {
      std::atomic<int>& running;
      ~Leave() { --running; }
    } leave{ *running };
    // A direct solver: SMP's default iterative one took seconds here.
    typedef CGAL::Eigen_solver_traits<
      Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> > > Direct;
    SMP::Discrete_authalic_parameterizer_3<DS::Chart_mesh, SMP::Circular_border_arc_length_parameterizer_3<DS::Chart_mesh>,
                                           Direct> authalic;
    return authalic.parameterize(mesh, border, uv, index, parameterized);
  }
};

// One that adds a vertex to the chart it is given.
struct Mesh_changing_parameterizer
{
  template <typename VertexUVMap, typename VertexIndexMap, typename VertexParameterizedMap>
  SMP::Error_code parameterize(DS::Chart_mesh& mesh, DS::Chart_mesh::Halfedge_index, VertexUVMap, VertexIndexMap,
                               VertexParameterizedMap)
  {
    mesh.add_vertex(DS::Chart_mesh::Point(0, 0, 0));
    return SMP::OK;
  }
};

// One whose solver never succeeds.
struct Failing_parameterizer
{
  template <typename VertexUVMap, typename VertexIndexMap, typename VertexParameterizedMap>
  SMP::Error_code parameterize(DS::Chart_mesh&, DS::Chart_mesh::Halfedge_index, VertexUVMap, VertexIndexMap,
                               VertexParameterizedMap)
  {
    return SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  }
};

std::size_t differing_uvs(const Mesh& tm, const Atlas& a, const Atlas& b)
{
  std::size_t differences = 0;
  for(Mesh::Face_index f : tm.faces())
    differences += a.patch[f] != b.patch[f] ? 1 : 0;
  for(Mesh::Halfedge_index h : tm.halfedges())
    if(!tm.is_border(h) && a.uv[h] != b.uv[h])
      ++differences;
  return differences;
}

} // namespace

TEST(Parameterizer, AnSmpObjectOrFactoryGivesTheAtlasOfTheBuiltInMethodOfTheSameClass)
{
  typedef SMP::LSCM_parameterizer_3<DS::Chart_mesh> Lscm;
  Mesh tm = load("elephant.off");
  Mesh object_mesh = tm, factory_mesh = tm;
  const Atlas by_name =
    make_atlas(tm, DS::parameters::parameterization_method(DS::Parameterization_method::LSCM).number_of_threads(2u));
  const Atlas by_object = make_atlas(object_mesh, DS::parameters::parameterizer(Lscm()).number_of_threads(2u));
  const Atlas by_factory =
    make_atlas(factory_mesh, DS::parameters::parameterizer([] { return Lscm(); }).number_of_threads(2u));
  expect_valid_atlas(object_mesh, by_object);
  expect_valid_atlas(factory_mesh, by_factory);
  EXPECT_EQ(differing_uvs(tm, by_name, by_object), 0u);
  EXPECT_EQ(differing_uvs(tm, by_name, by_factory), 0u);
  ASSERT_EQ(by_object.report.parameterization.charts.size(), by_name.report.parameterization.charts.size());
  for(std::size_t i = 0; i < by_object.report.parameterization.charts.size(); ++i)
  {
    const DS::Chart_report& named = by_name.report.parameterization.charts[i];
    const DS::Chart_report& object = by_object.report.parameterization.charts[i];
    EXPECT_EQ(named.requested, DS::Parameterization_method::LSCM);
    EXPECT_EQ(object.requested, DS::Parameterization_method::CUSTOM);
    EXPECT_EQ(object.fallback, named.fallback);
    EXPECT_EQ(object.used, named.fallback ? named.used : DS::Parameterization_method::CUSTOM);
  }
}

TEST(Parameterizer, AMethodOutsideTheEnumerationRunsOnEveryChartOnAnyNumberOfThreads)
{
  Mesh tm = load("elephant.off");
  Mesh two_threads = tm, conformal_mesh = tm;
  Counted_authalic_parameterizer authalic;
  // The paper's charts (no bound): under the default angle bound, an
  // area-preserving map splits the patches down to many small charts.
  const auto paper = DS::parameters::distortion_bound(DS::Distortion_bound::unbounded());
  const Atlas one = make_atlas(tm, paper.parameterizer(authalic).number_of_threads(1u));
  expect_valid_atlas(tm, one);
  std::size_t solved = 0;
  for(const DS::Chart_report& c : one.report.parameterization.charts)
  {
    EXPECT_EQ(c.requested, DS::Parameterization_method::CUSTOM);
    if(!c.fallback)
    {
      EXPECT_EQ(c.used, DS::Parameterization_method::CUSTOM);
      EXPECT_TRUE(c.valid);
    }
    solved += (c.used == DS::Parameterization_method::CUSTOM && c.faces > 1) ? 1 : 0;
  }
  ASSERT_GT(solved, 10u);
  // Every kept chart of two faces or more was solved by it, among the
  // candidates the choice of charts tried.
  EXPECT_GE(authalic.calls->load(), solved);

  // Its copies take turns, and two threads give the same atlas.
  const std::size_t calls_on_one_thread = authalic.calls->exchange(0);
  const Atlas two = make_atlas(two_threads, paper.parameterizer(authalic).number_of_threads(2u));
  EXPECT_EQ(differing_uvs(tm, one, two), 0u);
  EXPECT_EQ(authalic.calls->load(), calls_on_one_thread);
  EXPECT_EQ(authalic.most_running->load(), 1);

  // And it is not a built-in method under another name.
  const Atlas conformal =
    make_atlas(conformal_mesh, paper.parameterization_method(DS::Parameterization_method::DISCRETE_CONFORMAL));
  EXPECT_GT(differing_uvs(tm, one, conformal), 0u);
}

TEST(SolveCount, EveryRunOfTheMethodIsCountedWithItsFaces)
{
  Mesh tm = load("eight.off");
  Counted_authalic_parameterizer authalic;
  // Under the default bound, the authalic map's patches are split and the
  // small charts merged: many tries. No fallback: each try is one run of
  // the method.
  const Atlas a = make_atlas(tm, DS::parameters::parameterizer(authalic).use_fallback(false).number_of_threads(2u));
  const DS::Parameterization_report& p = a.report.parameterization;
  const std::size_t calls = authalic.calls->load(), faces_solved_by_it = authalic.faces->load();
  ASSERT_GT(calls, 0u);
  // The tries it was not called for are single triangles, laid out as they are.
  EXPECT_GE(p.number_of_solves, calls);
  EXPECT_EQ(p.solved_faces - faces_solved_by_it, p.number_of_solves - calls);
  EXPECT_GT(p.solved_faces_in_merges, 0u);
  // Every face is in some chart solved before the merges and reroutes.
  EXPECT_GE(p.solved_faces - p.solved_faces_in_merges - p.solved_faces_in_reroutes, tm.number_of_faces());
  EXPECT_DOUBLE_EQ(a.report.solves_per_face(), double(p.solved_faces) / double(tm.number_of_faces()));
}

TEST(SolveCount, EachFaceIsSolvedOnceWhenEveryPatchIsKept)
{
  Mesh tm = load("elephant.off");
  // The paper's charts: no bound, no merges, no reroutes.
  const Atlas a = make_atlas(tm, DS::parameters::distortion_bound(DS::Distortion_bound::unbounded()));
  const DS::Parameterization_report& p = a.report.parameterization;
  ASSERT_EQ(p.number_of_fallbacks, 0u);
  ASSERT_EQ(p.number_of_split_patches, 0u);
  EXPECT_EQ(p.solved_faces, tm.number_of_faces());
  EXPECT_EQ(p.number_of_solves, p.charts.size());
  EXPECT_EQ(p.solved_faces_in_merges + p.solved_faces_in_reroutes, 0u);
  EXPECT_DOUBLE_EQ(a.report.solves_per_face(), 1.);
}

TEST(Parameterizer, AFailingOrThrowingParameterizerGetsTheFallbacks)
{
  Mesh tm = make(TS::disk(6, 16));
  Patch_map patch = tm.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  UV_map uv = tm.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
  auto throwing = []() -> Failing_parameterizer { throw std::runtime_error("no parameterizer today"); };
  // SMP's own message for the code (CGAL 5.5's list of messages is one off).
  const std::string failed = SMP::get_error_message(SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM);
  for(const std::string expected : { failed, std::string("no parameterizer today"),
                                     std::string("the parameterizer changed the chart's mesh") })
  {
    SCOPED_TRACE(expected);
    for(Mesh::Face_index f : tm.faces())
      patch[f] = 0;
    const auto np = DS::parameters::distortion_bound(DS::Distortion_bound::unbounded()).merge_charts(false);
    const DS::Parameterization_report with =
      expected == failed ? DS::parameterize_patches(tm, patch, uv, np.parameterizer(Failing_parameterizer()))
      : expected.find("today") != std::string::npos
        ? DS::parameterize_patches(tm, patch, uv, np.parameterizer(throwing))
        : DS::parameterize_patches(tm, patch, uv, np.parameterizer(Mesh_changing_parameterizer()));
    ASSERT_EQ(with.charts.size(), 1u);
    EXPECT_TRUE(with.charts[0].valid);
    EXPECT_TRUE(with.charts[0].fallback);
    EXPECT_TRUE(with.charts[0].method_error);
    EXPECT_EQ(with.charts[0].requested, DS::Parameterization_method::CUSTOM);
    EXPECT_EQ(with.charts[0].used, DS::Parameterization_method::MEAN_VALUE);
    EXPECT_NE(with.charts[0].problem.find(expected), std::string::npos) << with.charts[0].problem;
    DS::pack_patches(tm, patch, uv);
    const TS::Atlas_report atlas = TS::check_atlas(tm, patch, uv, 512);
    EXPECT_TRUE(atlas.ok()) << atlas.summary();
  }
  for(Mesh::Face_index f : tm.faces())
    patch[f] = 0;
  const DS::Parameterization_report without = DS::parameterize_patches(
    tm, patch, uv, DS::parameters::parameterizer(Failing_parameterizer()).use_fallback(false)
                     .distortion_bound(DS::Distortion_bound::unbounded()).merge_charts(false));
  std::size_t solved = 0;
  for(const DS::Chart_report& c : without.charts)
  {
    solved += c.faces > 1 ? 1 : 0;
    EXPECT_FALSE(c.fallback);
    if(c.faces > 1)
    {
      EXPECT_EQ(c.used, DS::Parameterization_method::CUSTOM);
      EXPECT_FALSE(c.valid);
    }
  }
  EXPECT_GT(solved, 0u);
  EXPECT_EQ(without.number_of_fallbacks, 0u);
}

TEST(Parameterizer, CustomIsNotAMethodOneCanAskForByName)
{
  Mesh tm = make(TS::disk(4, 12));
  Patch_map patch = tm.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  UV_map uv = tm.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(7, 7)).first;
  try
  {
    DS::parameterize_patches(tm, patch, uv, DS::parameters::parameterization_method(DS::Parameterization_method::CUSTOM));
    ADD_FAILURE() << "CUSTOM was accepted without a parameterizer";
  }
  catch(const DS::Input_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("parameterizer"), std::string::npos) << e.what();
  }
  for(Mesh::Halfedge_index h : tm.halfedges())
    ASSERT_EQ(uv[h], K::Point_2(7, 7));
  EXPECT_THROW(DS::parameterization_method_from_string("custom"), DS::Input_error);
  EXPECT_EQ(DS::to_string(DS::Parameterization_method::CUSTOM), "custom");
  for(DS::Parameterization_method m : TS::all_parameterization_methods)
    EXPECT_EQ(DS::parameterization_method_from_string(DS::to_string(m)), m);
}

TEST(Atlas, EveryIndexRunsOnceOnAnyNumberOfThreadsLargestFirst)
{
  // Sizes with ties: the order must be by decreasing size, ties by index,
  // and each index must run exactly once whatever the number of threads.
  const std::size_t n = 1000;
  std::vector<std::size_t> size(n);
  for(std::size_t i = 0; i < n; ++i)
    size[i] = (i * 7919) % 37;
  const std::vector<std::size_t> order = DS::internal::largest_first(n, [&](std::size_t i) { return size[i]; });
  ASSERT_EQ(order.size(), n);
  for(std::size_t k = 1; k < n; ++k)
  {
    const std::size_t a = order[k - 1], b = order[k];
    EXPECT_TRUE(size[a] > size[b] || (size[a] == size[b] && a < b)) << "positions " << k - 1 << ", " << k;
  }
  auto size_of = [&](std::size_t i) { return size[i]; };
  for(unsigned int threads : { 0u, 1u, 2u, 3u })
  {
    std::vector<std::atomic<int> > runs(n);
    for(std::atomic<int>& r : runs)
      r = 0;
    auto on_threads = [&](std::size_t count, const auto& work) { DS::internal::for_each_index(count, threads, work); };
    DS::internal::for_each_largest_first(on_threads, n, size_of, [&](std::size_t i) { ++runs[i]; });
    EXPECT_EQ(std::count_if(runs.begin(), runs.end(), [](const std::atomic<int>& r) { return r == 1; }),
              static_cast<long>(n))
      << threads << " threads";
  }
  // In a sequential loop the work comes in that order.
  std::vector<std::size_t> visited;
  auto in_order = [](std::size_t count, const auto& work) {
    for(std::size_t k = 0; k < count; ++k)
      work(k);
  };
  DS::internal::for_each_largest_first(in_order, n, size_of, [&](std::size_t i) { visited.push_back(i); });
  EXPECT_EQ(visited, order);
}

TEST(Atlas, WorkThatMakesWorkRunsEveryItemOnceOnAnyNumberOfThreads)
{
  // Items are the nodes of a binary heap of n nodes: node i adds its
  // children 2i + 1 and 2i + 2 while they exist, so each node must run
  // exactly once, whatever the number of threads, and none runs twice.
  const std::size_t n = 5000;
  for(unsigned int threads : { 0u, 1u, 2u, 3u })
  {
    std::vector<std::atomic<int> > runs(n);
    for(std::atomic<int>& r : runs)
      r = 0;
    std::vector<std::size_t> roots(1, 0);
    DS::internal::for_each_growing(roots, threads, [&](std::size_t& i, const auto& add) {
      ++runs[i];
      for(std::size_t child : { 2 * i + 1, 2 * i + 2 })
        if(child < n)
          add(std::size_t(child));
    });
    EXPECT_EQ(std::count_if(runs.begin(), runs.end(), [](const std::atomic<int>& r) { return r == 1; }),
              static_cast<long>(n))
      << threads << " threads";
  }
  // On one thread the work runs depth first: the last item added first.
  std::vector<std::size_t> visited;
  DS::internal::for_each_growing(std::vector<std::size_t>{ 0, 1 }, 1, [&](std::size_t& i, const auto& add) {
    visited.push_back(i);
    if(i == 0)
    {
      add(std::size_t(2));
      add(std::size_t(3));
    }
  });
  EXPECT_EQ(visited, (std::vector<std::size_t>{ 0, 3, 2, 1 }));
}

TEST(Atlas, TightPackingKeepsOneTexelDensityAndBeatsTheGrid)
{
  // On the paper's charts and on the bounded ones, whose jagged, elongated
  // shapes leave their bounding rectangles mostly empty (on
  // elephant-with-holes the rectangles alone covered 0.37 of the square,
  // the grid 0.43: the chart profiles nest).
  const auto paper =
    DS::parameters::distortion_bound(DS::Distortion_bound::unbounded()).smooth_borders(false).crease_penalty(0.);
  const auto bounded = DS::parameters::distortion_bound(DS::Distortion_bound());
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "bones.off", "couplingdown.off" })
  for(int variant = 0; variant < 2; ++variant)
  {
    SCOPED_TRACE(std::string(name) + (variant == 0 ? ", the paper's charts" : ", bounded charts"));
    Mesh tm = load(name);
    const Atlas tight = variant == 0 ? make_atlas(tm, paper.packing_method(DS::Packing_method::TIGHT))
                                     : make_atlas(tm, bounded.packing_method(DS::Packing_method::TIGHT));
    const std::vector<double> scales = TS::chart_scales(tm, tight.patch, tight.uv);
    ASSERT_FALSE(scales.empty());
    const double lo = *std::min_element(scales.begin(), scales.end());
    const double hi = *std::max_element(scales.begin(), scales.end());
    EXPECT_LE(hi / lo, 1.01) << "texel density differs between charts";
    EXPECT_NEAR(tight.report.packing.efficiency, TS::uv_area_sum(tm, tight.uv), 1e-9);

    Mesh tm2 = load(name);
    const Atlas grid = variant == 0 ? make_atlas(tm2, paper.packing_method(DS::Packing_method::GRID))
                                    : make_atlas(tm2, bounded.packing_method(DS::Packing_method::GRID));
    expect_valid_atlas(tm2, grid);
    EXPECT_GE(tight.report.packing.efficiency, grid.report.packing.efficiency);
  }
}

namespace {

// Multiplies every coordinate by 2^exponent: exact, so results must not change.
struct Power_of_two_scaled_points
{
  typedef Mesh::Vertex_index key_type;
  typedef K::Point_3 value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;
  const Mesh* mesh;
  int exponent;
  friend value_type get(const Power_of_two_scaled_points& m, key_type v)
  {
    const K::Point_3& p = m.mesh->point(v);
    return K::Point_3(std::ldexp(p.x(), m.exponent), std::ldexp(p.y(), m.exponent), std::ldexp(p.z(), m.exponent));
  }
};

} // namespace

TEST(Atlas, HugeAndTinyCoordinatesGiveTheSameAtlas)
{
  Mesh tm = load("elephant-with-holes.off");
  const Atlas unit = make_atlas(tm, DS::parameters::default_values());
  for(int exponent : { -100, 100 })
  {
    SCOPED_TRACE(exponent);
    Mesh copy = tm;
    const Atlas scaled = make_atlas(copy, DS::parameters::vertex_point_map(Power_of_two_scaled_points{ &copy, exponent }));
    std::size_t different_patches = 0, different_uvs = 0;
    for(Mesh::Face_index f : tm.faces())
      different_patches += (unit.patch[f] != scaled.patch[f]) ? 1 : 0;
    for(Mesh::Halfedge_index h : tm.halfedges())
      if(!tm.is_border(h))
        different_uvs += (CGAL::squared_distance(unit.uv[h], scaled.uv[h]) > 1e-20) ? 1 : 0;
    EXPECT_EQ(different_patches, 0u);
    EXPECT_EQ(different_uvs, 0u);
    EXPECT_EQ(scaled.report.parameterization.number_of_fallbacks, unit.report.parameterization.number_of_fallbacks);
  }
}

TEST(Atlas, DegenerateFacesStillGiveAValidAtlas)
{
  // A square whose bottom edge has a midpoint vertex, making one face flat
  // (three collinear corners), plus a separate component that is a single
  // flat triangle, which cannot merge with anything.
  TS::Soup s;
  s.points = { {{ 0, 0, 0 }}, {{ 2, 0, 0 }}, {{ 2, 2, 0 }}, {{ 0, 2, 0 }}, {{ 1, 0, 0 }},
               {{ 5, 5, 5 }}, {{ 6, 5, 5 }}, {{ 7, 5, 5 }} };
  s.triangles = { {{ 0, 4, 3 }}, {{ 4, 2, 3 }}, {{ 4, 1, 2 }}, {{ 0, 1, 4 }}, {{ 5, 6, 7 }} };
  for(double threshold : { 0., 100. })
  {
    SCOPED_TRACE(threshold);
    Mesh tm = make(s);
    const Atlas a = make_atlas(tm, DS::parameters::number_of_seeds(5).merge_threshold(threshold));
    EXPECT_EQ(a.report.parameterization.number_of_invalid_charts, 0u);
    const TS::Atlas_report atlas = TS::check_atlas(tm, a.patch, a.uv, 512);
    EXPECT_TRUE(atlas.ok()) << atlas.summary();
    EXPECT_EQ(atlas.faces_zero_3d_area, 2u);
  }
}

// The indices of all faces of m, in order: a region that is the whole mesh.
std::vector<DS::internal::Index> every_face(const DS::internal::Indexed_triangle_mesh& m)
{
  std::vector<DS::internal::Index> all(m.number_of_faces());
  for(DS::internal::Index f = 0; f < all.size(); ++f)
    all[f] = f;
  return all;
}

TEST(Atlas, SplittingAChartGivesValidDiskPieces)
{
  // The last resort of the fallback chain, run directly on a chart that
  // does not need it: the pieces must cover the chart once, each a valid disk.
  const Mesh tm = make(TS::disk(10, 32));
  DS::internal::Indexed_triangle_mesh m;
  std::vector<Mesh::Face_index> face_handles;
  DS::internal::build_indexed_triangle_mesh(tm, DS::parameters::default_values(), m, face_handles);
  DS::internal::Splitter splitter(m);
  std::vector<DS::internal::Index> all = every_face(m);
  std::vector<DS::internal::Chart> pieces;
  std::vector<DS::internal::Chart_outcome> outcomes;
  std::vector<std::uint64_t> rejected;
  const DS::internal::Split_rule rule{ m, DS::Distortion_bound(), DS::default_max_chart_faces, true };
  const DS::internal::Chart_choice<DS::internal::Split_rule> choice(
    m, DS::internal::built_in_chart_method(DS::Parameterization_method::ARAP), true, rule);
  DS::internal::split_and_parameterize(choice, splitter, all, pieces, outcomes, rejected);
  ASSERT_GE(pieces.size(), 2u);
  std::vector<int> covered(m.number_of_faces(), 0);
  for(std::size_t i = 0; i < pieces.size(); ++i)
  {
    EXPECT_TRUE(outcomes[i].valid);
    std::vector<Mesh::Face_index> fs;
    for(DS::internal::Index f : pieces[i].faces)
    {
      ++covered[f];
      fs.push_back(face_handles[f]);
    }
    EXPECT_TRUE(TS::is_disk(tm, fs));
  }
  EXPECT_EQ(std::count(covered.begin(), covered.end(), 1), static_cast<long>(covered.size()));
}

// The angles of a triangle's corner at a (vectors to b and c), computed
// here from the law of cosines, apart from the package's code.
double corner_angle_by_cosines(const K::Point_3& a, const K::Point_3& b, const K::Point_3& c)
{
  const double ab2 = CGAL::squared_distance(a, b), ac2 = CGAL::squared_distance(a, c),
               bc2 = CGAL::squared_distance(b, c);
  const double cosine = (ab2 + ac2 - bc2) / (2. * std::sqrt(ab2 * ac2));
  return std::acos((std::max)(-1., (std::min)(1., cosine)));
}

TEST(Atlas, InteriorCurvatureOfARegionFollowsGaussBonnet)
{
  // Closed meshes hold 2 pi times their Euler characteristic; a flat disk
  // holds nothing inside; a cap of a sphere (a disk region) holds 2 pi minus
  // the turning of its border, sum over its border vertices of pi minus the
  // region's angles there.
  struct Case { const char* name; TS::Soup soup; double cap_height; };
  const Case cases[] = { { "sphere", TS::uv_sphere(12, 24), 0.3 }, { "torus", TS::torus(16, 8), 10. },
                         { "flat disk", TS::disk(6, 16), 10. } };
  const double expected_whole[] = { 4. * CGAL_PI, 0., 0. };
  for(int k = 0; k < 3; ++k)
  {
    SCOPED_TRACE(cases[k].name);
    const Mesh tm = make(cases[k].soup);
    DS::internal::Indexed_triangle_mesh m;
    std::vector<Mesh::Face_index> face_handles;
    DS::internal::build_indexed_triangle_mesh(tm, DS::parameters::default_values(), m, face_handles);
    const DS::internal::Interior_curvature curvature(m);
    std::vector<DS::internal::Index> all = every_face(m);
    EXPECT_NEAR(curvature.totals(m, all).signed_total, expected_whole[k], 1e-9);
    if(cases[k].cap_height > 1.)
      continue;

    std::vector<DS::internal::Index> cap;
    std::vector<Mesh::Face_index> cap_faces;
    for(DS::internal::Index f = 0; f < all.size(); ++f)
      if(CGAL::centroid(tm.point(tm.source(tm.halfedge(face_handles[f]))),
                        tm.point(tm.target(tm.halfedge(face_handles[f]))),
                        tm.point(tm.target(tm.next(tm.halfedge(face_handles[f]))))).z() > cases[k].cap_height)
      {
        cap.push_back(f);
        cap_faces.push_back(face_handles[f]);
      }
    ASSERT_TRUE(TS::is_disk(tm, cap_faces));
    std::map<Mesh::Vertex_index, double> angle;  // the cap's angles at each vertex
    std::map<Mesh::Vertex_index, int> faces_in_cap;
    for(Mesh::Face_index f : cap_faces)
      for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(tm.halfedge(f), tm))
      {
        angle[tm.target(h)] += corner_angle_by_cosines(tm.point(tm.target(h)), tm.point(tm.source(h)),
                                                       tm.point(tm.target(tm.next(h))));
        ++faces_in_cap[tm.target(h)];
      }
    double turning = 0.;
    for(const auto& entry : angle)
      if(faces_in_cap[entry.first] != static_cast<int>(CGAL::degree(entry.first, tm)))
        turning += CGAL_PI - entry.second;
    EXPECT_GT(std::abs(2. * CGAL_PI - turning), 1.);
    EXPECT_NEAR(curvature.totals(m, cap).signed_total, 2. * CGAL_PI - turning, 1e-9);
  }
}

// A square of n x n quads, each vertex raised to height(x, y).
template <typename Height>
TS::Soup raised_square(int n, const Height& height)
{
  TS::Soup s;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const double x = double(i) / n, y = double(j) / n;
      s.points.push_back({{ x, y, height(x, y, i, j) }});
    }
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const std::size_t a = std::size_t(j * (n + 1) + i), b = a + 1, c = a + std::size_t(n) + 2, d = a + std::size_t(n) + 1;
      s.triangles.push_back({{ a, b, c }});
      s.triangles.push_back({{ a, c, d }});
    }
  return s;
}

TEST(Atlas, CurvatureSpreadCountsSeparatedSignsButNotNoise)
{
  // A bump (positive curvature on top, negative around it, about zero in
  // all) and a square whose heights are noise (every vertex curved, the
  // signs alternating at the scale of an edge). Angle defects are computed
  // here from the law of cosines.
  struct Case { const char* name; TS::Soup soup; bool separated; };
  const Case cases[] = {
    { "bump", raised_square(48, [](double x, double y, int, int) {
        return 0.3 * std::exp(-((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)) / 0.03); }), true },
    { "noise", raised_square(48, [](double, double, int i, int j) {
        return 0.004 * double((i * 7919 + j * 104729) % 13 - 6) / 6.; }), false } };
  for(const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    const Mesh tm = make(c.soup);
    double signed_total = 0., absolute_total = 0.;
    for(Mesh::Vertex_index v : tm.vertices())
    {
      if(tm.is_border(v))
        continue;
      double defect = 2. * CGAL_PI;
      for(Mesh::Halfedge_index h : CGAL::halfedges_around_target(tm.halfedge(v), tm))
        defect -= corner_angle_by_cosines(tm.point(v), tm.point(tm.source(h)), tm.point(tm.target(tm.next(h))));
      signed_total += defect;
      absolute_total += std::abs(defect);
    }
    DS::internal::Indexed_triangle_mesh m;
    std::vector<Mesh::Face_index> face_handles;
    DS::internal::build_indexed_triangle_mesh(tm, DS::parameters::default_values(), m, face_handles);
    const DS::internal::Interior_curvature curvature(m);
    std::vector<DS::internal::Index> all = every_face(m);
    const DS::internal::Interior_curvature::Totals held = curvature.totals(m, all);
    const double spread = held.spread;
    EXPECT_NEAR(held.signed_total, signed_total, 1e-9);
    EXPECT_GE(spread, std::abs(signed_total) - 1e-9);
    EXPECT_LE(spread, absolute_total + 1e-9);
    if(c.separated)
    {
      EXPECT_LT(std::abs(signed_total), 0.1 * absolute_total);
      EXPECT_GT(spread, 0.5 * absolute_total);
    }
    else
    {
      EXPECT_GT(absolute_total, 1.);
      EXPECT_LT(spread, 0.1 * absolute_total);
    }
  }
}

TEST(Atlas, RegionSlotsNumberKeysInTheOrderFirstMet)
{
  // Checked against std::map on runs of consecutive keys (the usual case),
  // keys a multiple of a power of two apart and random keys; with the keys'
  // range given (the array, left for the table when a key falls outside)
  // or not (the table), with too little room at first.
  std::mt19937 random(7);
  for(int pattern = 0; pattern < 3; ++pattern)
    for(int round = 0; round < 40; ++round)
    {
      DS::internal::Region_slots slots;
      if(round % 2 == 0)
        slots.clear(random() % 40);
      else
        slots.clear(random() % 40, 5000, DS::internal::Index(5000 + random() % 400));
      std::map<DS::internal::Index, DS::internal::Index> number;
      const int n = int(random() % 3000);
      for(int i = 0; i < n; ++i)
      {
        const DS::internal::Index key = pattern == 0   ? DS::internal::Index(5000 + random() % 4000)
                                        : pattern == 1 ? DS::internal::Index((random() % 64) * 4096 + random() % 4)
                                                       : DS::internal::Index(random() % 4000000000u);
        const auto known = number.find(key);
        const DS::internal::Index expected = known == number.end() ? DS::internal::Index(number.size()) : known->second;
        number.emplace(key, expected);
        ASSERT_EQ(slots.insert(key), expected);
      }
      ASSERT_EQ(slots.size(), number.size());
      for(const auto& kn : number)
        ASSERT_EQ(slots.find(kn.first), kn.second);
      for(int i = 0; i < 1000; ++i)
      {
        const DS::internal::Index key = DS::internal::Index(random() % 10000);
        const auto known = number.find(key);
        ASSERT_EQ(slots.find(key), known == number.end() ? DS::internal::no_index : known->second);
      }
    }
}

TEST(Atlas, RegionValuesKeepAValuePerKeyAcrossClears)
{
  // Region_values against std::map: values written through operator[] and
  // set(), read through at() (which gives no slot) for keys in and out of
  // the range given at clear, over rounds that reuse the same object.
  std::mt19937 random(11);
  DS::internal::Region_values<int> values(-1);
  for(int round = 0; round < 30; ++round)
  {
    std::vector<DS::internal::Index> region;
    const DS::internal::Index first = DS::internal::Index(random() % 100000);
    for(int i = 0, n = int(random() % 2000); i < n; ++i)
      region.push_back(first + DS::internal::Index(random() % 3000));
    values.clear_for_keys(region);
    std::map<DS::internal::Index, int> expected;
    for(int i = 0, n = int(random() % 4000); i < n; ++i)
    {
      const DS::internal::Index key =
        i % 5 == 0 ? DS::internal::Index(random() % 4000000000u) : first + DS::internal::Index(random() % 3000);
      const int value = int(random() % 100);
      if(i % 2 == 0)
        values.set(key, value);
      else
        values[key] += value;
      int& e = expected.emplace(key, -1).first->second;
      e = (i % 2 == 0) ? value : e + value;
    }
    for(const auto& kv : expected)
      ASSERT_EQ(values.at(kv.first), kv.second);
    for(int i = 0; i < 1000; ++i)
    {
      const DS::internal::Index key = first + DS::internal::Index(random() % 6000);
      const auto known = expected.find(key);
      ASSERT_EQ(values.at(key), known == expected.end() ? -1 : known->second);
    }
  }
}

// A UV sphere's indexed mesh (no split vertex) and the valence of its vertices.
static void indexed_sphere(DS::internal::Indexed_triangle_mesh& m, std::vector<std::size_t>& valence)
{
  const Mesh tm = make(TS::uv_sphere(6, 8));
  std::vector<Mesh::Face_index> face_handles;
  DS::internal::build_indexed_triangle_mesh(tm, DS::parameters::default_values(), m, face_handles);
  valence.assign(m.number_of_vertices(), 0);
  for(const auto& corners : m.corners)
    for(DS::internal::Index v : corners)
      ++valence[v];
}

TEST(Atlas, TheDiskTestJoinsTheCopiesOfASplitVertex)
{
  // A closed sphere whose two poles are copies of one input vertex (as the
  // package splits a vertex where two closed fans meet): on the input it is
  // a sphere pinched at one point, chi = 1, edge-connected and no disk.
  DS::internal::Indexed_triangle_mesh m;
  std::vector<std::size_t> valence;
  indexed_sphere(m, valence);
  ASSERT_TRUE(m.split_from.empty());
  const std::vector<DS::internal::Index> all = every_face(m);
  DS::internal::Region_topology topology(m);
  ASSERT_EQ(topology.count(all).euler_characteristic(), 2);
  // The two vertices of highest valence are the poles.
  std::vector<DS::internal::Index> by_valence(m.number_of_vertices());
  for(DS::internal::Index v = 0; v < by_valence.size(); ++v)
    by_valence[v] = v;
  std::sort(by_valence.begin(), by_valence.end(),
            [&](DS::internal::Index a, DS::internal::Index b) { return valence[a] > valence[b] || (valence[a] == valence[b] && a < b); });
  m.split_from.resize(m.number_of_vertices());
  for(DS::internal::Index v = 0; v < m.split_from.size(); ++v)
    m.split_from[v] = v;
  m.split_from[by_valence[1]] = by_valence[0];
  DS::internal::Region_topology joined(m);
  const DS::internal::Region_counts c = joined.count(all);
  EXPECT_EQ(c.euler_characteristic(), 1);
  EXPECT_EQ(c.edge_components, 1u);
  EXPECT_FALSE(c.is_disk());
  // Without the faces around one pole, one copy is left: the rest of the
  // sphere, a disk.
  std::vector<DS::internal::Index> rest;
  for(DS::internal::Index f : all)
  {
    const auto& k = m.corners[f];
    if(std::find(k.begin(), k.end(), by_valence[1]) == k.end())
      rest.push_back(f);
  }
  EXPECT_TRUE(joined.count(rest).is_disk());
}

TEST(Atlas, TheDiskTestJoinsTwoCopiesWhateverOrderItMeetsThemIn)
{
  // A sphere without the faces around its north pole is a disk. Made two
  // copies of one input vertex, any two of its vertices not on one edge
  // pinch it (chi 0 on the input). The disk test once missed a copy met
  // right after the first meeting of its input vertex (it took the copy's
  // number, the latest one, for a new one) and passed such regions.
  DS::internal::Indexed_triangle_mesh m;
  std::vector<std::size_t> valence;
  indexed_sphere(m, valence);
  ASSERT_TRUE(m.split_from.empty());
  const DS::internal::Index pole = DS::internal::Index(
    std::find(valence.begin(), valence.end(), 8u) - valence.begin());
  ASSERT_LT(pole, m.number_of_vertices());
  std::vector<DS::internal::Index> rest;
  std::set<std::pair<DS::internal::Index, DS::internal::Index> > edges;
  for(DS::internal::Index f = 0; f < m.number_of_faces(); ++f)
  {
    const auto& k = m.corners[f];
    if(std::find(k.begin(), k.end(), pole) != k.end())
      continue;
    rest.push_back(f);
    for(int i = 0; i < 3; ++i)
      edges.insert(std::minmax(k[i], k[(i + 1) % 3]));
  }
  DS::internal::Region_topology alone(m);
  ASSERT_TRUE(alone.count(rest).is_disk());

  std::size_t pairs = 0;
  for(DS::internal::Index a = 0; a < m.number_of_vertices(); ++a)
    for(DS::internal::Index b = 0; b < m.number_of_vertices(); ++b)
    {
      if(a == b || a == pole || b == pole || edges.count(std::minmax(a, b)) > 0)
        continue;
      m.split_from.resize(m.number_of_vertices());
      for(DS::internal::Index v = 0; v < m.split_from.size(); ++v)
        m.split_from[v] = v;
      m.split_from[b] = a;
      DS::internal::Region_topology joined(m);
      const DS::internal::Region_counts c = joined.count(rest);
      ASSERT_TRUE(c.joins_split_vertex) << "copies " << a << " and " << b;
      ASSERT_EQ(c.euler_characteristic(), 0) << "copies " << a << " and " << b;
      ASSERT_FALSE(c.is_disk()) << "copies " << a << " and " << b;
      ++pairs;
    }
  EXPECT_GT(pairs, 1000u);
}

TEST(Atlas, TheSplitScratchHoldsMemoryForTheRegionNotTheMesh)
{
  // Every thread that splits charts has its own sampler, disk test, labels
  // and chart-building slots: arrays sized to the mesh cost about 60 bytes
  // per face per thread. The allocator measures it, not the scratch.
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
  const Mesh tm = make(TS::torus(400, 150));  // 120k faces
  DS::internal::Indexed_triangle_mesh m;
  std::vector<Mesh::Face_index> face_handles;
  DS::internal::build_indexed_triangle_mesh(tm, DS::parameters::default_values(), m, face_handles);
  ASSERT_EQ(m.number_of_faces(), 120000u);
  const DS::internal::Interior_curvature curvature(m);  // shared by the threads
  const DS::internal::Border_smoother smoother(m);
  std::vector<DS::internal::Index> region;  // 400 faces, not an interval
  for(DS::internal::Index f = 0; f < 1000; ++f)
    if(f < 200 || f >= 800)
      region.push_back(f);
  // Heap chunks and mmapped blocks (large arrays) in use.
  auto allocated = [] {
    const struct mallinfo2 info = ::mallinfo2();
    return info.uordblks + info.hblkhd;
  };
  const std::size_t before = allocated();
  std::size_t held = 0;
  {
    DS::internal::Splitter splitter(m);
    ASSERT_FALSE(splitter.fps.run(region, 5).empty());
    ASSERT_EQ(splitter.fps.cells().size(), region.size());
    EXPECT_EQ(splitter.topology.count(region).faces, region.size());
    std::vector<std::vector<DS::internal::Index> > parts(2);
    for(std::size_t k = 0; k < region.size(); ++k)
      parts[k < 200 ? 0 : 1].push_back(region[k]);
    DS::internal::smooth_parts(smoother, splitter, region, parts);
    EXPECT_EQ(parts[0].size() + parts[1].size(), region.size());
    curvature.totals(m, region);
    DS::internal::Chart whole = DS::internal::make_chart(m, region);
    for(DS::internal::Index v : whole.vertices)
      whole.uv.push_back({{ m.points[v][0], m.points[v][1] }});
    DS::internal::Chart part = DS::internal::make_chart(m, parts[0]);
    DS::internal::restrict_chart(whole, part, splitter.parent_vertices);
    held = allocated() - before;
  }
  if(before == 0)
    GTEST_SKIP() << "the allocator keeps no statistics (sanitizers)";
  EXPECT_LT(held, std::size_t(256 * 1024)) << "a 400-face region of a 120k-face mesh";
#else
  GTEST_SKIP() << "needs glibc's mallinfo2()";
#endif
}

TEST(Atlas, AConePointIsSplitThroughByTwoSeedsAroundIt)
{
  // A disk whose centre is raised: the apex is a cone point. The split seeds
  // must sit on opposite sides of it, so that both cells hold faces around
  // it (it is on the border of both) and each holds about half the disk.
  TS::Soup soup = TS::disk(6, 16);
  soup.points[0][2] = 1.;
  const Mesh tm = make(soup);
  DS::internal::Indexed_triangle_mesh m;
  std::vector<Mesh::Face_index> face_handles;
  DS::internal::build_indexed_triangle_mesh(tm, DS::parameters::default_values(), m, face_handles);
  std::vector<DS::internal::Index> all = every_face(m);

  const DS::internal::Interior_curvature curvature(m);
  double defect = 0.;
  const DS::internal::Index apex = curvature.sharpest_interior_vertex(m, all, defect);
  ASSERT_NE(apex, DS::internal::no_index);
  DS::internal::Index highest = 0;  // the indexed mesh may rescale the points
  for(DS::internal::Index v = 1; v < m.number_of_vertices(); ++v)
    if(m.points[v][2] > m.points[highest][2])
      highest = v;
  EXPECT_EQ(apex, highest);
  EXPECT_GT(defect, DS::internal::smallest_cone_defect);

  const std::vector<DS::internal::Index> seeds = DS::internal::opposite_faces_around(m, all, apex);
  ASSERT_EQ(seeds.size(), 2u);
  // Opposite: the directions from the apex to the two faces' centroids
  // (seen from above) point away from each other.
  double direction[2][2];
  for(int k = 0; k < 2; ++k)
  {
    double x = 0., y = 0.;
    for(DS::internal::Index v : m.corners[seeds[k]])
    {
      x += (m.points[v][0] - m.points[apex][0]) / 3.;
      y += (m.points[v][1] - m.points[apex][1]) / 3.;
    }
    direction[k][0] = x;
    direction[k][1] = y;
  }
  EXPECT_LT(direction[0][0] * direction[1][0] + direction[0][1] * direction[1][1], 0.);

  DS::internal::Voronoi_fps fps(m);
  ASSERT_TRUE(fps.run_from_seeds(all, seeds));
  std::size_t size[2] = { 0, 0 }, around_apex[2] = { 0, 0 };
  for(std::size_t k = 0; k < all.size(); ++k)
  {
    const DS::internal::Index f = all[k], c = fps.cells()[k];
    ASSERT_LT(c, 2u);
    ++size[c];
    const auto& corners = m.corners[f];
    if(std::find(corners.begin(), corners.end(), apex) != corners.end())
      ++around_apex[c];
  }
  EXPECT_GT(around_apex[0], 0u);
  EXPECT_GT(around_apex[1], 0u);
  EXPECT_GT(size[0], all.size() / 4);
  EXPECT_GT(size[1], all.size() / 4);

  // A seed outside the region: no partition.
  std::vector<DS::internal::Index> without_a_seed;
  for(DS::internal::Index f : all)
    if(f != seeds[1])
      without_a_seed.push_back(f);
  EXPECT_FALSE(fps.run_from_seeds(without_a_seed, seeds));
}

TEST(Atlas, WorksOnPolyhedron)
{
  typedef CGAL::Polyhedron_3<K> Polyhedron;
  Polyhedron p;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data_path("knot1.off"), p));
  auto patch = get(CGAL::dynamic_face_property_t<std::size_t>(), p);
  auto uv = get(CGAL::dynamic_halfedge_property_t<K::Point_2>(), p);
  const DS::Atlas_report r = DS::uv_atlas(p, uv, DS::parameters::face_patch_map(patch));
  EXPECT_EQ(r.parameterization.number_of_invalid_charts, 0u);
  const TS::Atlas_report atlas = TS::check_atlas(p, patch, uv, 512);
  EXPECT_TRUE(atlas.ok()) << atlas.summary();
}

// `fans` open fans of four triangles meeting only at their apex (a pinched
// vertex), each in its own plane through the apex.
Mesh pinched_fans(int fans)
{
  Mesh tm;
  const Mesh::Vertex_index o = tm.add_vertex(K::Point_3(0, 0, 0));
  for(int fan = 0; fan < fans; ++fan)
  {
    const double tilt = 0.9 * fan, start = 2.1 * fan;
    std::vector<Mesh::Vertex_index> rim;
    for(int i = 0; i <= 4; ++i)
    {
      const double a = start + 0.3 * i;
      rim.push_back(tm.add_vertex(K::Point_3(std::cos(a), std::sin(a) * std::cos(tilt), std::sin(a) * std::sin(tilt))));
    }
    for(int i = 0; i < 4; ++i)
      if(tm.add_face(o, rim[i], rim[i + 1]) == Mesh::null_face())
        ADD_FAILURE() << "Surface_mesh refused a face of fan " << fan;
  }
  return tm;
}

TEST(Atlas, PinchedVerticesAreCutNotRejected)
{
  // Before: "the mesh is not manifold: the faces around vertex #0 form more
  // than one fan". Now each fan gets its own copy of the vertex inside the
  // package; the user's mesh is left as it is.
  for(int fans : { 2, 3 })
  {
    Mesh tm = pinched_fans(fans);
    ASSERT_EQ(tm.number_of_faces(), std::size_t(4 * fans));
    for(DS::Parameterization_method method : TS::all_parameterization_methods)
    {
      SCOPED_TRACE(std::to_string(fans) + " fans, " + DS::to_string(method));
      Mesh copy = tm;
      // Unbounded: a fan pinned on a circle breaks the default bound.
      const TS::Atlas a = TS::make_atlas(copy, DS::parameters::parameterization_method(method).number_of_seeds(1)
                                                 .distortion_bound(DS::Distortion_bound::unbounded()));
      TS::expect_valid_atlas(copy, a);
      // No patch holds two fans: they share no edge.
      EXPECT_EQ(a.report.number_of_charts, std::size_t(fans));
      EXPECT_EQ(copy.number_of_vertices(), tm.number_of_vertices());
    }
  }
}

// A UV sphere without, around each of three vertices of its second ring,
// two opposite faces of the six: each vertex keeps two fans of two faces,
// where the border of a hole passes twice. `pair` names the opposite faces:
// 0, 1 or 2 for (first, fourth), (second, fifth), (third, sixth) in turn
// around the vertex.
TS::Soup sphere_with_pinched_holes(int n_lat, int n_lon, int pair)
{
  TS::Soup s = TS::uv_sphere(n_lat, n_lon);
  auto ring = [n_lon](int k, int j) { return std::size_t(1 + (k - 1) * n_lon + (j + n_lon) % n_lon); };
  std::set<std::array<std::size_t, 3> > gone;
  for(int j : { 0, 3, 6 })
  {
    const int k = 2;
    const std::array<std::size_t, 3> around[6] = {
      { { ring(k - 1, j - 1), ring(k, j - 1), ring(k, j) } },     { { ring(k - 1, j - 1), ring(k, j), ring(k - 1, j) } },
      { { ring(k - 1, j), ring(k, j), ring(k, j + 1) } },         { { ring(k, j), ring(k + 1, j + 1), ring(k, j + 1) } },
      { { ring(k, j), ring(k + 1, j), ring(k + 1, j + 1) } },     { { ring(k, j - 1), ring(k + 1, j), ring(k, j) } } };
    gone.insert(around[pair]);
    gone.insert(around[pair + 3]);
  }
  const std::size_t before = s.triangles.size();
  s.triangles.erase(std::remove_if(s.triangles.begin(), s.triangles.end(),
                                   [&gone](const std::array<std::size_t, 3>& t) { return gone.count(t) > 0; }),
                    s.triangles.end());
  if(s.triangles.size() + 6 != before)
    ADD_FAILURE() << "not every face to remove was found";
  return s;
}

TEST(Atlas, PatchesOfAFileAreDisksOfItsMeshAtPinchedVertices)
{
  // As disk_uv does: the file read by read_triangle_mesh(), then uv_atlas()
  // with the tool's defaults. The reader once gave each extra fan its own
  // vertex, and uv_atlas(), which could not know they were one, made
  // patches holding both fans: no disks on the file's mesh (chi 0).
  for(const std::array<int, 2>& size : { std::array<int, 2>{ { 8, 12 } }, std::array<int, 2>{ { 12, 16 } } })
    for(int pair : { 0, 1, 2 })
    {
      SCOPED_TRACE("sphere " + std::to_string(size[0]) + " x " + std::to_string(size[1]) + ", pair " +
                   std::to_string(pair));
      const TS::Soup soup = sphere_with_pinched_holes(size[0], size[1], pair);
      const std::string path = std::string(::testing::TempDir()) + "/disk_uv_test_pinched_holes.off";
      {
        std::ofstream out(path);
        out.precision(17);
        out << "OFF\n" << soup.points.size() << " " << soup.triangles.size() << " 0\n";
        for(const auto& p : soup.points)
          out << p[0] << " " << p[1] << " " << p[2] << "\n";
        for(const auto& t : soup.triangles)
          out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
      }
      Mesh read;
      const DS::IO::Read_changes changes = DS::IO::read_triangle_mesh(path, read);
      std::remove(path.c_str());
      EXPECT_EQ(changes.pinched_vertices_split, 3u);
      EXPECT_EQ(read.number_of_vertices(), soup.points.size());
      Patch_map patch = read.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
      UV_map uv = read.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
      DS::uv_atlas(read, uv, DS::IO::atlas_parameters(DS::IO::Atlas_options()).face_patch_map(patch));

      // The file's mesh, its pinched vertices kept; face i of both meshes is
      // the file's face i.
      Mesh file;
      for(const auto& p : soup.points)
        file.add_vertex(K::Point_3(p[0], p[1], p[2]));
      for(const auto& t : soup.triangles)
        ASSERT_NE(file.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]), Mesh::Vertex_index(t[2])),
                  Mesh::null_face());
      Patch_map file_patch = file.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
      for(Mesh::Face_index f : file.faces())
        file_patch[f] = patch[f];
      const TS::Partition_report r = TS::check_disk_partition(file, file_patch);
      EXPECT_TRUE(r.ok) << r.problem;
    }
}

TEST(Parameters, ChainsGiveTheSameAtlasInEitherOrder)
{
  // Every parameter of uv_atlas, then the same chain reversed: the named
  // parameters are looked up by tag, so the order cannot matter.
  Mesh a = load("eight.off"), b = load("eight.off");
  UV_map uv_a = a.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  UV_map uv_b = b.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  auto patch_a = a.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  auto patch_b = b.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  std::size_t calls_a = 0, calls_b = 0;
  const DS::Atlas_report ra = DS::uv_atlas(a, uv_a,
    DS::parameters::vertex_point_map(a.points()).geom_traits(K()).face_patch_map(patch_a)
      .number_of_seeds(7).number_of_subsamples(4).merge_threshold(0.6).random_seed(5u)
      .parameterization_method(DS::Parameterization_method::ARAP).use_fallback(true)
      .max_angle_distortion(0.08).max_area_distortion(0.15).max_stretch(8.).max_area_scale(8.)
      .max_stretch_p95(1.3).max_chart_faces(5000u).number_of_threads(1u).smooth_borders(true)
      .merge_charts(true).packing_method(DS::Packing_method::TIGHT).texture_resolution(512u)
      .padding_in_texels(3.).progress_callback([&](const std::string&, std::size_t, std::size_t) { ++calls_a; }));
  const DS::Atlas_report rb = DS::uv_atlas(b, uv_b,
    DS::parameters::progress_callback([&](const std::string&, std::size_t, std::size_t) { ++calls_b; })
      .padding_in_texels(3.).texture_resolution(512u).packing_method(DS::Packing_method::TIGHT)
      .merge_charts(true).smooth_borders(true).number_of_threads(1u).max_chart_faces(5000u)
      .max_stretch_p95(1.3).max_area_scale(8.).max_stretch(8.).max_area_distortion(0.15)
      .max_angle_distortion(0.08).use_fallback(true).parameterization_method(DS::Parameterization_method::ARAP)
      .random_seed(5u).merge_threshold(0.6).number_of_subsamples(4).number_of_seeds(7)
      .face_patch_map(patch_b).geom_traits(K()).vertex_point_map(b.points()));
  EXPECT_EQ(ra.number_of_voronoi_cells, 7u);
  EXPECT_EQ(rb.number_of_voronoi_cells, 7u);
  EXPECT_EQ(ra.number_of_charts, rb.number_of_charts);
  EXPECT_GT(calls_a, 0u);
  EXPECT_EQ(calls_a, calls_b);
  for(Mesh::Face_index f : a.faces())
    ASSERT_EQ(patch_a[f], patch_b[f]);
  for(Mesh::Halfedge_index h : a.halfedges())
    ASSERT_EQ(uv_a[h], uv_b[h]);
  // The parameters are read, not only accepted: another seed count changes the cells.
  Mesh c = load("eight.off");
  UV_map uv_c = c.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  EXPECT_EQ(DS::uv_atlas(c, uv_c, DS::parameters::number_of_threads(1u).number_of_seeds(3)).number_of_voronoi_cells,
            3u);
}


TEST(Atlas, FacesListedInAnotherOrderGiveTheSameAtlas)
{
  // The package numbers faces along the surface, not in the order the mesh
  // lists them: the same triangles listed in another order (here a stride
  // through the list) must get the same chart and the same UVs at every
  // corner, up to rounding.
  const Mesh a = load("elephant.off");
  TS::Soup soup;
  for(Mesh::Vertex_index v : a.vertices())
    soup.points.push_back({{ a.point(v).x(), a.point(v).y(), a.point(v).z() }});
  std::vector<std::array<std::size_t, 3> > triangles;
  for(Mesh::Face_index f : a.faces())
  {
    std::array<std::size_t, 3> t;
    int i = 0;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(a.halfedge(f), a))
      t[i++] = std::size_t(v);
    triangles.push_back(t);
  }
  const std::size_t n = triangles.size(), stride = 7919;  // a prime that does not divide n
  ASSERT_NE(n % stride, 0u);
  std::vector<std::size_t> position_in_b(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    position_in_b[(k * stride) % n] = k;
    soup.triangles.push_back(triangles[(k * stride) % n]);
  }
  Mesh b;
  TS::to_mesh(soup, b);

  Mesh a_copy = a;
  UV_map uv_a = a_copy.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  UV_map uv_b = b.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
  Patch_map patch_a = a_copy.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  Patch_map patch_b = b.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  const DS::Atlas_report ra = DS::uv_atlas(a_copy, uv_a, DS::parameters::face_patch_map(patch_a));
  const DS::Atlas_report rb = DS::uv_atlas(b, uv_b, DS::parameters::face_patch_map(patch_b));
  ASSERT_EQ(ra.number_of_charts, rb.number_of_charts);
  std::vector<Mesh::Face_index> faces_b(b.faces().begin(), b.faces().end());
  std::size_t k = 0;
  for(Mesh::Face_index fa : a_copy.faces())
  {
    const Mesh::Face_index fb = faces_b[position_in_b[k++]];
    ASSERT_EQ(patch_a[fa], patch_b[fb]);
    // The corners of fb, by vertex (vertices keep their order in b).
    std::map<std::size_t, K::Point_2> corner_uv;
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(b.halfedge(fb), b))
      corner_uv[std::size_t(b.target(h))] = uv_b[h];
    // Packing sums over the faces in the mesh's order: equal up to rounding.
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(a_copy.halfedge(fa), a_copy))
    {
      const K::Point_2 p = corner_uv.at(std::size_t(a_copy.target(h)));
      ASSERT_NEAR(uv_a[h].x(), p.x(), 1e-9);
      ASSERT_NEAR(uv_a[h].y(), p.y(), 1e-9);
    }
  }
}

TEST(Atlas, BadParametersAreRejectedBeforeAnythingIsWritten)
{
  Mesh tm = load("eight.off");
  UV_map uv = tm.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(7, 7)).first;
  EXPECT_THROW(DS::uv_atlas(tm, uv, DS::parameters::texture_resolution(0u)), DS::Input_error);
  EXPECT_THROW(DS::uv_atlas(tm, uv, DS::parameters::padding_in_texels(-1.)), DS::Input_error);
  EXPECT_THROW(DS::uv_atlas(tm, uv, DS::parameters::number_of_seeds(0)), DS::Input_error);
  // Negative counts used to wrap around to huge ones (-3 seeds: 634 charts).
  const auto negative = [&](const auto& np, const char* name) {
    try
    {
      DS::uv_atlas(tm, uv, np);
      ADD_FAILURE() << name << ": no exception";
    }
    catch(const DS::Input_error& e)
    {
      const std::string message = e.what();
      EXPECT_NE(message.find(name), std::string::npos) << message;
      EXPECT_NE(message.find("negative"), std::string::npos) << message;
    }
  };
  negative(DS::parameters::number_of_seeds(-3), "number_of_seeds");
  negative(DS::parameters::number_of_subsamples(-1), "number_of_subsamples");
  negative(DS::parameters::texture_resolution(-5), "texture_resolution");
  negative(DS::parameters::number_of_threads(-2), "number_of_threads");
  negative(DS::parameters::max_chart_faces(-1L), "max_chart_faces");
  for(Mesh::Halfedge_index h : tm.halfedges())
    ASSERT_EQ(uv[h], K::Point_2(7, 7));
  EXPECT_THROW(DS::parameterization_method_from_string("harmonic?"), DS::Input_error);
  EXPECT_EQ(DS::parameterization_method_from_string("arap"), DS::Parameterization_method::ARAP);
}

// What the caller gave uv_atlas() and the stages, as it was before the call.
struct Caller_outputs
{
  Patch_map patch;
  UV_map uv;
  DS::Merge_tree tree;
  std::vector<Mesh::Face_index> seeds;

  explicit Caller_outputs(Mesh& tm)
  {
    patch = tm.add_property_map<Mesh::Face_index, std::size_t>("f:caller", 0).first;
    uv = tm.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:caller", K::Point_2(0, 0)).first;
    for(Mesh::Face_index f : tm.faces())
      patch[f] = 12345 + std::size_t(f);
    for(Mesh::Halfedge_index h : tm.halfedges())
      uv[h] = K::Point_2(7, double(std::size_t(h)));
    tree.face_leaves.assign(3, 99);
  }

  void expect_untouched(const Mesh& tm, const std::string& what) const
  {
    std::size_t changed = 0;
    for(Mesh::Face_index f : tm.faces())
      changed += patch[f] != 12345 + std::size_t(f) ? 1 : 0;
    for(Mesh::Halfedge_index h : tm.halfedges())
      changed += uv[h] != K::Point_2(7, double(std::size_t(h))) ? 1 : 0;
    EXPECT_EQ(changed, 0u) << what;
    EXPECT_EQ(tree.face_leaves, std::vector<std::size_t>(3, 99)) << what;
    EXPECT_TRUE(tree.merges.empty()) << what;
    EXPECT_TRUE(seeds.empty()) << what;
  }
};

TEST(Atlas, AFailedOrCancelledCallLeavesTheCallersMapsAsTheyWere)
{
  Mesh tm = load("elephant.off");
  Caller_outputs out(tm);
  const auto outputs = [&](const auto& np) {
    return np.face_patch_map(out.patch).merge_tree(&out.tree).seeds_output_iterator(std::back_inserter(out.seeds));
  };
  // A callback that returns false cancels, in each stage; one that throws
  // is let through. Before, the packing ran on the caller's maps, already
  // written by the two stages before it.
  std::vector<std::string> stages_seen;
  for(const std::string stage : { "segmentation", "parameterization", "packing" })
    for(unsigned int threads : { 1u, 2u })
    {
      std::size_t calls = 0;
      const std::function<bool(const std::string&, std::size_t, std::size_t)> cancel_in_stage =
        [&](const std::string& s, std::size_t, std::size_t) {
          ++calls;
          stages_seen.push_back(s);
          return s != stage;
        };
      try
      {
        DS::uv_atlas(tm, out.uv, outputs(DS::parameters::progress_callback(cancel_in_stage).number_of_threads(threads)));
        ADD_FAILURE() << "not cancelled in " << stage;
      }
      catch(const DS::Cancelled& e)
      {
        EXPECT_EQ(e.stage(), stage);
      }
      out.expect_untouched(tm, "cancelled in " + stage);
      // Not called again once it asked to stop, on any thread.
      EXPECT_EQ(stages_seen.back(), stage);
      EXPECT_GT(calls, 0u);
    }
  EXPECT_NE(std::find(stages_seen.begin(), stages_seen.end(), "parameterization"), stages_seen.end());

  // Inside the packer: its first trial's report (not the stage's "0 of 1") cancels too.
  std::size_t trials_seen = 0;
  const std::function<bool(const std::string&, std::size_t, std::size_t)> cancel_in_packer =
    [&](const std::string& s, std::size_t, std::size_t total) {
      if(s != "packing" || total == 1)
        return true;
      ++trials_seen;
      return false;
    };
  EXPECT_THROW(DS::uv_atlas(tm, out.uv, outputs(DS::parameters::progress_callback(cancel_in_packer).number_of_threads(2u))),
               DS::Cancelled);
  EXPECT_EQ(trials_seen, 1u);
  out.expect_untouched(tm, "cancelled inside the packer");

  const auto throw_in_packing = [](const std::string& s, std::size_t, std::size_t) {
    if(s == "packing")
      throw std::logic_error("user's own error");
  };
  EXPECT_THROW(DS::uv_atlas(tm, out.uv, outputs(DS::parameters::progress_callback(throw_in_packing))),
               std::logic_error);
  out.expect_untouched(tm, "the callback threw in the packing");

  // 16 texels with 3 of padding hold fewer than (13/3)^2 < 19 charts: the
  // segmentation's patches tell it before the parameterization.
  Patch_map patches = tm.add_property_map<Mesh::Face_index, std::size_t>("f:patches", 0).first;
  ASSERT_GE(DS::segment_into_disks(tm, patches, DS::parameters::number_of_seeds(40)), 19u);
  std::vector<std::string> stages;
  try
  {
    DS::uv_atlas(tm, out.uv,
                 outputs(DS::parameters::number_of_seeds(40).texture_resolution(16u).padding_in_texels(3.)
                           .progress_callback([&](const std::string& s, std::size_t, std::size_t) { stages.push_back(s); })));
    ADD_FAILURE() << "19 or more charts packed with a padding of 3 on 16 texels";
  }
  catch(const DS::Input_error& e)
  {
    const std::string message = e.what();
    EXPECT_NE(message.find("padding_in_texels"), std::string::npos) << message;
    EXPECT_NE(message.find("texture_resolution"), std::string::npos) << message;
  }
  EXPECT_EQ(std::find(stages.begin(), stages.end(), "parameterization"), stages.end());
  out.expect_untouched(tm, "too much padding");

  // The stages alone keep their maps too.
  const auto cancel_all = [](const std::string&, std::size_t, std::size_t) { return false; };
  EXPECT_THROW(DS::segment_into_disks(tm, out.patch, DS::parameters::merge_tree(&out.tree).progress_callback(cancel_all)),
               DS::Cancelled);
  EXPECT_THROW(DS::parameterize_patches(tm, patches, out.uv, DS::parameters::progress_callback(cancel_all)),
               DS::Cancelled);
  out.expect_untouched(tm, "stages cancelled");

  // Then a call that goes through writes all of them; a callback that
  // returns nothing, or an empty one, cannot cancel.
  std::size_t calls = 0;
  const DS::Atlas_report report = DS::uv_atlas(
    tm, out.uv, outputs(DS::parameters::progress_callback([&](const std::string&, std::size_t, std::size_t) { ++calls; })));
  EXPECT_GT(calls, 3u);
  EXPECT_EQ(out.tree.face_leaves.size(), tm.number_of_faces());
  EXPECT_FALSE(out.seeds.empty());
  expect_valid_atlas(tm, Atlas{ out.patch, out.uv, report });
  const std::function<bool(const std::string&, std::size_t, std::size_t)> empty;
  EXPECT_NO_THROW(DS::uv_atlas(tm, out.uv, DS::parameters::progress_callback(empty)));
}

TEST(Atlas, ObjWrittenByTheToolReadsBackWithTheSameFacesAndUVs)
{
#ifndef DISK_UV_TOOL
  GTEST_SKIP() << "built without the disk_uv tool";
#else
  const std::string obj = std::string(::testing::TempDir()) + "/disk_uv_test_atlas.obj";
  std::remove(obj.c_str());
  const std::string command = std::string(DISK_UV_TOOL) + " " + data_path("elephant.off") + " --quiet -o " + obj;
  ASSERT_EQ(std::system(command.c_str()), 0) << command;

  TS::Obj_data data;
  std::string error;
  ASSERT_TRUE(TS::read_obj(obj, data, error)) << error;

  Mesh tm = load("elephant.off");
  const Atlas a = make_atlas(tm, DS::parameters::default_values());
  ASSERT_EQ(data.face_v.size(), tm.number_of_faces());
  ASSERT_EQ(data.v.size(), tm.number_of_vertices());
  // The OBJ lists the faces chart by chart, in mesh order within a chart.
  std::vector<Mesh::Face_index> obj_order(tm.faces().begin(), tm.faces().end());
  std::stable_sort(obj_order.begin(), obj_order.end(),
                   [&a](Mesh::Face_index f, Mesh::Face_index g) { return a.patch[f] < a.patch[g]; });
  std::size_t f_index = 0, mismatches = 0, wrong_groups = 0;
  for(Mesh::Face_index f : obj_order)
  {
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_face(tm.halfedge(f), tm))
    {
      // OBJ corners follow the face's vertex order starting anywhere: find it.
      const std::size_t v = std::size_t(tm.target(h));
      bool found = false;
      for(int j = 0; j < 3; ++j)
        if(data.face_v[f_index][j] == v)
        {
          const auto& t = data.vt[data.face_vt[f_index][j]];
          found = std::abs(t[0] - a.uv[h].x()) < 1e-12 && std::abs(t[1] - a.uv[h].y()) < 1e-12;
        }
      mismatches += found ? 0 : 1;
    }
    wrong_groups += (data.face_group[f_index] == "chart_" + std::to_string(a.patch[f])) ? 0 : 1;
    ++f_index;
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(wrong_groups, 0u) << "faces must be grouped by chart";
  std::size_t group_changes = 0;
  for(std::size_t i = 1; i < data.face_group.size(); ++i)
    group_changes += data.face_group[i] != data.face_group[i - 1] ? 1 : 0;
  EXPECT_EQ(group_changes + 1, a.report.number_of_charts) << "one run of faces per chart";
  std::remove(obj.c_str());
#endif
}

namespace {

// What keeps `uv` from mapping the chart's 3D vertices by a similarity: every edge
// scaled by the same factor (within `tolerance`, relative) and every
// triangle kept counterclockwise; empty if nothing. Checked edge by edge,
// apart from the library's distortion code.
std::string similarity_problem(const DS::internal::Indexed_triangle_mesh& m, const DS::internal::Chart& c,
                               const std::vector<std::array<double, 2> >& uv, double tolerance)
{
  double scale = -1;
  for(const auto& t : c.triangles)
  {
    const auto& a = uv[t[0]];
    const auto& b = uv[t[1]];
    const auto& d = uv[t[2]];
    if(!((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]) > 0))
      return "a triangle is clockwise or flat";
    for(int i = 0; i < 3; ++i)
    {
      const auto& p = m.points[c.vertices[t[i]]];
      const auto& q = m.points[c.vertices[t[(i + 1) % 3]]];
      const double l3 = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                  (p[2] - q[2]) * (p[2] - q[2]));
      const auto& u = uv[t[i]];
      const auto& v = uv[t[(i + 1) % 3]];
      const double l2 = std::sqrt((u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]));
      if(scale < 0)
        scale = l2 / l3;
      if(!(std::abs(l2 / l3 - scale) <= tolerance * scale))
        return "edge scaled by " + std::to_string(l2 / l3) + " instead of " + std::to_string(scale);
    }
  }
  return scale > 0 ? std::string() : std::string("zero scale");
}

struct Disk_chart
{
  Mesh tm;
  DS::internal::Indexed_triangle_mesh m;
  std::vector<Mesh::Face_index> face_handles;
};

// A disk, its inner vertices moved in the plane (by less than a third of
// the shortest edge, so no triangle folds) so that no two triangles have
// the same shape, then lifted to z = height(x, y).
template <typename Height>
void make_disk_chart(Disk_chart& p, const Height& height)
{
  p.tm = make(TS::disk(6, 12));
  CGAL::Random rng(7);
  for(Mesh::Vertex_index v : vertices(p.tm))
  {
    const auto& q = p.tm.point(v);
    const double x = q.x() + (is_border(v, p.tm) ? 0. : rng.get_double(-0.01, 0.01));
    const double y = q.y() + (is_border(v, p.tm) ? 0. : rng.get_double(-0.01, 0.01));
    p.tm.point(v) = K::Point_3(x, y, height(x, y));
  }
  DS::internal::build_indexed_triangle_mesh(p.tm, DS::parameters::default_values(), p.m, p.face_handles);
}

void make_planar_chart(Disk_chart& p)
{
  make_disk_chart(p, [](double, double) { return 0.; });
}

// The chart of all of the disk's faces.
DS::internal::Chart whole_chart(const Disk_chart& p)
{
  std::vector<DS::internal::Index> all(p.m.number_of_faces());
  for(DS::internal::Index f = 0; f < all.size(); ++f) all[f] = f;
  return DS::internal::make_chart(p.m, all);
}

} // namespace

TEST(Atlas, FreeBorderLscmAndArapKeepAPlanarChartUpToASimilarity)
{
  // A planar chart has a conformal (indeed isometric) flattening: LSCM must
  // find it up to a similarity, and ARAP from it must keep it.
  Disk_chart p;
  make_planar_chart(p);
  DS::internal::Chart c = whole_chart(p);
  const std::vector<DS::internal::Index> border = DS::internal::chart_border_loop(c);
  ASSERT_EQ(border.size(), 12u);
  const DS::internal::Chart_geometry g = DS::internal::chart_geometry(p.m, c);
  std::vector<std::array<double, 2> > lscm;
  ASSERT_TRUE(DS::internal::free_border_lscm(g, std::vector<std::size_t>(border.begin(), border.end()), lscm));
  EXPECT_EQ(similarity_problem(p.m, c, lscm, 1e-6), "");

  std::vector<DS::internal::Index> loop;
  ASSERT_TRUE(DS::internal::arap_from_lscm(p.m, c, loop));
  EXPECT_EQ(similarity_problem(p.m, c, c.uv, 1e-6), "");
}

TEST(Atlas, FreeBorderLscmStaysExactOnNeedles)
{
  // Three needles of a fan around a center (angles of 2 pi / 200000 there,
  // cotangents of 3e4) and one hinged on their rim towards an apex, as at
  // the rim of a closed cone of valence 200k: developable, so LSCM must
  // flatten it by a similarity. Cotangents clamped at 1e4 made its energy
  // indefinite: the center landed inside the rim and the map folded.
  const double a = 6.283185307179586 / 200000.;
  TS::Soup s;
  s.points = { {{ 0., 0., 0. }}, {{ 1., 0., 0. }}, {{ std::cos(a), std::sin(a), 0. }},
               {{ std::cos(2 * a), std::sin(2 * a), 0. }}, {{ std::cos(3 * a), std::sin(3 * a), 0. }},
               {{ 0., 0., 0.3 }} };
  s.triangles = { {{ 0, 2, 1 }}, {{ 0, 3, 2 }}, {{ 0, 4, 3 }}, {{ 5, 2, 3 }} };
  Disk_chart p;
  p.tm = make(s);
  DS::internal::build_indexed_triangle_mesh(p.tm, DS::parameters::default_values(), p.m, p.face_handles);
  DS::internal::Chart c = whole_chart(p);
  const std::vector<DS::internal::Index> border = DS::internal::chart_border_loop(c);
  ASSERT_EQ(border.size(), 6u);
  const DS::internal::Chart_geometry g = DS::internal::chart_geometry(p.m, c);
  std::vector<std::array<double, 2> > lscm;
  ASSERT_TRUE(DS::internal::free_border_lscm(g, std::vector<std::size_t>(border.begin(), border.end()), lscm));
  DS::internal::keep_winding(c, lscm);
  EXPECT_EQ(similarity_problem(p.m, c, lscm, 1e-5), "");
  std::vector<DS::internal::Index> loop;
  ASSERT_TRUE(DS::internal::arap_from_lscm(p.m, c, loop));
  EXPECT_EQ(similarity_problem(p.m, c, c.uv, 1e-5), "");
}

TEST(Atlas, ChartsBuiltFromSolvedChartsInheritTheirEliminationOrders)
{
  // Two halves of a curved disk get their orders when their solvers'
  // view is built. Their union inherits one: each vertex once, the first
  // half's own vertices, then the second's (each in its half's order),
  // then the shared ones, which separate the others. The solvers eliminate
  // in that order and find the map a fresh order gives, up to rounding. A
  // piece of the union inherits the union's order restricted to it.
  typedef DS::internal::Index Index;
  Disk_chart p;
  make_disk_chart(p, [](double x, double y) { return 0.3 * (x * x - y * y) + 0.2 * std::exp(-4. * (x * x + y * y)); });
  const DS::internal::Indexed_triangle_mesh& m = p.m;
  std::vector<Index> left, right, all;
  for(Index f = 0; f < m.number_of_faces(); ++f)
  {
    double x = 0.;
    for(int i = 0; i < 3; ++i)
      x += m.points[m.corners[f][i]][0];
    (x < 0. ? left : right).push_back(f);
    all.push_back(f);
  }
  DS::internal::Chart a = DS::internal::make_chart(m, left), b = DS::internal::make_chart(m, right);
  auto position_in = [](const std::vector<Index>& order) {
    std::map<Index, std::size_t> at;
    for(std::size_t k = 0; k < order.size(); ++k)
      at[order[k]] = k;
    return at;
  };
  auto is_permutation_of_vertices = [](const DS::internal::Chart& c) {
    std::vector<Index> x = c.elimination_order, y = c.vertices;
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    return x == y;
  };
  for(DS::internal::Chart* half : { &a, &b })
  {
    ASSERT_TRUE(half->elimination_order.empty());
    const DS::internal::Chart_geometry g = DS::internal::chart_geometry(m, *half);
    ASSERT_TRUE(is_permutation_of_vertices(*half));
    for(std::size_t v = 0; v < half->vertices.size(); ++v)
      EXPECT_EQ(half->elimination_order[std::size_t(g.elimination_rank[v])], half->vertices[v]);
  }

  DS::internal::Chart u = DS::internal::make_chart(m, all);
  DS::internal::inherit_union_order(a, b, u);
  ASSERT_TRUE(is_permutation_of_vertices(u));
  const std::set<Index> in_a(a.vertices.begin(), a.vertices.end()), in_b(b.vertices.begin(), b.vertices.end());
  std::map<Index, std::size_t> at_a = position_in(a.elimination_order), at_b = position_in(b.elimination_order);
  std::size_t shared = 0;
  for(std::size_t k = 0; k < u.elimination_order.size(); ++k)
  {
    const Index v = u.elimination_order[k];
    const int group = in_a.count(v) && in_b.count(v) ? 2 : (in_a.count(v) ? 0 : 1);
    shared += group == 2 ? 1 : 0;
    if(k == 0)
      continue;
    const Index w = u.elimination_order[k - 1];
    const int before = in_a.count(w) && in_b.count(w) ? 2 : (in_a.count(w) ? 0 : 1);
    ASSERT_LE(before, group) << "vertex " << v;
    if(before == group)
    {
      const std::map<Index, std::size_t>& at = group == 1 ? at_b : at_a;
      EXPECT_LT(at.at(w), at.at(v)) << "vertex " << v;
    }
  }
  EXPECT_GT(shared, 2u);
  for(const auto& t : u.triangles)
  {
    bool only_a = false, only_b = false;
    for(Index i : t)
    {
      only_a = only_a || !in_b.count(u.vertices[i]);
      only_b = only_b || !in_a.count(u.vertices[i]);
    }
    EXPECT_FALSE(only_a && only_b);
  }

  const std::vector<Index> inherited = u.elimination_order;
  const DS::internal::Chart_geometry g = DS::internal::chart_geometry(m, u);
  EXPECT_EQ(u.elimination_order, inherited);
  const std::map<Index, std::size_t> at_u = position_in(inherited);
  for(std::size_t v = 0; v < u.vertices.size(); ++v)
    EXPECT_EQ(std::size_t(g.elimination_rank[v]), at_u.at(u.vertices[v]));
  DS::internal::Chart fresh = u;
  fresh.elimination_order.clear();
  std::vector<Index> loop;
  ASSERT_TRUE(DS::internal::arap_from_lscm(m, u, loop));
  ASSERT_TRUE(DS::internal::arap_from_lscm(m, fresh, loop));
  EXPECT_NE(fresh.elimination_order, inherited);  // else the comparison below shows nothing
  for(std::size_t v = 0; v < u.vertices.size(); ++v)
    for(int i = 0; i < 2; ++i)
      EXPECT_NEAR(u.uv[v][i], fresh.uv[v][i], 1e-9);

  DS::internal::Chart piece = DS::internal::make_chart(m, left);
  DS::internal::inherit_restricted_order(u, piece);
  ASSERT_TRUE(is_permutation_of_vertices(piece));
  for(std::size_t k = 1; k < piece.elimination_order.size(); ++k)
    EXPECT_LT(at_u.at(piece.elimination_order[k - 1]), at_u.at(piece.elimination_order[k]));
  DS::internal::Chart outside = DS::internal::make_chart(m, right);
  DS::internal::inherit_restricted_order(a, outside);
  EXPECT_TRUE(outside.elimination_order.empty());
}

TEST(Atlas, ArapEndsItsIterationsWhereTheEarlyLookSays)
{
  // ARAP from LSCM on a curved chart, with a look at the iterate after
  // arap_early_look_iterations iterations: stopping there (either verdict)
  // must leave that iterate, going on must leave the iterate of the full
  // count, each compared with plain iterations run here for that count.
  Disk_chart p;
  make_disk_chart(p, [](double x, double y) { return 0.3 * (x * x - y * y) + 0.2 * std::exp(-4. * (x * x + y * y)); });
  DS::internal::Chart c = whole_chart(p);
  const std::vector<DS::internal::Index> border = DS::internal::chart_border_loop(c);
  ASSERT_FALSE(border.empty());
  const DS::internal::Chart_geometry g = DS::internal::chart_geometry(p.m, c);
  DS::internal::Chart start_chart = c;
  ASSERT_TRUE(DS::internal::free_border_lscm(g, std::vector<std::size_t>(border.begin(), border.end()), start_chart.uv));
  DS::internal::keep_winding(start_chart);
  const DS::internal::Chart_uv start = start_chart.uv;
  auto iterated = [&](int count) {
    DS::internal::Chart_uv uv = start;
    EXPECT_EQ(DS::internal::local_global_arap(g, uv, count, [](const DS::internal::Chart_uv&) { return true; }), count);
    return uv;
  };
  auto distance = [](const DS::internal::Chart_uv& a, const DS::internal::Chart_uv& b) {
    double d = 0.;
    for(std::size_t i = 0; i < a.size(); ++i)
      d = (std::max)(d, std::hypot(a[i][0] - b[i][0], a[i][1] - b[i][1]));
    return d;
  };
  const int early = DS::internal::arap_early_look_iterations;
  const DS::internal::Chart_uv after_early = iterated(early), after_all = iterated(DS::internal::arap_iterations);
  ASSERT_GT(distance(after_early, after_all), 1e-6);  // else the test could not tell them apart

  for(DS::internal::Early_verdict verdict :
      { DS::internal::Early_verdict::iterate_on, DS::internal::Early_verdict::good_enough,
        DS::internal::Early_verdict::hopeless })
  {
    int looks = 0;
    double seen = -1.;
    const DS::internal::Arap_early_look judge = [&](const DS::internal::Chart&, const DS::internal::Chart_uv& uv) {
      ++looks;
      seen = distance(uv, after_early);
      return DS::internal::Early_judgement{ verdict, 42. };
    };
    DS::internal::Early_look look{ &judge, DS::internal::Early_judgement() };
    DS::internal::Chart run = c;
    ASSERT_TRUE(DS::internal::arap_from(run, border, g, start, &look));
    EXPECT_EQ(looks, 1);
    EXPECT_LT(seen, 1e-9);
    const DS::internal::Chart_uv& expected = verdict == DS::internal::Early_verdict::iterate_on ? after_all : after_early;
    EXPECT_LT(distance(run.uv, expected), 1e-9) << "verdict " << int(verdict);
    // The judgement is handed back only when the chart ends on the judged map.
    EXPECT_EQ(look.ended.verdict, verdict);
    EXPECT_EQ(look.ended.measure, verdict == DS::internal::Early_verdict::iterate_on ? 0. : 42.);
  }
}

TEST(Atlas, TheEarlyVerdictOfTheSplitRuleFollowsTheBound)
{
  // A planar chart laid out isometrically meets any bound: good enough at
  // once. The same layout stretched 1.5 times along u has a mean
  // |log(s1/s2)| of log 1.5 = 0.41, far over the default 0.06: hopeless.
  // Under a looser angle bound of 0.5 it is neither.
  Disk_chart p;
  make_planar_chart(p);
  const DS::internal::Chart c = whole_chart(p);
  DS::internal::Chart_uv flat(c.vertices.size()), stretched(c.vertices.size());
  for(std::size_t i = 0; i < c.vertices.size(); ++i)
  {
    const auto& q = p.m.points[c.vertices[i]];
    flat[i] = {{ q[0], q[1] }};
    stretched[i] = {{ 1.5 * q[0], q[1] }};
  }
  const DS::internal::Split_rule rule{ p.m, DS::Distortion_bound(), DS::default_max_chart_faces, true };
  EXPECT_EQ(rule.early_verdict(c, flat).verdict, DS::internal::Early_verdict::good_enough);
  EXPECT_EQ(rule.early_verdict(c, stretched).verdict, DS::internal::Early_verdict::hopeless);
  EXPECT_NEAR(rule.early_verdict(c, stretched).measure, std::log(1.5) / DS::Distortion_bound().max_angle_distortion,
              1e-9);
  DS::Distortion_bound loose;
  loose.max_angle_distortion = 0.5;
  loose.max_area_distortion = 1.;
  loose.max_stretch_p95 = 2.;
  const DS::internal::Split_rule loose_rule{ p.m, loose, DS::default_max_chart_faces, true };
  EXPECT_EQ(loose_rule.early_verdict(c, stretched).verdict, DS::internal::Early_verdict::iterate_on);
  // No look without a bound; the fallback, which is about validity only, does not matter.
  const DS::internal::Split_rule unbounded_rule{ p.m, DS::Distortion_bound::unbounded(), DS::default_max_chart_faces,
                                                 true };
  const DS::internal::Split_rule rule_without_fallback{ p.m, DS::Distortion_bound(), DS::default_max_chart_faces,
                                                        false };
  EXPECT_FALSE(unbounded_rule.early_look());
  EXPECT_TRUE(rule_without_fallback.early_look());
  EXPECT_TRUE(rule.early_look());
}

TEST(Atlas, FreeBorderLscmIsStationaryForTheConformalEnergyOnACurvedChart)
{
  // LSCM minimizes the conformal energy with two vertices pinned: on a
  // curved chart (a saddle with a bump, its vertices jittered) the energy's
  // gradient must vanish at every vertex but the two pins. The energy is
  // computed here per triangle, sum of A_T |J grad u - grad v|^2 in the
  // triangle's own frame (J: a quarter turn), not as the library assembles
  // it (cotangent Laplacian and a border term, in u + iv); its gradient by
  // central differences, exact for a quadratic up to rounding.
  Disk_chart p;
  make_disk_chart(p, [](double x, double y) { return 0.3 * (x * x - y * y) + 0.2 * std::exp(-4. * (x * x + y * y)); });
  const DS::internal::Indexed_triangle_mesh& m = p.m;
  DS::internal::Chart c = whole_chart(p);
  const std::vector<DS::internal::Index> border = DS::internal::chart_border_loop(c);
  ASSERT_FALSE(border.empty());
  const DS::internal::Chart_geometry g = DS::internal::chart_geometry(m, c);
  std::vector<std::array<double, 2> > uv;
  ASSERT_TRUE(DS::internal::free_border_lscm(g, std::vector<std::size_t>(border.begin(), border.end()), uv));

  auto energy = [&](const std::vector<std::array<double, 2> >& z) {
    double e = 0.;
    for(const auto& t : c.triangles)
    {
      const auto& p0 = m.points[c.vertices[t[0]]];
      const auto& p1 = m.points[c.vertices[t[1]]];
      const auto& p2 = m.points[c.vertices[t[2]]];
      const K::Vector_3 e1(p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]);
      const K::Vector_3 e2(p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]);
      const K::Vector_3 normal = CGAL::cross_product(e1, e2);
      const double twice_area = std::sqrt(normal.squared_length());
      const K::Vector_3 ex = e1 / std::sqrt(e1.squared_length());
      const K::Vector_3 ey = CGAL::cross_product(normal / twice_area, ex);
      // Corners in the frame; grad f = sum f_i J (p_k - p_j) / 2A over the
      // corners i, with j, k the next ones counterclockwise.
      const double x[3] = { 0., e1 * ex, e2 * ex }, y[3] = { 0., e1 * ey, e2 * ey };
      double gu[2] = { 0., 0. }, gv[2] = { 0., 0. };
      for(int i = 0; i < 3; ++i)
      {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const double nx = -(y[k] - y[j]), ny = x[k] - x[j];
        gu[0] += z[t[i]][0] * nx / twice_area; gu[1] += z[t[i]][0] * ny / twice_area;
        gv[0] += z[t[i]][1] * nx / twice_area; gv[1] += z[t[i]][1] * ny / twice_area;
      }
      const double rx = -gu[1] - gv[0], ry = gu[0] - gv[1];  // J grad u - grad v
      e += 0.5 * twice_area * (rx * rx + ry * ry);
    }
    return e;
  };
  const double h = 1e-4;
  std::vector<double> gradient(uv.size());
  double largest = 0.;
  for(std::size_t k = 0; k < uv.size(); ++k)
  {
    double g2 = 0.;
    for(int d = 0; d < 2; ++d)
    {
      std::vector<std::array<double, 2> > plus(uv), minus(uv);
      plus[k][d] += h;
      minus[k][d] -= h;
      const double gd = (energy(plus) - energy(minus)) / (2 * h);
      g2 += gd * gd;
    }
    gradient[k] = std::sqrt(g2);
    largest = (std::max)(largest, gradient[k]);
  }
  ASSERT_GT(largest, 0.) << "a curved chart has no conformal map: the pins must carry a force";
  std::size_t not_stationary = 0;
  for(double gk : gradient)
    not_stationary += gk > 1e-6 * largest ? 1 : 0;
  EXPECT_LE(not_stationary, 2u);
  // The map keeps the 3D winding (not the minimizer's mirror image).
  for(const auto& t : c.triangles)
    EXPECT_GT((uv[t[1]][0] - uv[t[0]][0]) * (uv[t[2]][1] - uv[t[0]][1]) -
                (uv[t[1]][1] - uv[t[0]][1]) * (uv[t[2]][0] - uv[t[0]][0]), 0.);
}

TEST(Atlas, PairedSolvesMatchADenseSolveOfTheSameSystem)
{
  // ARAP solves its u and v right-hand sides in one pass over the sparse
  // LDL^T factor (solve_pairs). Checked against a dense Cholesky solve of
  // the same matrix, rebuilt here entry by entry: a symmetric positive
  // definite band (a path's Laplacian with longer links, shifted), so that
  // the factor has fill and every column of L has several entries.
  const int n = 120;
  auto entry = [](int i, int j) {
    if(i == j) return 4.5 + 0.01 * i;
    const int d = std::abs(i - j);
    return d == 1 ? -1. : d == 5 ? -0.75 : d == 17 ? -0.25 : 0.;
  };
  Eigen::SparseMatrix<double> a;
  DS::internal::assemble_upper_triangle(Eigen::Index(n), std::size_t(4 * n), [&](Eigen::Index k, const auto& add) {
    for(int i = 0; i <= int(k); ++i)
      if(entry(i, int(k)) != 0.)
        add(Eigen::Index(i), entry(i, int(k)));
  }, a);
  const DS::internal::Ordered_sparse_ldlt<double> solver(a);
  ASSERT_EQ(solver.info(), Eigen::Success);
  Eigen::MatrixXd dense(n, n), b(n, 2);
  std::vector<std::array<double, 2> > x(n);
  for(int i = 0; i < n; ++i)
  {
    for(int j = 0; j < n; ++j)
      dense(i, j) = entry(i, j);
    x[i] = {{ std::sin(0.3 * i) + 0.5, std::cos(0.7 * i) - 0.25 * i }};
    b(i, 0) = x[i][0];
    b(i, 1) = x[i][1];
  }
  DS::internal::solve_pairs(solver, x);
  const Eigen::MatrixXd expected = dense.llt().solve(b);
  for(int i = 0; i < n; ++i)
    for(int c = 0; c < 2; ++c)
      EXPECT_NEAR(x[i][c], expected(i, c), 1e-10 * (1. + std::abs(expected(i, c)))) << "row " << i << ", column " << c;
}

TEST(Atlas, HermitianSolvesMatchADenseSolveOfTheSameSystem)
{
  // LSCM's complex system is factored by Hermitian_ldlt. Checked against
  // Eigen's dense LDL^T of the same Hermitian positive definite band,
  // rebuilt here entry by entry (complex links of several lengths, so that
  // the factor has fill), and, with a singular matrix, its refusal.
  const int n = 150;
  typedef std::complex<double> Complex;
  auto entry = [](int i, int j) {
    if(i == j) return Complex(5. + 0.02 * i, 0.);
    const int d = std::abs(i - j);
    const Complex upper = d == 1 ? Complex(-1., 0.5) : d == 4 ? Complex(-0.5, -0.75) : d == 13 ? Complex(0.25, 0.25)
                                                                                          : Complex(0., 0.);
    return i < j ? upper : std::conj(upper);
  };
  Eigen::SparseMatrix<Complex> a;
  DS::internal::assemble_upper_triangle(Eigen::Index(n), std::size_t(4 * n), [&](Eigen::Index k, const auto& add) {
    for(int i = 0; i <= int(k); ++i)
      if(entry(i, int(k)) != Complex(0., 0.))
        add(Eigen::Index(i), entry(i, int(k)));
  }, a);
  const DS::internal::Hermitian_ldlt solver(a);
  ASSERT_TRUE(solver.ok());
  Eigen::MatrixXcd dense(n, n);
  Eigen::VectorXcd b(n);
  for(int i = 0; i < n; ++i)
  {
    for(int j = 0; j < n; ++j)
      dense(i, j) = entry(i, j);
    b[i] = Complex(std::sin(0.3 * i) + 0.5, std::cos(0.7 * i) - 0.02 * i);
  }
  Eigen::VectorXcd x = b;
  solver.solve(x);
  const Eigen::VectorXcd expected = dense.ldlt().solve(b);
  for(int i = 0; i < n; ++i)
    EXPECT_NEAR(std::abs(x[i] - expected[i]), 0., 1e-10 * (1. + std::abs(expected[i]))) << "row " << i;

  // [1, 1; 1, 1]: the second pivot is zero.
  Eigen::SparseMatrix<Complex> singular;
  DS::internal::assemble_upper_triangle(Eigen::Index(2), std::size_t(3), [&](Eigen::Index k, const auto& add) {
    for(int i = 0; i <= int(k); ++i)
      add(Eigen::Index(i), Complex(1., 0.));
  }, singular);
  EXPECT_FALSE(DS::internal::Hermitian_ldlt(singular).ok());
}

TEST(Atlas, ChartEdgesListEveryEdgeOnceAroundBothEnds)
{
  // The edge list the LSCM and ARAP matrices are assembled from, checked
  // against the triangles' sides collected here in a std::map: each side
  // maps to the edge joining its two corners, each edge is some side, the
  // chart (a disk) has V - E + F = 1, and every vertex lists each neighbor
  // once, in increasing order, with the edge that joins them.
  Disk_chart p;
  make_planar_chart(p);
  DS::internal::Chart c = whole_chart(p);
  const DS::internal::Chart_geometry g = DS::internal::chart_geometry(p.m, c);
  const DS::internal::Chart_edges& edges = g.edges;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> sides;  // -> how many triangles have it
  for(std::size_t t = 0; t < g.triangles.size(); ++t)
    for(int i = 0; i < 3; ++i)
    {
      const std::size_t a = g.triangles[t][i], b = g.triangles[t][(i + 1) % 3];
      const std::pair<std::size_t, std::size_t> side((std::min)(a, b), (std::max)(a, b));
      ++sides[side];
      const std::array<std::size_t, 2>& ends = edges.ends[edges.of_triangle[t][i]];
      EXPECT_EQ(std::make_pair(ends[0], ends[1]), side);
    }
  ASSERT_EQ(edges.ends.size(), sides.size());
  EXPECT_EQ(long(g.points.size()) - long(edges.ends.size()) + long(g.triangles.size()), 1L);
  std::size_t listed = 0;
  for(std::size_t v = 0; v < g.points.size(); ++v)
    for(std::size_t k = edges.first[v]; k < edges.first[v + 1]; ++k, ++listed)
    {
      const std::size_t w = edges.neighbor[k];
      const std::array<std::size_t, 2>& ends = edges.ends[edges.edge[k]];
      EXPECT_EQ(std::make_pair(ends[0], ends[1]), std::make_pair((std::min)(v, w), (std::max)(v, w)));
      EXPECT_EQ(sides.count(std::make_pair((std::min)(v, w), (std::max)(v, w))), 1u);
      EXPECT_EQ(edges.between(w, v), edges.edge[k]);
      if(k > edges.first[v])
        EXPECT_LT(edges.neighbor[k - 1], w);
    }
  EXPECT_EQ(listed, 2 * sides.size());
  // A border edge is the side of one triangle; the chart's border loop runs
  // along exactly those.
  const std::vector<DS::internal::Index> border = DS::internal::chart_border_loop(c);
  std::size_t border_sides = 0;
  for(const auto& side : sides)
    border_sides += side.second == 1 ? 1 : 0;
  EXPECT_EQ(border_sides, border.size());
  for(std::size_t k = 0; k < border.size(); ++k)
  {
    const std::size_t e = edges.between(border[k], border[(k + 1) % border.size()]);
    ASSERT_NE(e, DS::internal::Chart_edges::none);
    EXPECT_EQ(sides[std::make_pair(edges.ends[e][0], edges.ends[e][1])], 1u);
  }
}

TEST(Atlas, TwoChartMapsGlueIntoTheMapOfTheirUnion)
{
  // Two halves of a planar chart, each laid out by its own similarity (other
  // rotation, scale and place): glued, they give one similarity of the
  // whole, and ARAP from the glued map keeps it.
  Disk_chart p;
  make_planar_chart(p);
  std::vector<DS::internal::Index> left, right, all;
  for(DS::internal::Index f = 0; f < p.m.number_of_faces(); ++f)
  {
    double x = 0;
    for(int i = 0; i < 3; ++i)
      x += p.m.points[p.m.corners[f][i]][0];
    (x < 0 ? left : right).push_back(f);
    all.push_back(f);
  }
  auto laid_out = [&](const std::vector<DS::internal::Index>& faces, double angle, double scale, double dx, double dy) {
    DS::internal::Chart c = DS::internal::make_chart(p.m, faces);
    c.uv.clear();
    for(DS::internal::Index v : c.vertices)
    {
      const auto& q = p.m.points[v];
      c.uv.push_back({{ scale * (std::cos(angle) * q[0] - std::sin(angle) * q[1]) + dx,
                        scale * (std::sin(angle) * q[0] + std::cos(angle) * q[1]) + dy }});
    }
    return c;
  };
  const DS::internal::Chart a = laid_out(left, 0.3, 2., 5., 1.);
  const DS::internal::Chart b = laid_out(right, -1.1, 0.5, -3., 2.);
  DS::internal::Chart u = DS::internal::make_chart(p.m, all);
  const std::vector<std::array<double, 2> > glued = DS::internal::glue_chart_maps(a, b, u);
  ASSERT_EQ(glued.size(), u.vertices.size());
  EXPECT_EQ(similarity_problem(p.m, u, glued, 1e-9), "");
  ASSERT_EQ(DS::internal::built_in_chart_method(DS::Parameterization_method::ARAP).parameterize_from_map(p.m, u, glued,
                                                                                                        nullptr),
            "");
  EXPECT_EQ(similarity_problem(p.m, u, u.uv, 1e-6), "");

  // Charts that share no vertex have no glued map.
  const DS::internal::Chart lone = laid_out(std::vector<DS::internal::Index>(1, left.front()), 0., 1., 0., 0.);
  const DS::internal::Chart far = laid_out(std::vector<DS::internal::Index>(1, right.back()), 0., 1., 0., 0.);
  EXPECT_TRUE(DS::internal::glue_chart_maps(lone, far, u).empty());
}
