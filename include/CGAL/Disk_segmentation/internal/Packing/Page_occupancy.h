// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cells of the raster packer's page that placed charts cover, kept as
// runs so that the leftmost free position of a chart is found in jumps.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PAGE_OCCUPANCY_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PAGE_OCCUPANCY_H

#include <CGAL/Disk_segmentation/internal/Packing/Cell_rows.h>
#include <CGAL/Disk_segmentation/internal/Packing/Raster_footprint.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The cells of a strip of rows that placed charts cover, and per cell the
// free and occupied runs that start there: a zone's leftmost fit on a row
// is then found by jumps rather than cell by cell.
class Page_occupancy
{
public:
  // An empty strip of `rows` rows of `columns` cells.
  void reset(std::size_t rows, std::size_t columns)
  {
    n_ = columns;
    atlas_.reset(rows, n_);
    longest_free_.assign(rows, static_cast<long>(n_));
    occupied_run_.assign(rows * n_, 0);
    free_run_.resize(rows * n_);
    blocks_per_row_ = (n_ >> block_bits) + 1;
    block_longest_.resize(rows * blocks_per_row_);
    free_cells_ = rows * n_;
    for(std::size_t r = 0; r < rows; ++r)
    {
      for(std::size_t c = 0; c < n_; ++c)
        free_run_[r * n_ + c] = static_cast<std::uint16_t>(n_ - c);
      for(std::size_t b = 0; b < blocks_per_row_; ++b)
        block_longest_[r * blocks_per_row_ + b] = static_cast<std::uint16_t>(n_ - (std::min)(n_, b << block_bits));
    }
  }

  // The cells no chart covers.
  std::size_t free_cells() const { return free_cells_; }

  // The leftmost position on row y at which f's zone meets no occupied
  // cell.
  bool leftmost_fit(const Raster_footprint& f, long y, long& x_out) const
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
          const Cell_interval& iv = f.zone[j];
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

  void place(const Raster_footprint& f, long x, long y)
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

private:
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

  std::size_t n_ = 0;  // columns
  std::size_t free_cells_ = 0;
  Cell_rows atlas_;
  std::vector<long> longest_free_;
  std::vector<std::uint16_t> free_run_, occupied_run_;  // per cell, row by row
  static constexpr int block_bits = 4;
  std::size_t blocks_per_row_ = 0;
  std::vector<std::uint16_t> block_longest_;  // per block of cells, the longest free run starting in it
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PAGE_OCCUPANCY_H
