// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The layouts packing tries: the grid of cells of the raster packer, the
// scale of the charts, and the pages they are spread over.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CHART_LAYOUTS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CHART_LAYOUTS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/internal/Packing/Chart_packer.h>
#include <CGAL/Disk_segmentation/internal/Packing/Chart_set.h>
#include <CGAL/Disk_segmentation/internal/Packing/Packing_settings.h>
#include <CGAL/Disk_segmentation/internal/Packing/Profile_packer.h>
#include <CGAL/Disk_segmentation/internal/Packing/Raster_packer.h>
#include <CGAL/Disk_segmentation/internal/Packing/packing_geometry.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Cells of at least one texel, at most 512 across: each trial costs the
// columns times the charts' widths in cells.
// Measured on 10 meshes of CGAL's data: 256 columns pack 0.551 of the
// square (median), 512 0.594, 1024 0.588 at 2.4 times the time of 512.
inline std::size_t shape_columns(const Packing_settings& s)
{
  return (std::min)(std::size_t(512), static_cast<std::size_t>(s.resolution));
}

// The page's rows of square cells (its height over a cell's side, rounded
// down: a partial row is left empty).
inline std::size_t shape_rows(const Packing_settings& s, std::size_t columns)
{
  return (std::max)(std::size_t(1),
                    static_cast<std::size_t>(std::floor(page_aspect(s) * double(columns) * (1. + 1e-12))));
}

// The padding in whole cells, rounded up.
inline std::size_t shape_pad_cells(const Packing_settings& s, std::size_t columns)
{
  return (std::max)(std::size_t(1), static_cast<std::size_t>(std::ceil(s.padding * double(columns) / s.resolution)));
}

// The charts as the shape packers read them. Not copyable: `charts` points
// into the other members.
struct Shape_input
{
  std::vector<Planar_point> framed;  // corners in the chart's frame
  std::vector<unsigned char> border_edges;
  std::vector<Profile_chart> charts;
  double total_area = 0.;  // of the charts at one UV unit per unit of length

  template <typename TriangleMesh>
  Shape_input(const Chart_set<TriangleMesh>& set, const std::vector<double>& density)
  {
    const std::size_t n = set.size();
    framed.reserve(set.corners.size());
    border_edges.reserve(set.corners.size() / 3);
    charts.resize(n);
    std::vector<std::size_t> first_corner(1, 0);  // of each chart in `framed`, and the end
    for(std::size_t p = 0; p < n; ++p)
    {
      // Only the triangles with an edge on the border: a chart's lowest and
      // highest point over any vertical slab lie on its border, and its
      // border bounds the cells it covers (about the square root of the
      // chart's triangles).
      for(std::size_t i = set.first_face[p]; i < set.first_face[p + 1]; ++i)
      {
        if(set.border_edges[i] == 0)
          continue;
        for(std::size_t j = 0; j < 3; ++j)
          framed.push_back(set.rotation[p](set.corners[3 * i + j]));
        border_edges.push_back(set.border_edges[i]);
      }
      first_corner.push_back(framed.size());
      charts[p].density = density[p];
      charts[p].area = set.uv_area[p];
      total_area += density[p] * density[p] * set.uv_area[p];
    }
    for(std::size_t p = 0; p < n; ++p)
    {
      charts[p].corners = framed.data() + first_corner[p];
      charts[p].border_edges = border_edges.data() + first_corner[p] / 3;
      charts[p].number_of_corners = first_corner[p + 1] - first_corner[p];
    }
  }
  Shape_input(const Shape_input&) = delete;
  Shape_input& operator=(const Shape_input&) = delete;
};

