// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quality_table: the paper's Table 1 for any folder of meshes.
//
//   quality_table MESH_DIR --out OUT_DIR [--segmentations components,voronoi,ours,ours-nosplit,ours-nofallback]
//                 [--methods conformal,lscm,arap] [--time-limit 60] [--jobs 2] [-n 10]
//
// Every mesh x segmentation x method ("case") runs in its own forked child
// process: segmentation, parameterize_patches(), pack_patches(),
// atlas_quality(). The child streams its results to the parent through a
// pipe, one "key<TAB>value" line at a time, so that what it measured before
// a crash or a time-out is kept. The parent runs up to --jobs children at
// once, kills a child that passes --time-limit seconds, and writes
// OUT_DIR/quality_per_mesh.csv (one row per case, in mesh, segmentation,
// method order whatever --jobs is) and OUT_DIR/quality_table.md (the paper's
// layout; see benchmark/Disk_segmentation/README.md and Atlas_quality).
//
// The parent never calls the library (and so never starts TBB threads),
// which keeps fork() safe: each child starts from a single-threaded process.

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/atlas_quality.h>
#include <CGAL/Disk_segmentation/pack_patches.h>
#include <CGAL/Disk_segmentation/parameterize_patches.h>
#include <CGAL/Disk_segmentation/parameters.h>
#include <CGAL/Disk_segmentation/segment_into_disks.h>
#include <CGAL/Disk_segmentation/voronoi_fps_segmentation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

namespace DS = CGAL::Disk_segmentation;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Property_map<Mesh::Face_index, std::size_t> Patch_map;
typedef Mesh::Property_map<Mesh::Halfedge_index, Kernel::Point_2> UV_map;
typedef std::chrono::steady_clock Clock;

const std::vector<std::string> all_segmentations = { "components", "voronoi", "ours", "ours-nosplit",
                                                      "ours-nofallback" };

// ---------------------------------------------------------------------------
// Small helpers

std::vector<std::string> split_list(const std::string& text)
{
  std::vector<std::string> items;
  std::string item;
  std::istringstream in(text);
  while(std::getline(in, item, ','))
  {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if(!item.empty())
      items.push_back(item);
  }
  return items;
}

