// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// quality_table: the types, aliases and small helpers its parts share (one
// translation unit: quality_table.cpp includes every part once).

#ifndef DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_SUPPORT_H
#define DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_SUPPORT_H

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/atlas_quality.h>
#include <CGAL/Disk_segmentation/default_values.h>
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
// Cases, results and options, shared by the pool and the writers

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
  double crease_penalty = DS::default_crease_penalty;
  std::string machine_note;
  std::string peers_file;
  bool quiet = false;
};

} // namespace

#endif // DISK_SEGMENTATION_BENCHMARK_QUALITY_TABLE_SUPPORT_H
