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

#include <CGAL/Disk_segmentation/internal/Packing/Profile_packer.h>
#include <CGAL/Disk_segmentation/internal/Execution/parallel.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <atomic>
#endif

#if defined(_MSC_VER)
#  include <intrin.h>
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

// Index of the lowest set bit of a non-zero word.
inline std::size_t lowest_set_bit(std::uint64_t v)
{
#if defined(_MSC_VER)
  unsigned long index;
  _BitScanForward64(&index, v);
  return static_cast<std::size_t>(index);
#else
  return static_cast<std::size_t>(__builtin_ctzll(v));
#endif
}

// Rows of cells, one bit per cell.
class Cell_rows
{
public:
  void reset(std::size_t rows, std::size_t columns)
  {
    columns_ = columns;
    words_ = (columns + 63) / 64;
    bits_.assign(rows * words_, 0);
  }

  std::size_t columns() const { return columns_; }

  // Marks cells [first, last] of row r.
  void set(std::size_t r, std::size_t first, std::size_t last)
  {
    std::uint64_t* row = &bits_[r * words_];
    const std::size_t w0 = first >> 6, w1 = last >> 6;
    const std::uint64_t head = ~std::uint64_t(0) << (first & 63);
    const std::uint64_t tail = ~std::uint64_t(0) >> (63 - (last & 63));
    if(w0 == w1)
    {
      row[w0] |= head & tail;
      return;
    }
    row[w0] |= head;
    for(std::size_t w = w0 + 1; w < w1; ++w)
      row[w] = ~std::uint64_t(0);
    row[w1] |= tail;
  }

  // The first marked cell of row r in [first, end), or end.
  std::size_t first_set(std::size_t r, std::size_t first, std::size_t end) const
  {
    const std::uint64_t* row = &bits_[r * words_];
    std::size_t w = first >> 6;
    std::uint64_t v = row[w] & (~std::uint64_t(0) << (first & 63));
    for(;;)
    {
      if(v != 0)
        return (std::min)(end, (w << 6) + lowest_set_bit(v));
      if(++w >= words_ || (w << 6) >= end)
        return end;
      v = row[w];
    }
  }

  // The first unmarked cell of row r from `first` on, or columns().
  std::size_t first_clear(std::size_t r, std::size_t first) const
  {
    const std::uint64_t* row = &bits_[r * words_];
    std::size_t w = first >> 6;
    std::uint64_t v = ~row[w] & (~std::uint64_t(0) << (first & 63));
    for(;;)
    {
      if(v != 0)
        return (std::min)(columns_, (w << 6) + lowest_set_bit(v));
      if(++w >= words_)
        return columns_;
      v = ~row[w];
    }
  }

private:
  std::size_t columns_ = 0, words_ = 0;
  std::vector<std::uint64_t> bits_;
};

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
  std::size_t free_cells() const { return free_cells_; }

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
    atlas_.reset(rows_, n_);
    longest_free_.assign(rows_, static_cast<long>(n_));
    occupied_run_.assign(rows_ * n_, 0);
    free_run_.resize(rows_ * n_);
    used_rows_ = 0;
    blocks_per_row_ = (n_ >> block_bits) + 1;
    block_longest_.resize(rows_ * blocks_per_row_);
    lowest_row_.clear();
    free_cells_ = rows_ * n_;
    for(std::size_t r = 0; r < rows_; ++r)
    {
      for(std::size_t c = 0; c < n_; ++c)
        free_run_[r * n_ + c] = static_cast<std::uint16_t>(n_ - c);
      for(std::size_t b = 0; b < blocks_per_row_; ++b)
        block_longest_[r * blocks_per_row_ + b] = static_cast<std::uint16_t>(n_ - (std::min)(n_, b << block_bits));
    }
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
    place(footprints_[best_turns], best_x, best_y);
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
      usable_[eighths] = eighths % step == 0 && footprint(chart, scale, eighths, footprints_[eighths]);
    });
    return side_by_side;
  }

public:
  // Whether the turns of a large chart are rasterized and searched on
  // several threads (with TBB). The layout is the same either way.
  void set_parallel(bool parallel) { parallel_ = with_tbb && parallel; }