std::string lower(std::string s)
{
  for(char& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// One line of text: no tab, carriage return or newline (they separate the
// fields of the child's protocol).
std::string one_line(std::string s)
{
  for(char& c : s)
    if(c == '\n' || c == '\r' || c == '\t')
      c = ' ';
  return s;
}

std::string format_double(double x)
{
  if(std::isnan(x))
    return "nan";
  if(std::isinf(x))
    return x > 0 ? "inf" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.9g", x);
  return buffer;
}

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Writes all of `text` to `fd`, retrying on partial writes and EINTR.
void write_all(int fd, const std::string& text)
{
  std::size_t done = 0;
  while(done < text.size())
  {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if(n < 0)
    {
      if(errno == EINTR)
        continue;
      return;
    }
    done += static_cast<std::size_t>(n);
  }
}

// ---------------------------------------------------------------------------
// The child: one case

// The child's side of the protocol: "\n@@\tkey\tvalue\n". The leading
// newline ends whatever the library may have written to stderr (which goes
// to the same pipe) without a newline; the parent skips empty lines. Each
// line is one write() shorter than PIPE_BUF, so it is never interleaved.
struct Reporter
{
  int fd;
  void operator()(const std::string& key, const std::string& value) const
  {
    std::string line = "\n@@\t" + key + "\t" + one_line(value);
    if(line.size() > 3500)
      line.resize(3500);
    write_all(fd, line + "\n");
  }
  void operator()(const std::string& key, double value) const { (*this)(key, format_double(value)); }
  void operator()(const std::string& key, std::size_t value) const { (*this)(key, std::to_string(value)); }
};

// Checks what the library assumes of its input; returns the problem, or an empty string.
std::string input_problem(const Mesh& mesh)
{
  if(faces(mesh).empty())
    return "no face";
  if(!CGAL::is_triangle_mesh(mesh))
    return "not a triangle mesh";
  if(!CGAL::is_valid_polygon_mesh(mesh))
    return "not a valid polygon mesh";
  // A vertex is non-manifold when the halfedges that point to it form more
  // than one umbrella: the cycle around it then misses some of them. (This
  // is PMP::is_non_manifold_vertex(), in linear time for the whole mesh.)
  std::vector<std::size_t> incoming(num_vertices(mesh), 0);
  for(Mesh::Halfedge_index h : halfedges(mesh))
    ++incoming[std::size_t(target(h, mesh))];
  std::size_t non_manifold = 0;
  for(Mesh::Vertex_index v : vertices(mesh))
  {
    if(mesh.is_isolated(v))
      continue;
    std::size_t around = 0;
    for(Mesh::Halfedge_index h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh))
    {
      CGAL_USE(h);
      ++around;
    }
    if(around != incoming[std::size_t(v)])
      ++non_manifold;
  }
  if(non_manifold > 0)
    return std::to_string(non_manifold) + " non-manifold vertices";
  for(Mesh::Vertex_index v : vertices(mesh))
  {
    const Kernel::Point_3& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return "non-finite coordinate";
  }
  return std::string();
}

struct Case_settings
{
  std::string file;
  std::string segmentation;
  DS::Parameterization_method method;
  std::size_t seeds;
  unsigned int threads;
  unsigned int texture_resolution;
};

template <typename NamedParameters>
DS::Parameterization_report parameterize(const Mesh& mesh, Patch_map patches, UV_map uv, const NamedParameters& np)
{
  return DS::parameterize_patches(mesh, patches, uv, np);
}

// Runs one case and reports it; the first failure reason wins.
void run_case(const Case_settings& s, const Reporter& report)
{
  Mesh mesh;
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_mesh(s.file, mesh);
  }
  catch(const std::exception& e)
  {
    report("input_error", std::string("cannot read: ") + e.what());
    return;
  }
  if(!read)
  {
    report("input_error", "cannot read the file as a polygon mesh");
    return;
  }
  report("faces", static_cast<std::size_t>(num_faces(mesh)));
  const std::string problem = input_problem(mesh);
  if(!problem.empty())
  {
    report("input_error", problem);
    return;
  }

  Patch_map patches = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:patch", 0).first;
  UV_map uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv", Kernel::Point_2(0, 0)).first;
  bool failed = false;
  auto fail = [&](const std::string& kind, const std::string& reason) {
    if(failed)
      return;
    failed = true;
    report("failure_kind", kind);
    report("reason", reason);
  };

  // Segmentation.
  Clock::time_point start = Clock::now();
  std::size_t count = 0;
  DS::Merge_tree tree;
  try
  {
    if(s.segmentation == "components")
      count = PMP::connected_components(mesh, patches);
    else if(s.segmentation == "voronoi")
      count = DS::voronoi_fps_segmentation(mesh, patches, DS::parameters::number_of_seeds(s.seeds));
    else if(s.segmentation == "ours")
      // What uv_atlas() does: smoothed borders, merge tree for the bound.
      count = DS::segment_into_disks(
        mesh, patches, DS::parameters::number_of_seeds(s.seeds).merge_tree(&tree).smooth_borders(true));
    else
      count = DS::segment_into_disks(mesh, patches, DS::parameters::number_of_seeds(s.seeds));
  }
  catch(const std::exception& e)
  {
    report("seconds_segmentation", seconds_since(start));
    fail("exception", std::string("segmentation: ") + e.what());
    return;
  }
  report("seconds_segmentation", seconds_since(start));
  report("segments", count);

  // Parameterization: baselines without fallback and with non-disk charts
  // allowed; ours with the defaults (fallback, and splitting of charts of
  // high area distortion); ours-nosplit with the fallback only (the paper's
  // charts, invalid ones repaired); ours-nofallback with neither.
  start = Clock::now();
  DS::Parameterization_report p;
  try
  {
    const auto np = DS::parameters::parameterization_method(s.method).number_of_threads(s.threads);
    const double inf = std::numeric_limits<double>::infinity();
    if(s.segmentation == "ours")
      p = parameterize(mesh, patches, uv, np.merge_tree(&tree));
    else if(s.segmentation == "ours-nosplit")
      p = parameterize(mesh, patches, uv,
                       np.distortion_bound(DS::Distortion_bound::unbounded())
                         .smooth_borders(false));
    else if(s.segmentation == "ours-nofallback")
      p = parameterize(mesh, patches, uv, np.use_fallback(false).smooth_borders(false));
    else
      p = parameterize(mesh, patches, uv, np.use_fallback(false).require_disk_patches(false));
  }
  catch(const std::exception& e)
  {
    report("seconds_parameterization", seconds_since(start));
    fail("exception", std::string("parameterize_patches: ") + e.what());
    return;
  }
  report("seconds_parameterization", seconds_since(start));
  report("fallbacks", p.number_of_fallbacks);
  report("split_patches", p.number_of_split_patches);
  report("invalid_charts", p.number_of_invalid_charts);
  report("method_errors", p.number_of_method_errors);
  const bool fallback_on = (s.segmentation == "ours" || s.segmentation == "ours-nosplit");
  if(!fallback_on && p.number_of_method_errors > 0)
  {
    for(const DS::Chart_report& c : p.charts)
      if(c.method_error)
      {
        report("reason_problem", c.problem);
        fail("method error", c.problem + " (chart " + std::to_string(c.patch) + " of " +
                                std::to_string(p.charts.size()) + ", " + std::to_string(c.faces) + " faces; " +
                                std::to_string(p.number_of_method_errors) + " charts failed)");
        break;
      }
  }

  // The paper's GRID packing of the same charts, measured apart: TIGHT
  // packing gives every chart the same texel density, so its
  // atlas-normalized distortion equals the chart-normalized one, while GRID
  // scales every chart to its cell. Not timed, not a failure if it throws.
  if(!failed)
  {
    UV_map grid_uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:grid_uv", Kernel::Point_2(0, 0)).first;
    for(Mesh::Halfedge_index h : halfedges(mesh))
      grid_uv[h] = uv[h];
    try
    {
      DS::pack_patches(mesh, patches, grid_uv,
                       DS::parameters::packing_method(DS::Packing_method::GRID).texture_resolution(s.texture_resolution));
      const DS::Atlas_quality g = DS::atlas_quality(mesh, grid_uv, patches, DS::parameters::texture_resolution(0u));
      if(!g.failed)
      {
        report("grid_benchmark_atlas_area_distortion", g.benchmark_atlas_area_distortion);
        report("grid_log_atlas_area_mean", g.atlas_area_distortion.mean);
        report("grid_packing_efficiency", g.packing_efficiency);
      }
    }
    catch(const std::exception& e)
    {
      report("grid_packing_error", e.what());
    }
    mesh.remove_property_map(grid_uv);
  }

  // Packing (needs charts of positive UV area, which a failed chart may not
  // have): on an exception the atlas is measured unpacked.
  start = Clock::now();
  bool packed = false;
  try
  {
    DS::pack_patches(mesh, patches, uv, DS::parameters::texture_resolution(s.texture_resolution));
    packed = true;
  }
  catch(const std::exception& e)
  {
    report("packing_error", e.what());
    fail("exception", std::string("pack_patches: ") + e.what());
  }
  report("seconds_packing", seconds_since(start));

  // Quality.
  start = Clock::now();
  DS::Atlas_quality q;
  try
  {
    q = DS::atlas_quality(mesh, uv, patches, DS::parameters::texture_resolution(packed ? s.texture_resolution : 0u));
  }
  catch(const std::exception& e)
  {
    report("seconds_quality", seconds_since(start));
    fail("exception", std::string("atlas_quality: ") + e.what());
    return;
  }
  report("seconds_quality", seconds_since(start));
  if(q.failed)
  {
    fail("non-finite UV", q.failure_reason);
    return;
  }
  report("charts", q.number_of_charts);
  report("smallest_chart_faces", q.smallest_chart_faces);
  report("single_face_charts", q.single_face_charts);
  report("flipped_faces", q.flipped_faces);
  report("flipped_percent", q.flipped_percent);
  report("degenerate_percent", q.degenerate_percent);
  report("benchmark_area_distortion", q.benchmark_area_distortion);
  report("benchmark_angle_distortion", q.benchmark_angle_distortion);
  report("benchmark_atlas_area_distortion", q.benchmark_atlas_area_distortion);
  report("benchmark_symmetric_dirichlet", q.benchmark_symmetric_dirichlet);
  report("log_area_mean", q.area_distortion.mean);
  report("log_area_p95", q.area_distortion.percentile_95);
  report("log_area_max", q.area_distortion.max);
  report("log_angle_mean", q.angle_distortion.mean);
  report("log_angle_p95", q.angle_distortion.percentile_95);
  report("log_angle_max", q.angle_distortion.max);
  report("log_atlas_area_mean", q.atlas_area_distortion.mean);
  report("conformal_ratio_p95", q.conformal_ratio_p95);
  report("max_conformal_ratio", q.max_conformal_ratio);
  report("min_area_scale", q.min_area_scale);
  report("max_area_scale", q.max_area_scale);
  report("cut_length", q.cut_length);
  report("packing_efficiency", q.packing_efficiency);
  if(packed)
    report("texel_overlaps", q.texel_overlaps);
}

