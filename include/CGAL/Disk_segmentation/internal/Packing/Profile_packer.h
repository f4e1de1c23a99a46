// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Packing of chart shapes rather than of their bounding rectangles: each
// chart, in each of its four quarter turns, is reduced to its column
// profile on a grid of cells (per column, the lowest and the highest cell
// it touches), and charts are dropped, largest first, onto the skyline of
// those already placed, at the column and turn where their top ends
// lowest. A jagged or bent chart then nests into the dents of the skyline
// instead of reserving its whole rectangle.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PROFILE_PACKER_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PROFILE_PACKER_H

#include <CGAL/Disk_segmentation/internal/Packing/packing_geometry.h>
#include <CGAL/Disk_segmentation/internal/Execution/parallel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Where a shape packer put a chart: `turns` quarter turns counterclockwise
// after its frame (then an eighth of a turn if `diagonal`), and the lower
// left corner of its box in that frame at (x, y), in units of the square's
// side.
struct Profile_placement
{
  int turns = 0;
  bool diagonal = false;  // then turned by another eighth of a turn
  double x = 0., y = 0.;
};

// One chart as the shape packers need it: its triangles (three corners
// each) in its frame, which of their edges are on its border (bit j: from
// corner j to corner j + 1; read by the raster packer), and the density that
// turns its lengths into UV lengths at scale 1.
struct Profile_chart
{
  const Planar_point* corners = nullptr;
  std::size_t number_of_corners = 0;
  const unsigned char* border_edges = nullptr;
  double density = 1.;
  double area = 0.;  // UV area in its frame, to order the charts
};

// The charts' indices by decreasing UV area at a common scale: the order in
// which the shape packers place them.
inline std::vector<std::size_t> largest_first(const std::vector<Profile_chart>& charts)
{
  std::vector<std::size_t> order(charts.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return charts[a].density * charts[a].density * charts[a].area >
           charts[b].density * charts[b].density * charts[b].area;
  });
  return order;
}

class Profile_packer
{
public:
  // `columns` cells across the page and `rows` up (the unit square by
  // default); every chart keeps `pad_cells` empty cells between itself and
  // any other chart or the page's sides.
  Profile_packer(std::size_t columns, std::size_t pad_cells, std::size_t rows = 0)
    : n_(columns), rows_(rows == 0 ? columns : rows), pad_(pad_cells)
  {}

  // Packs every chart at `scale` (UV length = scale * density * length in
  // its frame). Returns false if one does not fit.
  bool run(const std::vector<Profile_chart>& charts, double scale, std::vector<Profile_placement>& out)
  {
    out.assign(charts.size(), Profile_placement());
    const std::vector<std::size_t> order = largest_first(charts);
    skyline_.assign(n_, 0);
    for(std::size_t i : order)
    {
      // Each turn on its own, then the turns in order: the same choice as
      // one scan over all turns and columns, whatever the threads.
      bool fits[4];
      Placement found[4];
      for_each_piece(4, parallel_, [&](int turns) {
        fits[turns] = profile(charts[i], scale, turns, profiles_[turns]);
        if(fits[turns])
          found[turns] = lowest_placement(profiles_[turns], turns);
      });
      Placement best;
      for(int turns = 0; turns < 4; ++turns)
      {
        if(!fits[turns])
          return false;
        if(found[turns].turns >= 0 && found[turns].better_than(best))
          best = found[turns];
      }
      const long best_x = best.x, best_y = best.y;
      const int best_turns = best.turns;
      if(best_turns < 0)
        return false;
      const Profile& p = profiles_[best_turns];
      for(std::size_t c = 0; c < p.high.size(); ++c)
        if(p.high[c] > 0)
          skyline_[best_x + c] = (std::max)(skyline_[best_x + c], best_y + p.high[c]);
      out[i].turns = best_turns;
      out[i].x = double(best_x + static_cast<long>(pad_)) / double(n_);
      out[i].y = double(best_y + static_cast<long>(pad_)) / double(n_);
    }
    return true;
  }

  // Whether the turns of a chart are profiled and placed on several threads
  // (with TBB). The layout is the same either way.
  void set_parallel(bool parallel) { parallel_ = with_tbb && parallel; }

private:
  // A chart's footprint: per column, the lowest cell its padding needs free
  // (`low`) and one above the highest cell the chart itself covers (`high`,
  // 0 in the padding columns), relative to the footprint's lower left;
  // `height` is the footprint's top with the padding.
  struct Profile
  {
    std::vector<long> low, high;
    long height = 0;
    std::vector<Planar_point> points;  // scratch, one per turn
  };

  // A chart's place: its score (top plus weighted waste), then its row.
  struct Placement
  {
    long score = (std::numeric_limits<long>::max)(), y = 0, x = 0;
    int turns = -1;  // -1: none

    // The order of the scan: a later placement wins only if it is better.
    bool better_than(const Placement& o) const { return score < o.score || (score == o.score && y < o.y); }
  };

