// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Rectangle packing of the tight chart layout: a skyline packer with the
// best-fit rule of Burke, Kendall & Whitwell (2004), run inside a search for
// the largest common scale at which all rectangles fit in the unit square.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CHART_PACKER_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CHART_PACKER_H

#include <CGAL/disable_warnings.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Lower-left corner of a packed rectangle; `rotated` when it was placed with
// its sides swapped (a quarter turn counterclockwise).
struct Packed_rectangle
{
  double x = 0., y = 0.;
  bool rotated = false;
};

// Packs rectangles of sizes (scale * w[i] + pad, scale * h[i] + pad) into a
// strip of a given width, and says how high the packing goes.
//
// The skyline is a list of segments. At each step the lowest segment (then
// the leftmost) is the gap to fill, and the widest remaining rectangle that
// fits its width, in either orientation, goes in it, against the higher of
// the gap's two neighbors. When nothing fits, the gap is raised to its lower
// neighbor and the area below is lost. Rectangles of a given width are found
// by binary search in orders sorted once for all scales (an affine map with a
// positive factor keeps the order), and removed ones are skipped with
// union-find links, so one run costs O(n log n).
class Chart_packer
{
public:
  Chart_packer(const std::vector<double>& w, const std::vector<double>& h)
  {
    CGAL_precondition(w.size() == h.size());
    const std::size_t n = w.size();
    std::vector<std::size_t> by_w(n), by_h(n);
    std::iota(by_w.begin(), by_w.end(), std::size_t(0));
    std::iota(by_h.begin(), by_h.end(), std::size_t(0));
    // Among equal widths the last position, which the search finds first,
    // is the taller rectangle, then the larger id.
    std::sort(by_w.begin(), by_w.end(), [&](std::size_t a, std::size_t b)
              { return w[a] < w[b] || (w[a] == w[b] && (h[a] < h[b] || (h[a] == h[b] && a < b))); });
    std::sort(by_h.begin(), by_h.end(), [&](std::size_t a, std::size_t b)
              { return h[a] < h[b] || (h[a] == h[b] && (w[a] < w[b] || (w[a] == w[b] && a < b))); });
    std::vector<std::size_t> rank_w(n), rank_h(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      rank_w[by_w[k]] = k;
      rank_h[by_h[k]] = k;
    }
    // Each order keeps what a placement reads next to each other.
    upright_.resize(n);
    turned_.resize(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      upright_[k] = Entry{ w[by_w[k]], h[by_w[k]], by_w[k], rank_h[by_w[k]] };
      turned_[k] = Entry{ h[by_h[k]], w[by_h[k]], by_h[k], rank_w[by_h[k]] };
    }
  }

  std::size_t size() const { return upright_.size(); }

