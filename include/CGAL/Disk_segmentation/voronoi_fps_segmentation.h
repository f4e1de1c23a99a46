// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_VORONOI_FPS_SEGMENTATION_H
#define CGAL_DISK_SEGMENTATION_VORONOI_FPS_SEGMENTATION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Segmentation_settings.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps_labels.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
/// \ingroup PkgDiskSegmentationRef
///
/// Partitions the faces of `tm` into the geodesic Voronoi cells of `n`
/// farthest-point seeds, computed jointly on the dual graph (faces are the
/// nodes; two faces sharing an edge are joined by an arc whose length is the
/// path from one centroid through the edge midpoint to the other centroid).
///
/// Each new seed is the face farthest from all seeds chosen so far; only the
/// faces that get closer to it are revisited, which costs
/// \f$ O(F \log F \log n) \f$ expected time instead of `n` full Dijkstras.
/// Every connected component receives at least one seed, so `max(n, number of
/// components)` seeds are used, and at most `num_faces(tm)` (`n` is clamped).
///
/// Cells are edge-connected but need not be disks: see
/// `refine_to_topological_disks()`.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///         whose faces are triangles
/// @tparam FacePatchMap a model of `WritablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
///         an integral value type (`std::size_t` recommended)
/// @tparam NamedParameters a sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters"
///
/// @param tm a triangle mesh, manifold, without garbage
/// @param face_patch_map receives for every face the id of its cell; cell `i`
///        is the cell of the `i`-th seed (ids are `0` to the returned value minus one)
/// @param np an optional sequence of \ref PkgDiskSegmentationNamedParameters "Named Parameters" among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_seeds}
///     \cgalParamDescription{the number `n` of seeds}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`10`}
///     \cgalParamExtra{must be at least 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{crease_penalty}
///     \cgalParamDescription{a dual arc across an edge whose two faces' normals make an angle
///       \f$ \theta \f$ is \f$ 1 + k (1 - \cos\theta) \f$ times longer, so that Voronoi cells, and
///       the borders of the regions, follow creases (not in the paper; see \ref DS_Creases)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_crease_penalty` (10); `0` is the paper's geodesic distance on the dual mesh}
///     \cgalParamExtra{must be a finite number \f$ \geq 0 \f$}
///   \cgalParamNEnd
///   \cgalParamNBegin{random_seed}
///     \cgalParamDescription{when given, the first seed of every component is drawn at random with this seed; without it, the first seed of every component is the face farthest from the component's first face in the package's face order (see \ref DS_FaceOrder)}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{no randomness}
///   \cgalParamNEnd
///   \cgalParamNBegin{seeds_output_iterator}
///     \cgalParamDescription{receives the seed faces, in the order they were chosen}
///     \cgalParamType{a model of `OutputIterator` accepting `face_descriptor`}
///     \cgalParamDefault{unused}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key type and the traits' `Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class, used only to read coordinates: they are converted with `CGAL::to_double()` and all computation runs in `double` whatever the kernel}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal Kernel deduced from the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in `[0, num_faces(tm))`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in `[0, num_vertices(tm))`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// @return the number of cells
///
/// @throws Input_error if `tm` has no face, a face that is not a triangle or
///         a non-finite coordinate, or if a parameter is out of range.
///         `face_patch_map` is not written then. A pinched vertex is cut
///         (each of its fans gets its own vertex in the package's copy).
///
/// The result depends only on the mesh (faces and vertices in the order of
/// `faces(tm)` and `vertices(tm)`) and the parameters: it is the same for
/// `Surface_mesh` and `Polyhedron_3` holding the same mesh.
///
/// Complexity, for `F` faces and `V` vertices: \f$ O(F + V) \f$ time to read
/// the mesh, then expected \f$ O(F \log F \log n) \f$ time for the seeds and
/// cells (worst case \f$ O(n F \log F) \f$: the Dijkstra of each new seed
/// visits only the faces that join its cell, at most all of them).
/// Memory: \f$ O(F + V) \f$.
template <typename TriangleMesh, typename FacePatchMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t voronoi_fps_segmentation(const TriangleMesh& tm,
                                     FacePatchMap face_patch_map,
                                     const NamedParameters& np = parameters::default_values())
{
  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  static_assert(internal::Check_named_parameters<NamedParameters>::value, "");
  const internal::Segmentation_settings settings = internal::segmentation_settings(np);
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  internal::Indexed_triangle_mesh m;
  std::vector<face_descriptor> face_handles;
  internal::build_indexed_triangle_mesh(tm, internal::stage_parameters(np, settings), m, face_handles);

  internal::Voronoi_fps fps(m);
  std::vector<internal::Index> labels;
  const std::vector<internal::Index> seeds =
    internal::voronoi_fps_labels(m, face_handles, fps, settings.number_of_seeds, np, labels);

  std::vector<face_descriptor> seed_faces;
  for(internal::Index s : seeds)
    seed_faces.push_back(face_handles[s]);
  internal::write_seeds(np, seed_faces);
  auto patch_map = internal::checked_patch_map<TriangleMesh>(face_patch_map);
  internal::write_face_labels(face_handles, labels, patch_map);
  return seeds.size();
}

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_VORONOI_FPS_SEGMENTATION_H
