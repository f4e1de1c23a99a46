// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's parallel loops: on TBB with a bound on the threads, or
// serial without TBB.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_EXECUTION_PARALLEL_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_EXECUTION_PARALLEL_H

#include <CGAL/use.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_for_each.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <iterator>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Runs `work()` on up to `threads` threads (0: TBB's choice): the TBB
// loops it starts use no more. Without TBB, or with one thread, it runs
// `work()` as it is.
template <typename Work>
void within_arena(unsigned int threads, const Work& work)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(threads != 1)
  {
    // More threads than the machine runs would only make TBB warn.
    const int available = tbb::info::default_concurrency();
    const int wanted = threads == 0 || threads > static_cast<unsigned int>(available) ? available
                                                                                      : static_cast<int>(threads);
    tbb::task_arena arena(wanted);
    arena.execute([&] { work(); });
    return;
  }
#else
  CGAL_USE(threads);
#endif
  work();
}

// Whether the TBB loops below can run in parallel at all.
#ifdef CGAL_LINKED_WITH_TBB
constexpr bool with_tbb = true;
#else
constexpr bool with_tbb = false;
#endif

// Runs `work(i)` for i in [0, n): as tasks of the current arena (see
// within_arena()) if `parallel`, else in order. For a few large pieces of
// work; each call must touch only its own data.
template <typename Work>
void for_each_piece(int n, bool parallel, const Work& work)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(parallel)
  {
    tbb::parallel_for(0, n, [&](int i) { work(i); });
    return;
  }
#else
  CGAL_USE(parallel);
#endif
  for(int i = 0; i < n; ++i)
    work(i);
}

// Runs `work(i)` for i in [0, n), on up to `threads` threads (0: TBB's
// choice), each thread taking the next index as soon as it is free: given
// the costliest work first (see largest_first()), the threads end together.
// Each call must touch only its own data.
template <typename Work>
void for_each_index(std::size_t n, unsigned int threads, const Work& work)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(threads != 1 && n > 1)
  {
    within_arena(threads, [&] {
      std::atomic<std::size_t> next(0);
      // One task per thread of the arena; a task that starts late finds
      // less (or nothing) left.
      tbb::parallel_for(0, tbb::this_task_arena::max_concurrency(), [&](int) {
        for(std::size_t i = next++; i < n; i = next++)
          work(i);
      });
    });
    return;
  }
#else
  CGAL_USE(threads);
#endif
  for(std::size_t i = 0; i < n; ++i)
    work(i);
}

// Runs `work(item, add)` for every item of `items` and every item that a
// call adds by `add(std::move(next))`, on up to `threads` threads (0: TBB's
// choice). A thread takes new work as soon as it is free, so work that
// makes more work (a chart rejected into its pieces) keeps every thread
// busy without a barrier per level. Without TBB, or with one thread, the
// last item added runs first (depth first). Each call must touch only its
// own data; the order of the calls is not fixed.
template <typename Item, typename Work>
void for_each_growing(std::vector<Item> items, unsigned int threads, const Work& work)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(threads != 1)
  {
    within_arena(threads, [&] {
      tbb::parallel_for_each(items.begin(), items.end(), [&](Item& item, tbb::feeder<Item>& feeder) {
        work(item, [&feeder](Item&& next) { feeder.add(std::move(next)); });
      });
    });
    return;
  }
#else
  CGAL_USE(threads);
#endif
  std::vector<Item> stack(std::make_move_iterator(items.rbegin()), std::make_move_iterator(items.rend()));
  // Ends when the work stops adding items.
  while(!stack.empty())
  {
    Item item = std::move(stack.back());
    stack.pop_back();
    work(item, [&stack](Item&& next) { stack.push_back(std::move(next)); });
  }
}

// The indices [0, n) by decreasing `size(i)`, equal sizes by index: the
// order in which to hand out work whose cost grows with its size.
template <typename Size>
std::vector<std::size_t> largest_first(std::size_t n, const Size& size)
{
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return size(a) > size(b); });
  return order;
}

// Runs `work(i)` for i in [0, n) through `for_each` (a loop like
// for_each_index(), given `n` and the work on a position), the largest
// `size(i)` handed out first.
template <typename ForEach, typename Size, typename Work>
void for_each_largest_first(const ForEach& for_each, std::size_t n, const Size& size, const Work& work)
{
  const std::vector<std::size_t> order = largest_first(n, size);
  for_each(n, [&](std::size_t k) { work(order[k]); });
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_EXECUTION_PARALLEL_H
