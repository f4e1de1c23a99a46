// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Google Benchmark of the inputs that once made the time grow faster than
// the mesh (issue 39): the time per face of a whole atlas, to be read
// against that of a torus of as many faces, measured in the same run.
//
//   BM_atlas/torus:F          a torus of about F faces: the normal time per face
//   BM_atlas/fan:N            an open cone: N slivers around one vertex of
//                             valence N (N faces)
//   BM_atlas/cone:N           a closed cone: two vertices of valence N (2N faces)
//   BM_atlas/tetrahedra:N     N tetrahedra beside a torus of 100k faces
//   BM_pack_pages/pages:N     pack_patches() of N separate triangles at a
//                             density that puts one on each page of 64
//                             texels: N pages (beyond the 999 UDIM tiles the
//                             front ends allow; counter us_per_page)
//   BM_build/ours:N, BM_build/cgal:N
//                             a fan of valence N turned into a Surface_mesh:
//                             the readers' builder and CGAL's
//                             polygon_soup_to_polygon_mesh() (quadratic:
//                             measured up to N = 50k only)
//
// Counters: us_per_face (wall-clock microseconds per face), faces, charts,
// pack_ms (uv_atlas()'s packing time). uv_atlas() runs on one thread, so
// that the ratios do not depend on the machine's cores. Wall-clock times:
// read them as ratios between lines of one run (repetitions: min).

#include <CGAL/Disk_segmentation/IO/internal/Triangle_soup_to_mesh.h>
#include <CGAL/Disk_segmentation/pack_patches.h>
#include <CGAL/Disk_segmentation/uv_atlas.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace {

namespace DS = CGAL::Disk_segmentation;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

struct Soup
{
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > triangles;

  std::size_t add(double x, double y, double z)
  {
    points.emplace_back(x, y, z);
    return points.size() - 1;
  }
};

const double two_pi = 6.283185307179586;

// n slivers around an apex over the unit circle; `closed` adds the fan
// around the circle's center.
Soup cone(std::size_t n, bool closed)
{
  Soup s;
  const std::size_t apex = s.add(0., 0., 0.3);
  for(std::size_t i = 0; i < n; ++i)
    s.add(std::cos(two_pi * double(i) / double(n)), std::sin(two_pi * double(i) / double(n)), 0.);
  for(std::size_t i = 0; i < n; ++i)
    s.triangles.push_back({ apex, 1 + i, 1 + (i + 1) % n });
  if(closed)
  {
    const std::size_t center = s.add(0., 0., 0.);
    for(std::size_t i = 0; i < n; ++i)
      s.triangles.push_back({ center, 1 + (i + 1) % n, 1 + i });
  }
  return s;
}

