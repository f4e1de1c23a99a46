// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Marks on the vertices or faces of a mesh that a search clears all at once
// in constant time: an element is marked in a round when its stamp is that
// round's number, so that a new round forgets every mark of the last.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_ROUND_STAMPS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_ROUND_STAMPS_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

class Round_stamps
{
public:
  explicit Round_stamps(std::size_t size) : stamp_(size, 0) {}

  // The number of a new round; the stamps are reset only when the counter
  // wraps around (once in 2^32 rounds).
  std::uint32_t next_round()
  {
    if(++round_ == 0)
    {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      round_ = 1;
    }
    return round_;
  }

  std::uint32_t& operator[](std::size_t i) { return stamp_[i]; }
  std::uint32_t operator[](std::size_t i) const { return stamp_[i]; }

private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t round_ = 0;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_ROUND_STAMPS_H
