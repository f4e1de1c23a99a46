// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Planar geometry of chart packing: the choice of the rotation under which
// a chart is boxed, and the slabs its edges cross.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PACKING_GEOMETRY_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PACKING_GEOMETRY_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Geometry/Planar_hull.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// A rotation p -> (c x - s y, s x + c y). It is kept as a (cosine, sine)
// pair so that quarter turns compose exactly.
struct Packing_rotation
{
  double c = 1., s = 0.;

  Planar_point operator()(const Planar_point& p) const { return { c * p.x - s * p.y, s * p.x + c * p.y }; }

  // This rotation followed by a quarter turn counterclockwise.
  Packing_rotation quarter_turned() const { return { -s, c }; }

  // This rotation followed by an eighth of a turn counterclockwise.
  Packing_rotation eighth_turned() const
  {
    const double h = std::sqrt(0.5);
    return { h * (c - s), h * (s + c) };
  }

  // The rotation that maps the unit direction u onto the x axis.
  static Packing_rotation aligning(const Planar_point& u) { return { u.x, -u.y }; }
};

// Axis-aligned bounding box of a chart in its rotated frame.
struct Packing_box
{
  double xmin = (std::numeric_limits<double>::max)(), ymin = (std::numeric_limits<double>::max)();
  double xmax = -(std::numeric_limits<double>::max)(), ymax = -(std::numeric_limits<double>::max)();

  double width() const { return xmax - xmin; }
  double height() const { return ymax - ymin; }

  void add(const Planar_point& p)
  {
    xmin = (std::min)(xmin, p.x); xmax = (std::max)(xmax, p.x);
    ymin = (std::min)(ymin, p.y); ymax = (std::max)(ymax, p.y);
  }

  // The box of the same points after a further quarter turn counterclockwise,
  // (x, y) -> (-y, x); negation is exact, so this equals recomputing it.
  Packing_box quarter_turned() const
  {
    Packing_box b;
    b.xmin = -ymax; b.xmax = -ymin; b.ymin = xmin; b.ymax = xmax;
    return b;
  }
};

// Extents of a convex polygon in the frame of a unit vector u: u and
// v = u turned a quarter counterclockwise. `e` joins the extreme vertices
// along -u and u, `g` those along -v and v, so that width = e.u and
// height = g.v; both stay valid for nearby frames until a support vertex
// changes, which lets callers solve for a frame in closed form.
struct Frame_extents
{
  double width = 0., height = 0.;
  Planar_point e{0., 0.}, g{0., 0.};
};

inline Planar_point quarter_turn(const Planar_point& u) { return { -u.y, u.x }; }

// The range [lo, hi] of the y-coordinates of segment ab over the slab
// left <= x <= right: its ends inside the slab and its crossings of the
// slab's two sides. Returns false if the segment misses the slab.
inline bool segment_slab_range(const Planar_point& a, const Planar_point& b, double left, double right,
                               double& lo, double& hi)
{
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for(const Planar_point* end : { &a, &b })
    if(end->x >= left && end->x <= right)
    {
      lo = (std::min)(lo, end->y);
      hi = (std::max)(hi, end->y);
    }
  for(double side : { left, right })
    if((a.x - side) * (b.x - side) < 0)
    {
      const double y = a.y + (b.y - a.y) * (side - a.x) / (b.x - a.x);
      lo = (std::min)(lo, y);
      hi = (std::max)(hi, y);
    }
  return lo <= hi;
}

// Calls visit(s, lo, hi) for each slab s <= x <= s + 1 (widened by
// `slack` on both sides), s in [0, slabs), that segment ab meets, with the
// range [lo, hi] of its y-coordinates there.
template <typename Visit>
void for_each_slab_of_segment(const Planar_point& a, const Planar_point& b, long slabs, double slack,
                              const Visit& visit)
{
  const long s0 = (std::max)(0L, static_cast<long>(std::floor((std::min)(a.x, b.x) - slack)));
  const long s1 = (std::min)(slabs - 1, static_cast<long>(std::floor((std::max)(a.x, b.x) + slack)));
  for(long s = s0; s <= s1; ++s)
  {
    double lo, hi;
    if(segment_slab_range(a, b, double(s) - slack, double(s + 1) + slack, lo, hi))
      visit(s, lo, hi);
  }
}

// An eighth of a turn counterclockwise, as Packing_rotation::eighth_turned().
inline Planar_point eighth_turn(const Planar_point& u)
{
  const double h = std::sqrt(0.5);
  return { h * (u.x - u.y), h * (u.x + u.y) };
}

inline Planar_point normalized(const Planar_point& u)
{
  const double l = std::sqrt(planar_dot(u, u));
  return { u.x / l, u.y / l };
}

// Rotating calipers: the four support vertices of a convex polygon in the
// directions u, v, -u, -v move counterclockwise as u turns counterclockwise,
// so a sequence of queries turning counterclockwise by less than a turn in
// all costs O(polygon size + number of queries).
class Support_sweep
{
public:
  explicit Support_sweep(const std::vector<Planar_point>& hull) : hull_(hull) {}