  // Packs into [0, width] x [0, infinity) and returns the height reached, or
  // infinity as soon as a rectangle would end above `height_limit`. `out`
  // gets one entry per rectangle, in input order.
  double run(double scale, double pad, double width, double height_limit, std::vector<Packed_rectangle>& out)
  {
    const double infinity = std::numeric_limits<double>::infinity();
    const std::size_t n = size();
    out.assign(n, Packed_rectangle());
    if(n == 0)
      return 0.;
    // Placed widths, upright and turned, in search order.
    sorted_upright_.resize(n);
    sorted_turned_.resize(n);
    for(std::size_t k = 0; k < n; ++k)
    {
      sorted_upright_[k] = scale * upright_[k].width + pad;
      sorted_turned_[k] = scale * turned_[k].width + pad;
      if((std::max)(sorted_upright_[k], scale * upright_[k].height + pad) > (std::min)(width, height_limit))
        return infinity;
    }
    alive_upright_.resize(n);
    alive_turned_.resize(n);
    std::iota(alive_upright_.begin(), alive_upright_.end(), std::size_t(0));
    std::iota(alive_turned_.begin(), alive_turned_.end(), std::size_t(0));
    std::size_t narrowest_upright = 0, narrowest_turned = 0;

    segments_.clear();
    segments_.reserve(n + 2);
    heap_ = Heap();
    segments_.push_back(Segment{ 0., width, 0., none, none, 0, true });
    push(0);

    // Bound: a pass places a rectangle (n times, at most one new segment
    // each) or raises a gap to a neighbor's height and merges the two (also
    // with NaN heights), which kills a segment: at most n raises, 2 n passes.
    double top = 0.;
    for(std::size_t remaining = n; remaining > 0;)
    {
      const std::size_t s = pop_lowest();
      const double gap = segments_[s].end - segments_[s].begin;
      // Most gaps that nothing fits are narrower than every rectangle left.
      // The positions only move past removed rectangles, and `remaining` > 0
      // are alive: below n, and n steps per run in all.
      while(alive_upright_[narrowest_upright] != narrowest_upright) ++narrowest_upright;
      while(alive_turned_[narrowest_turned] != narrowest_turned) ++narrowest_turned;
      std::size_t ku = none, kt = none;
      if(!(gap < sorted_upright_[narrowest_upright]))
        ku = find(alive_upright_, last_not_above(sorted_upright_, gap));
      if(!(gap < sorted_turned_[narrowest_turned]))
        kt = find(alive_turned_, last_not_above(sorted_turned_, gap));
      if(ku == none && kt == none)
      {
        if(!raise(s))
          return infinity;
        continue;
      }
      // The wider fit wins; on a tie the upright one.
      const bool turned = ku == none || (kt != none && sorted_turned_[kt] > sorted_upright_[ku]);
      const Entry& e = turned ? turned_[kt] : upright_[ku];
      const double placed_width = scale * e.width + pad;
      const double placed_height = scale * e.height + pad;
      if(segments_[s].y + placed_height > height_limit)
        return infinity;
      top = (std::max)(top, segments_[s].y + placed_height);
      out[e.id] = place(s, placed_width, placed_height);
      out[e.id].rotated = turned;
      kill(alive_upright_, turned ? e.other_rank : ku);
      kill(alive_turned_, turned ? kt : e.other_rank);
      --remaining;
    }
    return top;
  }

private:
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();
  // Heights closer than this are merged (the lower segment is raised), which
  // only wastes area and never makes rectangles overlap.
  static constexpr double merge_tolerance = 1e-13;

  struct Segment
  {
    double begin, end, y;
    std::size_t prev, next;
    std::uint32_t version;
    bool alive;
  };

  struct Heap_entry
  {
    double y, x;
    std::size_t segment;
    std::uint32_t version;
    bool operator>(const Heap_entry& o) const
    {
      return y > o.y || (y == o.y && (x > o.x || (x == o.x && segment > o.segment)));
    }
  };
  typedef std::priority_queue<Heap_entry, std::vector<Heap_entry>, std::greater<Heap_entry> > Heap;

  // Last position whose value is <= `value`, or `none`.
  static std::size_t last_not_above(const std::vector<double>& sorted, double value)
  {
    const std::size_t end = static_cast<std::size_t>(std::upper_bound(sorted.begin(), sorted.end(), value) - sorted.begin());
    return end == 0 ? none : end - 1;
  }

  // Largest position <= k still alive, or `none`. A live position links to
  // itself, a removed one to a smaller position (or `none`), so both loops
  // end within k + 1 steps.
  static std::size_t find(std::vector<std::size_t>& link, std::size_t k)
  {
    std::size_t root = k;
    while(root != none && link[root] != root) root = link[root];
    while(k != none && link[k] != k)
    {
      const std::size_t next = link[k];
      link[k] = root;
      k = next;
    }
    return root;
  }

  static void kill(std::vector<std::size_t>& link, std::size_t k) { link[k] = (k == 0) ? none : k - 1; }

