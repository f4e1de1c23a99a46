// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Packing of chart shapes on a grid of cells, holes included: each chart,
// in each of its four quarter turns, becomes the set of cells it touches,
// and charts are placed, largest first, where their top ends lowest among
// the positions where that set, grown by the padding, meets no cell of a
// chart already placed. Unlike a skyline, the free cells under an overhang
// stay available, so the small charts that come last fill the holes the
// large ones leave.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_RASTER_PACKER_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_RASTER_PACKER_H

#include <CGAL/Disk_segmentation/internal/Execution/parallel.h>
#include <CGAL/Disk_segmentation/internal/Packing/Page_occupancy.h>
#include <CGAL/Disk_segmentation/internal/Packing/Profile_packer.h>
#include <CGAL/Disk_segmentation/internal/Packing/Raster_footprint.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <atomic>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Places charts on the page, each in the turn and at the position where
// its top ends lowest (see the top of this file); rasterizes them with
// rasterize_footprint() and keeps the page in a Page_occupancy.
class Raster_packer
{
public:
  // `columns` cells across the page and `page_rows` up (the unit square by
  // default); every chart keeps `pad_cells` empty cells between itself and
  // any other chart or the page's sides. run() packs the charts in a strip
  // of `columns` cells and twice the page's rows, so that a packing that
  // does not fit says by how much.
  Raster_packer(std::size_t columns, std::size_t pad_cells, std::size_t page_rows = 0)
    : n_(columns), page_rows_(page_rows == 0 ? columns : page_rows), rows_(2 * page_rows_), pad_(pad_cells)
  {}

  // Rows the last run used, padding included; above the page's rows it did
  // not fit.
  std::size_t used_rows() const { return used_rows_; }

  // Packs every chart at `scale` (UV length = scale * density * length in
  // its frame). The charts' `border_edges` must be set. Returns false if
  // they do not fit in the square.
  bool run(const std::vector<Profile_chart>& charts, double scale, std::vector<Profile_placement>& out)
  {
    out.assign(charts.size(), Profile_placement());
    rows_ = 2 * page_rows_;
    return pack(charts, largest_first(charts), scale, out) && used_rows_ <= page_rows_;
  }

  // Pages filled one after the other: start_page() empties the page (the
  // square), then each place_on_page() places a chart where run() would.
  void start_page()
  {
    rows_ = page_rows_;
    clear();
  }

  // The cells of the page no chart covers: a chart whose zone covers more
  // fits nowhere on it.
  std::size_t free_cells() const { return occupancy_.free_cells(); }

  // Places `chart` at `scale` on the page, in `out`, if it fits anywhere.
  // `zone_area` gets the fewest cells its zone covers in the turns it may
  // take (the largest std::size_t if none): at this scale the chart fits
  // no page with fewer free_cells(), which the caller need not try.
  bool place_on_page(const Profile_chart& chart, double scale, Profile_placement& out, std::size_t& zone_area)
  {
    return place_chart(chart, scale, out, zone_area) == Fit::placed;
  }

  // The cells of the chart last rasterized (by place_on_page() or
  // rasterize()) in every turn it may take, as a list of numbers: two
  // charts with the same key are placed alike on any page, or fail alike.
  void footprint_key(std::vector<long>& key) const
  {
    key.clear();
    for(int eighths = 0; eighths < 8; ++eighths)
    {
      key.push_back(usable_[eighths] ? 1 : 0);
      if(!usable_[eighths])
        continue;
      const Footprint& f = footprints_[eighths];
      key.insert(key.end(), f.shape.begin(), f.shape.end());
      for(long r = 0; r < f.height; ++r)
      {
        key.push_back(static_cast<long>(f.core_begin[r + 1] - f.core_begin[r]));
        for(std::size_t j = f.core_begin[r]; j < f.core_begin[r + 1]; ++j)
        {
          key.push_back(f.core[j].first);
          key.push_back(f.core[j].second);
        }
      }
    }
  }

  // Rasterizes `chart` at `scale` as place_on_page() would, without placing
  // it: for footprint_key().
  void rasterize(const Profile_chart& chart, double scale) { rasterize_turns(chart, scale); }

private:
  enum class Fit { too_large, no_room, placed };

  // An empty strip of rows_ rows.
  void clear()
  {
    occupancy_.reset(rows_, n_);
    used_rows_ = 0;
    lowest_row_.clear();
  }