// The similarities of the charts placed by a shape packer at `scale`.
template <typename TriangleMesh>
std::vector<Chart_similarity> shape_similarities(const Chart_set<TriangleMesh>& charts,
                                                 const std::vector<Profile_placement>& placement,
                                                 const std::vector<double>& density, double scale)
{
  std::vector<Chart_similarity> result(charts.size());
  for(std::size_t p = 0; p < charts.size(); ++p)
  {
    Chart_similarity& sim = result[p];
    sim.rotation = charts.rotation[p];
    Packing_box b = charts.box[p];
    for(int t = 0; t < placement[p].turns; ++t)
    {
      sim.rotation = sim.rotation.quarter_turned();
      b = b.quarter_turned();
    }
    if(placement[p].diagonal)
    {
      sim.rotation = sim.rotation.eighth_turned();
      b = Packing_box();
      for(std::size_t k = 3 * charts.first_face[p]; k < 3 * charts.first_face[p + 1]; ++k)
        b.add(sim.rotation(charts.corners[k]));
    }
    sim.scale = scale * density[p];
    sim.tx = placement[p].x - sim.scale * b.xmin;
    sim.ty = placement[p].y - sim.scale * b.ymin;
  }
  return result;
}

// Above this many charts only the raster packer runs; its search starts at
// this multiple of the rectangles' scale (see shape_layout()).
constexpr std::size_t profile_packer_max_charts = 64;
constexpr double raster_start_over_rectangles = 1.2;

// The better of the two shape packers' layouts (profile, then raster) at
// the largest scale each reaches, if that is above `rectangle_scale` (the
// rectangle packing's); else an empty vector.
template <typename TriangleMesh>
std::vector<Chart_similarity> shape_layout(const Chart_set<TriangleMesh>& charts, const Packing_settings& s,
                                             const std::vector<double>& density, double rectangle_scale,
                                             double& global_scale)
{
  const std::size_t n = charts.size();
  const std::size_t columns = shape_columns(s);
  const std::size_t pad_cells = shape_pad_cells(s, columns);
  const Shape_input shapes(charts, density);
  const std::vector<Profile_chart>& input = shapes.charts;
  const double total = shapes.total_area;
  const std::size_t rows = shape_rows(s, columns);
  const double hi = total > 0. ? std::sqrt(page_aspect(s) / total) : rectangle_scale;
  std::size_t trial = 0;  // reported, after the rectangles' (see report_packing_trial())

  // The profile packer's largest scale in [rectangle_scale, hi) at which
  // every chart fits, to 1 percent (about seven trials), and its
  // placements; 0 if it does not fit them at rectangle_scale. Measured on
  // 90 atlases (30 meshes, 3 bounds): the same UV area as to 0.2 percent on
  // the mean, 10 % less packing time.
  auto profile_search = [&](std::vector<Profile_placement>& best) {
    Profile_packer packer(columns, pad_cells, rows);
    packer.set_parallel(s.threads != 1);
    std::vector<Profile_placement> placement;
    double lo = rectangle_scale, top = hi;
    report_packing_trial(s, trial);
    if(!(top > lo) || !packer.run(input, lo, placement))
      return 0.;
    best.swap(placement);
    while(top - lo > 1e-2 * lo)
    {
      const double mid = 0.5 * (lo + top);
      report_packing_trial(s, trial);
      if(packer.run(input, mid, placement))
      {
        lo = mid;
        best.swap(placement);
      }
      else
        top = mid;
    }
    return lo;
  };

  // The rows a raster packing uses grow about as the square of the scale:
  // each trial aims at the scale that would just fill the square, then
  // bisection between the best fit and the smallest failure, to 1 percent
  // (4 to 6 trials on 10 meshes of CGAL's data). It starts from the
  // profile packer's scale and gives up if it cannot reach it. Without
  // the profile packer (many charts), it starts 20 % above the rectangles'
  // scale, about where it ends, and a failure only aims lower.
  auto raster_search = [&](double profile_scale, std::vector<Profile_placement>& best) {
    Raster_packer packer(columns, pad_cells, rows);
    packer.set_parallel(s.threads != 1);
    std::vector<Profile_placement> placement;
    const bool after_profile = profile_scale > 0.;
    double fit = 0., fail = hi;
    double scale = after_profile ? (std::max)(profile_scale, rectangle_scale)
                                 : (std::min)(hi, raster_start_over_rectangles * rectangle_scale);
    const double target = double(rows);
    const double tol = 0.01;
    const int max_trials = 6;
    for(int raster_trial = 0; raster_trial < max_trials && fail > fit * (1. + tol); ++raster_trial)
    {
      report_packing_trial(s, trial);
      const bool packed = packer.run(input, scale, placement);
      const double used = double(packer.used_rows());
      if(packed)
      {
        fit = scale;
        best.swap(placement);
      }
      else if(fit == 0. && after_profile)
        break;
      else
        fail = (std::min)(fail, scale);
      double next = used > 0. ? scale * std::sqrt(target / used) : 0.;
      if(packed && !(next > fit * (1. + 0.5 * tol)))
        next = fit * (1. + tol);
      // Before any fit, bisect from the rectangles' scale, which every chart
      // fits: a trial where some chart is wider than the square at any turn
      // (a long chart) says nothing about the rows.
      if(!(next > fit) || !(next < fail))
        next = 0.5 * ((fit > 0. ? fit : rectangle_scale) + fail);
      scale = next;
    }
    return fit;
  };

  // With many charts the raster packer alone packs as much (30 meshes,
  // above 64 charts: -0.019 to +0.008 of the square, median +0.001) in
  // 0.4-0.7 of the time (ChineseDragon-10kv 256 charts, b9_mesh 455,
  // cheese 922); with few, the profile packer's layout or scale often wins
  // (anchor +0.135, head +0.090). The two searches could run side by side
  // if the raster one did not start from the profile packer's scale; on 30
  // atlases that took 1.06 times the packing time with one thread, 0.8
  // with two, for the same median UV area. Within each search, the turns
  // of each chart run side by side.
  std::vector<Profile_placement> best, raster_best;
  double lo = 0.;
  within_arena(s.threads, [&] {
    if(n <= profile_packer_max_charts)
      lo = profile_search(best);
    const double fit = raster_search(lo, raster_best);
    if(fit > lo)
    {
      lo = fit;
      best.swap(raster_best);
    }
  });
  if(!(lo > rectangle_scale * (1. + 1e-3)))
    return std::vector<Chart_similarity>();
  global_scale = lo;
  return shape_similarities(charts, best, density, lo);
}

