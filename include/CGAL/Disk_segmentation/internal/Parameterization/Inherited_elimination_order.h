// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Elimination orders that charts built from solved charts inherit, so
// that their solves skip the minimum degree ordering.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_INHERITED_ELIMINATION_ORDER_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_INHERITED_ELIMINATION_ORDER_H

#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_slots.h>

#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Elimination orders for charts built from charts already solved, so that
// their solves skip the minimum degree ordering, which cost as much as a
// factorization on meshes of 75k-90k faces (one thread: refined_elephant
// 0.084 s of ordering against 0.078 s of real and 0.065 s of complex
// LDL^T). An inherited order leaves a few percent more fill than a fresh
// one (see the benchmark README); inheriting it along a border rerouting,
// where the chart gains vertices on its border, left more.

inline bool has_elimination_order(const Chart& c) { return c.elimination_order.size() == c.vertices.size(); }

// Per-thread marks of the vertices of one or two charts, sized to them.
inline Region_values<unsigned char>& chart_vertex_marks_of_this_thread()
{
  thread_local Region_values<unsigned char> marks(0);
  return marks;
}

// Appends to `out` the vertices of `order` marked `value`, in that order.
inline void append_marked(const Region_values<unsigned char>& mark, const std::vector<Index>& order,
                          unsigned char value, std::vector<Index>& out)
{
  for(Index v : order)
    if(mark.at(v) == value)
      out.push_back(v);
}

// The order of the union `u` of two solved charts `a` and `b` with
// elimination orders: the vertices of `a` only, then those of `b` only,
// each in their chart's order, then the vertices the two share. The shared
// ones separate the others (no triangle holds a vertex of each), so this is
// one step of a nested dissection over two orders already fill-reducing.
inline void inherit_union_order(const Chart& a, const Chart& b, Chart& u)
{
  CGAL_precondition(has_elimination_order(a) && has_elimination_order(b));
  Region_values<unsigned char>& mark = chart_vertex_marks_of_this_thread();
  mark.clear_for_keys(u.vertices);
  for(Index v : a.elimination_order)
    mark[v] |= 1;
  for(Index v : b.elimination_order)
    mark[v] |= 2;
  u.elimination_order.clear();
  u.elimination_order.reserve(u.vertices.size());
  append_marked(mark, a.elimination_order, 1, u.elimination_order);
  append_marked(mark, b.elimination_order, 2, u.elimination_order);
  append_marked(mark, a.elimination_order, 3, u.elimination_order);
  CGAL_postcondition(has_elimination_order(u));
}

// The order of a chart `piece` cut out of a solved chart `whole`: the
// order of `whole` restricted to the vertices of `piece`.
inline void inherit_restricted_order(const Chart& whole, Chart& piece)
{
  CGAL_precondition(has_elimination_order(whole));
  Region_values<unsigned char>& mark = chart_vertex_marks_of_this_thread();
  mark.clear_for_keys(whole.vertices);
  for(Index v : piece.vertices)
    mark[v] = 1;
  piece.elimination_order.clear();
  piece.elimination_order.reserve(piece.vertices.size());
  append_marked(mark, whole.elimination_order, 1, piece.elimination_order);
  // A piece that is not inside `whole` solves with an order of its own.
  if(!has_elimination_order(piece))
    piece.elimination_order.clear();
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_INHERITED_ELIMINATION_ORDER_H
