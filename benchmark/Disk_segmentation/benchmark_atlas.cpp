// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Google Benchmark of the UV atlas pipeline, stage by stage and as a whole:
//
//   BM_parameterize/faces:F/threads:T     parameterize_patches() with the
//                                         default method (ARAP) on the
//                                         segment_into_disks() patches;
//                                         T = 1 or all (TBB's choice)
//   BM_parameterize_method/faces:F/method:M
//                                         the same on one thread with method
//                                         M (conformal, lscm, mvc, tutte, arap)
//   BM_parameterize_final_charts/faces:F/threads:T
//                                         parameterize_patches() without a
//                                         bound on the charts the defaults
//                                         end with: each face solved once,
//                                         the least the parameterization of
//                                         today's atlas could cost
//   BM_pack/faces:F/method:M              pack_patches() (M = tight or grid)
//                                         on the ARAP charts
//   BM_uv_atlas/faces:F/threads:T         uv_atlas(): segmentation,
//                                         parameterization and packing
//
// The meshes are those of benchmark_segmentation (see benchmark_meshes.h).
// The segmentation that feeds the parameterization benchmarks and the charts
// that feed the packing benchmarks are computed once per mesh, on first use,
// and are not timed; the patch ids (and for packing, the UVs) are copied
// back in with the timer paused before each iteration.
//
// All times are wall-clock (UseRealTime), so that the threads:all runs show
// their speed-up; every rate below is per wall-clock second. The CPU column
// is the CPU time of the whole process (MeasureProcessCPUTime), all threads
// together.
//
// Counters:
//   items_per_second   faces per second
//   patches            patches given to parameterize_patches()
//   charts             charts produced (patches plus pieces of split patches)
//   charts_per_second  charts per second
//   fallbacks          charts whose requested method was replaced
//   splits             patches split because no method gave a valid chart
//   area_distortion    face-weighted mean of the charts' area distortion
//   largest_chart      share of the faces in the largest chart (the parallel
//                      speed-up cannot exceed its inverse)
//   efficiency         covered fraction of the unit square after packing
//   segment_ms, parameterize_ms, pack_ms
//                      uv_atlas()'s own per-stage times, averaged over the
//                      iterations (segment_ms leaves out building the indexed
//                      mesh, which is counted in the total only)
//
// Extra command-line options (besides the --benchmark_* ones):
//   --mesh=FILE       base mesh instead of the test data's elephant.off
//   --max_level=L     largest subdivision level to register (default 4)

#include "benchmark_meshes.h"

#include <CGAL/Disk_segmentation/pack_patches.h>
#include <CGAL/Disk_segmentation/parameterize_patches.h>
#include <CGAL/Disk_segmentation/segment_into_disks.h>
#include <CGAL/Disk_segmentation/uv_atlas.h>

#include <benchmark/benchmark.h>

#include <boost/property_map/property_map.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

using namespace Disk_segmentation_benchmark;

namespace DS = CGAL::Disk_segmentation;

typedef K::Point_2 Point_2;

// Writable property map halfedge -> Point_2 stored in `uvs` (by halfedge index).
typedef boost::iterator_property_map<std::vector<Point_2>::iterator,
                                     boost::property_map<Mesh, boost::halfedge_index_t>::const_type>
  UV_map;

UV_map uv_map(const Mesh& mesh, std::vector<Point_2>& uvs)
{
  return UV_map(uvs.begin(), get(boost::halfedge_index, mesh));
}

// One subdivision level with the inputs of the stages (filled on demand).
struct Level
{
  explicit Level(const Mesh_level& base)
    : mesh(base.mesh), faces(base.faces), halfedges(num_halfedges(base.mesh))
  {}

  const Mesh& mesh;
  std::size_t faces = 0;
  std::size_t halfedges = 0;

  bool has_segmentation = false;
  std::vector<std::size_t> segment_labels;  // segment_into_disks(), by face index
  std::size_t patches = 0;

