// The whole disk_uv pipeline on a mesh file given as bytes: what the
// libFuzzer target (fuzz_disk_uv.cpp) runs, and what the test suite replays
// on the seed corpus and on every input the fuzzer ever crashed on
// (test_fuzz_corpus.cpp).
//
// The format is guessed from the first bytes (as a user's wrong extension
// would not help); the parameters come from a hash of the bytes, so that one
// input always runs the same way. Bad input must end in a File_error or an
// Input_error; anything else escaping is a crash. An accepted mesh must give
// an atlas that the independent checkers of the test suite accept (see
// below for the one check that is replaced), or the process aborts.

#ifndef DISK_SEGMENTATION_FUZZ_PIPELINE_H
#define DISK_SEGMENTATION_FUZZ_PIPELINE_H

#include "../independent_atlas.h"
#include "../independent_topology.h"
#include <CGAL/Disk_segmentation/IO/read_triangle_mesh.h>

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace fuzz_pipeline {

enum class Outcome { REJECTED_FILE, REJECTED_PARAMETERS, ATLAS };

// Stops the process with a message: libFuzzer records the input as a crash.
[[noreturn]] inline void invariant_broken(const std::string& what)
{
  std::fprintf(stderr, "fuzz_pipeline: invariant broken: %s\n", what.c_str());
  std::abort();
}

inline std::string guess_extension(const std::string& bytes)
{
  auto starts_with = [&](const char* prefix) { return bytes.compare(0, std::strlen(prefix), prefix) == 0; };
  if(starts_with("ply"))
    return "ply";
  if(starts_with("solid") || (bytes.size() >= 84 && bytes.find('\n') == std::string::npos))
    return "stl";
  if(starts_with("GOCAD"))
    return "ts";
  if(bytes.find("OFF") != std::string::npos && bytes.find("OFF") < 8)
    return "off";
  return "obj";
}

// Where --repair and --triangulate come from: the hash (as for every other
// parameter), or --triangulate alone, forced (to replay an input that hung
// in the triangulation under whatever its hash draws).
enum class Soup_options { FROM_HASH, TRIANGULATE_ONLY };

inline Outcome run(const std::uint8_t* data, std::size_t size, Soup_options soup_options = Soup_options::FROM_HASH)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  namespace DS = CGAL::Disk_segmentation;

  const std::string bytes(reinterpret_cast<const char*>(data), size);
  std::uint64_t hash = 1469598103934665603ull;  // FNV-1a
  for(unsigned char c : bytes)
    hash = (hash ^ c) * 1099511628211ull;

  CGAL::Disk_segmentation::IO::Read_options options;
  options.repair = soup_options == Soup_options::FROM_HASH && ((hash >> 1) & 1);
  options.triangulate = soup_options == Soup_options::TRIANGULATE_ONLY || ((hash >> 2) & 1);
  Mesh mesh;
  try
  {
    std::vector<K::Point_3> points;
    std::vector<std::vector<std::size_t> > polygons;
    const std::string ext = guess_extension(bytes);
    CGAL::Disk_segmentation::IO::internal::read_polygon_soup_from(bytes, ext, "fuzz input", points, polygons);
    CGAL::Disk_segmentation::IO::internal::prepare_triangle_soup(points, polygons, options, "fuzz input");
    CGAL::Disk_segmentation::IO::internal::checked_triangle_soup_to_mesh(points, polygons, mesh);
  }
  catch(const CGAL::Disk_segmentation::IO::File_error&)
  {
    return Outcome::REJECTED_FILE;
  }

  auto patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv", K::Point_2(0, 0)).first;
  const DS::Parameterization_method methods[] = {
    DS::Parameterization_method::ARAP, DS::Parameterization_method::DISCRETE_CONFORMAL,
    DS::Parameterization_method::LSCM, DS::Parameterization_method::MEAN_VALUE, DS::Parameterization_method::TUTTE };
  const unsigned resolution = 256;
  DS::Atlas_report report;
  try
  {
    report = DS::uv_atlas(
      mesh, uv,
      DS::parameters::number_of_seeds(std::size_t(1 + (hash >> 8) % 12))
        .number_of_subsamples(std::size_t(2 + (hash >> 12) % 5))
        .merge_threshold(double((hash >> 16) % 16) / 8.)
        .parameterization_method(methods[(hash >> 20) % 5])
        .packing_method(((hash >> 24) & 1) ? DS::Packing_method::GRID : DS::Packing_method::TIGHT)
        .max_chart_faces(std::size_t(1) << (2 + (hash >> 28) % 12))
        .texture_resolution(resolution)
        .number_of_threads(1u)
        .face_patch_map(patch));
  }
  catch(const DS::Input_error&)
  {
    // Only an input the reader accepted but the library refuses; both check
    // the same things, so this is a mismatch worth a look, not a crash.
    return Outcome::REJECTED_PARAMETERS;
  }

  if(report.parameterization.number_of_invalid_charts != 0)
    invariant_broken(std::to_string(report.parameterization.number_of_invalid_charts) + " invalid charts");
  const test_support::Partition_report partition = test_support::check_disk_partition(mesh, patch);
  if(!partition.ok)
    invariant_broken("partition: " + partition.problem);
  if(partition.number_of_patches != report.number_of_charts)
    invariant_broken("the report's chart count differs from the patch map's");
  // The checker's `degenerate` count also flags faces whose UV-to-3D area
  // ratio is below 1e-12 of the atlas mean. Fuzzed coordinates make 3D face
  // areas span 1e70 and more, and grid packing gives each chart its own
  // scale, so that ratio says nothing about validity there; every UV
  // triangle must instead turn left exactly (neither flipped nor collinear).
  test_support::Atlas_report atlas = test_support::check_atlas(mesh, patch, uv, resolution);
  atlas.degenerate = 0;
  if(!atlas.ok())
    invariant_broken("atlas: " + atlas.summary());
  for(Mesh::Face_index f : mesh.faces())
  {
    const Mesh::Halfedge_index h = mesh.halfedge(f);
    if(CGAL::orientation(uv[mesh.prev(h)], uv[h], uv[mesh.next(h)]) != CGAL::LEFT_TURN)
      invariant_broken("face " + std::to_string(std::size_t(f)) + " has a flipped or collinear UV triangle");
  }
  return Outcome::ATLAS;
}

} // namespace fuzz_pipeline

#endif // DISK_SEGMENTATION_FUZZ_PIPELINE_H