// ---------------------------------------------------------------------------
// The parent: cases, children, results

struct Case
{
  std::size_t mesh = 0;  // index in the sorted file list
  std::string segmentation;
  DS::Parameterization_method method = DS::Parameterization_method::LSCM;
};

struct Result
{
  std::map<std::string, std::string> values;  // what the child reported
  std::string stderr_tail;                    // the child's last non-protocol output
  double wall_seconds = 0;

  bool has(const std::string& key) const { return values.count(key) > 0; }
  std::string get(const std::string& key) const
  {
    const auto it = values.find(key);
    return it == values.end() ? std::string() : it->second;
  }
  double number(const std::string& key) const
  {
    const auto it = values.find(key);
    return it == values.end() ? std::nan("") : std::strtod(it->second.c_str(), nullptr);
  }
  bool input_error() const { return has("input_error"); }
  bool failed() const { return input_error() || has("failure_kind"); }
  // Records a failure found by the parent, keeping an earlier reason first.
  void fail(const std::string& kind, const std::string& reason)
  {
    if(has("failure_kind"))
    {
      values["reason"] += "; then " + reason;
      return;
    }
    values["failure_kind"] = kind;
    values["reason"] = reason;
  }
};

struct Running
{
  std::size_t index = 0;
  pid_t pid = -1;
  int fd = -1;
  bool eof = false;
  Clock::time_point start, deadline;
  std::string buffer;
};