private:
  typedef std::pair<long, long> Interval;  // cells [first, end) of a row

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
        const bool fits = leftmost_fit(f, y, x);
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
        if(!leftmost_fit(f, y, x))
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

  // A chart in one turn: the cells it covers (`core`, offset by the
  // padding) and the cells that must be free for it (`zone`: the core
  // grown by the padding in every direction), as intervals per row,
  // relative to the zone's lower left.
  struct Footprint
  {
    long width = 0, height = 0;
    std::size_t core_area = 0, zone_area = 0;  // in cells
    std::vector<Interval> core, zone;
    std::vector<std::size_t> core_begin, zone_begin;  // per row, and the end
    std::vector<long> longest;  // per row, the zone's longest interval
    std::vector<long> shape;    // width, height, then the zone's intervals row by row
    // Scratch of its rasterization, one per turn so that the turns of a
    // chart can be rasterized side by side.
    std::vector<Packing_point> points;
    Cell_rows cells, zone_cells;
    std::vector<std::pair<long, double>> crossings;
  };

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
  static constexpr double slack = 1e-9;

  // The leftmost position on row y at which f's zone meets no occupied
  // cell.
  bool leftmost_fit(const Footprint& f, long y, long& x_out) const
  {
    const long side = static_cast<long>(n_);
    for(long r = 0; r < f.height; ++r)
      if(longest_free_[y + r] < f.longest[r])
        return false;
    long x = 0;
    long failed_row = 0;  // checked first: it often fails again
    while(x + f.width <= side)
    {
      long jump = -1;
      // Rows from failed_row on, wrapping around (no division: this loop
      // is most of the packing time).
      for(long k = 0, r = failed_row; k < f.height && jump < 0; ++k, r = (r + 1 == f.height ? 0 : r + 1))
      {
        const std::size_t row = static_cast<std::size_t>(y + r) * n_;
        for(std::size_t j = f.zone_begin[r]; j < f.zone_begin[r + 1]; ++j)
        {
          const Interval& iv = f.zone[j];
          const std::size_t first = row + static_cast<std::size_t>(x + iv.first);
          const long length = iv.second - iv.first;
          if(free_run_[first] < length)
          {
            // The next shift at which this interval fits its row.
            jump = next_free_run(y + r, x + iv.first, length) - iv.first;
            failed_row = r;
            break;
          }
        }
      }
      if(jump < 0)
      {
        x_out = x;
        return true;
      }
      x = (std::max)(x + 1, jump);
    }
    return false;
  }

  // The first cell of row r from `c` on where `length` free cells start,
  // or n: blocks of cells where no such run starts are skipped whole.
  long next_free_run(long r, long c, long length) const
  {
    const std::size_t row = static_cast<std::size_t>(r) * n_;
    const std::size_t blocks = static_cast<std::size_t>(r) * blocks_per_row_;
    const long side = static_cast<long>(n_);
    while(c < side)
    {
      if(block_longest_[blocks + static_cast<std::size_t>(c >> block_bits)] < length)
      {
        c = (c | ((1L << block_bits) - 1)) + 1;
        continue;
      }
      const long free = free_run_[row + static_cast<std::size_t>(c)];
      if(free >= length)
        return c;
      c += free;
      if(c < side)
        c += occupied_run_[row + static_cast<std::size_t>(c)];
    }
    return side;
  }

  void place(const Footprint& f, long x, long y)
  {
    free_cells_ -= f.core_area;
    for(long r = 0; r < f.height; ++r)
    {
      const std::size_t row = static_cast<std::size_t>(y + r);
      for(std::size_t j = f.core_begin[r]; j < f.core_begin[r + 1]; ++j)
        atlas_.set(row, static_cast<std::size_t>(x + f.core[j].first),
                   static_cast<std::size_t>(x + f.core[j].second - 1));
      if(f.core_begin[r] != f.core_begin[r + 1])
        update_runs(row);
    }
  }

  // The free and occupied runs that start at each cell of row r, and the
  // row's longest free run.
  void update_runs(std::size_t r)
  {
    std::uint16_t* free = &free_run_[r * n_];
    std::uint16_t* occupied = &occupied_run_[r * n_];
    std::uint16_t* block = &block_longest_[r * blocks_per_row_];
    std::fill(block, block + blocks_per_row_, std::uint16_t(0));
    std::size_t longest = 0;
    // Run by run (a cell by cell scan was 1.6 % of one thread's time): a
    // free run [c, e), then an occupied run [e, o).
    for(std::size_t c = 0; c < n_;)
    {
      const std::size_t e = atlas_.first_set(r, c, n_);
      for(std::size_t k = c; k < e; ++k)
      {
        free[k] = static_cast<std::uint16_t>(e - k);
        occupied[k] = 0;
      }
      if(e > c)
      {
        longest = (std::max)(longest, e - c);
        // In each block, the longest free run starting there starts at
        // the run's first cell in that block.
        std::size_t b = c >> block_bits;
        block[b] = (std::max)(block[b], static_cast<std::uint16_t>(e - c));
        for(++b; (b << block_bits) < e; ++b)
          block[b] = (std::max)(block[b], static_cast<std::uint16_t>(e - (b << block_bits)));
      }
      if(e >= n_)
        break;
      const std::size_t o = atlas_.first_clear(r, e);
      for(std::size_t k = e; k < o; ++k)
      {
        occupied[k] = static_cast<std::uint16_t>(o - k);
        free[k] = 0;
      }
      c = o;
    }
    longest_free_[r] = static_cast<long>(longest);
  }

  // Rasterizes the chart at `scale` after `eighths` eighths of a turn.
  // Returns false if its zone is larger than the square.
  bool footprint(const Profile_chart& chart, double scale, int eighths, Footprint& f) const
  {
    const double to_cells = scale * chart.density * double(n_);
    std::vector<Packing_point>& points = f.points;
    Cell_rows& cells = f.cells;
    Cell_rows& zone_cells = f.zone_cells;
    std::vector<std::pair<long, double>>& crossings = f.crossings;
    points.resize(chart.number_of_corners);
    Packing_box box;
    for(std::size_t k = 0; k < chart.number_of_corners; ++k)
    {
      Packing_point q = chart.corners[k];
      for(int t = 0; t < eighths / 2; ++t)
        q = quarter_turn(q);
      if(eighths % 2 == 1)
        q = eighth_turn(q);
      points[k] = q;
      box.add(q);
    }
    const double w = to_cells * box.width(), h = to_cells * box.height();
    const long pad = static_cast<long>(pad_);
    if(!(w + double(2 * pad) < double(n_)) || !(h + double(2 * pad) < double(page_rows_)))
      return false;
    const long columns = (std::max)(1L, static_cast<long>(std::ceil(w + slack)));
    const long rows = (std::max)(1L, static_cast<long>(std::ceil(h + slack)));
    for(Packing_point& q : points)
      q = { to_cells * (q.x - box.xmin), to_cells * (q.y - box.ymin) };

    cells.reset(static_cast<std::size_t>(rows), static_cast<std::size_t>(columns));
    crossings.clear();
    // The cells the border touches, then those whose center is inside it:
    // a cell the chart covers but its border misses lies inside it. Whole
    // triangles cost their height in rows each, quadratic for the slivers
    // around a vertex of high valence.
    for(std::size_t k = 0; k + 2 < chart.number_of_corners; k += 3)
    {
      const Packing_point* t = &points[k];
      const unsigned char border = chart.border_edges[k / 3];
      for(int j = 0; j < 3; ++j)
        if(border & (1 << j))
        {
          mark_segment(t[j], t[(j + 1) % 3], rows, columns, cells);
          add_crossings(t[j], t[(j + 1) % 3], rows, crossings);
        }
    }
    std::sort(crossings.begin(), crossings.end());
    for(std::size_t k = 0; k + 1 < crossings.size(); k += 2)
    {
      if(crossings[k].first != crossings[k + 1].first)
      {
        --k;  // an odd count on a row (rounding): skip its last crossing
        continue;
      }
      const long first = static_cast<long>(std::ceil(crossings[k].second - 0.5));
      const long last = static_cast<long>(std::floor(crossings[k + 1].second - 0.5));
      if(first <= last && last >= 0 && first < columns)
        cells.set(static_cast<std::size_t>(crossings[k].first), static_cast<std::size_t>((std::max)(0L, first)),
                   static_cast<std::size_t>((std::min)(columns - 1, last)));
    }

    f.width = columns + 2 * pad;
    f.height = rows + 2 * pad;
    zone_cells.reset(static_cast<std::size_t>(f.height), static_cast<std::size_t>(f.width));
    f.core.clear();
    f.core_area = 0;
    f.core_begin.assign(1, 0);
    for(long r = 0; r < pad; ++r)
      f.core_begin.push_back(0);
    for(long r = 0; r < rows; ++r)
    {
      const std::size_t cols = static_cast<std::size_t>(columns);
      std::size_t c = cells.first_set(static_cast<std::size_t>(r), 0, cols);
      while(c < cols)
      {
        const std::size_t end = (std::min)(cols, cells.first_clear(static_cast<std::size_t>(r), c));
        f.core.emplace_back(static_cast<long>(c) + pad, static_cast<long>(end) + pad);
        f.core_area += end - c;
        for(long d = 0; d <= 2 * pad; ++d)
          zone_cells.set(static_cast<std::size_t>(r + d), c, end - 1 + static_cast<std::size_t>(2 * pad));
        if(end >= cols)
          break;
        c = cells.first_set(static_cast<std::size_t>(r), end, cols);
      }
      f.core_begin.push_back(f.core.size());
    }
    for(long r = 0; r < pad; ++r)
      f.core_begin.push_back(f.core.size());
    f.zone.clear();
    f.zone_area = 0;
    f.zone_begin.assign(1, 0);
    f.longest.assign(static_cast<std::size_t>(f.height), 0);
    const std::size_t width = static_cast<std::size_t>(f.width);
    for(long r = 0; r < f.height; ++r)
    {
      std::size_t c = zone_cells.first_set(static_cast<std::size_t>(r), 0, width);
      while(c < width)
      {
        const std::size_t end = (std::min)(width, zone_cells.first_clear(static_cast<std::size_t>(r), c));
        f.zone.emplace_back(static_cast<long>(c), static_cast<long>(end));
        f.zone_area += end - c;
        f.longest[r] = (std::max)(f.longest[r], static_cast<long>(end - c));
        if(end >= width)
          break;
        c = zone_cells.first_set(static_cast<std::size_t>(r), end, width);
      }
      f.zone_begin.push_back(f.zone.size());
    }
    f.shape.assign({ f.width, f.height });
    for(long r = 0; r < f.height; ++r)
    {
      f.shape.push_back(static_cast<long>(f.zone_begin[r + 1] - f.zone_begin[r]));
      for(std::size_t j = f.zone_begin[r]; j < f.zone_begin[r + 1]; ++j)
      {
        f.shape.push_back(f.zone[j].first);
        f.shape.push_back(f.zone[j].second);
      }
    }
    return true;
  }

  // Marks every cell the segment ab touches: per row, its x-range over the
  // row's slab.
  static void mark_segment(const Packing_point& a, const Packing_point& b, long rows, long columns, Cell_rows& cells)
  {
    // Rows are the slabs of the segment transposed.
    for_each_slab_of_segment({ a.y, a.x }, { b.y, b.x }, rows, slack, [&](long r, double xlo, double xhi) {
      const long c0 = (std::max)(0L, static_cast<long>(std::floor(xlo - slack)));
      const long c1 = (std::min)(columns - 1, static_cast<long>(std::floor(xhi + slack)));
      if(c0 <= c1)
        cells.set(static_cast<std::size_t>(r), static_cast<std::size_t>(c0), static_cast<std::size_t>(c1));
    });
  }

  // Where the border edge (a, b) crosses the centers of rows: a point is
  // counted on the side of its larger y, so that a closed border crosses
  // every row an even number of times.
  static void add_crossings(const Packing_point& a, const Packing_point& b, long rows,
                            std::vector<std::pair<long, double>>& crossings)
  {
    const double lo = (std::min)(a.y, b.y), hi = (std::max)(a.y, b.y);
    const long r0 = (std::max)(0L, static_cast<long>(std::ceil(lo - 0.5)));
    const long r1 = (std::min)(rows - 1, static_cast<long>(std::ceil(hi - 0.5)) - 1);
    for(long r = r0; r <= r1; ++r)
    {
      const double yc = double(r) + 0.5;
      if(!(lo <= yc && yc < hi))
        continue;
      crossings.emplace_back(r, a.x + (b.x - a.x) * (yc - a.y) / (b.y - a.y));
    }
  }

  std::size_t n_, page_rows_, rows_, pad_;
  std::size_t used_rows_ = 0;
  std::size_t free_cells_ = 0;
  Cell_rows atlas_;
  std::vector<long> longest_free_;
  std::vector<std::uint16_t> free_run_, occupied_run_;  // per cell, row by row
  static constexpr int block_bits = 4;
  std::size_t blocks_per_row_ = 0;
  std::vector<std::uint16_t> block_longest_;  // per block of cells, the longest free run starting in it
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
