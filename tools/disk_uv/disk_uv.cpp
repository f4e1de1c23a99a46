// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// disk_uv: UV atlas of a triangle mesh through a segmentation into
// topological disks (Maggioli & Melzi, EG 2025).
//
//   disk_uv INPUT [-o OUT.obj] [--glb OUT.glb] [--atlas-png OUT.png]
//           [--report OUT.json] [--patch-ids FILE] [--colored FILE.ply]
//           [--method arap|conformal|lscm|mvc|tutte] [--packer tight|grid]
//           [--resolution 1024|WxH] [--padding 2] [-n 10] [-k 5]
//           [--threshold 0.7624] [--max-distortion 1] [--max-chart-faces 131072]
//           [--threads 0] [--repair] [--triangulate] [--allow-special-input]
//           [--no-fallback] [--quiet]
//
// Inputs are used as they are (a pinched vertex, whose faces meet in
// several fans, is kept: the charts cut the mesh there): a non-manifold edge,
// inconsistently oriented or duplicated faces are rejected with a message
// naming the first bad element, unless --repair (CGAL's polygon soup repair
// and orientation) and --triangulate (polygons to triangles) are given;
// outputs then follow the repaired mesh's face order.
//
// Prints a one-line summary; on any error prints one line on stderr and
// exits with status 1 (2 for bad command-line usage). Output paths are all
// checked before any work, and the outputs replace their files only once
// all were written (output_files.h): a failed run changes no file.

#include <CGAL/Disk_segmentation/IO/Atlas_options.h>
#include <CGAL/Disk_segmentation/IO/atlas_report_JSON.h>
#include <CGAL/Disk_segmentation/IO/packing_warnings.h>
#include <CGAL/Disk_segmentation/IO/read_triangle_mesh.h>
#include <CGAL/Disk_segmentation/IO/udim_tiles.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_GLB.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_OBJ.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_PNG.h>
#include "output_files.h"
#include "peak_memory.h"
#include "stop_signals.h"

#include <CGAL/Disk_segmentation.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>
#include <string_view>
#include <set>
#include <vector>
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

namespace DS = CGAL::Disk_segmentation;
namespace DS_IO = CGAL::Disk_segmentation::IO;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Face_index, std::size_t> Patch_map;
typedef Mesh::Property_map<Mesh::Halfedge_index, Kernel::Point_2> UV_map;

namespace {

void write_colored_ply(std::ostream& out, const Mesh& mesh, const Patch_map& patch)
{
  out << "ply\nformat ascii 1.0\ncomment patches of disk_uv\n"
      << "element vertex " << mesh.number_of_vertices() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.number_of_faces() << "\nproperty list uchar int vertex_indices\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  out.precision(17);
  for(Mesh::Vertex_index v : mesh.vertices())
    out << mesh.point(v).x() << ' ' << mesh.point(v).y() << ' ' << mesh.point(v).z() << '\n';
  for(Mesh::Face_index f : mesh.faces())
  {
    out << 3;
    for(Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      out << ' ' << std::size_t(v);
    const std::array<unsigned char, 3> c = CGAL::Disk_segmentation::IO::chart_color(patch[f]);
    out << ' ' << int(c[0]) << ' ' << int(c[1]) << ' ' << int(c[2]) << '\n';
  }
}

void write_patch_ids(std::ostream& out, const Mesh& mesh, const Patch_map& patch)
{
  for(Mesh::Face_index f : mesh.faces())
    out << patch[f] << '\n';
}

// --material-ids: one integer per face of the mesh as read, one per line
// (the format of --patch-ids); blank lines and `#` comments are skipped.
std::vector<std::int64_t> read_material_ids(const std::string& path, std::size_t faces, bool allow_special_input)
{
  std::string bytes;
  try
  {
    bytes = DS_IO::internal::read_input_file(path, allow_special_input, std::uint64_t(1) << 32);
  }
  catch(const DS_IO::File_error& e)
  {
    throw DS_IO::File_error(std::string("--material-ids: ") + e.what());
  }
  // An editor's UTF-8 byte-order mark would read as part of the first id.
  if(bytes.compare(0, 3, "\xEF\xBB\xBF") == 0)
    throw disk_uv::Tool_error("--material-ids: '" + path + "' starts with a UTF-8 byte-order mark (BOM); save it "
                              "without one (as plain ASCII)");
  std::vector<std::int64_t> ids;
  ids.reserve(faces);
  std::size_t line_number = 0, begin = 0;
  while(begin < bytes.size())
  {
    std::size_t end = bytes.find('\n', begin);
    if(end == std::string::npos)
      end = bytes.size();
    ++line_number;
    std::string_view line(bytes.data() + begin, end - begin);
    begin = end + 1;
    const std::size_t comment = line.find('#');
    if(comment != std::string_view::npos)
      line = line.substr(0, comment);
    const std::size_t first = line.find_first_not_of(" \t\r");
    if(first == std::string_view::npos)
      continue;
    line = line.substr(first, line.find_last_not_of(" \t\r") + 1 - first);
    std::int64_t id = 0;
    const auto result = std::from_chars(line.data(), line.data() + line.size(), id);
    if(result.ec != std::errc() || result.ptr != line.data() + line.size())
      throw disk_uv::Tool_error("--material-ids: '" + path + "' line " + std::to_string(line_number) + ": '" +
                                std::string(line.substr(0, 40)) + "' is not an integer");
    ids.push_back(id);
  }
  if(ids.size() != faces)
    throw disk_uv::Tool_error("--material-ids: '" + path + "' has " + std::to_string(ids.size()) + " ids for " +
                              std::to_string(faces) + " faces (one per face, in the order of the faces)");
  return ids;
}

// A packing that wastes its texture is said rather than left for the user
// to find in the picture; the wording is the library's, as for Python.
void warn_if_sparse(const DS::Packing_report& packing, std::size_t charts, const std::string& resolution,
                    double padding, double texels_per_unit)
{
  const std::string warning = DS_IO::sparse_packing_warning(packing.efficiency, packing.number_of_pages, charts,
                                                            resolution, padding, texels_per_unit,
                                                            DS_IO::Front_end::command_line);
  if(!warning.empty())
    std::fprintf(stderr, "disk_uv: warning: %s\n", warning.c_str());
}

// Charts below a texel hold no texel of their own: said, as the user may
// not look at every chart (a tiny mesh among large ones, a low density).
void warn_of_charts_below_a_texel(const DS::Packing_report& packing, const std::string& resolution,
                                  double texels_per_unit)
{
  const std::string warning =
    DS_IO::charts_below_a_texel_warning(packing.number_of_charts_below_a_texel, packing.number_of_charts, resolution,
                                        texels_per_unit, DS_IO::Front_end::command_line);
  if(!warning.empty())
    std::fprintf(stderr, "disk_uv: warning: %s\n", warning.c_str());
}

// `path` split before the extension of its file name: "out/atlas.png" ->
// ("out/atlas", ".png"); ("out/atlas", "") without an extension.
std::pair<std::string, std::string> split_extension(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot <= slash + 1) || dot == 0)
    return { path, std::string() };
  return { path.substr(0, dot), path.substr(dot) };
}