// A torus of about `faces` triangles (the tube 2.857 times finer around).
void add_torus(Soup& s, std::size_t faces)
{
  const std::size_t minor = (std::max)(std::size_t(3), std::size_t(std::sqrt(double(faces) / (2. * 2.857))));
  const std::size_t major = (std::max)(std::size_t(3), std::size_t(2.857 * double(minor)));
  const std::size_t first = s.points.size();
  for(std::size_t i = 0; i < major; ++i)
    for(std::size_t j = 0; j < minor; ++j)
    {
      const double u = two_pi * double(i) / double(major), v = two_pi * double(j) / double(minor);
      s.add((1. + 0.35 * std::cos(v)) * std::cos(u), (1. + 0.35 * std::cos(v)) * std::sin(u), 0.35 * std::sin(v));
    }
  auto at = [&](std::size_t i, std::size_t j) { return first + (i % major) * minor + j % minor; };
  for(std::size_t i = 0; i < major; ++i)
    for(std::size_t j = 0; j < minor; ++j)
    {
      s.triangles.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      s.triangles.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
}

Soup torus(std::size_t faces)
{
  Soup s;
  add_torus(s, faces);
  return s;
}

// n tetrahedra of side 0.01 on a grid beside a torus of 100k faces.
Soup tetrahedra_beside_a_torus(std::size_t n)
{
  Soup s;
  add_torus(s, 100000);
  const std::size_t side = std::size_t(std::ceil(std::cbrt(double(n))));
  for(std::size_t k = 0; k < n; ++k)
  {
    const double x = 3. + 0.05 * double(k % side), y = 0.05 * double(k / side % side), z = 0.05 * double(k / side / side);
    const std::size_t a = s.add(x, y, z), b = s.add(x + 0.01, y, z), c = s.add(x, y + 0.01, z), d = s.add(x, y, z + 0.01);
    s.triangles.push_back({ a, c, b });
    s.triangles.push_back({ a, b, d });
    s.triangles.push_back({ a, d, c });
    s.triangles.push_back({ b, c, d });
  }
  return s;
}

// Each input built once, on first use.
const Mesh& mesh_of(const std::string& key, const std::function<Soup()>& make)
{
  static std::map<std::string, Mesh> cache;
  auto it = cache.find(key);
  if(it == cache.end())
  {
    const Soup s = make();
    it = cache.emplace(key, Mesh()).first;
    DS::IO::internal::checked_triangle_soup_to_mesh(s.points, s.triangles, it->second);
  }
  return it->second;
}

void BM_atlas(benchmark::State& state, const std::string& key, const std::function<Soup()>& make)
{
  const Mesh* mesh = &mesh_of(key, make);
  std::vector<std::size_t> labels(mesh->number_of_faces());
  std::vector<K::Point_2> uvs(mesh->number_of_halfedges());
  auto patch = boost::make_iterator_property_map(labels.begin(), get(boost::face_index, *mesh));
  auto uv = boost::make_iterator_property_map(uvs.begin(), get(boost::halfedge_index, *mesh));
  DS::Atlas_report report;
  double pack_seconds = 0.;
  for(auto _ : state)
  {
    report = DS::uv_atlas(*mesh, uv, DS::parameters::number_of_threads(1).face_patch_map(patch));
    pack_seconds += report.packing_seconds;
    benchmark::DoNotOptimize(uvs.data());
  }
  const double faces = double(mesh->number_of_faces());
  state.counters["faces"] = faces;
  state.counters["charts"] = double(report.number_of_charts);
  state.counters["us_per_face"] =
    benchmark::Counter(faces * 1e-6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pack_ms"] = benchmark::Counter(1e3 * pack_seconds, benchmark::Counter::kAvgIterations);
}

// N equilateral triangles of side 1 apart from each other, each its own
// chart with its planar coordinates as UVs; 56 texels per unit on pages of
// 64 texels with a texel of padding: one chart a page.
void BM_pack_pages(benchmark::State& state, std::size_t n)
{
  Soup s;
  for(std::size_t k = 0; k < n; ++k)
  {
    const double x = 3. * double(k % 100), y = 3. * double(k / 100);
    const std::size_t a = s.add(x, y, 0.), b = s.add(x + 1., y, 0.), c = s.add(x + 0.5, y + 0.8660254037844386, 0.);
    s.triangles.push_back({ a, b, c });
  }
  Mesh mesh;
  DS::IO::internal::checked_triangle_soup_to_mesh(s.points, s.triangles, mesh);
  std::vector<std::size_t> labels(mesh.number_of_faces());
  for(Mesh::Face_index f : mesh.faces())
    labels[std::size_t(f)] = std::size_t(f);
  std::vector<K::Point_2> uvs(mesh.number_of_halfedges());
  auto patch = boost::make_iterator_property_map(labels.begin(), get(boost::face_index, mesh));
  auto uv = boost::make_iterator_property_map(uvs.begin(), get(boost::halfedge_index, mesh));
  DS::Packing_report report;
  for(auto _ : state)
  {
    state.PauseTiming();
    for(Mesh::Halfedge_index h : mesh.halfedges())
      if(!mesh.is_border(h))
        put(uv, h, K::Point_2(mesh.point(mesh.target(h)).x(), mesh.point(mesh.target(h)).y()));
    state.ResumeTiming();
    report = DS::pack_patches(mesh, patch, uv,
                              DS::parameters::texture_resolution(64u).padding_in_texels(1.).texels_per_unit(56.)
                                .max_number_of_pages(n).number_of_threads(1u));
  }
  state.counters["pages"] = double(report.number_of_pages);
  state.counters["us_per_page"] =
    benchmark::Counter(double(n) * 1e-6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_build(benchmark::State& state, std::size_t valence, bool ours)
{
  const Soup s = cone(valence, false);
  for(auto _ : state)
  {
    Mesh m;
    if(ours)
      DS::IO::internal::checked_triangle_soup_to_mesh(s.points, s.triangles, m);
    else
      CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.triangles, m);
    benchmark::DoNotOptimize(m.number_of_faces());
  }
  state.counters["us_per_face"] = benchmark::Counter(
    double(valence) * 1e-6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

double minimum(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

void register_atlas(const std::string& name, const std::function<Soup()>& make)
{
  benchmark::RegisterBenchmark(("BM_atlas/" + name).c_str(), BM_atlas, name, make)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1)
    ->ComputeStatistics("min", minimum);
}

} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  for(std::size_t faces : { 50000, 100000, 200000, 400000 })
    register_atlas("torus:" + std::to_string(faces), [=] { return torus(faces); });
  for(std::size_t n : { 25000, 50000, 100000, 200000, 400000 })
    register_atlas("fan:" + std::to_string(n), [=] { return cone(n, false); });
  for(std::size_t n : { 25000, 50000, 100000, 200000 })
    register_atlas("cone:" + std::to_string(n), [=] { return cone(n, true); });
  for(std::size_t n : { 1000, 5000, 10000, 20000, 40000 })
    register_atlas("tetrahedra:" + std::to_string(n), [=] { return tetrahedra_beside_a_torus(n); });
  for(std::size_t n : { 1000, 2000, 4000, 6000 })
    benchmark::RegisterBenchmark(("BM_pack_pages/pages:" + std::to_string(n)).c_str(), BM_pack_pages, n)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->ComputeStatistics("min", minimum);
  for(std::size_t n : { 12500, 25000, 50000, 100000, 200000 })
    for(bool ours : { true, false })
    {
      if(!ours && n > 50000)
        continue;
      benchmark::RegisterBenchmark(("BM_build/" + std::string(ours ? "ours:" : "cgal:") + std::to_string(n)).c_str(),
                                   BM_build, n, ours)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->ComputeStatistics("min", minimum);
    }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