  // The best placement of the chart in one turn: every column of the
  // chart checked against the skyline at every position, at most n
  // columns times its width.
  Placement lowest_placement(const Profile& p, int turns) const
  {
    const long side = static_cast<long>(n_);
    const long width = static_cast<long>(p.low.size());
    Placement best;
    for(long x = 0; x + width <= side; ++x)
    {
      // A position whose top is already above the square or above the
      // best score (the waste below only adds to it) cannot win: its
      // columns are not all read.
      const long ceiling = (std::min)(static_cast<long>(rows_), best.score) - p.height;
      long y = 0;
      for(long c = 0; c < width && y <= ceiling; ++c)
        y = (std::max)(y, skyline_[x + c] - p.low[c]);
      if(y > ceiling)
        continue;
      const long top = y + p.height;
      // The cells left empty below the chart, at a small weight: enough
      // to prefer a dent the chart fits, not to climb for it.
      long waste = 0;
      for(long c = 0; c < width; ++c)
        waste += y + p.low[c] - skyline_[x + c];
      waste = waste * waste_weight_percent / 100;
      Placement here;
      here.score = top + waste;
      here.y = y;
      here.x = x;
      here.turns = turns;
      if(here.better_than(best))
        best = here;
    }
    return best;
  }

  // Measured on 10 meshes of CGAL's data (median UV area over the square):
  // 0.559 without the waste term, 0.583 at 2 %, 0.594 at 5 %, 0.582 at 10 %
  // and 20 %, 0.572 at 100 %.
  static constexpr long waste_weight_percent = 5;

  // Rounding of the coordinates must not move a corner out of its cells.
  static constexpr double slack = 1e-9;

  bool profile(const Profile_chart& chart, double scale, int turns, Profile& p) const
  {
    const double to_cells = scale * chart.density * double(n_);
    std::vector<Planar_point>& points = p.points;
    points.resize(chart.number_of_corners);
    Packing_box box;
    for(std::size_t k = 0; k < chart.number_of_corners; ++k)
    {
      Planar_point q = chart.corners[k];
      for(int t = 0; t < turns; ++t)
        q = quarter_turn(q);
      points[k] = q;
      box.add(q);
    }
    const double w = to_cells * box.width(), h = to_cells * box.height();
    if(!(w < double(n_)) || !(h < double(rows_)))
      return false;
    const long columns = static_cast<long>(std::ceil(w + slack));
    const long pad = static_cast<long>(pad_);
    std::vector<long> bottom(static_cast<std::size_t>(columns), std::numeric_limits<long>::max());
    std::vector<long> top(static_cast<std::size_t>(columns), 0);
    // The border edges only: a chart's lowest and highest point over a
    // column lie on its border. Whole triangles cost their width in
    // columns each, quadratic for the slivers around a vertex of high
    // valence.
    for(std::size_t k = 0; k + 2 < chart.number_of_corners; k += 3)
    {
      Planar_point t[3];
      for(int j = 0; j < 3; ++j)
        t[j] = { to_cells * (points[k + j].x - box.xmin), to_cells * (points[k + j].y - box.ymin) };
      for(int j = 0; j < 3; ++j)
      {
        if(!(chart.border_edges[k / 3] & (1 << j)))
          continue;
        for_each_slab_of_segment(t[j], t[(j + 1) % 3], columns, slack, [&](long c, double ylo, double yhi) {
          bottom[c] = (std::min)(bottom[c], static_cast<long>(std::floor(ylo - slack)));
          top[c] = (std::max)(top[c], static_cast<long>(std::floor(yhi + slack)) + 1);
        });
      }
    }
    // A chart is connected, so its columns form one run; a column no
    // triangle reached (rounding) takes its neighbors' extent.
    for(long c = 0; c < columns; ++c)
      if(bottom[c] == std::numeric_limits<long>::max())
      {
        bottom[c] = c > 0 ? bottom[c - 1] : 0;
        top[c] = c > 0 ? top[c - 1] : static_cast<long>(std::ceil(h + slack));
      }
    // The footprint: pad columns on each side, pad rows below and above;
    // the low side of every column is grown by the padding of its
    // neighbors within pad columns, so that the gap holds sideways too.
    const long width = columns + 2 * pad;
    p.low.assign(static_cast<std::size_t>(width), std::numeric_limits<long>::max());
    p.high.assign(static_cast<std::size_t>(width), 0);
    long highest = 0;
    for(long c = 0; c < columns; ++c)
    {
      highest = (std::max)(highest, top[c]);
      p.high[c + pad] = top[c] + pad;
      for(long d = c; d <= c + 2 * pad; ++d)
        p.low[d] = (std::min)(p.low[d], bottom[c]);
    }
    p.height = highest + 2 * pad;
    return p.height <= static_cast<long>(rows_);
  }

  std::size_t n_, rows_, pad_;
  std::vector<long> skyline_;
  Profile profiles_[4];
  bool parallel_ = false;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PROFILE_PACKER_H
