// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the Google Benchmark programs of this folder share: the subdivided
// copies of the base mesh (elephant.off by default), built once each and
// kept for the whole run, the command-line options --mesh and --max_level,
// and the "min" statistic.
//
// Level L is the base mesh after L Loop subdivision steps, so it has 4^L
// times as many faces (the base mesh being closed). Level L is built from
// level L-1 on first use.

#ifndef DISK_SEGMENTATION_BENCHMARK_MESHES_H
#define DISK_SEGMENTATION_BENCHMARK_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#ifndef DISK_SEGMENTATION_BENCHMARK_DATA_DIR
#define DISK_SEGMENTATION_BENCHMARK_DATA_DIR "."
#endif

namespace Disk_segmentation_benchmark {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

// The base mesh; --mesh=FILE replaces it.
inline std::string base_mesh_file = std::string(DISK_SEGMENTATION_BENCHMARK_DATA_DIR) + "/elephant.off";

// Writable property map face -> std::size_t stored in `labels` (by face index).
typedef boost::iterator_property_map<std::vector<std::size_t>::iterator,
                                     boost::property_map<Mesh, boost::face_index_t>::const_type>
  Patch_map;

inline Patch_map patch_map(const Mesh& mesh, std::vector<std::size_t>& labels)
{
  return Patch_map(labels.begin(), get(boost::face_index, mesh));
}

// One subdivision level of the base mesh.
struct Mesh_level
{
  Mesh mesh;
  std::size_t faces = 0;
};

inline Mesh read_base_mesh()
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(base_mesh_file, mesh) || is_empty(mesh) || !CGAL::is_triangle_mesh(mesh))
    throw std::runtime_error("cannot read a triangle mesh from " + base_mesh_file);
  return mesh;
}

// The static cache: level L is level L-1 after one Loop subdivision step.
inline const Mesh_level& mesh_level(int L)
{
  static std::map<int, std::unique_ptr<Mesh_level> > cache;
  std::unique_ptr<Mesh_level>& slot = cache[L];
  if(!slot)
  {
    std::unique_ptr<Mesh_level> data(new Mesh_level);
    if(L == 0)
      data->mesh = read_base_mesh();
    else
    {
      data->mesh = mesh_level(L - 1).mesh;
      CGAL::Subdivision_method_3::Loop_subdivision(data->mesh, CGAL::parameters::number_of_iterations(1));
    }
    if(data->mesh.has_garbage())
      data->mesh.collect_garbage();
    data->faces = num_faces(data->mesh);
    slot = std::move(data);
  }
  return *slot;
}

// A program's per-level data (its `Level` type caches its own results),
// built from mesh_level(L) on first use and kept for the whole run.
template <typename Level>
Level& cached_level(int L)
{
  static std::map<int, std::unique_ptr<Level> > cache;
  std::unique_ptr<Level>& slot = cache[L];
  if(!slot)
    slot.reset(new Level(mesh_level(L)));
  return *slot;
}

// The fastest repetition, reported next to the mean/median/stddev/cv
// aggregates when --benchmark_repetitions is above 1.
inline double minimum(const std::vector<double>& v)
{
  return v.empty() ? 0. : *std::min_element(v.begin(), v.end());
}

// Removes "--name=value" from argv and returns value ("" when absent).
inline std::string take_option(int& argc, char** argv, const std::string& name)
{
  const std::string prefix = "--" + name + "=";
  std::string value;
  int out = 1;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(arg.compare(0, prefix.size(), prefix) == 0)
      value = arg.substr(prefix.size());
    else
      argv[out++] = argv[i];
  }
  argc = out;
  return value;
}

// Reads --mesh and --max_level (to be called after benchmark::Initialize),
// loads the base mesh and returns the (level, faces) pairs to register.
// Face counts name the benchmarks; a closed triangle mesh has exactly four
// times as many faces after each Loop step. Returns false, after a message
// on std::cerr, on an unknown argument or an unreadable mesh.
inline bool mesh_sizes(int& argc, char** argv, const std::string& program,
                       std::vector<std::pair<int, std::size_t> >& sizes)
{
  const std::string mesh_option = take_option(argc, argv, "mesh");
  const std::string level_option = take_option(argc, argv, "max_level");
  if(benchmark::ReportUnrecognizedArguments(argc, argv))
    return false;
  if(!mesh_option.empty())
    base_mesh_file = mesh_option;
  const int max_level = level_option.empty() ? 4 : std::atoi(level_option.c_str());

  std::size_t base_faces = 0;
  try
  {
    base_faces = mesh_level(0).faces;
  }
  catch(const std::exception& e)
  {
    std::cerr << program << ": " << e.what() << std::endl;
    return false;
  }

  sizes.clear();
  for(int L = 0; L <= max_level; ++L)
    sizes.push_back(std::make_pair(L, base_faces << (2 * L)));
  return true;
}

} // namespace Disk_segmentation_benchmark

#endif // DISK_SEGMENTATION_BENCHMARK_MESHES_H