// Extra gap, in UV units, on top of the requested padding, that absorbs the
// rounding of the final similarity (coordinates are at most 1).
constexpr double packing_rounding_margin = 1e-12;

// The charts left by the pages filled so far, in the order each page tries
// them, and what a page need not try: a chart whose zone covers more cells
// than the page has free, and the charts of the same footprints in every
// turn (a class: copies of a part) as one that found no room on the page.
// A min-tree over the positions holds, at each class's first chart left,
// the cells its charts need (0 at a chart not tried yet, which has no class
// yet; none elsewhere), and finds the next chart to try in O(log n). Each
// page tried every chart left, which made the pages quadratic (one triangle
// per page of 64 texels: 1000 pages 34 s, 4000 341 s; now 0.26 and 0.94 s).
class Paged_charts
{
public:
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

  explicit Paged_charts(std::size_t n) : class_of_(n, none), leaves_(1)
  {
    while(leaves_ < n)
      leaves_ *= 2;
    need_.assign(2 * leaves_, none);
    std::fill(need_.begin() + leaves_, need_.begin() + leaves_ + n, std::size_t(0));
    for(std::size_t v = leaves_ - 1; v > 0; --v)
      need_[v] = (std::min)(need_[2 * v], need_[2 * v + 1]);
  }

  // The first chart from position `from` on that a page with `free_cells`
  // cells free tries, or none.
  std::size_t next(std::size_t from, std::size_t free_cells) const
  {
    return first(1, 0, leaves_, from, free_cells);
  }