void consume_lines(Running& r, Result& result, bool flush)
{
  std::size_t begin = 0;
  for(;;)
  {
    std::size_t end = r.buffer.find('\n', begin);
    if(end == std::string::npos)
    {
      if(!flush || begin >= r.buffer.size())
        break;
      end = r.buffer.size();
    }
    const std::string line = r.buffer.substr(begin, end - begin);
    begin = (end < r.buffer.size()) ? end + 1 : end;
    if(line.empty())
      continue;
    if(line.compare(0, 3, "@@\t") == 0)
    {
      const std::size_t tab = line.find('\t', 3);
      if(tab != std::string::npos)
        result.values[line.substr(3, tab - 3)] = line.substr(tab + 1);
    }
    else
    {
      result.stderr_tail = one_line(line);
      if(result.stderr_tail.size() > 300)
        result.stderr_tail.resize(300);
    }
  }
  r.buffer.erase(0, begin);
}

std::string signal_name(int sig)
{
  const char* name = ::strsignal(sig);
  return name ? std::string(name) : std::string("?");
}

void finish(Running& r, int status, bool timed_out, double time_limit, Result& result)
{
  consume_lines(r, result, true);
  result.wall_seconds = seconds_since(r.start);
  if(timed_out)
  {
    char text[64];
    std::snprintf(text, sizeof(text), "time-out after %g s", time_limit);
    result.fail("time-out", text);
  }
  else if(WIFSIGNALED(status))
  {
    std::string reason = "crashed (signal " + std::to_string(WTERMSIG(status)) + ", " + signal_name(WTERMSIG(status)) + ")";
    if(!result.stderr_tail.empty())
      reason += ": " + result.stderr_tail;
    result.fail("crash", reason);
  }
  else if(WIFEXITED(status) && (WEXITSTATUS(status) != 0 || !result.has("done")))
  {
    std::string reason = "child exited with status " + std::to_string(WEXITSTATUS(status));
    if(!result.has("done"))
      reason += " before it finished";
    if(!result.stderr_tail.empty())
      reason += ": " + result.stderr_tail;
    result.fail("crash", reason);
  }
  ::close(r.fd);
}