  void push(std::size_t s)
  {
    Segment& g = segments_[s];
    ++g.version;
    heap_.push(Heap_entry{ g.y, g.begin, s, g.version });
  }

  // Lazy heap: every live segment has an entry of its current version (each
  // change is followed by push), so this ends within the pushes: at most
  // 1 + 2 per placement + 1 per raise.
  std::size_t pop_lowest()
  {
    for(;;)
    {
      CGAL_assertion(!heap_.empty());
      const Heap_entry e = heap_.top();
      heap_.pop();
      const Segment& g = segments_[e.segment];
      if(g.alive && g.version == e.version)
        return e.segment;
    }
  }

  // Merges `b` into its left neighbor `a` if their heights (nearly) agree.
  // Returns the segment that now holds `b`'s span: `a` if merged, else `b`.
  std::size_t merge(std::size_t a, std::size_t b)
  {
    if(a == none || b == none)
      return a == none ? b : a;
    Segment& l = segments_[a];
    Segment& r = segments_[b];
    if(std::abs(l.y - r.y) > merge_tolerance)
      return b;
    l.end = r.end;
    l.y = (std::max)(l.y, r.y);
    l.next = r.next;
    if(r.next != none) segments_[r.next].prev = a;
    r.alive = false;
    return a;
  }

  // Raises a gap that no rectangle fits to its lower neighbor.
  bool raise(std::size_t s)
  {
    const std::size_t l = segments_[s].prev, r = segments_[s].next;
    if(l == none && r == none)
      return false;
    const double yl = (l == none) ? (std::numeric_limits<double>::max)() : segments_[l].y;
    const double yr = (r == none) ? (std::numeric_limits<double>::max)() : segments_[r].y;
    segments_[s].y = (std::min)(yl, yr);
    const std::size_t m = merge(l, s);
    merge(m, segments_[m].next);
    push(m);
    return true;
  }

  Packed_rectangle place(std::size_t s, double width, double height)
  {
    const double infinity = (std::numeric_limits<double>::max)();
    const std::size_t l = segments_[s].prev, r = segments_[s].next;
    const double yl = (l == none) ? infinity : segments_[l].y;
    const double yr = (r == none) ? infinity : segments_[r].y;
    const double y = segments_[s].y;
    const double top = y + height;
    Packed_rectangle placed;
    placed.y = y;

    if(!(segments_[s].begin + width < segments_[s].end))
    {
      // Exact fit: the gap itself rises.
      placed.x = segments_[s].begin;
      segments_[s].y = top;
      const std::size_t m = merge(l, s);
      merge(m, segments_[m].next);
      push(m);
      return placed;
    }

    const std::size_t t = segments_.size();
    if(yl >= yr)
    {
      // Against the left neighbor (or wall): the rectangle's segment comes first.
      const double split = segments_[s].begin + width;
      segments_.push_back(Segment{ segments_[s].begin, split, top, l, s, 0, true });
      if(l != none) segments_[l].next = t;
      segments_[s].prev = t;
      segments_[s].begin = split;
      placed.x = segments_[t].begin;
      push(s);
      push(merge(l, t));
    }
    else
    {
      const double split = segments_[s].end - width;
      segments_.push_back(Segment{ split, segments_[s].end, top, s, r, 0, true });
      if(r != none) segments_[r].prev = t;
      segments_[s].next = t;
      segments_[s].end = split;
      placed.x = split;
      push(s);
      merge(t, r);
      push(t);
    }
    return placed;
  }

  // A rectangle in one search order, with its position in the other order.
  struct Entry
  {
    double width, height;
    std::size_t id;
    std::size_t other_rank;
  };

  std::vector<Entry> upright_, turned_;
  std::vector<double> sorted_upright_, sorted_turned_;
  std::vector<std::size_t> alive_upright_, alive_turned_;
  std::vector<Segment> segments_;
  Heap heap_;
};

// Result of `pack_in_square()`: the common scale and each rectangle's place.
struct Square_packing
{
  double scale = 0.;
  std::vector<Packed_rectangle> rectangles;
};

