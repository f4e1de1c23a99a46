// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_GLB_H
#define CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_GLB_H

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/IO/internal/Atlas_corners.h>
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
///         corners, a coordinate or a UV is not finite, or the mesh is too
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

  const std::size_t n = a.textures.size();
  std::vector<float> positions(3 * n), normals(3 * n), texcoords(2 * n);
  std::vector<double> normal_sums(3 * n, 0.0);
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * a.number_of_faces());

  for(std::size_t i = 0; i < n; ++i)
  {
    const internal::Texture_vertex& t = a.textures[i];
    const std::array<double, 3>& p = a.points[t.vertex];
    for(int k = 0; k < 3; ++k)
    {
      if(!std::isfinite(p[k]))
        throw Input_error("cannot write a glTF file: vertex #" + std::to_string(t.vertex) +
                                 " has a non-finite coordinate");
      positions[3 * i + k] = static_cast<float>(p[k]);
    }
    if(!std::isfinite(t.u) || !std::isfinite(t.v))
      throw Input_error("cannot write a glTF file: a corner of vertex #" + std::to_string(t.vertex) +
                               " has a non-finite UV");
    texcoords[2 * i] = static_cast<float>(t.u);
    texcoords[2 * i + 1] = static_cast<float>(1.0 - t.v);
  }

  for(std::size_t f = 0; f < a.number_of_faces(); ++f)
  {
    const std::size_t begin = a.face_begin[f], size = a.face_size(f);
    if(size < 3)
      throw Input_error("cannot write a glTF file: face #" + std::to_string(f) + " has fewer than 3 corners");
    // Newell's normal: twice the vector area, exact for triangles.
    double normal[3] = { 0, 0, 0 };
    for(std::size_t k = 0; k < size; ++k)
    {
      const std::array<double, 3>& p = a.points[a.corner_vertex[begin + k]];
      const std::array<double, 3>& q = a.points[a.corner_vertex[begin + (k + 1) % size]];
      normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
      normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
      normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    for(std::size_t k = 0; k < size; ++k)
      for(int d = 0; d < 3; ++d)
        normal_sums[3 * a.corner_texture[begin + k] + d] += normal[d];
    for(std::size_t k = 1; k + 1 < size; ++k)
    {
      indices.push_back(static_cast<std::uint32_t>(a.corner_texture[begin]));
      indices.push_back(static_cast<std::uint32_t>(a.corner_texture[begin + k]));
      indices.push_back(static_cast<std::uint32_t>(a.corner_texture[begin + k + 1]));
    }
  }

  for(std::size_t i = 0; i < n; ++i)
  {
    const double* s = &normal_sums[3 * i];
    const double length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if(length > 0 && std::isfinite(length))
      for(int d = 0; d < 3; ++d)
        normals[3 * i + d] = static_cast<float>(s[d] / length);
    else // degenerate faces only: any unit vector keeps the file valid
    {
      normals[3 * i] = 0.f; normals[3 * i + 1] = 0.f; normals[3 * i + 2] = 1.f;
    }
  }

  std::vector<double> min_position(3, std::numeric_limits<double>::infinity());
  std::vector<double> max_position(3, -std::numeric_limits<double>::infinity());
  for(std::size_t i = 0; i < n; ++i)
    for(int k = 0; k < 3; ++k)
    {
      min_position[k] = std::min(min_position[k], double(positions[3 * i + k]));
      max_position[k] = std::max(max_position[k], double(positions[3 * i + k]));
    }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "CGAL::Disk_segmentation";

  tinygltf::Buffer buffer;
  struct View { std::size_t offset, length; };
  const View position_view = { buffer.data.size(), positions.size() * sizeof(float) };
  internal::append_bytes(buffer.data, positions);
  const View normal_view = { buffer.data.size(), normals.size() * sizeof(float) };
  internal::append_bytes(buffer.data, normals);
  const View texcoord_view = { buffer.data.size(), texcoords.size() * sizeof(float) };
  internal::append_bytes(buffer.data, texcoords);
  const View index_view = { buffer.data.size(), indices.size() * sizeof(std::uint32_t) };
  internal::append_bytes(buffer.data, indices);
  if(buffer.data.size() > std::size_t(std::numeric_limits<std::uint32_t>::max()) - 64)
    throw Input_error("cannot write a glTF file: the mesh is too large for a GLB file");
  model.buffers.push_back(std::move(buffer));

  auto add_view = [&model](const View& v, int target) {
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = v.offset;
    view.byteLength = v.length;
    view.target = target;
    model.bufferViews.push_back(view);
    return int(model.bufferViews.size()) - 1;
  };
  auto add_accessor = [&model](int view, int component_type, int type, std::size_t count) {
    tinygltf::Accessor accessor;
    accessor.bufferView = view;
    accessor.byteOffset = 0;
    accessor.componentType = component_type;
    accessor.type = type;
    accessor.count = count;
    model.accessors.push_back(accessor);
    return int(model.accessors.size()) - 1;
  };

  const int position_accessor = add_accessor(add_view(position_view, TINYGLTF_TARGET_ARRAY_BUFFER),
                                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  model.accessors[position_accessor].minValues = min_position;
  model.accessors[position_accessor].maxValues = max_position;
  const int normal_accessor = add_accessor(add_view(normal_view, TINYGLTF_TARGET_ARRAY_BUFFER),
                                           TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  const int texcoord_accessor = add_accessor(add_view(texcoord_view, TINYGLTF_TARGET_ARRAY_BUFFER),
                                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n);
  const int index_accessor = add_accessor(add_view(index_view, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                          indices.size());

  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = position_accessor;
  primitive.attributes["NORMAL"] = normal_accessor;
  primitive.attributes["TEXCOORD_0"] = texcoord_accessor;
  primitive.indices = index_accessor;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;

  tinygltf::Mesh gltf_mesh;
  gltf_mesh.name = "atlas";
  gltf_mesh.primitives.push_back(primitive);
  model.meshes.push_back(gltf_mesh);

  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);

  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

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