  bool has_charts = false;
  std::vector<std::size_t> chart_labels;    // after parameterize_patches() (splits included)
  std::vector<Point_2> chart_uvs;           // ARAP UVs, by halfedge index, not packed
  std::size_t charts = 0;
};

Level& level(int L) { return cached_level<Level>(L); }

const Level& level_with_segmentation(int L)
{
  Level& d = level(L);
  if(!d.has_segmentation)
  {
    d.segment_labels.assign(d.faces, 0);
    d.patches = DS::segment_into_disks(d.mesh, patch_map(d.mesh, d.segment_labels));
    d.has_segmentation = true;
  }
  return d;
}

const Level& level_with_charts(int L)
{
  level_with_segmentation(L);
  Level& d = level(L);
  if(!d.has_charts)
  {
    d.chart_labels = d.segment_labels;
    d.chart_uvs.assign(d.halfedges, Point_2(0, 0));
    const DS::Parameterization_report report =
      DS::parameterize_patches(d.mesh, patch_map(d.mesh, d.chart_labels), uv_map(d.mesh, d.chart_uvs));
    d.charts = report.charts.size();
    d.has_charts = true;
  }
  return d;
}

std::int64_t total(const benchmark::State& state, std::size_t per_iteration)
{
  return static_cast<std::int64_t>(per_iteration) * static_cast<std::int64_t>(state.iterations());
}