  Frame_extents operator()(const Planar_point& u)
  {
    Frame_extents r;
    if(hull_.empty())
      return r;
    const Planar_point d[4] = { u, { -u.y, u.x }, { -u.x, -u.y }, { u.y, -u.x } };
    for(int k = 0; k < 4; ++k)
      support_[k] = started_ ? advance(support_[k], d[k]) : scan(d[k]);
    started_ = true;
    const Planar_point& a = hull_[support_[0]]; const Planar_point& b = hull_[support_[2]];
    const Planar_point& c = hull_[support_[1]]; const Planar_point& e = hull_[support_[3]];
    r.e = { a.x - b.x, a.y - b.y };
    r.g = { c.x - e.x, c.y - e.y };
    r.width = planar_dot(r.e, u);
    r.height = planar_dot(r.g, d[1]);
    return r;
  }

private:
  std::size_t scan(const Planar_point& d) const
  {
    std::size_t best = 0;
    for(std::size_t i = 1; i < hull_.size(); ++i)
      if(planar_dot(hull_[i], d) > planar_dot(hull_[best], d)) best = i;
    return best;
  }

  // The bound on steps keeps rounding on nearly flat hulls from looping.
  std::size_t advance(std::size_t j, const Planar_point& d) const
  {
    const std::size_t n = hull_.size();
    for(std::size_t step = 0; step < n; ++step)
    {
      const std::size_t next = (j + 1 == n) ? 0 : j + 1;
      if(!(planar_dot(hull_[next], d) > planar_dot(hull_[j], d)))
        break;
      j = next;
    }
    return j;
  }

  const std::vector<Planar_point>& hull_;
  std::size_t support_[4] = { 0, 0, 0, 0 };
  bool started_ = false;
};

// Unit directions of the hull edges modulo a quarter turn, i.e. turned into
// the quadrant x > 0, y >= 0, sorted counterclockwise (by y), without
// repeats. A box of minimum area, or of minimum larger side, changes its
// support vertices only at these directions.
inline std::vector<Planar_point> hull_edge_directions(const std::vector<Planar_point>& hull)
{
  std::vector<Planar_point> directions;
  if(hull.size() < 2)
    return directions;
  directions.reserve(hull.size());
  for(std::size_t i = 0; i < hull.size(); ++i)
  {
    const Planar_point& a = hull[i];
    const Planar_point& b = hull[(i + 1) % hull.size()];
    Planar_point d{ b.x - a.x, b.y - a.y };
    if(d.x == 0. && d.y == 0.)
      continue;
    // Quarter turns clockwise, (x, y) -> (y, -x), are exact.
    for(int turns = 0; turns < 4 && !(d.x > 0. && d.y >= 0.); ++turns)
      d = { d.y, -d.x };
    directions.push_back(normalized(d));
  }
  std::sort(directions.begin(), directions.end(), [](const Planar_point& a, const Planar_point& b)
            { return a.y < b.y || (a.y == b.y && a.x > b.x); });
  directions.erase(std::unique(directions.begin(), directions.end(), [](const Planar_point& a, const Planar_point& b)
                               { return a.x == b.x && a.y == b.y; }),
                   directions.end());
  return directions;
}

// The frame (unit vector u) in which the hull has a bounding box of minimum
// area: one side of such a box contains a hull edge (Freeman & Shapira).
// Ties keep the first direction.
inline Planar_point minimum_area_box_direction(const std::vector<Planar_point>& hull)
{
  const std::vector<Planar_point> directions = hull_edge_directions(hull);
  Support_sweep sweep(hull);
  Planar_point best{ 1., 0. };
  double best_area = (std::numeric_limits<double>::max)();
  for(const Planar_point& u : directions)
  {
    const Frame_extents x = sweep(u);
    const double area = x.width * x.height;
    if(area < best_area)
    {
      best_area = area;
      best = u;
    }
  }
  return best;
}

// The frame (unit vector u) in which the larger side of the hull's bounding
// box is smallest, i.e. in which the chart can be scaled largest inside a
// square. Between two consecutive edge directions the support vertices are
// fixed, width and height are positive sinusoids of the angle, hence concave
// there, and the larger of the two is smallest at an end of the interval or
// where they cross; the crossing is solved in closed form. Ties keep the
// first direction found.
inline Planar_point minimum_square_box_direction(const std::vector<Planar_point>& hull)
{
  const std::vector<Planar_point> events = hull_edge_directions(hull);
  Planar_point best{ 1., 0. };
  if(events.empty())
    return best;
  Support_sweep sweep(hull);
  double best_side = (std::numeric_limits<double>::max)();
  auto consider = [&](const Planar_point& u, double side)
  {
    if(side < best_side)
    {
      best_side = side;
      best = u;
    }
  };
  for(std::size_t i = 0; i < events.size(); ++i)
  {
    const Planar_point& lo = events[i];
    const Planar_point hi = (i + 1 < events.size()) ? events[i + 1] : quarter_turn(events.front());
    const Frame_extents at_lo = sweep(lo);
    consider(lo, (std::max)(at_lo.width, at_lo.height));

    // Within the interval, width - height = a cos t + b sin t, which vanishes
    // along (b, -a) and its opposite.
    const Frame_extents mid = sweep(normalized({ lo.x + hi.x, lo.y + hi.y }));
    const double a = mid.e.x - mid.g.y, b = mid.e.y + mid.g.x;
    if(a == 0. && b == 0.)
      continue;
    Planar_point u = normalized({ b, -a });
    if(planar_dot(u, { lo.x + hi.x, lo.y + hi.y }) < 0.)
      u = { -u.x, -u.y };
    const Planar_point origin{ 0., 0. };
    if(planar_cross(origin, lo, u) >= 0. && planar_cross(origin, u, hi) >= 0.)
    {
      const double width = planar_dot(mid.e, u);
      const double height = planar_dot(mid.g, quarter_turn(u));
      consider(u, (std::max)(width, height));
    }
  }
  return best;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PACKING_GEOMETRY_H
