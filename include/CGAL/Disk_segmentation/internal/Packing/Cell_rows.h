// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Rows of grid cells, one bit per cell: set a run, find the next set or
// clear cell. The raster packer draws its page and its charts in them.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CELL_ROWS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CELL_ROWS_H

#if defined(_MSC_VER)
#  include <intrin.h>
#endif

#include <cstddef>
#include <cstdint>
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

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CELL_ROWS_H
