// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quality_table's outputs: the CSV of every case and the Markdown table in
// the paper's layout, from the results alone (no library call).

#ifndef DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_WRITERS_H
#define DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_WRITERS_H

#include "quality_table_support.h"

namespace {

// ---------------------------------------------------------------------------
// Outputs

std::string csv_field(const std::string& s)
{
  if(s.find_first_of(",\"\n") == std::string::npos)
    return s;
  std::string quoted = "\"";
  for(char c : s)
  {
    if(c == '"')
      quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

const std::vector<std::pair<std::string, std::string> >& csv_columns()
{
  // (column, key reported by the child); keys starting with '=' are computed here.
  static const std::vector<std::pair<std::string, std::string> > columns = {
    { "mesh", "=mesh" },
    { "faces", "faces" },
    { "segmentation", "=segmentation" },
    { "method", "=method" },
    { "input_error", "input_error" },
    { "failed", "=failed" },
    { "failure_kind", "failure_kind" },
    { "reason", "reason" },
    { "segments", "segments" },
    { "charts", "charts" },
    { "fallbacks", "fallbacks" },
    { "split_patches", "split_patches" },
    { "invalid_charts", "invalid_charts" },
    { "method_errors", "method_errors" },
    { "solves_per_face", "solves_per_face" },
    { "flipped_faces", "flipped_faces" },
    { "flipped_percent", "flipped_percent" },
    { "degenerate_percent", "degenerate_percent" },
    { "benchmark_area_distortion", "benchmark_area_distortion" },
    { "benchmark_angle_distortion", "benchmark_angle_distortion" },
    { "benchmark_atlas_area_distortion", "benchmark_atlas_area_distortion" },
    { "benchmark_symmetric_dirichlet", "benchmark_symmetric_dirichlet" },
    { "log_area_mean", "log_area_mean" },
    { "log_area_p95", "log_area_p95" },
    { "log_area_max", "log_area_max" },
    { "log_angle_mean", "log_angle_mean" },
    { "log_angle_p95", "log_angle_p95" },
    { "log_angle_max", "log_angle_max" },
    { "log_atlas_area_mean", "log_atlas_area_mean" },
    { "conformal_ratio_p95", "conformal_ratio_p95" },
    { "max_conformal_ratio", "max_conformal_ratio" },
    { "min_area_scale", "min_area_scale" },
    { "max_area_scale", "max_area_scale" },
    { "cut_length", "cut_length" },
    { "packing_efficiency", "packing_efficiency" },
    { "grid_benchmark_atlas_area_distortion", "grid_benchmark_atlas_area_distortion" },
    { "grid_log_atlas_area_mean", "grid_log_atlas_area_mean" },
    { "grid_packing_efficiency", "grid_packing_efficiency" },
    { "texel_overlaps", "texel_overlaps" },
    { "smallest_chart_faces", "smallest_chart_faces" },
    { "single_face_charts", "single_face_charts" },
    { "seconds_segmentation", "seconds_segmentation" },
    { "seconds_parameterization", "seconds_parameterization" },
    { "seconds_packing", "seconds_packing" },
    { "seconds_quality", "seconds_quality" },
    { "seconds_wall", "=seconds_wall" },
  };
  return columns;
}

void write_csv(const fs::path& path, const std::vector<fs::path>& files, const std::vector<Case>& cases,
               const std::vector<Result>& results)
{
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot write " + path.string());
  bool first = true;
  for(const auto& column : csv_columns())
  {
    out << (first ? "" : ",") << column.first;
    first = false;
  }
  out << "\n";
  for(std::size_t i = 0; i < cases.size(); ++i)
  {
    const Case& c = cases[i];
    const Result& r = results[i];
    first = true;
    for(const auto& column : csv_columns())
    {
      std::string value;
      if(column.second == "=mesh")
        value = files[c.mesh].filename().string();
      else if(column.second == "=segmentation")
        value = c.segmentation;
      else if(column.second == "=method")
        value = DS::to_string(c.method);
      else if(column.second == "=failed")
        value = r.failed() ? "1" : "0";
      else if(column.second == "failure_kind" && r.input_error() && !r.has("failure_kind"))
        value = "input error";
      else if(column.second == "reason" && r.input_error() && !r.has("reason"))
        value = r.get("input_error");
      else if(column.second == "=seconds_wall")
        value = format_double(r.wall_seconds);
      else
        value = r.get(column.second);
      out << (first ? "" : ",") << csv_field(value);
      first = false;
    }
    out << "\n";
  }
}

std::string segmentation_title(const std::string& s)
{
  if(s == "components")
    return "Conn. Comp.";
  if(s == "voronoi")
    return "Voronoi";
  if(s == "ours")
    return "Ours";
  if(s == "ours-nosplit")
    return "Ours, no split";
  if(s == "ours-nofallback")
    return "Ours, no fallback";
  return s;
}

std::string method_title(DS::Parameterization_method m)
{
  switch(m)
  {
    case DS::Parameterization_method::DISCRETE_CONFORMAL:
      return "`conformal`: discrete conformal map, border on a circle (the paper's \"Harmonic\")";
    case DS::Parameterization_method::LSCM:
      return "`lscm`: least squares conformal map, free border (the paper's \"Conformal\")";
    case DS::Parameterization_method::ARAP:
      return "`arap`: as-rigid-as-possible from the LSCM map (mean value map if LSCM folds) (the paper's \"ARAP\")";
    case DS::Parameterization_method::MEAN_VALUE:
      return "`mvc`: mean value coordinates, border on a circle (not in the paper)";
    case DS::Parameterization_method::TUTTE:
      return "`tutte`: Tutte's barycentric map, border on a circle (not in the paper)";
    case DS::Parameterization_method::CUSTOM:
      return "`custom`: the caller's parameterizer object";
  }
  return DS::to_string(m);
}

std::string fixed(double x, int digits)
{
  if(std::isnan(x))
    return "–";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", digits, x);
  return buffer;
}

// Means over the successful cases of one (segmentation, method) cell.
struct Cell
{
  std::size_t all = 0, failed = 0, successes = 0;
  std::map<std::string, std::vector<double> > values;  // one per successful mesh
  double mean(const std::string& key) const
  {
    const auto it = values.find(key);
    if(successes == 0 || it == values.end())
      return std::nan("");
    double sum = 0;
    for(double v : it->second)
      sum += v;
    return sum / double(it->second.size());
  }
  // The largest (or, with `smallest`, the smallest) value over the meshes.
  double extreme(const std::string& key, bool smallest = false) const
  {
    const auto it = values.find(key);
    if(successes == 0 || it == values.end() || it->second.empty())
      return std::nan("");
    return smallest ? *std::min_element(it->second.begin(), it->second.end())
                    : *std::max_element(it->second.begin(), it->second.end());
  }
  double median(const std::string& key) const
  {
    const auto it = values.find(key);
    if(successes == 0 || it == values.end())
      return std::nan("");
    std::vector<double> v = it->second;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return (n % 2 == 1) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }
};

Cell cell_of(const std::vector<Case>& cases, const std::vector<Result>& results, const std::string& segmentation,
             DS::Parameterization_method method)
{
  static const std::vector<std::string> keys = {
    "benchmark_area_distortion", "benchmark_angle_distortion", "benchmark_atlas_area_distortion",
    "flipped_percent", "degenerate_percent", "cut_length", "log_area_mean", "log_angle_mean", "log_atlas_area_mean", "charts",
    "seconds_segmentation", "seconds_parameterization", "seconds_packing", "fallbacks", "packing_efficiency",
    "grid_benchmark_atlas_area_distortion", "grid_log_atlas_area_mean", "conformal_ratio_p95",
    "max_conformal_ratio", "min_area_scale", "max_area_scale"
  };
  Cell cell;
  for(std::size_t i = 0; i < cases.size(); ++i)
  {
    if(cases[i].segmentation != segmentation || cases[i].method != method || results[i].input_error())
      continue;
    ++cell.all;
    if(results[i].failed())
    {
      ++cell.failed;
      continue;
    }
    ++cell.successes;
    for(const std::string& key : keys)
    {
      const double v = results[i].number(key);
      if(std::isfinite(v))  // a missing value (e.g. GRID packing failed) is left out
        cell.values[key].push_back(v);
    }
  }
  return cell;
}

// The reason of a failure without its chart numbers, to group failures.
std::string reason_group(const Result& r)
{
  const std::string kind = r.get("failure_kind");
  if(kind == "method error" && r.has("reason_problem"))
    return "method error: " + r.get("reason_problem");
  if(kind == "time-out" || kind == "crash")
  {
    const std::string reason = r.get("reason");
    const std::size_t colon = reason.find(':');
    return reason.substr(0, colon);
  }
  std::string reason = r.get("reason");
  // "non-finite UV at face #123" -> "non-finite UV at face"
  const std::size_t hash = reason.find(" #");
  if(hash != std::string::npos)
    reason.erase(hash);
  return kind + ": " + reason;
}

// The peers' numbers (a CSV with a header line: mesh,tool,faces,unwrap_s,
// charts,log_angle,log_area,p95,cut,uv_bbox,mirrored,valid) beside ours for
// the meshes of this run that it names.
void write_peers_block(std::ostream& out, const Options& o, const std::vector<fs::path>& files,
                       const std::vector<Case>& cases, const std::vector<Result>& results)
{
  if(o.peers_file.empty())
    return;
  std::ifstream in(o.peers_file);
  if(!in)
    throw std::runtime_error("cannot read the peers file " + o.peers_file);
  std::map<std::string, std::vector<std::vector<std::string> > > peers;  // mesh -> rows
  std::string line;
  std::getline(in, line);  // header
  while(std::getline(in, line))
  {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string field;
    while(std::getline(ss, field, ','))
      fields.push_back(field);
    if(fields.size() == 12)
      peers[fields[0]].push_back(fields);
  }
  out << "## Peers\n\n"
         "The numbers of xatlas and Blender's Smart UV Project in `" << fs::path(o.peers_file).filename().string()
      << "` (copied from the project's PEERS.md, measured there with one independent checker on the same "
         "meshes of CGAL's data set), beside this run's for the meshes both have. Ours: UV area / unit square "
         "after packing; peers: UV area / bounding box. Peers' seconds were measured on another run of the "
         "same machine; ours are this run's (segmentation + parameterization + packing). \"valid\" is the "
         "peers' checker's verdict (xatlas mirrors charts; Blender overlaps texels on some meshes); ours are "
         "checked by the test suite.\n\n"
         "| mesh | faces | tool | seconds | charts | log angle | log area | p95 s1/s2 | cut length | UV area | "
         "valid |\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  bool any = false;
  for(std::size_t m = 0; m < files.size(); ++m)
  {
    const auto it = peers.find(files[m].stem().string());
    if(it == peers.end())
      continue;
    any = true;
    for(std::size_t i = 0; i < cases.size(); ++i)
    {
      const Result& r = results[i];
      if(cases[i].mesh != m || r.failed() || cases[i].method != DS::default_parameterization_method ||
         (cases[i].segmentation != "ours" && cases[i].segmentation != "ours-nosplit"))
        continue;
      const double seconds =
        r.number("seconds_segmentation") + r.number("seconds_parameterization") + r.number("seconds_packing");
      out << "| " << it->first << " | " << r.get("faces") << " | disk_uv, " << segmentation_title(cases[i].segmentation)
          << " | " << fixed(seconds, 3) << " | " << r.get("charts") << " | " << fixed(r.number("log_angle_mean"), 3)
          << " | " << fixed(r.number("log_area_mean"), 3) << " | " << fixed(r.number("conformal_ratio_p95"), 2)
          << " | " << fixed(r.number("cut_length"), 1) << " | " << fixed(r.number("packing_efficiency"), 3)
          << " | yes |\n";
    }
    for(const std::vector<std::string>& p : it->second)
      out << "| " << p[0] << " | " << p[2] << " | " << p[1] << " | " << p[3] << " | " << p[4] << " | " << p[5]
          << " | " << p[6] << " | " << p[7] << " | " << p[8] << " | " << p[9] << " | " << p[11] << " |\n";
  }
  if(!any)
    out << "No mesh of this run is in the peers file.\n";
  out << "\n";
}

void write_markdown(const fs::path& path, const Options& o, const std::vector<fs::path>& files,
                    const std::vector<Case>& cases, const std::vector<Result>& results, double total_seconds)
{
  std::ofstream out(path);
  if(!out)
    throw std::runtime_error("cannot write " + path.string());

  // Meshes: faces and input errors, from the first case of each mesh.
  std::vector<std::string> faces(files.size()), input_errors(files.size());
  for(std::size_t i = 0; i < cases.size(); ++i)
  {
    const std::size_t m = cases[i].mesh;
    if(faces[m].empty())
      faces[m] = results[i].get("faces");
    if(input_errors[m].empty() && results[i].input_error())
      input_errors[m] = results[i].get("input_error");
  }
  std::size_t valid = 0;
  for(std::size_t m = 0; m < files.size(); ++m)
    valid += input_errors[m].empty() ? 1 : 0;

  out << "# Atlas quality, in the layout of the paper's Table 1\n\n";
  out << "Generated by `quality_table` (benchmark/Disk_segmentation/quality_table.cpp) on " << files.size()
      << " meshes of `" << o.mesh_dir << "`";
  if(valid != files.size())
    out << " (" << valid << " valid, " << files.size() - valid << " input errors, left out of every figure)";
  out << ". Machine: " << o.machine_note << ". Settings: " << o.jobs << " cases at once, " << o.threads
      << " thread(s) per case, time limit " << format_double(o.time_limit)
      << " s per case (mesh x segmentation x method), " << o.seeds
      << " seeds for `voronoi` and `ours`, TIGHT packing, texture resolution " << o.texture_resolution;
  out << ", `crease_penalty(" << format_double(o.crease_penalty) << ")` for `ours`";
  if(o.crease_penalty == 0)
    out << " (the paper's distance)";
  out << ". Total wall time " << fixed(total_seconds, 0) << " s.\n\n";
  out << "**Distortion variant: the benchmark's** (Shay, Solomon & Stein 2022; see the manual's Quality Metrics and "
         "`Atlas_quality` in include/CGAL/Disk_segmentation/atlas_quality.h): per triangle "
         "with Jacobian singular values s1 >= s2, area dist. = s1 s2 + 1/(s1 s2) - 2 and angle dist. = "
         "s1/s2 + s2/s1 - 2, area-weighted means over the non-flipped, non-degenerate faces. **Area distortion is "
         "chart-normalized**: each chart is scaled so that its UV area equals its 3D area before it is measured "
         "(the atlas-normalized variant is in the second table). Flipped triangles: % of faces with det J < 0. "
         "Cut length: seam length / sqrt(surface area). Failure rate: failed meshes / all meshes (failure: an "
         "exception, a time-out, a crash, a non-finite UV, or, without fallback, a chart whose method itself "
         "failed; flipped triangles are not failures). Every other column is the mean over the meshes that did "
         "not fail, as in the paper, so cells of a block average different subsets of meshes. `log area`/`log "
         "angle`: the log variant (|log s1 s2|, |log s1/s2|, chart-normalized). Degenerate: % of faces whose "
         "UV area is (numerically) zero; like flipped faces they are left out of the distortion means. "
         "Seconds are wall-clock means per stage.\n\n";
  out << "Segmentations: Conn. Comp. = one chart per connected component; Voronoi = geodesic Voronoi cells of "
      << o.seeds << " farthest-point seeds (`voronoi_fps_segmentation` with `crease_penalty(0)`, the paper's "
         "distance; no refinement or merging); both parameterized with `use_fallback(false)`, "
         "`require_disk_patches(false)` and no distortion bound, so non-disk charts are attempted as in the "
         "paper. Ours = `segment_into_disks` and `parameterize_patches` with their defaults: "
         "an invalid chart is redone with mean value coordinates, then Tutte, then split, and a chart that "
         "exceeds the default `Distortion_bound` (mean |log s1/s2| "
      << format_double(DS::Distortion_bound().max_angle_distortion) << ", mean |log s1 s2| "
      << format_double(DS::Distortion_bound().max_area_distortion) << ", s1/s2 "
      << format_double(DS::Distortion_bound().max_stretch) << ", s1 s2 within 1/"
      << format_double(DS::Distortion_bound().max_area_scale) << " to "
      << format_double(DS::Distortion_bound().max_area_scale)
      << ") is replaced by its two children in the merge tree, down to the refined regions, then split by "
         "Voronoi cells (this is not in the paper); "
         "Ours, no split = the same without bound (`Distortion_bound::unbounded()`): the paper's charts (with "
         "`--crease-penalty 0`), invalid ones repaired; Ours, no fallback = the same segmentation with `use_fallback(false)` (no repair, no split)."
         "\n\n";

  const char* header =
    "| segmentation | area dist. | angle dist. | flipped triangles | cut length | failure rate | log area | "
    "log angle | degenerate | charts | seg. s | param. s | pack. s |\n"
    "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(DS::Parameterization_method method : o.methods)
  {
    out << "## " << method_title(method) << "\n\n" << header;
    for(const std::string& segmentation : o.segmentations)
    {
      const Cell c = cell_of(cases, results, segmentation, method);
      const double rate = c.all > 0 ? 100. * double(c.failed) / double(c.all) : std::nan("");
      out << "| " << segmentation_title(segmentation) << " | " << fixed(c.mean("benchmark_area_distortion"), 2)
          << " | " << fixed(c.mean("benchmark_angle_distortion"), 2) << " | "
          << fixed(c.mean("flipped_percent"), 2) << "% | " << fixed(c.mean("cut_length"), 2) << " | "
          << fixed(rate, 1) << "% (" << c.failed << "/" << c.all << ") | " << fixed(c.mean("log_area_mean"), 3)
          << " | " << fixed(c.mean("log_angle_mean"), 3) << " | " << fixed(c.mean("degenerate_percent"), 2)
          << "% | " << fixed(c.mean("charts"), 1) << " | "
          << fixed(c.mean("seconds_segmentation"), 3) << " | " << fixed(c.mean("seconds_parameterization"), 3)
          << " | " << fixed(c.mean("seconds_packing"), 3) << " |\n";
    }
    out << "\n";
  }

  out << "## Atlas-normalized area distortion\n\n"
         "One scale for the whole atlas instead of one per chart, so uneven texel density between charts "
         "counts as distortion. Benchmark variant (log variant in parentheses); means over the same "
         "successful meshes as above. With the default TIGHT packing every chart gets the same texel "
         "density, so this equals the chart-normalized area distortion of the tables above; the GRID "
         "columns measure the same charts after the paper's packer (`Packing_method::GRID`: each chart "
         "scaled to fill an equal square cell).\n\n| segmentation |";
  for(DS::Parameterization_method method : o.methods)
    out << " " << DS::to_string(method) << ", TIGHT | " << DS::to_string(method) << ", GRID |";
  out << "\n|---|";
  for(std::size_t i = 0; i < o.methods.size(); ++i)
    out << "---:|---:|";
  out << "\n";
  for(const std::string& segmentation : o.segmentations)
  {
    out << "| " << segmentation_title(segmentation) << " |";
    for(DS::Parameterization_method method : o.methods)
    {
      const Cell c = cell_of(cases, results, segmentation, method);
      out << " " << fixed(c.mean("benchmark_atlas_area_distortion"), 2) << " ("
          << fixed(c.mean("log_atlas_area_mean"), 3) << ") | "
          << fixed(c.mean("grid_benchmark_atlas_area_distortion"), 2) << " ("
          << fixed(c.mean("grid_log_atlas_area_mean"), 3) << ") |";
    }
    out << "\n";
  }
  out << "\n";

  out << "## Medians over the successful meshes\n\n"
         "The benchmark variant grows like 1/(s1 s2) where a chart is shrunk, so a few meshes with long "
         "charts (limbs mapped to a disk) dominate the means above. Medians over the same meshes, as "
         "area dist. / angle dist. (benchmark variant, chart-normalized), then log area / log angle.\n\n"
         "| segmentation |";
  for(DS::Parameterization_method method : o.methods)
    out << " " << DS::to_string(method) << " |";
  out << "\n|---|";
  for(std::size_t i = 0; i < o.methods.size(); ++i)
    out << "---:|";
  out << "\n";
  for(const std::string& segmentation : o.segmentations)
  {
    out << "| " << segmentation_title(segmentation) << " |";
    for(DS::Parameterization_method method : o.methods)
    {
      const Cell c = cell_of(cases, results, segmentation, method);
      out << " " << fixed(c.median("benchmark_area_distortion"), 2) << " / "
          << fixed(c.median("benchmark_angle_distortion"), 2) << "; " << fixed(c.median("log_area_mean"), 3)
          << " / " << fixed(c.median("log_angle_mean"), 3) << " |";
    }
    out << "\n";
  }
  out << "\n";

  out << "## Tails: the worst triangle of the worst mesh\n\n"
         "Per triangle, chart-normalized: the largest 95th percentile (over a mesh's triangles, unweighted) "
         "of s1/s2, the largest s1/s2, and the smallest and largest s1 s2 over the successful meshes. "
         "A nearly collapsed UV triangle shows here long before it moves a mean.\n\n"
         "| segmentation | method | p95 s1/s2 (worst mesh) | largest s1/s2 | smallest s1 s2 | largest s1 s2 |\n"
         "|---|---|---:|---:|---:|---:|\n";
  for(const std::string& segmentation : o.segmentations)
    for(DS::Parameterization_method method : o.methods)
    {
      const Cell c = cell_of(cases, results, segmentation, method);
      out << "| " << segmentation_title(segmentation) << " | " << DS::to_string(method) << " | "
          << fixed(c.extreme("conformal_ratio_p95"), 3) << " | " << format_double(c.extreme("max_conformal_ratio"))
          << " | " << format_double(c.extreme("min_area_scale", true)) << " | "
          << format_double(c.extreme("max_area_scale")) << " |\n";
    }
  out << "\n";

  write_peers_block(out, o, files, cases, results);

  // Failures, grouped by reason.
  std::map<std::tuple<std::string, std::string, std::string>, std::vector<std::string> > groups;
  for(std::size_t i = 0; i < cases.size(); ++i)
    if(results[i].failed() && !results[i].input_error())
      groups[std::make_tuple(cases[i].segmentation, DS::to_string(cases[i].method), reason_group(results[i]))]
        .push_back(files[cases[i].mesh].stem().string());
  out << "## Failures\n\n";
  if(groups.empty())
    out << "None.\n\n";
  else
  {
    out << "Grouped by reason (the per-mesh CSV has each one in full, with the chart it happened on).\n\n"
           "| segmentation | method | reason | meshes |\n|---|---|---|---|\n";
    for(const std::string& segmentation : o.segmentations)
      for(DS::Parameterization_method method : o.methods)
        for(const auto& g : groups)
        {
          if(std::get<0>(g.first) != segmentation || std::get<1>(g.first) != DS::to_string(method))
            continue;
          std::string reason = std::get<2>(g.first);
          for(char& ch : reason)
            if(ch == '|')
              ch = '/';
          out << "| " << segmentation_title(segmentation) << " | " << std::get<1>(g.first) << " | " << reason
              << " | " << g.second.size() << ": ";
          for(std::size_t k = 0; k < g.second.size(); ++k)
            out << (k ? ", " : "") << g.second[k];
          out << " |\n";
        }
    out << "\n";
  }

  out << "## Meshes\n\n";
  for(std::size_t m = 0; m < files.size(); ++m)
  {
    out << (m ? ", " : "") << files[m].filename().string() << " (";
    if(input_errors[m].empty())
      out << faces[m] << " faces)";
    else
      out << "input error: " << input_errors[m] << ")";
  }
  out << "\n";
}

} // namespace

#endif // DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_WRITERS_H