struct Options
{
  std::string mesh_dir, out_dir;
  std::vector<std::string> segmentations;
  std::vector<DS::Parameterization_method> methods;
  double time_limit = 60;
  unsigned int jobs = 2;
  std::size_t seeds = 10;
  unsigned int threads = 1;
  unsigned int texture_resolution = 1024;
  std::string machine_note;
  std::string peers_file;
  bool quiet = false;
};

// Starts the child of `c`; returns false if fork or pipe failed.
bool start_child(const Options& o, const std::vector<fs::path>& files, const std::vector<Case>& cases,
                 std::size_t index, Running& r)
{
  int fds[2];
  if(::pipe(fds) != 0)
    return false;
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if(pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    return false;
  }
  if(pid == 0)
  {
    // Child: stdout and stderr into the pipe, stdin from /dev/null.
    ::close(fds[0]);
    ::dup2(fds[1], STDOUT_FILENO);
    ::dup2(fds[1], STDERR_FILENO);
    const int null = ::open("/dev/null", O_RDONLY);
    if(null >= 0)
      ::dup2(null, STDIN_FILENO);
    const Reporter report{ fds[1] };
    const Case& c = cases[index];
    Case_settings s{ files[c.mesh].string(), c.segmentation, c.method, o.seeds, o.threads, o.texture_resolution };
    try
    {
      run_case(s, report);
    }
    catch(const std::exception& e)
    {
      report("failure_kind", "exception");
      report("reason", std::string("uncaught: ") + e.what());
    }
    catch(...)
    {
      report("failure_kind", "exception");
      report("reason", "uncaught unknown exception");
    }
    report("done", "1");
    std::cout.flush();
    std::cerr.flush();
    ::_exit(0);
  }
  ::close(fds[1]);
  r.index = index;
  r.pid = pid;
  r.fd = fds[0];
  r.eof = false;
  r.buffer.clear();
  r.start = Clock::now();
  r.deadline = r.start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.time_limit));
  return true;
}

