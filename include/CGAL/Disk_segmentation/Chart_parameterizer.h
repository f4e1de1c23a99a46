// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_CHART_PARAMETERIZER_H
#define CGAL_DISK_SEGMENTATION_CHART_PARAMETERIZER_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// The mesh a chart is copied into before a parameterizer given with the
/// named parameter `parameterizer` runs on it: one chart, a triangulated
/// topological disk, with the chart's vertices and faces only.
///
/// A `parameterizer` is either
/// - a copy-constructible model of the concept `Parameterizer_3` of \cgal's
///   Surface_mesh_parameterization package with `Chart_mesh` as its
///   `TriangleMesh` (e.g.
///   `Surface_mesh_parameterization::Discrete_authalic_parameterizer_3<Chart_mesh>`,
///   or a class of the user's with the same member template
///   `parameterize(mesh, border_halfedge, uv_map, vertex_index_map,
///   vertex_parameterized_map)`), or
/// - a callable with no argument, callable as `const`, that returns such a
///   model (a factory).
///
/// `parameterize()` writes the UVs and must leave the mesh as it is (a
/// chart whose mesh it changed is rejected like a failed solve). SMP's
/// parameterizers keep their linear solver behind a shared pointer, so
/// copies of one object share it: within one call of the package, the
/// copies of a parameterizer object solve one chart at a time (the rest of
/// the work stays parallel); an object shared by calls running at once
/// must be made safe by its owner. A factory is called for each chart,
/// from several threads at once, and its charts are solved in parallel:
/// it must be safe to call concurrently and each parameterizer it returns
/// must own its solver (construct it, do not copy a configured one). Either
/// way the charts, and the atlas, are the same for any number of threads.
/// Charts of one triangle are laid out isometrically without calling it.
///
/// The named parameter `parameterization_method` is the shorthand for the
/// package's built-in methods; the two cannot be given together.
typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Chart_mesh;

} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_CHART_PARAMETERIZER_H