// `path` with the UDIM tile before its extension: "atlas.png" ->
// "atlas.1002.png" (the names Blender's UDIM images read).
std::string page_file_name(const std::string& path, unsigned int tile)
{
  const auto parts = split_extension(path);
  return parts.first + "." + std::to_string(tile) + parts.second;
}

// The UDIM tile in `name` if it is the file name of a page picture of the
// picture named `picture` ("atlas.1004.png" for "atlas.png"), else 0.
unsigned int page_picture_tile(const std::string& name, const std::string& picture)
{
  const auto parts = split_extension(picture);
  const std::string& stem = parts.first;
  const std::string& extension = parts.second;
  if(name.size() != stem.size() + 5 + extension.size() || name.compare(0, stem.size(), stem) != 0 ||
     name[stem.size()] != '.' || name.compare(stem.size() + 5, extension.size(), extension) != 0)
    return 0;
  const std::string digits = name.substr(stem.size() + 1, 4);
  if(digits.find_first_not_of("0123456789") != std::string::npos)
    return 0;
  const unsigned int tile = static_cast<unsigned int>(std::stoul(digits));
  return tile >= DS_IO::udim_tile(0) && tile <= DS_IO::udim_tile(DS_IO::max_udim_pages - 1) ? tile : 0;
}

// Page pictures beside --atlas-png that this run did not write (an earlier
// run's, with more pages): a UDIM reader would take them as pages of this
// atlas. Said, not removed: they are the user's files.
void warn_of_other_page_pictures(const std::string& png_path, const std::vector<std::string>& written)
{
  const std::string folder = disk_uv::internal::directory_of(png_path);
  const std::string picture = disk_uv::internal::file_name_of(png_path);
  std::set<std::string> ours;
  for(const std::string& path : written)
    ours.insert(disk_uv::internal::file_name_of(path));
  std::vector<std::string> others;
  if(DIR* dir = ::opendir(folder.c_str()))
  {
    while(const dirent* entry = ::readdir(dir))
      if(page_picture_tile(entry->d_name, picture) != 0 && ours.count(entry->d_name) == 0)
        others.push_back(entry->d_name);
    ::closedir(dir);
  }
  if(others.empty())
    return;
  std::sort(others.begin(), others.end());
  std::string names;
  for(std::size_t i = 0; i < others.size() && i < 3; ++i)
    names += (i ? ", " : "") + others[i];
  if(others.size() > 3)
    names += ", ...";
  std::fprintf(stderr,
               "disk_uv: warning: %zu UDIM page %s not of this atlas %s beside --atlas-png '%s' (%s): a UDIM "
               "reader takes them for pages of this atlas; remove them\n",
               others.size(), others.size() == 1 ? "picture" : "pictures", others.size() == 1 ? "is" : "are",
               png_path.c_str(), names.c_str());
}