void run_all(const Options& o, const std::vector<fs::path>& files, const std::vector<Case>& cases,
             std::vector<Result>& results)
{
  results.assign(cases.size(), Result());
  std::vector<Running> running;
  std::size_t next = 0, finished = 0;
  auto progress = [&](std::size_t index) {
    ++finished;
    if(o.quiet)
      return;
    const Case& c = cases[index];
    const Result& r = results[index];
    std::cerr << "[" << finished << "/" << cases.size() << "] " << files[c.mesh].filename().string() << " "
              << c.segmentation << " " << DS::to_string(c.method) << ": ";
    if(r.input_error())
      std::cerr << "input error (" << r.get("input_error") << ")";
    else if(r.failed())
      std::cerr << "FAILED (" << r.get("reason") << ")";
    else
      std::cerr << "ok, " << r.get("charts") << " charts, " << r.get("flipped_percent") << "% flipped";
    std::cerr << ", " << format_double(std::round(r.wall_seconds * 100) / 100) << " s" << std::endl;
  };

  while(next < cases.size() || !running.empty())
  {
    while(running.size() < o.jobs && next < cases.size())
    {
      Running r;
      if(!start_child(o, files, cases, next, r))
      {
        if(running.empty())
        {
          results[next].fail("exception", std::string("cannot start a child process: ") + std::strerror(errno));
          progress(next);
          ++next;
          continue;
        }
        break;  // retry once a running child ends
      }
      running.push_back(r);
      ++next;
    }

    // Wait for output, or for the nearest deadline.
    const Clock::time_point now = Clock::now();
    Clock::time_point nearest = Clock::time_point::max();
    std::vector<pollfd> polled;
    bool pending_exit = false;
    for(const Running& r : running)
    {
      nearest = (std::min)(nearest, r.deadline);
      if(r.eof)
        pending_exit = true;
      else
        polled.push_back(pollfd{ r.fd, POLLIN, 0 });
    }
    long timeout_ms = nearest > now
      ? static_cast<long>(std::chrono::duration_cast<std::chrono::milliseconds>(nearest - now).count()) + 1
      : 0;
    if(pending_exit)
      timeout_ms = (std::min)(timeout_ms, 10L);
    timeout_ms = (std::min)(timeout_ms, 1000L);
    if(!polled.empty())
    {
      if(::poll(polled.data(), polled.size(), static_cast<int>(timeout_ms)) < 0 && errno != EINTR)
        throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    }
    else if(timeout_ms > 0)
      ::usleep(static_cast<useconds_t>(timeout_ms * 1000));

    for(const pollfd& p : polled)
    {
      if(!(p.revents & (POLLIN | POLLHUP | POLLERR)))
        continue;
      for(Running& r : running)
        if(r.fd == p.fd)
        {
          char chunk[65536];
          const ssize_t n = ::read(r.fd, chunk, sizeof(chunk));
          if(n > 0)
          {
            r.buffer.append(chunk, static_cast<std::size_t>(n));
            consume_lines(r, results[r.index], false);
          }
          else if(n == 0 || (errno != EINTR && errno != EAGAIN))
            r.eof = true;
        }
    }

    // Children that ended, or ran out of time.
    for(std::size_t i = 0; i < running.size();)
    {
      Running& r = running[i];
      int status = 0;
      bool done = false, timed_out = false;
      if(r.eof)
      {
        const pid_t w = ::waitpid(r.pid, &status, WNOHANG);
        done = (w == r.pid);
      }
      if(!done && Clock::now() >= r.deadline)
      {
        ::kill(r.pid, SIGKILL);
        ::waitpid(r.pid, &status, 0);
        done = true;
        timed_out = true;
      }
      if(done)
      {
        // Whatever the child wrote before it ended.
        char chunk[65536];
        ssize_t n;
        const int flags = ::fcntl(r.fd, F_GETFL);
        ::fcntl(r.fd, F_SETFL, flags | O_NONBLOCK);
        while((n = ::read(r.fd, chunk, sizeof(chunk))) > 0)
          r.buffer.append(chunk, static_cast<std::size_t>(n));
        finish(r, status, timed_out, o.time_limit, results[r.index]);
        progress(r.index);
        running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
      }
      else
        ++i;
    }
  }
}

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
      << " seeds for `voronoi` and `ours`, TIGHT packing, texture resolution " << o.texture_resolution
      << ". Total wall time " << fixed(total_seconds, 0) << " s.\n\n";
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
      << o.seeds << " farthest-point seeds (`voronoi_fps_segmentation`, no refinement or merging); both "
         "parameterized with `use_fallback(false)` and `require_disk_patches(false)`, so non-disk charts are "
         "attempted as in the paper. Ours = `segment_into_disks` and `parameterize_patches` with their defaults: "
         "an invalid chart is redone with mean value coordinates, then Tutte, then split, and a chart that "
         "exceeds the default `Distortion_bound` (mean |log s1/s2| "
      << format_double(DS::Distortion_bound().max_angle_distortion) << ", mean |log s1 s2| "
      << format_double(DS::Distortion_bound().max_area_distortion) << ", s1/s2 "
      << format_double(DS::Distortion_bound().max_stretch) << ", s1 s2 within 1/"
      << format_double(DS::Distortion_bound().max_area_scale) << " to "
      << format_double(DS::Distortion_bound().max_area_scale)
      << ") is replaced by its two children in the merge tree, down to the refined regions, then split by "
         "Voronoi cells (this is not in the paper); "
         "Ours, no split = the same without bound (`Distortion_bound::unbounded()`): the paper's charts, invalid ones "
         "repaired; Ours, no fallback = the same segmentation with `use_fallback(false)` (no repair, no split)."
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

