// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A chart rasterized on the packing grid in one of its eight turns: the
// cells it covers and the cells that must stay free around it.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_RASTER_FOOTPRINT_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_RASTER_FOOTPRINT_H

#include <CGAL/Disk_segmentation/internal/Packing/Cell_rows.h>
#include <CGAL/Disk_segmentation/internal/Packing/Profile_packer.h>
#include <CGAL/Disk_segmentation/internal/Packing/packing_geometry.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

typedef std::pair<long, long> Cell_interval;  // cells [first, end) of a row

// A chart in one turn: the cells it covers (`core`, offset by the
// padding) and the cells that must be free for it (`zone`: the core
// grown by the padding in every direction), as intervals per row,
// relative to the zone's lower left.
struct Raster_footprint
{
  long width = 0, height = 0;
  std::size_t core_area = 0, zone_area = 0;  // in cells
  std::vector<Cell_interval> core, zone;
  std::vector<std::size_t> core_begin, zone_begin;  // per row, and the end
  std::vector<long> longest;  // per row, the zone's longest interval
  std::vector<long> shape;    // width, height, then the zone's intervals row by row
  // Scratch of its rasterization, one per turn so that the turns of a
  // chart can be rasterized side by side.
  std::vector<Planar_point> points;
  Cell_rows cells, zone_cells;
  std::vector<std::pair<long, double>> crossings;
};

// Rounding of the coordinates must not move a corner out of its cells.
constexpr double raster_slack = 1e-9;

// Marks every cell the segment ab touches: per row, its x-range over the
// row's slab.
inline void mark_segment_cells(const Planar_point& a, const Planar_point& b, long rows, long columns,
                               Cell_rows& cells)
{
  // Rows are the slabs of the segment transposed.
  for_each_slab_of_segment({ a.y, a.x }, { b.y, b.x }, rows, raster_slack, [&](long r, double xlo, double xhi) {
    const long c0 = (std::max)(0L, static_cast<long>(std::floor(xlo - raster_slack)));
    const long c1 = (std::min)(columns - 1, static_cast<long>(std::floor(xhi + raster_slack)));
    if(c0 <= c1)
      cells.set(static_cast<std::size_t>(r), static_cast<std::size_t>(c0), static_cast<std::size_t>(c1));
  });
}

// Where the border edge (a, b) crosses the centers of rows: a point is
// counted on the side of its larger y, so that a closed border crosses
// every row an even number of times.
inline void add_row_crossings(const Planar_point& a, const Planar_point& b, long rows,
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

// Turns the corners of `chart` by `eighths` eighths of a turn into
// `f.points`, in cells (`to_cells` per unit of the chart's frame) from the
// lower left of their bounding box, `columns` by `rows` cells. False if
// that box, grown by `pad` cells on every side, is not smaller than the
// page (`page_columns` by `page_rows` cells).
inline bool turn_into_cells(const Profile_chart& chart, double to_cells, int eighths, long pad,
                            std::size_t page_columns, std::size_t page_rows, Raster_footprint& f, long& columns,
                            long& rows)
{
  std::vector<Planar_point>& points = f.points;
  points.resize(chart.number_of_corners);
  Packing_box box;
  for(std::size_t k = 0; k < chart.number_of_corners; ++k)
  {
    Planar_point q = chart.corners[k];
    for(int t = 0; t < eighths / 2; ++t)
      q = quarter_turn(q);
    if(eighths % 2 == 1)
      q = eighth_turn(q);
    points[k] = q;
    box.add(q);
  }
  const double w = to_cells * box.width(), h = to_cells * box.height();
  if(!(w + double(2 * pad) < double(page_columns)) || !(h + double(2 * pad) < double(page_rows)))
    return false;
  columns = (std::max)(1L, static_cast<long>(std::ceil(w + raster_slack)));
  rows = (std::max)(1L, static_cast<long>(std::ceil(h + raster_slack)));
  for(Planar_point& q : points)
    q = { to_cells * (q.x - box.xmin), to_cells * (q.y - box.ymin) };
  return true;
}

// Sets `f.cells` (`rows` by `columns`) to the cells the chart, its corners
// turned in `f.points`, covers: the cells its border touches, then those
// whose center is inside it (a cell the chart covers but its border misses
// lies inside it). Whole triangles would cost their height in rows each,
// quadratic for the slivers around a vertex of high valence.
inline void cover_chart_cells(const Profile_chart& chart, long rows, long columns, Raster_footprint& f)
{
  Cell_rows& cells = f.cells;
  std::vector<std::pair<long, double>>& crossings = f.crossings;
  cells.reset(static_cast<std::size_t>(rows), static_cast<std::size_t>(columns));
  crossings.clear();
  for(std::size_t k = 0; k + 2 < chart.number_of_corners; k += 3)
  {
    const Planar_point* t = &f.points[k];
    const unsigned char border = chart.border_edges[k / 3];
    for(int j = 0; j < 3; ++j)
      if(border & (1 << j))
      {
        mark_segment_cells(t[j], t[(j + 1) % 3], rows, columns, cells);
        add_row_crossings(t[j], t[(j + 1) % 3], rows, crossings);
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
}

// The core of `f` (its size, `core`, `core_begin`, `core_area`) from the
// covered cells (`rows` by `columns`, see cover_chart_cells()) offset by
// `pad`, and `f.zone_cells`: the core grown by `pad` in every direction.
inline void collect_core(long rows, long columns, long pad, Raster_footprint& f)
{
  const Cell_rows& cells = f.cells;
  Cell_rows& zone_cells = f.zone_cells;
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
}

// The zone of `f` (`zone`, `zone_begin`, `zone_area`, `longest`) from
// `f.zone_cells` (see collect_core()), and its `shape`.
inline void collect_zone(Raster_footprint& f)
{
  const Cell_rows& zone_cells = f.zone_cells;
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
}

// Rasterizes `chart` at `scale` (UV length = scale * density * length in
// its frame, on a page `page_columns` cells wide) after `eighths` eighths
// of a turn, its zone `pad_cells` wider on every side. Returns false if
// its zone is larger than the page (`page_columns` by `page_rows` cells).
inline bool rasterize_footprint(const Profile_chart& chart, double scale, int eighths, std::size_t page_columns,
                                std::size_t page_rows, std::size_t pad_cells, Raster_footprint& f)
{
  const double to_cells = scale * chart.density * double(page_columns);
  const long pad = static_cast<long>(pad_cells);
  long columns = 0, rows = 0;
  if(!turn_into_cells(chart, to_cells, eighths, pad, page_columns, page_rows, f, columns, rows))
    return false;
  cover_chart_cells(chart, rows, columns, f);
  collect_core(rows, columns, pad, f);
  collect_zone(f);
  return true;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_RASTER_FOOTPRINT_H