  // The first chart left, or none; once a page is over (end_page()).
  std::size_t front() const { return first(1, 0, leaves_, 0, none - 1); }

  std::size_t class_of(std::size_t k) const { return class_of_[k]; }

  // The position of the first chart of class `c`, to compare footprints.
  std::size_t representative(std::size_t c) const { return classes_[c].representative; }

  // A new class for the chart at `k` (tried for the first time), whose
  // charts need `cells` free cells (none - 1: they fit no page).
  std::size_t new_class(std::size_t k, std::size_t cells)
  {
    Chart_class c;
    c.need = (std::min)(cells, none - 1);
    c.representative = k;
    classes_.push_back(c);
    class_of_[k] = classes_.size() - 1;
    return classes_.size() - 1;
  }

  // The chart at `k`, tried for the first time, is of class `c`.
  void join(std::size_t k, std::size_t c) { class_of_[k] = c; }

  // The chart at `k` was placed on the page: the next of its class is tried
  // after it.
  void placed(std::size_t k)
  {
    Chart_class& c = classes_[class_of_[k]];
    set(k, none);
    if(c.head == c.left.size() || c.left[c.head] != k)
      return;  // tried for the first time: not in `left`
    ++c.head;
    if(c.head < c.left.size())
      set(c.left[c.head], c.need);
  }

  // The chart at `k` found no room on the page: nor would the others of its
  // class, until the next page.
  void failed(std::size_t k)
  {
    const std::size_t id = class_of_[k];
    Chart_class& c = classes_[id];
    // Unless it is the class's first chart left, it is tried for the first
    // time, after all the others of its class (the first page tries all).
    if(c.head == c.left.size() || c.left[c.head] != k)
      c.left.push_back(k);
    set(k, none);
    if(!c.failed)
    {
      c.failed = true;
      failed_.push_back(id);
    }
  }

  // The classes that failed on the page are tried again on the next.
  void end_page()
  {
    for(std::size_t id : failed_)
    {
      Chart_class& c = classes_[id];
      c.failed = false;
      if(c.head < c.left.size())
        set(c.left[c.head], c.need);
    }
    failed_.clear();
  }

private:
  struct Chart_class
  {
    std::size_t need = 0, representative = 0;
    std::vector<std::size_t> left;  // positions of its charts tried and not placed, from `head` on
    std::size_t head = 0;
    bool failed = false;            // on the current page
  };

  void set(std::size_t k, std::size_t cells)
  {
    k += leaves_;
    need_[k] = cells;
    for(k /= 2; k > 0; k /= 2)
      need_[k] = (std::min)(need_[2 * k], need_[2 * k + 1]);
  }

  std::size_t first(std::size_t node, std::size_t begin, std::size_t end, std::size_t from, std::size_t cells) const
  {
    if(end <= from || need_[node] > cells)
      return none;
    if(end - begin == 1)
      return begin;
    const std::size_t middle = begin + (end - begin) / 2;
    const std::size_t left = first(2 * node, begin, middle, from, cells);
    return left != none ? left : first(2 * node + 1, middle, end, from, cells);
  }

  std::vector<std::size_t> class_of_;  // per position
  std::vector<Chart_class> classes_;
  std::vector<std::size_t> failed_;    // classes that failed on the current page
  std::size_t leaves_;
  std::vector<std::size_t> need_;      // per node of the tree, the least need below it
};

