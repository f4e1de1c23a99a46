// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_GLB_H
#define CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_GLB_H

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/IO/internal/Atlas_corners.h>
#include <CGAL/Disk_segmentation/IO/internal/Glb_model.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {

/// \ingroup PkgDiskSegmentationIO
///
/// Writes the per-corner UV atlas of `mesh` as a binary glTF 2.0 file
/// (`.glb`): one mesh with one `TRIANGLES` primitive whose vertices are the
/// texture vertices (a vertex seen from one chart), with the attributes
/// `POSITION`, `NORMAL` (area-weighted over the chart's faces around the
/// vertex), `TEXCOORD_0` (\f$ (u, 1 - v) \f$: glTF's texture origin is the
/// top left) and 32-bit indices, faces in the order of `faces(mesh)`
/// (polygons split in fans).
///
/// Needs tinygltf (Debian's `libtinygltf-dev`, CMake target
/// `TinyGLTF::TinyGLTF`): include this header only where it is available;
/// `TINYGLTF_IMPLEMENTATION` must not be defined (the implementation is in
/// the library).
///
/// @tparam TriangleMesh, FacePatchMap, UVMap as in `write_atlas_OBJ()`
///
/// @throws Input_error if the mesh has no face, a face has fewer than three
///         corners, a coordinate or a UV is not finite, a triangle would be
///         degenerate or flipped in glTF's 32-bit float UVs (charts far
///         smaller than a texel: nothing is written then), or the mesh is too
///         large for a GLB file (4 GiB)
/// @throws std::runtime_error if tinygltf or the stream fails
///
/// Complexity: \f$ O(C) \f$ expected time and memory for `C` corners.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap>
void write_atlas_GLB(std::ostream& out, const TriangleMesh& mesh, FacePatchMap patch, UVMap uv)
{
  static_assert(CGAL::Disk_segmentation::internal::Check_patch_map<FacePatchMap>::value, "");
  const internal::Atlas_corners a = internal::flatten(mesh, patch, uv);
  if(a.number_of_faces() == 0)
    throw Input_error("cannot write a glTF file of a mesh without faces");
  if(a.textures.size() >= std::size_t(std::numeric_limits<std::uint32_t>::max()))
    throw Input_error("too many vertices for a glTF file");

  internal::Glb_arrays arrays;
  internal::fill_positions_and_texcoords(a, arrays);
  internal::fill_triangles_and_normals(a, arrays);
  tinygltf::Model model = internal::glb_model(arrays);
  tinygltf::TinyGLTF writer;
  if(!writer.WriteGltfSceneToStream(&model, out, false, true))
    throw std::runtime_error("tinygltf failed to write the glTF file");
  if(!out)
    throw std::runtime_error("error while writing the glTF file");
}

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_GLB_H