  // Places the charts of `order` in turn on an empty strip of rows_ rows;
  // stops at the first chart that fits nowhere (returns false).
  bool pack(const std::vector<Profile_chart>& charts, const std::vector<std::size_t>& order, double scale,
            std::vector<Profile_placement>& out)
  {
    clear();
    std::size_t zone_area = 0;
    for(std::size_t i : order)
    {
      const Fit fit = place_chart(charts[i], scale, out[i], zone_area);
      if(fit != Fit::placed)
      {
        used_rows_ = fit == Fit::too_large ? 0 : rows_ + 1;
        return false;
      }
    }
    return true;
  }

  // Places one chart where its top ends lowest (see below); used_rows_
  // grows to its top.
  Fit place_chart(const Profile_chart& chart, double scale, Profile_placement& out, std::size_t& zone_area)
  {
    const bool side_by_side = rasterize_turns(chart, scale);
    zone_area = (std::numeric_limits<std::size_t>::max)();
    for(int eighths = 0; eighths < 8; ++eighths)
      if(usable_[eighths])
        zone_area = (std::min)(zone_area, footprints_[eighths].zone_area);
    if(std::find(usable_, usable_ + 8, true) == usable_ + 8)
      return Fit::too_large;
    // The orientation and position where the chart's top ends lowest,
    // then the lowest, then the leftmost. Measured on the 23 shipped
    // meshes (median UV area over the square): 0.558 with the lowest
    // bottom first, 0.586 with the lowest top; on 90 atlases (30 meshes,
    // 3 bounds) it packs 0.008-0.020 more on the mean, better on 56, worse
    // on 12.
    const Position best = side_by_side ? lowest_position_by_turn() : lowest_position();
    if(best.turns < 0)
      return Fit::no_room;
    const long best_x = best.x, best_y = best.y;
    const int best_turns = best.turns;
    occupancy_.place(footprints_[best_turns], best_x, best_y);
    used_rows_ = (std::max)(used_rows_, static_cast<std::size_t>(best_y + footprints_[best_turns].height));
    out.turns = best_turns / 2;
    out.diagonal = best_turns % 2 == 1;
    out.x = double(best_x + static_cast<long>(pad_)) / double(n_);
    out.y = double(best_y + static_cast<long>(pad_)) / double(n_);
    return Fit::placed;
  }

  // Rasterizes the chart in the turns it may take (usable_, footprints_);
  // returns whether its turns are searched side by side.
  bool rasterize_turns(const Profile_chart& chart, double scale)
  {
    // Small charts gain little from more orientations and are most of the
    // search on meshes with hundreds of charts. Measured on cheese (964
    // charts): 8 orientations for all 0.354 of the square in 10.1 s, as
    // here 0.334 in 1.2 s; ChineseDragon-10kv 0.655 in 0.89 s, as here
    // 0.658 in 0.57 s.
    const double cells = chart.area * std::pow(scale * chart.density * double(n_), 2);
    const int step = cells < 100. ? 4 : cells < 400. ? 2 : 1;
    // Measured with two threads on 30 atlases: 0.77 of the time with the
    // turns of the large charts side by side, 0.67 with those of all
    // charts (cheese, 922 charts: 0.60). Not below 64 cells, where
    // handing the turns out costs more than their search once full rows
    // are skipped (see lowest_row()): 20k tetrahedra beside a torus
    // 2.6 -> 0.9 s, cheese and b9_mesh unchanged.
    const bool side_by_side = parallel_ && cells >= 64.;
    for_each_piece(8, side_by_side, [&](int eighths) {
      usable_[eighths] = eighths % step == 0 &&
                         rasterize_footprint(chart, scale, eighths, n_, page_rows_, pad_, footprints_[eighths]);
    });
    return side_by_side;
  }

public:
  // Whether the turns of a large chart are rasterized and searched on
  // several threads (with TBB). The layout is the same either way.
  void set_parallel(bool parallel) { parallel_ = with_tbb && parallel; }

private:
  typedef Raster_footprint Footprint;

  // A position of the current chart: lower left of its zone and turn.
  struct Position
  {
    long top = (std::numeric_limits<long>::max)(), y = -1, x = 0;
    int turns = -1;  // in eighths; -1: none

    bool operator<(const Position& o) const
    {
      return top < o.top || (top == o.top && (y < o.y || (y == o.y && (x < o.x || (x == o.x && turns < o.turns)))));
    }
  };