// The layout at the fixed density `s.texels_per_unit`: pages are filled
// one after the other by the raster packer, each with the charts left that
// fit on it, largest first; `page_of_chart` says where each went.
template <typename TriangleMesh>
std::vector<Chart_similarity> paged_layout(const Chart_set<TriangleMesh>& charts, const Packing_settings& s,
                                           const std::vector<double>& density, double& global_scale,
                                           std::vector<std::size_t>& page_of_chart)
{
  const std::size_t n = charts.size();
  // Texels per unit of the input's length = scale * resolution * length_scale.
  const double scale = s.texels_per_unit / (s.resolution * charts.length_scale);
  global_scale = scale;
  const Shape_input shapes(charts, density);
  // Pages never hold more than their area: a quick "no" before any packing.
  const double least_pages = shapes.total_area * scale * scale / page_aspect(s);
  auto too_many_pages = [&] {
    std::ostringstream message;
    message << "pack_patches: at texels_per_unit " << s.texels_per_unit << " the charts need more than "
            << pages_text(s.max_pages) << " of " << texture_size(s) << " (max_number_of_pages); lower "
            << "texels_per_unit or raise texture_resolution or max_number_of_pages";
    return Input_error(message.str());
  };
  if(!(least_pages <= static_cast<double>(s.max_pages)))
    throw too_many_pages();

  const std::size_t columns = shape_columns(s);
  Raster_packer packer(columns, shape_pad_cells(s, columns), shape_rows(s, columns));
  packer.set_parallel(s.threads != 1);
  std::vector<Profile_placement> placement(n);
  const std::vector<std::size_t> order = largest_first(shapes.charts);
  // Each page tries the charts left in this order, but those it could not
  // hold (Paged_charts): the layout is the same.
  Paged_charts left(n);
  std::unordered_map<std::size_t, std::vector<std::size_t> > classes_of_hash;
  std::vector<long> key, other;
  // The class of the chart at k, just tried for the first time: its
  // footprints' key is compared with those of the classes of the same hash.
  auto classify = [&](std::size_t k, std::size_t need) {
    packer.footprint_key(key);
    std::uint64_t hash = 0xcbf29ce484222325ull;
    for(long v : key)
      hash = (hash ^ static_cast<std::uint64_t>(v)) * 0x100000001b3ull;
    std::vector<std::size_t>& same_hash = classes_of_hash[static_cast<std::size_t>(hash)];
    for(std::size_t c : same_hash)
    {
      packer.rasterize(shapes.charts[order[left.representative(c)]], scale);
      packer.footprint_key(other);
      if(other == key)
        return left.join(k, c);
    }
    same_hash.push_back(left.new_class(k, need));
  };
  page_of_chart.assign(n, 0);
  std::size_t trial = 0;
  for(std::size_t page = 0; left.front() != Paged_charts::none; ++page)
  {
    if(page == s.max_pages)
      throw too_many_pages();
    report_packing_trial(s, trial);
    std::size_t count = 0;
    within_arena(s.threads, [&] {
      packer.start_page();
      for(std::size_t k = left.next(0, packer.free_cells()); k != Paged_charts::none;
          k = left.next(k + 1, packer.free_cells()))
      {
        const std::size_t i = order[k];
        std::size_t need = 0;
        const bool fits = packer.place_on_page(shapes.charts[i], scale, placement[i], need);
        if(left.class_of(k) == Paged_charts::none)
          classify(k, need);
        if(fits)
        {
          left.placed(k);
          page_of_chart[i] = page;
          ++count;
        }
        else
          left.failed(k);
      }
    });
    left.end_page();
    if(count == 0)
    {
      // None of them fits an empty page: the largest is named.
      const std::size_t p = order[left.front()];
      const double to_texels = scale * density[p] * s.resolution;
      std::ostringstream message;
      message << "pack_patches: at texels_per_unit " << s.texels_per_unit << ", " << patch_name(p) << " is "
              << std::ceil(charts.box[p].width() * to_texels) << " x "
              << std::ceil(charts.box[p].height() * to_texels) << " texels and does not fit a page of "
              << texture_size(s) << " (texture_resolution) with padding_in_texels " << s.padding
              << "; lower texels_per_unit or raise texture_resolution";
      throw Input_error(message.str());
    }
  }
  return shape_similarities(charts, placement, density, scale);
}