bool is_mesh_file(const fs::path& p)
{
  const std::string e = lower(p.extension().string());
  return e == ".off" || e == ".obj" || e == ".ply" || e == ".stl";
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  std::string segmentations = "components,voronoi,ours,ours-nosplit,ours-nofallback";
  std::string methods = "conformal,lscm,arap";
  o.machine_note = "2-core shared VM";

  CLI::App app{ "Atlas quality of several segmentations and parameterization methods on a folder of meshes, "
                "in the layout of Table 1 of the paper (metrics: Atlas_quality in atlas_quality.h)." };
  app.add_option("MESH_DIR", o.mesh_dir, "folder of meshes (.off .obj .ply .stl), read in sorted name order")
    ->required()
    ->check(CLI::ExistingDirectory);
  app.add_option("--out", o.out_dir, "output folder: quality_per_mesh.csv and quality_table.md")->required();
  app.add_option("--segmentations", segmentations, "comma-separated: components, voronoi, ours, ours-nosplit, ours-nofallback")
    ->capture_default_str();
  app.add_option("--methods", methods, "comma-separated: conformal, lscm, arap, mvc, tutte")->capture_default_str();
  app.add_option("--time-limit", o.time_limit, "seconds per case (mesh x segmentation x method)")
    ->capture_default_str()
    ->check(CLI::PositiveNumber);
  app.add_option("--jobs,-j", o.jobs, "cases run at once, each in its own process")
    ->capture_default_str()
    ->check(CLI::Range(1u, 256u));
  app.add_option("-n,--seeds", o.seeds, "number of seeds of voronoi and ours")
    ->capture_default_str()
    ->check(CLI::Range(std::size_t(1), std::size_t(1) << 30));
  app.add_option("--threads", o.threads, "threads per case for parameterize_patches (0: TBB's choice)")
    ->capture_default_str();
  app.add_option("--texture-resolution", o.texture_resolution, "packing and texel-overlap resolution")
    ->capture_default_str()
    ->check(CLI::Range(1u, 16384u));
  app.add_option("--machine-note", o.machine_note, "machine description printed in the table")
    ->capture_default_str();
  app.add_option("--peers", o.peers_file, "CSV of the peers' numbers to print beside ours (see peers.csv)");
  app.add_flag("--quiet,-q", o.quiet, "no progress lines on stderr");
  CLI11_PARSE(app, argc, argv);

  try
  {
    o.segmentations = split_list(segmentations);
    for(const std::string& s : o.segmentations)
      if(std::find(all_segmentations.begin(), all_segmentations.end(), s) == all_segmentations.end())
        throw DS::Input_error("unknown segmentation '" + s + "' (expected components, voronoi, ours, ours-nosplit or ours-nofallback)");
    for(const std::string& m : split_list(methods))
      o.methods.push_back(DS::parameterization_method_from_string(m));
    if(o.segmentations.empty() || o.methods.empty())
      throw DS::Input_error("no segmentation or no method");
  }
  catch(const std::exception& e)
  {
    std::cerr << "quality_table: " << e.what() << std::endl;
    return 2;
  }

  std::vector<fs::path> files;
  for(const fs::directory_entry& entry : fs::directory_iterator(o.mesh_dir))
    if(entry.is_regular_file() && is_mesh_file(entry.path()))
      files.push_back(entry.path());
  std::sort(files.begin(), files.end(),
            [](const fs::path& a, const fs::path& b) { return a.filename().string() < b.filename().string(); });
  if(files.empty())
  {
    std::cerr << "quality_table: no .off, .obj, .ply or .stl file in " << o.mesh_dir << std::endl;
    return 2;
  }

  std::vector<Case> cases;
  for(std::size_t m = 0; m < files.size(); ++m)
    for(const std::string& s : o.segmentations)
      for(DS::Parameterization_method method : o.methods)
      {
        Case c;
        c.mesh = m;
        c.segmentation = s;
        c.method = method;
        cases.push_back(c);
      }

  ::signal(SIGPIPE, SIG_IGN);
  std::vector<Result> results;
  const Clock::time_point start = Clock::now();
  try
  {
    fs::create_directories(o.out_dir);
    if(!o.quiet)
      std::cerr << "quality_table: " << files.size() << " meshes, " << cases.size() << " cases, " << o.jobs
                << " at once" << std::endl;
    run_all(o, files, cases, results);
    const double total = seconds_since(start);
    write_csv(fs::path(o.out_dir) / "quality_per_mesh.csv", files, cases, results);
    write_markdown(fs::path(o.out_dir) / "quality_table.md", o, files, cases, results, total);
  }
  catch(const std::exception& e)
  {
    std::cerr << "quality_table: " << e.what() << std::endl;
    return 1;
  }
  std::size_t failed = 0;
  for(const Result& r : results)
    failed += r.failed() ? 1 : 0;
  std::cout << "quality_table: " << cases.size() << " cases on " << files.size() << " meshes, " << failed
            << " failed, in " << fixed(seconds_since(start), 1) << " s; wrote "
            << (fs::path(o.out_dir) / "quality_table.md").string() << " and "
            << (fs::path(o.out_dir) / "quality_per_mesh.csv").string() << std::endl;
  return 0;
}
