// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Local numbering of the faces or vertices a region meets, in memory
// proportional to the region: thread scratch that never grows to the mesh.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_SLOTS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_SLOTS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Lets `scratch` go when its room is far more than `needed`: thread scratch
// sized by one large region would otherwise keep that size.
template <typename T>
void release_if_far_larger(std::vector<T>& scratch, std::size_t needed)
{
  if(scratch.capacity() > 1024 && scratch.capacity() > 8 * needed)
    std::vector<T>().swap(scratch);
}

// Numbers the mesh elements (faces or vertices) a region meets 0, 1, 2...
// in the order they are first met, in memory proportional to the region,
// not to the mesh: scratch held by every thread (chart splitters) would
// otherwise grow with mesh size times threads (measured at 16 threads on a
// 356k-face mesh: a third of the heap). The number an element gets does not
// depend on how it is stored, so results are the same either way:
// - when the caller gives the range of the keys and it is at most a few
//   times the region (the mesh is numbered along its surface, so a
//   region's indices are close together), an array over that range:
//   as fast as a mesh-sized one (a hash table made the disk test 2.6x
//   slower, 5 % of the whole atlas);
// - else an open-addressing table (Fibonacci hashing, linear probing).
class Region_slots
{
public:
  // Forgets every element; makes room for `expected` of them, all in
  // [lowest, highest]. O(expected) (scratch far larger than needed is let
  // go, so that one large region does not keep its size for the life of a
  // thread). A key outside the range later still works, only slower.
  void clear(std::size_t expected, Index lowest, Index highest)
  {
    const std::size_t span = lowest <= highest ? std::size_t(highest - lowest) + 1 : 0;
    if(span == 0 || span > (std::max)(std::size_t(64), direct_span_factor * expected))
    {
      clear(expected);
      return;
    }
    size_ = 0;
    lowest_ = lowest;
    release_if_far_larger(keys_, 0);
    release_if_far_larger(slots_, 0);
    keys_.clear();
    release_if_far_larger(direct_, span);
    direct_.assign(span, no_index);
  }

  // The same, with the keys' range unknown: the table.
  void clear(std::size_t expected)
  {
    size_ = 0;
    release_if_far_larger(direct_, 0);
    direct_.clear();
    clear_table(expected);
  }

  // Ranges over the keys of `keys` / over the corners of `faces`.
  template <typename Keys>
  void clear_for_keys(const Keys& keys)
  {
    Index lowest = no_index, highest = 0;
    for(Index k : keys)
    {
      lowest = (std::min)(lowest, k);
      highest = (std::max)(highest, k);
    }
    clear(keys.size(), lowest, highest);
  }
  void clear_for_corners(const Indexed_triangle_mesh& m, const std::vector<Index>& faces)
  {
    // A face's smallest vertex comes first (see Indexed_triangle_mesh).
    Index lowest = no_index, highest = 0;
    for(Index f : faces)
    {
      lowest = (std::min)(lowest, m.corners[f][0]);
      highest = (std::max)(highest, (std::max)(m.corners[f][1], m.corners[f][2]));
    }
    clear(faces.size(), lowest, highest);
  }

  std::size_t size() const { return size_; }

  // The number of `key`, given now if it has none yet.
  Index insert(Index key)
  {
    if(!direct_.empty())
    {
      if(Index(key - lowest_) < direct_.size())
      {
        Index& slot = direct_[Index(key - lowest_)];
        if(slot == no_index)
          slot = static_cast<Index>(size_++);
        return slot;
      }
      move_to_table();
    }
    if(2 * (size_ + 1) > keys_.size())
      grow();
    std::size_t i = home(key);
    while(keys_[i] != no_index)
    {
      if(keys_[i] == key)
        return slots_[i];
      i = (i + 1) & (keys_.size() - 1);
    }
    keys_[i] = key;
    slots_[i] = static_cast<Index>(size_);
    return static_cast<Index>(size_++);
  }

  // The number of `key`, or no_index if it has none.
  Index find(Index key) const
  {
    if(!direct_.empty())
      return Index(key - lowest_) < direct_.size() ? direct_[Index(key - lowest_)] : no_index;
    if(keys_.empty())
      return no_index;
    for(std::size_t i = home(key);; i = (i + 1) & (keys_.size() - 1))
    {
      if(keys_[i] == key)
        return slots_[i];
      if(keys_[i] == no_index)
        return no_index;
    }
  }

private:
  static constexpr std::size_t direct_span_factor = 32;

  static int bit_count(std::size_t power_of_two)
  {
    int bits = 0;
    while((std::size_t(1) << bits) < power_of_two)
      ++bits;
    return bits;
  }

  void clear_table(std::size_t expected)
  {
    std::size_t capacity = 16;
    while(capacity < 2 * expected)
      capacity *= 2;
    release_if_far_larger(keys_, capacity);
    release_if_far_larger(slots_, capacity);
    keys_.assign(capacity, no_index);
    slots_.resize(capacity);
    shift_ = 64 - bit_count(capacity);
  }

  std::size_t home(Index key) const
  {
    return static_cast<std::size_t>((static_cast<std::uint64_t>(key) * 0x9E3779B97F4A7C15ull) >> shift_);
  }

  void put(Index key, Index slot)
  {
    std::size_t i = home(key);
    while(keys_[i] != no_index)
      i = (i + 1) & (keys_.size() - 1);
    keys_[i] = key;
    slots_[i] = slot;
  }

  void grow()
  {
    std::vector<Index> keys, slots;
    keys.swap(keys_);
    slots.swap(slots_);
    clear_table((std::max)(std::size_t(8), keys.size()));
    for(std::size_t j = 0; j < keys.size(); ++j)
      if(keys[j] != no_index)
        put(keys[j], slots[j]);
  }

  void move_to_table()
  {
    std::vector<Index> direct;
    direct.swap(direct_);
    clear_table((std::max)(size_, direct.size() / direct_span_factor));
    for(std::size_t j = 0; j < direct.size(); ++j)
      if(direct[j] != no_index)
        put(Index(lowest_ + j), direct[j]);
  }

  std::vector<Index> direct_;  // slots of lowest_, lowest_ + 1...; empty: the table holds them
  Index lowest_ = 0;
  std::vector<Index> keys_, slots_;
  int shift_ = 64;
  std::size_t size_ = 0;
};

// A value for each element of a region (faces or vertices), numbered by
// Region_slots, so in memory proportional to the region; an element never
// given one reads as `absent`.
template <typename T>
class Region_values
{
public:
  explicit Region_values(T absent) : absent_(absent) {}

  // Forgets every value; most elements given one will be those of `keys`.
  void clear_for_keys(const std::vector<Index>& keys)
  {
    slots_.clear_for_keys(keys);
    release_if_far_larger(values_, keys.size());
    values_.clear();
  }

  // The value of `key`, `absent` until set.
  T& operator[](Index key)
  {
    const Index slot = slots_.insert(key);
    if(slot == values_.size())
      values_.push_back(absent_);
    return values_[slot];
  }

  // The value of `key` without giving it one.
  T at(Index key) const
  {
    const Index slot = slots_.find(key);
    return slot == no_index ? absent_ : values_[slot];
  }

  void set(Index key, T value) { (*this)[key] = value; }

private:
  Region_slots slots_;
  std::vector<T> values_;
  T absent_;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_REGION_SLOTS_H