void print_pages(const DS::Packing_report& packing, const std::vector<std::string>& pictures, bool quiet)
{
  if(quiet || packing.number_of_pages <= 1)
    return;
  std::printf("%zu pages at %g texels per unit, as UDIM tiles 1001 to %u in the UVs; covered:",
              packing.number_of_pages, packing.texels_per_unit,
              CGAL::Disk_segmentation::IO::udim_tile(packing.number_of_pages - 1));
  for(double e : packing.page_efficiency)
    std::printf(" %.1f%%", 100 * e);
  std::printf("\n");
  for(const std::string& picture : pictures)
    std::printf("  %s\n", picture.c_str());
}

// Several inputs, one atlas (uv_atlas_of_meshes()): the meshes as read,
// their maps and what the library reported.
struct Several_atlas
{
  std::vector<std::string> inputs;
  std::vector<Mesh> meshes;
  std::vector<DS_IO::Read_changes> changes;
  std::vector<Patch_map> patches;
  std::vector<UV_map> uvs;
  DS::Multi_mesh_atlas_report report;
  double read_seconds = 0;
};

template <typename NamedParameters>
Several_atlas atlas_of_several(const std::vector<std::string>& inputs, const DS_IO::Read_options& read_options,
                               const NamedParameters& np)
{
  Several_atlas s;
  s.inputs = inputs;
  s.meshes.resize(inputs.size());
  CGAL::Real_timer timer;
  timer.start();
  for(std::size_t i = 0; i < inputs.size(); ++i)
  {
    s.changes.push_back(DS_IO::read_triangle_mesh(inputs[i], s.meshes[i], read_options));
    s.patches.push_back(s.meshes[i].add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first);
    s.uvs.push_back(s.meshes[i].add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv").first);
  }
  s.read_seconds = timer.time();
  std::vector<const Mesh*> pointers;
  for(const Mesh& m : s.meshes)
    pointers.push_back(&m);
  try
  {
    s.report = DS::uv_atlas_of_meshes(pointers, s.uvs, s.patches, np);
  }
  catch(const DS::Input_error& e)
  {
    // "mesh #i: ..." names the file the user gave.
    std::string message = e.what();
    for(std::size_t i = 0; i < inputs.size(); ++i)
    {
      const std::string tag = "mesh #" + std::to_string(i) + ": ";
      if(message.compare(0, tag.size(), tag) == 0)
        message = "'" + inputs[i] + "': " + message.substr(tag.size());
    }
    throw DS::Input_error(message);
  }
  return s;
}

// The meshes one after the other in `all`, with their charts and UVs: what
// the writers write.
void combine(const Several_atlas& s, Mesh& all, Patch_map& patch, UV_map& uv)
{
  patch = all.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  uv = all.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  std::vector<const Mesh*> meshes;
  for(const Mesh& m : s.meshes)
    meshes.push_back(&m);
  DS::internal::reserve_for_copies(all, meshes);
  for(std::size_t i = 0; i < s.meshes.size(); ++i)
  {
    std::vector<std::pair<Mesh::Halfedge_index, Mesh::Halfedge_index> > halfedges;
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > faces;
    CGAL::copy_face_graph(s.meshes[i], all,
                          CGAL::parameters::halfedge_to_halfedge_output_iterator(std::back_inserter(halfedges))
                            .face_to_face_output_iterator(std::back_inserter(faces)));
    for(const auto& f : faces)
      patch[f.second] = s.patches[i][f.first];
    for(const auto& h : halfedges)
      if(!s.meshes[i].is_border(h.first))
        uv[h.second] = s.uvs[i][h.first];
  }
}

nlohmann::json several_report_json(const Several_atlas& s, const std::string& method, const std::string& packer)
{
  std::vector<std::size_t> vertices;
  for(const Mesh& m : s.meshes)
    vertices.push_back(m.number_of_vertices());
  return DS_IO::atlas_of_meshes_report_json(s.inputs, vertices, s.report, method, packer, s.read_seconds, s.changes);
}

void print_several_summary(const Several_atlas& s)
{
  for(std::size_t i = 0; i < s.meshes.size(); ++i)
  {
    const DS::Atlas_report& r = s.report.meshes[i];
    std::printf("%s: %zu faces -> %zu charts (ids %zu to %zu), %zu fallbacks, %zu invalid\n", s.inputs[i].c_str(),
                r.number_of_faces, r.number_of_charts, s.report.first_chart[i], s.report.first_chart[i + 1] - 1,
                r.parameterization.number_of_fallbacks, r.parameterization.number_of_invalid_charts);
  }
  std::printf("%zu meshes -> %zu charts in one atlas, packing %.1f%%; time read %.3f s, pack %.3f s, total %.3f s\n",
              s.meshes.size(), s.report.first_chart.back(), 100 * s.report.packing.efficiency, s.read_seconds,
              s.report.packing_seconds, s.report.total_seconds);
}

bool several_charts_are_valid(const Several_atlas& s)
{
  std::size_t invalid = 0;
  for(const DS::Atlas_report& r : s.report.meshes)
    invalid += r.parameterization.number_of_invalid_charts;
  if(invalid > 0)
    std::cerr << "disk_uv: error: " << invalid << " charts have invalid UVs (run without --no-fallback to repair them)"
              << std::endl;
  return invalid == 0;
}

// CLI11 reads "-1" into an unsigned option as a huge number and saturates
// overflowing ones: counts are checked as text first.
const CLI::Validator non_negative_count(
  [](std::string& text) -> std::string {
    std::uint64_t value = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if(text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
      return "'" + text + "' is not a non-negative integer";
    if(result.ec != std::errc() || value > std::numeric_limits<unsigned int>::max())
      return "'" + text + "' is too large";
    return std::string();
  },
  "COUNT");

const CLI::Validator texture_size(
  [](std::string& text) -> std::string {
    unsigned int width, height;
    return DS_IO::parse_texture_size(text, width, height)
             ? std::string()
             : "'" + text + "' is not a non-negative integer or WIDTHxHEIGHT of them (or is too large)";
  },
  "N|WxH");

// CLI11 reads an empty value into a real option as 0: a real must be
// written out ("inf" for no bound).
const CLI::Validator real_number(
  [](std::string& text) -> std::string {
    if(text.empty())
      return "the value is empty (a number is expected)";
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() ? std::string() : "'" + text + "' is not a number";
  },
  "REAL");

const CLI::Validator non_empty_path(
  [](std::string& text) -> std::string { return text.empty() ? "the file name is empty" : std::string(); },
  "FILE");

// Progress on stderr, once the run has lasted a second, and only on a
// terminal-like stream: a line rewritten in place.
class Progress_display
{
public:
  explicit Progress_display(bool enabled) : enabled_(enabled) { timer_.start(); }
  void operator()(const std::string& stage, std::size_t done, std::size_t total)
  {
    if(!enabled_ || timer_.time() < 1.0)
      return;
    if(stage == last_stage_ && done != total && timer_.time() - last_print_ < 0.2)
      return;
    std::fprintf(stderr, "\r%-18s %zu/%zu   ", stage.c_str(), done, total);
    std::fflush(stderr);
    printed_ = true;
    last_stage_ = stage;
    last_print_ = timer_.time();
  }
  void finish()
  {
    if(printed_)
      std::fprintf(stderr, "\r%40s\r", "");
  }

private:
  bool enabled_;
  bool printed_ = false;
  CGAL::Real_timer timer_;
  std::string last_stage_;
  double last_print_ = 0;
};

// What the command line asks for.
struct Command_line
{
  std::vector<std::string> inputs;
  std::string obj_path, glb_path, png_path, report_path, patch_ids_path, colored_path, material_ids_path;
  DS_IO::Atlas_options options;
  std::string resolution = std::to_string(DS::default_texture_resolution);
  bool no_fallback = false, quiet = false;
  DS_IO::Read_options read_options;

  // Every file the run reads: no output may replace one.
  std::vector<disk_uv::Output_files::Read_file> read_files() const
  {
    std::vector<disk_uv::Output_files::Read_file> files;
    for(const std::string& input : inputs)
      files.push_back({ input, "the input file" });
    if(!material_ids_path.empty())
      files.push_back({ material_ids_path, "the --material-ids file" });
    return files;
  }
};

void add_options(CLI::App& app, Command_line& line)
{
  DS_IO::Atlas_options& options = line.options;
  DS_IO::Read_options& read_options = line.read_options;
  DS::Distortion_bound& bound = options.bound;
  app.add_option("INPUT", line.inputs,
                 "input triangle mesh (.off .obj .ply .stl .ts); several: one atlas for all, each mesh "
                 "segmented alone")->required();
  app.add_option("-o,--obj", line.obj_path, "write the atlas as OBJ (per-corner vt, one group per chart)")->check(non_empty_path);
  app.add_option("--glb", line.glb_path, "write the atlas as binary glTF 2.0 (TEXCOORD_0)")->check(non_empty_path);
  app.add_option("--atlas-png", line.png_path, "draw the atlas layout (flipped triangles in red)")->check(non_empty_path);
  app.add_option("--report", line.report_path, "write all statistics as JSON")->check(non_empty_path);
  app.add_option("--patch-ids", line.patch_ids_path, "write one chart id per face, in input face order")->check(non_empty_path);
  app.add_option("--colored", line.colored_path, "write a PLY mesh with one color per chart")->check(non_empty_path);
  app.add_option("--method", options.method, "parameterization: arap, conformal, lscm, mvc or tutte")
    ->capture_default_str();
  app.add_option("--packer", options.packer, "packing: tight (one texel density) or grid (the paper's)")
    ->capture_default_str();
  app.add_option("--resolution", line.resolution,
                 "target texture side in texels, or WIDTHxHEIGHT (e.g. 2048x1024) for a non-square one (tight packer)")
    ->capture_default_str()->check(texture_size);
  app.add_option("--padding", options.padding_in_texels, "gap around charts in texels")->capture_default_str()->check(real_number);
  app.add_option("--texels-per-unit", options.texels_per_unit,
                 "fixed texel density (texels per unit of length, tight packer): the charts fill as many pages of "
                 "--resolution texels as they need, laid out as UDIM tiles (0: the largest density that fits one "
                 "page)")->capture_default_str()->check(real_number);
  app.add_option("--max-pages", options.max_number_of_pages, "most pages --texels-per-unit may fill")
    ->capture_default_str()->check(non_negative_count);
  app.add_option("-n,--seeds", options.number_of_seeds, "number of farthest-point seeds")->capture_default_str()->check(non_negative_count);
  app.add_option("-k,--subsamples", options.number_of_subsamples, "seeds used to re-sample a region that is not a disk")->capture_default_str()->check(non_negative_count);
  app.add_option("--threshold", options.merge_threshold, "merge score threshold (eps_5 = 0.7624 by default)")->capture_default_str()->check(real_number);
  app.add_option("--crease-penalty", options.crease_penalty,
                 "Voronoi distances cross bent edges at 1 + K (1 - cos(dihedral angle)) times their length: "
                 "borders follow creases (0: the paper's geodesic distance)")->capture_default_str()->check(real_number);
  app.add_option("--max-angle-distortion", bound.max_angle_distortion,
                 "largest mean |log(s1/s2)| of a chart (inf: no bound)")->capture_default_str()->check(real_number);
  app.add_option("--max-area-distortion", bound.max_area_distortion,
                 "largest mean |log(s1 s2)| of a chart, scaled to its 3D area (inf: no bound)")->capture_default_str()->check(real_number);
  app.add_option("--max-stretch", bound.max_stretch,
                 "largest s1/s2 of any triangle (inf: no bound)")->capture_default_str()->check(real_number);
  app.add_option("--max-area-scale", bound.max_area_scale,
                 "largest s1 s2 and 1/(s1 s2) of any triangle (inf: no bound)")->capture_default_str()->check(real_number);
  app.add_option("--max-stretch-p95", bound.max_stretch_p95,
                 "largest 95th percentile of s1/s2 over a chart's triangles (inf: no bound)")->capture_default_str()->check(real_number);
  app.add_option("--min-convexity", bound.min_convexity,
                 "smallest UV area / UV convex hull area of a chart holding 3% of the mesh's area or more, "
                 "0.8 times it for smaller charts (0: no bound; packs tighter)")->capture_default_str()->check(real_number);
  app.add_flag("--unbounded", options.unbounded,
               "no distortion or convexity bound (with --rough-borders --crease-penalty 0: the paper's charts; "
               "only invalid ones are redone or split)");
  app.add_flag("--rough-borders", options.rough_borders,
               "keep the saw teeth of chart borders (the paper's segmentation; smoothed and straightened by default)");
  app.add_option("--max-chart-faces", options.max_chart_faces,
                 "split larger patches before parameterizing them (bounds memory)")->capture_default_str()->check(non_negative_count);
  app.add_option("--max-charts", options.max_number_of_charts,
                 "chart budget: merge charts past the distortion bound until there are at most this many "
                 "(0: no budget; with several inputs, for each input)")->capture_default_str()->check(non_negative_count);
  app.add_option("--threads", options.number_of_threads, "maximum number of threads (0: all)")->capture_default_str()->check(non_negative_count);
  app.add_flag("--repair", read_options.repair,
               "merge duplicated vertices, drop duplicated and degenerate faces, orient the faces and "
               "cut the mesh at non-manifold edges and vertices");
  app.add_flag("--triangulate", read_options.triangulate,
               "triangulate faces with more than 3 vertices (a polygon split by the charts is then moved whole "
               "into one of them)");
  app.add_option("--material-ids", line.material_ids_path,
                 "one integer per input face (after --triangulate), one per line: faces with different ids never "
                 "share a chart")->check(non_empty_path);
  app.add_flag("--allow-special-input", read_options.allow_special_input,
               "read INPUT even if it is not a regular file (a pipe, a device: read to its end, at most 4 GiB); "
               "without it such an input is refused");
  app.add_flag("--no-fallback", line.no_fallback, "keep invalid charts (and report them) instead of redoing them");
  app.add_flag("-q,--quiet", line.quiet, "no progress display and no summary");
}

// The outputs the command line names, checked before any work and written
// together at the end (output_files.h), and the atlas they are written from.
struct Atlas_outputs
{
  const Command_line& line;
  unsigned int width, height;
  std::vector<disk_uv::Output_files::Read_file> read_files;
  disk_uv::Output_files files;
  std::vector<disk_uv::Output_files::Writer> writers;
  std::vector<std::string> page_pictures;
  std::vector<std::vector<Mesh::Face_index> > page_faces;
  Mesh mesh;
  Patch_map patch;
  UV_map uv;
  // What --report writes: one mesh's report, or the report of several.
  const DS::Atlas_report* report = nullptr;
  const DS_IO::Read_changes* changes = nullptr;
  const nlohmann::json* several_report = nullptr;
  double read_seconds = 0;

  Atlas_outputs(const Command_line& command_line, unsigned int texture_width, unsigned int texture_height)
    : line(command_line), width(texture_width), height(texture_height), read_files(command_line.read_files())
  {
    add("-o", line.obj_path, [this](std::ostream& o) { DS_IO::write_atlas_OBJ(o, mesh, patch, uv); });
    add("--glb", line.glb_path, [this](std::ostream& o) { DS_IO::write_atlas_GLB(o, mesh, patch, uv); });
    // With a fixed density the pages are known at the end: one picture each.
    if(line.options.texels_per_unit == 0)
      add("--atlas-png", line.png_path,
          [this](std::ostream& o) { DS_IO::write_atlas_PNG(o, mesh, patch, uv, width, height); });
    add("--patch-ids", line.patch_ids_path, [this](std::ostream& o) { write_patch_ids(o, mesh, patch); });
    add("--colored", line.colored_path, [this](std::ostream& o) { write_colored_ply(o, mesh, patch); });
    // Killed runs' temporaries of page pictures, whatever their number of pages.
    if(!line.png_path.empty())
    {
      const std::string picture = disk_uv::internal::file_name_of(line.png_path);
      files.remove_stale_temporaries_of(disk_uv::internal::directory_of(line.png_path),
                                        [picture](const std::string& name) {
                                          return page_picture_tile(name, picture) != 0;
                                        });
    }
    add("--report", line.report_path, [this](std::ostream& o) {
      nlohmann::json json = several_report != nullptr
                              ? *several_report
                              : DS_IO::atlas_report_json(line.inputs.front(), mesh.number_of_vertices(), *report,
                                                           line.options.method, line.options.packer, read_seconds,
                                                           *changes);
      // The process's measure, which the library's report leaves out.
      json["peak_rss_mb"] = disk_uv::peak_rss_mb();
      // Several pages: the written UVs hold them as UDIM tiles.
      json["packing"]["udim_tiles"] = json["packing"]["pages"].get<std::size_t>() > 1;
      o << json.dump(2) << '\n';
    });
  }

  void add(const char* option, const std::string& path, disk_uv::Output_files::Writer writer)
  {
    if(path.empty())
      return;
    files.add(option, path, read_files);
    writers.push_back(std::move(writer));
  }

  // Several pages: the UVs written hold them as UDIM tiles, one picture each.
  void add_pages(const DS::Packing_report& packing)
  {
    const std::size_t pages = packing.number_of_pages;
    if(pages > 1)
      DS_IO::move_pages_to_udim_tiles(mesh, patch, uv, packing.page_of_chart);
    const std::string& png_path = line.png_path;
    if(line.options.texels_per_unit == 0 || png_path.empty())
      return;
    struct stat status;
    if(pages > 1 && ::stat(png_path.c_str(), &status) == 0 && !S_ISREG(status.st_mode))
      throw disk_uv::Tool_error("--atlas-png: the " + std::to_string(pages) + " pages need a picture each, named " +
                                "after a regular file's name (atlas.png: atlas.1001.png, ...); '" + png_path +
                                "' is not a regular file");
    // Each picture draws the faces of its page only, not all of them.
    page_faces = DS_IO::faces_of_pages(mesh, patch, packing.page_of_chart);
    for(std::size_t page = 0; page < pages; ++page)
    {
      const unsigned int tile = DS_IO::udim_tile(page);
      page_pictures.push_back(pages == 1 ? png_path : page_file_name(png_path, tile));
      add("--atlas-png", page_pictures.back(), [this, tile, page](std::ostream& o) {
        DS_IO::write_atlas_PNG_of_faces(o, mesh, page_faces[page], patch, uv, width, height, tile);
      });
    }
  }

  void write_all()
  {
    files.write_all(writers);
    if(!line.png_path.empty())
      warn_of_other_page_pictures(line.png_path, page_pictures.empty() ? std::vector<std::string>{ line.png_path }
                                                                        : page_pictures);
  }
};

typedef std::function<bool(const std::string&, std::size_t, std::size_t)> Progress_callback;

// One atlas for several meshes, each segmented alone.
template <typename Settings>
int run_several(const Command_line& line, const Settings& settings, const Progress_callback& keep_going,
                Progress_display& display, Atlas_outputs& out)
{
  const Several_atlas several = atlas_of_several(line.inputs, line.read_options, settings.progress_callback(keep_going));
  display.finish();
  if(disk_uv::Stop_signals::received() != 0)
    throw DS::Cancelled("packing");
  combine(several, out.mesh, out.patch, out.uv);
  out.add_pages(several.report.packing);
  const nlohmann::json json = several_report_json(several, line.options.method, line.options.packer);
  out.several_report = &json;
  out.write_all();
  if(!line.quiet)
    print_several_summary(several);
  print_pages(several.report.packing, out.page_pictures, line.quiet);
  warn_if_sparse(several.report.packing, several.report.first_chart.back(), line.resolution,
                 line.options.padding_in_texels, line.options.texels_per_unit);
  warn_of_charts_below_a_texel(several.report.packing, line.resolution, line.options.texels_per_unit);
  const std::size_t budget = line.options.max_number_of_charts;
  if(budget > 0 && several.report.first_chart.back() > budget)
    std::fprintf(stderr,
                 "disk_uv: warning: %zu charts in all: --max-charts (%zu) is a budget for each of the %zu inputs, "
                 "not for the atlas\n",
                 several.report.first_chart.back(), budget, line.inputs.size());
  return several_charts_are_valid(several) ? 0 : 1;
}

// Reads the one INPUT into `out.mesh`, with the maps uv_atlas() reads
// (each face its own polygon and one material unless the input says
// otherwise: both maps always given, one instantiation of uv_atlas()).
template <typename PolygonMap, typename MaterialMap>
DS_IO::Read_changes read_input(const Command_line& line, Atlas_outputs& out, PolygonMap& polygon, MaterialMap& material)
{
  Mesh& mesh = out.mesh;
  CGAL::Real_timer timer;
  timer.start();
  const DS_IO::Read_changes changes = DS_IO::read_triangle_mesh(line.inputs.front(), mesh, line.read_options);
  out.read_seconds = timer.time();
  out.patch = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  out.uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  polygon = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:polygon", 0).first;
  material = mesh.add_property_map<Mesh::Face_index, std::int64_t>("f:material", 0).first;
  for(Mesh::Face_index f : mesh.faces())
    polygon[f] = changes.polygon_of_face.empty() ? std::size_t(f) : changes.polygon_of_face[std::size_t(f)];
  if(!line.material_ids_path.empty())
  {
    const std::vector<std::int64_t> ids =
      read_material_ids(line.material_ids_path, mesh.number_of_faces(), line.read_options.allow_special_input);
    for(Mesh::Face_index f : mesh.faces())
      material[f] = ids[std::size_t(f)];
  }
  return changes;
}

void print_summary(const Command_line& line, const DS::Atlas_report& report, const DS_IO::Read_changes& changes,
                   double read_seconds)
{
  const char* input = line.inputs.front().c_str();
  if(line.quiet)
    return;
  if(changes.polygons_triangulated || changes.faces_removed || changes.vertices_added || changes.vertices_removed)
    std::printf("%s: input changed: %zu polygons triangulated (%zu as fans), %zu faces removed, "
                "%zu vertices removed, %zu vertices added\n",
                input, changes.polygons_triangulated, changes.fan_triangulations, changes.faces_removed,
                changes.vertices_removed, changes.vertices_added);
  // The mesh keeps them; only the charts split them.
  if(changes.pinched_vertices_split)
    std::printf("%s: %zu pinched vertices split by the charts (the outputs keep the file's vertices)\n", input,
                changes.pinched_vertices_split);
  std::printf("%s: %zu faces -> %zu charts (voronoi %zu, refined %zu), %s, %zu fallbacks, %zu invalid, "
              "packing %.1f%%; time read %.3f s, segment %.3f s, parameterize %.3f s (each face solved %.2f "
              "times), pack %.3f s\n",
              input, report.number_of_faces, report.number_of_charts, report.number_of_voronoi_cells,
              report.number_of_refined_regions, line.options.method.c_str(),
              report.parameterization.number_of_fallbacks, report.parameterization.number_of_invalid_charts,
              100 * report.packing.efficiency, read_seconds,
              report.voronoi_seconds + report.refine_seconds + report.merge_seconds,
              report.parameterization_seconds, report.solves_per_face(), report.packing_seconds);
  if(report.polygons_moved_whole + report.polygons_left_across_charts > 0)
    std::printf("%s: %zu polygons split by the charts moved whole into one of them, %zu left across charts\n",
                input, report.polygons_moved_whole, report.polygons_left_across_charts);
}

// The atlas of the one INPUT.
template <typename Settings>
int run_single(const Command_line& line, const Settings& settings, const Progress_callback& keep_going,
               Progress_display& display, Atlas_outputs& out)
{
  Mesh::Property_map<Mesh::Face_index, std::size_t> polygon;
  Mesh::Property_map<Mesh::Face_index, std::int64_t> material;
  const DS_IO::Read_changes changes = read_input(line, out, polygon, material);
  const DS::Atlas_report report = DS::uv_atlas(
    out.mesh, out.uv,
    settings.face_patch_map(out.patch).face_polygon_map(polygon).face_material_map(material)
      .progress_callback(keep_going));
  display.finish();
  // From here the writing's own handler (output_files.h) takes over: a
  // signal removes the temporaries and ends the run.
  if(disk_uv::Stop_signals::received() != 0)
    throw DS::Cancelled("packing");

  out.report = &report;
  out.changes = &changes;
  out.add_pages(report.packing);
  out.write_all();

  print_summary(line, report, changes, out.read_seconds);
  print_pages(report.packing, out.page_pictures, line.quiet);
  const std::size_t max_charts = line.options.max_number_of_charts;
  warn_if_sparse(report.packing, report.number_of_charts, line.resolution, line.options.padding_in_texels,
                 line.options.texels_per_unit);
  warn_of_charts_below_a_texel(report.packing, line.resolution, line.options.texels_per_unit);
  if(!report.parameterization.chart_budget_met)
    std::cerr << "disk_uv: warning: " << report.number_of_charts << " charts, over --max-charts (" << max_charts
              << "): no two adjacent charts unite into one disk with a valid map" << std::endl;
  else if(!line.quiet && report.parameterization.charts_before_budget > 0)
    std::printf("%s: %zu charts met the distortion bound; merged past it to --max-charts (%zu)\n",
                line.inputs.front().c_str(), report.parameterization.charts_before_budget, max_charts);
  // With the fallback off, invalid charts are a failure the caller must see.
  if(report.parameterization.number_of_invalid_charts > 0)
  {
    std::cerr << "disk_uv: error: " << report.parameterization.number_of_invalid_charts
              << " charts have invalid UVs (run without --no-fallback to repair them)" << std::endl;
    return 1;
  }
  return 0;
}

// The library's parameters for what the command line asks, every option
// checked before any file is read or written: a bad value, or options that
// no input could make work together, is a usage error (exit status 2).
auto checked_settings(Command_line& line)
{
  DS_IO::Atlas_options& options = line.options;
  DS_IO::parse_texture_size(line.resolution, options.texture_width, options.texture_height);
  for(unsigned int side : { options.texture_width, options.texture_height })
    if(!line.png_path.empty() && (side == 0 || side > DS_IO::max_atlas_png_resolution))
      throw disk_uv::Usage_error("--atlas-png needs --resolution between 1 and " +
                                 std::to_string(DS_IO::max_atlas_png_resolution) + ", not " + std::to_string(side));
  if(!line.material_ids_path.empty() && line.inputs.size() > 1)
    throw disk_uv::Usage_error("--material-ids takes one INPUT, not " + std::to_string(line.inputs.size()));
  options.use_fallback = !line.no_fallback;
  try
  {
    // Before the library's own check, to name the user's --resolution; an unknown packer is named first.
    if(options.texture_width != options.texture_height &&
       DS_IO::packing_method_from_string(options.packer) != DS::Packing_method::TIGHT)
      throw disk_uv::Usage_error("--resolution " + line.resolution + " is not square: the grid packer's cells are "
                                 "square (use --packer tight)");
    return DS_IO::atlas_parameters(options);
  }
  catch(const DS::Input_error& e)
  {
    throw disk_uv::Usage_error(DS_IO::in_user_terms(e.what(), DS_IO::Front_end::command_line));
  }
}

int run(Command_line& line, Progress_display& display)
{
  const auto settings = checked_settings(line);
  Atlas_outputs out(line, line.options.texture_width, line.options.texture_height);
  const Progress_callback keep_going([&display](const std::string& s, std::size_t d, std::size_t t) {
    display(s, d, t);
    return disk_uv::Stop_signals::received() == 0;
  });
  return line.inputs.size() > 1 ? run_several(line, settings, keep_going, display, out)
                                 : run_single(line, settings, keep_going, display, out);
}

} // namespace

int main(int argc, char** argv)
{
  disk_uv::Stop_signals::install();
  CLI::App app{"disk_uv: UV atlas of a triangle mesh through a segmentation into topological disks"};
  Command_line line;
  add_options(app, line);
  try
  {
    app.parse(argc, argv);
  }
  catch(const CLI::ParseError& e)
  {
    return app.exit(e) == 0 ? 0 : 2;
  }

  Progress_display display(!line.quiet && ::isatty(2));
  try
  {
    const int status = run(line, display);
    // The outputs were in place before the signal was seen: said, not undone.
    if(disk_uv::Stop_signals::received() != 0)
    {
      std::cerr << "disk_uv: " << disk_uv::Stop_signals::name()
                << " came after the outputs were written; they are complete" << std::endl;
      return disk_uv::Stop_signals::exit_status();
    }
    return status;
  }
  catch(const DS::Cancelled& e)
  {
    display.finish();
    std::cerr << "disk_uv: stopped by " << disk_uv::Stop_signals::name() << " during the " << e.stage()
              << "; no output was written" << std::endl;
    return disk_uv::Stop_signals::exit_status();
  }
  catch(const disk_uv::Stopped_while_writing&)
  {
    std::cerr << "disk_uv: stopped by " << disk_uv::Stop_signals::name()
              << " during the writing of the outputs; no output was written" << std::endl;
    return disk_uv::Stop_signals::exit_status();
  }
  catch(const disk_uv::Usage_error& e)
  {
    display.finish();
    std::cerr << "disk_uv: error: " << e.what() << std::endl;
    return 2;
  }
  catch(const DS::Input_error& e)
  {
    display.finish();
    std::cerr << "disk_uv: error: " << DS_IO::in_user_terms(e.what(), DS_IO::Front_end::command_line)
              << std::endl;
    return 1;
  }
  catch(const std::exception& e)
  {
    display.finish();
    std::cerr << "disk_uv: error: " << e.what() << std::endl;
    return 1;
  }
}