  // The least position (top, then row, then column, then turn) over the
  // usable turns: every turn is tried row by row, up to the row where even
  // the flattest one could not end lower.
  Position lowest_position()
  {
    long shortest = (std::numeric_limits<long>::max)();
    long lowest[8];  // per turn: rows below it do not fit
    for(int eighths = 0; eighths < 8; ++eighths)
      if(usable_[eighths])
      {
        shortest = (std::min)(shortest, footprints_[eighths].height);
        lowest[eighths] = lowest_row(footprints_[eighths]);
      }
    Position best;
    for(long y = 0; y < static_cast<long>(rows_) && y + shortest < best.top; ++y)
      for(int eighths = 0; eighths < 8; ++eighths)
      {
        const Footprint& f = footprints_[eighths];
        long x = 0;
        if(!usable_[eighths] || y < lowest[eighths] || y + f.height > static_cast<long>(rows_) ||
           !(y + f.height < best.top || (y + f.height == best.top && y == best.y)))
          continue;
        const bool fits = occupancy_.leftmost_fit(f, y, x);
        if(!fits && y == lowest[eighths])
          ++lowest[eighths];
        if(fits && (y + f.height < best.top || x < best.x))
        {
          best.x = x;
          best.y = y;
          best.top = y + f.height;
          best.turns = eighths;
        }
      }
    for(int eighths = 0; eighths < 8; ++eighths)
      if(usable_[eighths])
        raise_lowest_row(footprints_[eighths], lowest[eighths]);
    return best;
  }

  // The same position, each turn searched on its own from the bottom up to
  // its first fit, which is its least position. A turn stops early only
  // when it can no longer end as low as a top another turn reached, so
  // the least of the eight is the same whatever the threads' timing.
  Position lowest_position_by_turn()
  {
    Position found[8];
    long lowest[8];  // per turn: rows below it do not fit
    for(int eighths = 0; eighths < 8; ++eighths)
      lowest[eighths] = usable_[eighths] ? lowest_row(footprints_[eighths]) : 0;
#ifdef CGAL_LINKED_WITH_TBB
    std::atomic<long> lowest_top((std::numeric_limits<long>::max)());
#else
    long lowest_top = (std::numeric_limits<long>::max)();
#endif
    for_each_piece(8, true, [&](int eighths) {
      if(!usable_[eighths])
        return;
      const Footprint& f = footprints_[eighths];
      for(long& y = lowest[eighths]; y + f.height <= static_cast<long>(rows_); ++y)
      {
        long top = lowest_top;
        if(y + f.height > top)
          return;
        long x = 0;
        if(!occupancy_.leftmost_fit(f, y, x))
          continue;
        found[eighths].top = y + f.height;
        found[eighths].y = y;
        found[eighths].x = x;
        found[eighths].turns = eighths;
#ifdef CGAL_LINKED_WITH_TBB
        while(found[eighths].top < top && !lowest_top.compare_exchange_weak(top, found[eighths].top))
        {
        }
#else
        lowest_top = (std::min)(lowest_top, found[eighths].top);
#endif
        return;
      }
    });
    for(int eighths = 0; eighths < 8; ++eighths)
      if(usable_[eighths])
        raise_lowest_row(footprints_[eighths], lowest[eighths]);
    return *std::min_element(found, found + 8);
  }


  // The rows below which a zone of the same shape as f's did not fit,
  // earlier in this run: cells are only ever occupied during a run, so
  // such a row stays full for it. Many small charts (a mesh of thousands
  // of small parts) share a few zone shapes; each searched the filled rows
  // from the bottom again (20k tetrahedra beside a 100k-face torus: 58 s
  // of packing). The search is unchanged, it only skips rows known full.
  long lowest_row(const Footprint& f) const
  {
    const auto it = lowest_row_.find(f.shape);
    return it == lowest_row_.end() ? 0 : it->second;
  }

  void raise_lowest_row(const Footprint& f, long row)
  {
    long& lowest = lowest_row_[f.shape];
    lowest = (std::max)(lowest, row);
  }

  // Rounding of the coordinates must not move a corner out of its cells.
  std::size_t n_, page_rows_, rows_, pad_;
  std::size_t used_rows_ = 0;
  Page_occupancy occupancy_;
  struct Shape_hash
  {
    std::size_t operator()(const std::vector<long>& shape) const
    {
      std::uint64_t h = 0xcbf29ce484222325ull;
      for(long v : shape)
        h = (h ^ static_cast<std::uint64_t>(v)) * 0x100000001b3ull;
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  std::unordered_map<std::vector<long>, long, Shape_hash> lowest_row_;
  Footprint footprints_[8];
  bool usable_[8];
  bool parallel_ = false;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_RASTER_PACKER_H

