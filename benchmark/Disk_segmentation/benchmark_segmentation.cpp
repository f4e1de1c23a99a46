// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Google Benchmark of the steps of the disk segmentation, each on its own:
//
//   BM_voronoi/faces:F/seeds:n   voronoi_fps_segmentation() with n seeds
//   BM_refine/faces:F            refine_to_topological_disks() on the Voronoi
//                                output (10 seeds, the default)
//   BM_merge/faces:F             merge_disk_regions() on the refined output
//   BM_segment/faces:F           segment_into_disks() (the three steps)
//
// The meshes are elephant.off (level 0) and its Loop subdivisions (level L
// has 4^L times as many faces, see benchmark_meshes.h). Each level is built
// once, on first use, and kept for the whole run; so are the Voronoi and
// refined labels that feed the refine and merge benchmarks. None of that is
// timed.
//
// Items processed are faces, so the "items_per_second" column reads as
// faces per second. The "patches" counter is the number of regions the step
// returns; "input_patches" the number it received.
//
// Extra command-line options (besides the --benchmark_* ones):
//   --mesh=FILE       base mesh instead of the test data's elephant.off
//   --max_level=L     largest subdivision level to register (default 4)

#include "benchmark_meshes.h"

#include <CGAL/Disk_segmentation/merge_disk_regions.h>
#include <CGAL/Disk_segmentation/refine_to_topological_disks.h>
#include <CGAL/Disk_segmentation/segment_into_disks.h>
#include <CGAL/Disk_segmentation/voronoi_fps_segmentation.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace Disk_segmentation_benchmark;

namespace DS = CGAL::Disk_segmentation;

// One subdivision level of the base mesh (from the shared cache of
// benchmark_meshes.h), with the intermediate results the later steps start
// from (filled on demand).
struct Level
{
  explicit Level(const Mesh_level& base) : mesh(base.mesh), faces(base.faces) {}

  const Mesh& mesh;
  std::size_t faces = 0;

  bool has_voronoi = false;
  std::vector<std::size_t> voronoi_labels;  // indexed by face index
  std::size_t voronoi_patches = 0;

  bool has_refined = false;
  std::vector<std::size_t> refined_labels;
  std::size_t refined_patches = 0;
};

Level& level(int L) { return cached_level<Level>(L); }

const Level& level_with_voronoi(int L)
{
  Level& d = level(L);
  if(!d.has_voronoi)
  {
    d.voronoi_labels.assign(d.faces, 0);
    d.voronoi_patches = DS::voronoi_fps_segmentation(d.mesh, patch_map(d.mesh, d.voronoi_labels),
                                                     DS::parameters::number_of_seeds(10));
    d.has_voronoi = true;
  }
  return d;
}

const Level& level_with_refined(int L)
{
  level_with_voronoi(L);
  Level& d = level(L);
  if(!d.has_refined)
  {
    d.refined_labels = d.voronoi_labels;
    d.refined_patches = DS::refine_to_topological_disks(d.mesh, patch_map(d.mesh, d.refined_labels));
    d.has_refined = true;
  }
  return d;
}

void finish(benchmark::State& state, const Level& d, std::size_t patches, std::size_t input_patches = 0)
{
  state.SetItemsProcessed(static_cast<std::int64_t>(d.faces) * static_cast<std::int64_t>(state.iterations()));
  state.counters["patches"] = static_cast<double>(patches);
  if(input_patches != 0)
    state.counters["input_patches"] = static_cast<double>(input_patches);
}

void BM_voronoi(benchmark::State& state, int L, std::size_t seeds)
{
  const Level& d = level(L);
  std::vector<std::size_t> labels(d.faces, 0);
  const Patch_map pm = patch_map(d.mesh, labels);
  std::size_t patches = 0;
  for(auto _ : state)
  {
    patches = DS::voronoi_fps_segmentation(d.mesh, pm, DS::parameters::number_of_seeds(seeds));
    benchmark::DoNotOptimize(labels.data());
    benchmark::ClobberMemory();
  }
  finish(state, d, patches);
}

void BM_refine(benchmark::State& state, int L)
{
  const Level& d = level_with_voronoi(L);
  std::vector<std::size_t> labels(d.faces, 0);
  const Patch_map pm = patch_map(d.mesh, labels);
  std::size_t patches = 0;
  for(auto _ : state)
  {
    state.PauseTiming();
    std::copy(d.voronoi_labels.begin(), d.voronoi_labels.end(), labels.begin());
    state.ResumeTiming();
    patches = DS::refine_to_topological_disks(d.mesh, pm);
    benchmark::DoNotOptimize(labels.data());
    benchmark::ClobberMemory();
  }
  finish(state, d, patches, d.voronoi_patches);
}

void BM_merge(benchmark::State& state, int L)
{
  const Level& d = level_with_refined(L);
  std::vector<std::size_t> labels(d.faces, 0);
  const Patch_map pm = patch_map(d.mesh, labels);
  std::size_t patches = 0;
  for(auto _ : state)
  {
    state.PauseTiming();
    std::copy(d.refined_labels.begin(), d.refined_labels.end(), labels.begin());
    state.ResumeTiming();
    patches = DS::merge_disk_regions(d.mesh, pm);
    benchmark::DoNotOptimize(labels.data());
    benchmark::ClobberMemory();
  }
  finish(state, d, patches, d.refined_patches);
}

void BM_segment(benchmark::State& state, int L)
{
  const Level& d = level(L);
  std::vector<std::size_t> labels(d.faces, 0);
  const Patch_map pm = patch_map(d.mesh, labels);
  std::size_t patches = 0;
  for(auto _ : state)
  {
    patches = DS::segment_into_disks(d.mesh, pm);
    benchmark::DoNotOptimize(labels.data());
    benchmark::ClobberMemory();
  }
  finish(state, d, patches);
}

// Small meshes run for a minimum time; the large ones a fixed, small number
// of iterations, so that the whole suite stays within a few minutes on two
// cores.
void apply_run_policy(benchmark::internal::Benchmark* b, std::size_t faces)
{
  b->Unit(benchmark::kMillisecond);
  b->ComputeStatistics("min", minimum);
  if(faces <= 100000)
    b->MinTime(0.25);
  else if(faces <= 400000)
    b->Iterations(3);
  else
    b->Iterations(2);
}

} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);

  std::vector<std::pair<int, std::size_t> > sizes;
  if(!mesh_sizes(argc, argv, "benchmark_segmentation", sizes))
    return 1;

  for(const auto& s : sizes)
    for(std::size_t seeds : { std::size_t(10), std::size_t(100) })
    {
      const std::string name = "BM_voronoi/faces:" + std::to_string(s.second) + "/seeds:" + std::to_string(seeds);
      apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_voronoi, s.first, seeds), s.second);
    }
  for(const auto& s : sizes)
  {
    const std::string name = "BM_refine/faces:" + std::to_string(s.second);
    apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_refine, s.first), s.second);
  }
  for(const auto& s : sizes)
  {
    const std::string name = "BM_merge/faces:" + std::to_string(s.second);
    apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_merge, s.first), s.second);
  }
  for(const auto& s : sizes)
  {
    const std::string name = "BM_segment/faces:" + std::to_string(s.second);
    apply_run_policy(benchmark::RegisterBenchmark(name.c_str(), BM_segment, s.first), s.second);
  }

  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