void parameterization_counters(benchmark::State& state, const Level& d, const DS::Parameterization_report& r)
{
  state.SetItemsProcessed(total(state, d.faces));
  const double charts = static_cast<double>(r.charts.size());
  state.counters["patches"] = static_cast<double>(d.patches);
  state.counters["charts"] = charts;
  state.counters["charts_per_second"] = benchmark::Counter(charts, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["fallbacks"] = static_cast<double>(r.number_of_fallbacks);
  state.counters["splits"] = static_cast<double>(r.number_of_split_patches);
  state.counters["solves_per_face"] = static_cast<double>(r.solved_faces) / static_cast<double>(d.faces);
  double weighted = 0;
  std::size_t faces = 0, largest = 0;
  for(const DS::Chart_report& c : r.charts)
  {
    weighted += static_cast<double>(c.faces) * c.area_distortion;
    faces += c.faces;
    largest = (std::max)(largest, c.faces);
  }
  state.counters["area_distortion"] = faces == 0 ? 0. : weighted / static_cast<double>(faces);
  state.counters["largest_chart"] = faces == 0 ? 0. : static_cast<double>(largest) / static_cast<double>(faces);
}

// parameterize_patches() with `np`, each iteration from the patch ids
// `initial` (a split patch gets new ids, so every iteration starts again).
template <typename NamedParameters>
void time_parameterization(benchmark::State& state, const Level& d, const std::vector<std::size_t>& initial,
                           const NamedParameters& np)
{
  std::vector<std::size_t> labels(d.faces, 0);
  std::vector<Point_2> uvs(d.halfedges, Point_2(0, 0));
  const Patch_map pm = patch_map(d.mesh, labels);
  const UV_map uvm = uv_map(d.mesh, uvs);
  DS::Parameterization_report report;
  for(auto _ : state)
  {
    state.PauseTiming();
    std::copy(initial.begin(), initial.end(), labels.begin());
    state.ResumeTiming();
    report = DS::parameterize_patches(d.mesh, pm, uvm, np);
    benchmark::DoNotOptimize(uvs.data());
    benchmark::ClobberMemory();
  }
  parameterization_counters(state, d, report);
}

// parameterize_patches() with `method` on `threads` threads (0: all).
void BM_parameterize(benchmark::State& state, int L, unsigned int threads, DS::Parameterization_method method)
{
  const Level& d = level_with_segmentation(L);
  time_parameterization(state, d, d.segment_labels,
                        DS::parameters::number_of_threads(threads).parameterization_method(method));
}

// Every chart of the defaults solved once more, with nothing to test: what
// the descent, merges and reroutes cost is BM_parameterize less this.
void BM_parameterize_final_charts(benchmark::State& state, int L, unsigned int threads)
{
  const Level& d = level_with_charts(L);
  time_parameterization(
    state, d, d.chart_labels,
    DS::parameters::number_of_threads(threads).distortion_bound(DS::Distortion_bound::unbounded()));
  state.counters["patches"] = static_cast<double>(d.charts);
}

void BM_pack(benchmark::State& state, int L, DS::Packing_method method)
{
  const Level& d = level_with_charts(L);
  std::vector<std::size_t> labels = d.chart_labels;  // only read
  std::vector<Point_2> uvs(d.halfedges, Point_2(0, 0));
  const Patch_map pm = patch_map(d.mesh, labels);
  const UV_map uvm = uv_map(d.mesh, uvs);
  DS::Packing_report report;
  for(auto _ : state)
  {
    // Packing moves the charts in place: start every iteration unpacked.
    state.PauseTiming();
    std::copy(d.chart_uvs.begin(), d.chart_uvs.end(), uvs.begin());
    state.ResumeTiming();
    report = DS::pack_patches(d.mesh, pm, uvm, DS::parameters::packing_method(method));
    benchmark::DoNotOptimize(uvs.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(total(state, d.faces));
  state.counters["charts"] = static_cast<double>(report.number_of_charts);
  state.counters["charts_per_second"] =
    benchmark::Counter(static_cast<double>(report.number_of_charts), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["efficiency"] = report.efficiency;
}

void BM_uv_atlas(benchmark::State& state, int L, unsigned int threads)
{
  const Level& d = level(L);
  std::vector<std::size_t> labels(d.faces, 0);
  std::vector<Point_2> uvs(d.halfedges, Point_2(0, 0));
  const Patch_map pm = patch_map(d.mesh, labels);
  const UV_map uvm = uv_map(d.mesh, uvs);
  DS::Atlas_report report;
  double segment_seconds = 0, parameterize_seconds = 0, pack_seconds = 0;
  for(auto _ : state)
  {
    report = DS::uv_atlas(d.mesh, uvm, DS::parameters::number_of_threads(threads).face_patch_map(pm));
    benchmark::DoNotOptimize(uvs.data());
    benchmark::ClobberMemory();
    segment_seconds += report.voronoi_seconds + report.refine_seconds + report.merge_seconds;
    parameterize_seconds += report.parameterization_seconds;
    pack_seconds += report.packing_seconds;
  }
  state.SetItemsProcessed(total(state, d.faces));
  const double charts = static_cast<double>(report.number_of_charts);
  state.counters["charts"] = charts;
  state.counters["charts_per_second"] = benchmark::Counter(charts, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["fallbacks"] = static_cast<double>(report.parameterization.number_of_fallbacks);
  state.counters["splits"] = static_cast<double>(report.parameterization.number_of_split_patches);
  state.counters["solves_per_face"] = report.solves_per_face();
  state.counters["efficiency"] = report.packing.efficiency;
  state.counters["segment_ms"] = benchmark::Counter(1e3 * segment_seconds, benchmark::Counter::kAvgIterations);
  state.counters["parameterize_ms"] =
    benchmark::Counter(1e3 * parameterize_seconds, benchmark::Counter::kAvgIterations);
  state.counters["pack_ms"] = benchmark::Counter(1e3 * pack_seconds, benchmark::Counter::kAvgIterations);
}

// Wall-clock milliseconds (the CPU column is the CPU time of all threads of
// the process, so CPU / Time is the number of cores the run actually got),
// and the fastest repetition as an extra statistic.
// Cheap stages (packing) run like benchmark_segmentation: a minimum time up
// to 89k faces, then 3 and 2 iterations. The parameterization runs up to
// ~100 times longer, so its small meshes get fewer iterations and the
// largest one a single iteration; the whole program then takes a few
// minutes per repetition on two cores.
void apply_run_policy(benchmark::internal::Benchmark* b, std::size_t faces, bool cheap)
{
  b->Unit(benchmark::kMillisecond);
  b->UseRealTime();
  b->MeasureProcessCPUTime();
  b->ComputeStatistics("min", minimum);
  if(cheap)
  {
    if(faces <= 100000)
      b->MinTime(0.25);
    else if(faces <= 400000)
      b->Iterations(3);
    else
      b->Iterations(2);
  }
  else
  {
    if(faces <= 25000)
      b->MinTime(0.25);
    else if(faces <= 100000)
      b->Iterations(3);
    else if(faces <= 400000)
      b->Iterations(2);
    else
      b->Iterations(1);
  }
}

std::string threads_name(unsigned int threads)
{
  return threads == 0 ? std::string("all") : std::to_string(threads);
}

std::string method_name(DS::Packing_method m)
{
  return m == DS::Packing_method::TIGHT ? "tight" : "grid";
}

} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);

  std::vector<std::pair<int, std::size_t> > sizes;
  if(!mesh_sizes(argc, argv, "benchmark_atlas", sizes))
    return 1;

  // What threads:all means on this machine.
#ifdef CGAL_LINKED_WITH_TBB
  benchmark::AddCustomContext("threads_all", std::to_string(tbb::this_task_arena::max_concurrency()));
#else
  benchmark::AddCustomContext("threads_all", "1 (built without TBB)");
#endif
  benchmark::AddCustomContext("hardware_concurrency", std::to_string(std::thread::hardware_concurrency()));

  const unsigned int thread_counts[] = { 1u, 0u };
  const DS::Parameterization_method arap = DS::default_parameterization_method;

  for(const auto& s : sizes)
    for(unsigned int t : thread_counts)
    {
      const std::string name =
        "BM_parameterize/faces:" + std::to_string(s.second) + "/threads:" + threads_name(t);
      apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_parameterize, s.first, t, arap),
                       s.second, false);
    }

  for(const auto& s : sizes)
    for(unsigned int t : thread_counts)
    {
      const std::string name =
        "BM_parameterize_final_charts/faces:" + std::to_string(s.second) + "/threads:" + threads_name(t);
      apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_parameterize_final_charts, s.first, t),
                       s.second, false);
    }

  // The methods side by side on the 89k-face mesh (level 2), one thread.
  const int method_level = 2;
  for(const auto& s : sizes)
  {
    if(s.first != method_level)
      continue;
    for(DS::Parameterization_method m :
        { DS::Parameterization_method::DISCRETE_CONFORMAL, DS::Parameterization_method::LSCM,
          DS::Parameterization_method::MEAN_VALUE, DS::Parameterization_method::TUTTE,
          DS::Parameterization_method::ARAP })
    {
      const std::string name =
        "BM_parameterize_method/faces:" + std::to_string(s.second) + "/method:" + DS::to_string(m);
      apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_parameterize, s.first, 1u, m), s.second, false);
    }
  }

  for(const auto& s : sizes)
  {
    const std::string name = "BM_pack/faces:" + std::to_string(s.second) + "/method:" +
                             method_name(DS::Packing_method::TIGHT);
    apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_pack, s.first, DS::Packing_method::TIGHT),
                     s.second, true);
  }
  for(const auto& s : sizes)
  {
    if(s.first != method_level)
      continue;
    const std::string name = "BM_pack/faces:" + std::to_string(s.second) + "/method:" +
                             method_name(DS::Packing_method::GRID);
    apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_pack, s.first, DS::Packing_method::GRID),
                     s.second, true);
  }

  for(const auto& s : sizes)
    for(unsigned int t : thread_counts)
    {
      const std::string name = "BM_uv_atlas/faces:" + std::to_string(s.second) + "/threads:" + threads_name(t);
      apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_uv_atlas, s.first, t), s.second, false);
    }

  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