template <typename TriangleMesh>
std::vector<Chart_similarity> tight_layout(const Chart_set<TriangleMesh>& charts, const Packing_settings& s,
                                           double& global_scale, std::vector<std::size_t>& page_of_chart)
{
  const std::size_t n = charts.size();
  const double pad = s.padding / s.resolution + packing_rounding_margin;
  // Sizes at one UV unit per 3D unit of length.
  std::vector<double> density(n), w(n), h(n);
  for(std::size_t p = 0; p < n; ++p)
  {
    density[p] = std::sqrt(charts.surface_area[p] / charts.uv_area[p]);
    w[p] = density[p] * charts.box[p].width();
    h[p] = density[p] * charts.box[p].height();
  }
  if(s.texels_per_unit > 0.)
    return paged_layout(charts, s, density, global_scale, page_of_chart);
  page_of_chart.assign(n, 0);
  // Rectangles grown by the padding on their right and top fill [pad, 1]^2:
  // this leaves the padding between any two of them and along every side.
  const Square_packing packing = pack_in_rectangle(w, h, pad, 1. - pad, page_aspect(s) - pad);
  if(!(packing.scale > 0.))
  {
    std::ostringstream message;
    message << "pack_patches: padding_in_texels (" << s.padding << ") is too large to place " << n
            << " charts on a texture of " << texture_size(s);
    throw Input_error(message.str());
  }
  global_scale = packing.scale;
  // The chart shapes often nest better than their rectangles.
  {
    std::vector<Chart_similarity> shaped = shape_layout(charts, s, density, packing.scale, global_scale);
    if(!shaped.empty())
      return shaped;
  }

  std::vector<Chart_similarity> result(n);
  for(std::size_t p = 0; p < n; ++p)
  {
    const Packed_rectangle& rect = packing.rectangles[p];
    Chart_similarity& sim = result[p];
    sim.rotation = charts.rotation[p];
    Packing_box b = charts.box[p];
    if(rect.rotated)
    {
      sim.rotation = sim.rotation.quarter_turned();
      b = b.quarter_turned();
    }
    sim.scale = packing.scale * density[p];
    sim.tx = pad + rect.x - sim.scale * b.xmin;
    sim.ty = pad + rect.y - sim.scale * b.ymin;
  }
  return result;
}

template <typename TriangleMesh>
std::vector<Chart_similarity> grid_layout(const Chart_set<TriangleMesh>& charts, const Packing_settings& s)
{
  const std::size_t n = charts.size();
  // A step or two each: the double square root is within one of the integer one.
  std::size_t columns = static_cast<std::size_t>(std::sqrt(static_cast<double>(n)));
  while(columns * columns < n) ++columns;
  while(columns > 1 && (columns - 1) * (columns - 1) >= n) --columns;

  // Cells tile [pad/2, 1 - pad/2]^2 and every chart keeps pad/2 inside its
  // cell: charts are pad apart from each other and from the sides.
  const double pad = s.padding / s.resolution + packing_rounding_margin;
  const double cell = (1. - pad) / static_cast<double>(columns);
  const double room = cell - pad;
  if(!(room > 0.))
  {
    std::ostringstream message;
    message << "pack_patches: padding_in_texels (" << s.padding << ") is too large for a grid of " << columns
            << " x " << columns << " cells on a texture of " << s.resolution << " texels";
    throw Input_error(message.str());
  }

  std::vector<Chart_similarity> result(n);
  for(std::size_t p = 0; p < n; ++p)
  {
    const Packing_box& b = charts.box[p];
    Chart_similarity& sim = result[p];
    sim.rotation = charts.rotation[p];
    sim.scale = room / (std::max)(b.width(), b.height());
    const double cx = 0.5 * pad + (static_cast<double>(p % columns) + 0.5) * cell;
    const double cy = 0.5 * pad + (static_cast<double>(p / columns) + 0.5) * cell;
    sim.tx = cx - sim.scale * 0.5 * (b.xmin + b.xmax);
    sim.ty = cy - sim.scale * 0.5 * (b.ymin + b.ymax);
  }
  return result;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CHART_LAYOUTS_H