// The largest scale found at which the rectangles (scale * w[i] + pad,
// scale * h[i] + pad) pack into [0, width] x [0, height], with their
// places; a scale of 0 when none was found.
//
// Success is not monotone in the scale, so the search keeps the largest scale
// that succeeded. It starts at an upper bound (the area and the longest side
// of the rectangles), then each run's density (rectangle area over the area
// it used) predicts the scale at which the packing would just fill the
// square; steps are at least half a percent so that the boundary is soon
// crossed, and once a bracket is within 2 percent it is bisected down to
// `relative_precision`. This takes about half the runs of plain bisection.
inline Square_packing pack_in_rectangle(const std::vector<double>& w, const std::vector<double>& h, double pad,
                                        double width, double height, double relative_precision = 5e-4)
{
  Square_packing result;
  const std::size_t n = w.size();
  if(n == 0)
    return result;
  // Area of the grown rectangles at scale s: a s^2 + b s + c.
  double a = 0., b = 0., longest = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    a += w[i] * h[i];
    b += pad * (w[i] + h[i]);
    longest = (std::max)(longest, (std::max)(w[i], h[i]));
  }
  const double c = static_cast<double>(n) * pad * pad;
  const double area = width * height;
  if(!(longest > 0.) || !((std::min)(width, height) - pad > 0.) || !(c < area))
    return result;
  auto grown_area = [&](double s) { return (a * s + b) * s + c; };
  // The scale at which the grown area is `target` (> c).
  auto scale_for_area = [&](double target)
  {
    if(!(target > c)) return 0.;
    if(!(a > 0.)) return (b > 0.) ? (target - c) / b : 0.;
    return (-b + std::sqrt(b * b + 4. * a * (target - c))) / (2. * a);
  };

  // A rectangle may be turned, so the longest side bounds by the longer side.
  double upper = ((std::max)(width, height) - pad) / longest;
  if(a > 0.)
    upper = (std::min)(upper, std::sqrt(area / a));

  Chart_packer packer(w, h);
  std::vector<Packed_rectangle> trial;
  const double infinity = std::numeric_limits<double>::infinity();
  double lo = 0., hi = infinity, scale = upper;
  // At most 60 packing runs, whatever the scales (a NaN one ends the search).
  for(int run = 0; run < 60 && scale > 0.; ++run)
  {
    // Runs may go up to twice the height to measure how far off they are.
    const double used_height = packer.run(scale, pad, width, 2. * height, trial);
    if(used_height <= height)
    {
      if(scale > result.scale)
      {
        result.scale = scale;
        result.rectangles.swap(trial);
      }
      lo = (std::max)(lo, scale);
      if(scale >= upper)
        break;
    }
    else
      hi = (std::min)(hi, scale);
    if(lo > 0. && hi <= lo * (1. + relative_precision))
      break;

    double next;
    if(lo > 0. && hi <= lo * 1.02)
      next = 0.5 * (lo + hi);
    else
    {
      const double used = width * (used_height <= height ? used_height : (std::min)(used_height, 2. * height));
      next = scale_for_area(grown_area(scale) / used * area);
      next = (used_height <= height) ? (std::max)(next, scale * 1.005) : (std::min)(next, scale * 0.995);
      if(!(next > lo && next < hi))
        next = (lo > 0. && hi < infinity) ? 0.5 * (lo + hi) : (lo > 0. ? (std::min)(upper, 2. * lo) : 0.5 * hi);
    }
    scale = (std::min)(next, upper);
  }
  return result;
}

// pack_in_rectangle() into [0, side]^2.
inline Square_packing pack_in_square(const std::vector<double>& w, const std::vector<double>& h, double pad,
                                     double side, double relative_precision = 5e-4)
{
  return pack_in_rectangle(w, h, pad, side, side, relative_precision);
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_CHART_PACKER_H
