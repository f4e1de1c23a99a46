// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The arrays of the atlas's glTF primitive: positions, UVs, normals and
// triangles, one vertex per distinct (vertex, UV) pair.

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_GLB_MODEL_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_GLB_MODEL_H

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/IO/internal/Atlas_corners.h>
#include <CGAL/Disk_segmentation/IO/internal/Float_texcoords.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

// The vertex attributes and triangles of a glTF primitive, one vertex per
// distinct (vertex, UV) pair of the atlas.
struct Glb_arrays
{
  std::vector<float> positions, normals, texcoords;
  std::vector<std::uint32_t> indices;
  std::vector<double> min_position, max_position;
};

// Positions and UVs (v flipped: glTF's origin is the top left corner);
// throws Input_error on a non-finite one.
inline void fill_positions_and_texcoords(const Atlas_corners& a, Glb_arrays& g)
{
  const std::size_t n = a.textures.size();
  g.positions.resize(3 * n);
  g.texcoords.resize(2 * n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const Texture_vertex& t = a.textures[i];
    const std::array<double, 3>& p = a.points[t.vertex];
    for(int k = 0; k < 3; ++k)
    {
      if(!std::isfinite(p[k]))
        throw Input_error("cannot write a glTF file: vertex #" + std::to_string(t.vertex) +
                          " has a non-finite coordinate");
      g.positions[3 * i + k] = static_cast<float>(p[k]);
    }
    if(!std::isfinite(t.u) || !std::isfinite(t.v))
      throw Input_error("cannot write a glTF file: a corner of vertex #" + std::to_string(t.vertex) +
                        " has a non-finite UV");
    g.texcoords[2 * i] = static_cast<float>(t.u);
    g.texcoords[2 * i + 1] = static_cast<float>(1.0 - t.v);
  }
  g.min_position.assign(3, std::numeric_limits<double>::infinity());
  g.max_position.assign(3, -std::numeric_limits<double>::infinity());
  for(std::size_t i = 0; i < n; ++i)
    for(int k = 0; k < 3; ++k)
    {
      g.min_position[k] = std::min(g.min_position[k], double(g.positions[3 * i + k]));
      g.max_position[k] = std::max(g.max_position[k], double(g.positions[3 * i + k]));
    }
}

// Fans of the faces, and per-vertex normals summed from the faces' Newell
// normals; throws Input_error on a face of fewer than three corners, or on
// triangles that the float UVs collapse.
inline void fill_triangles_and_normals(const Atlas_corners& a, Glb_arrays& g)
{
  const std::size_t n = a.textures.size();
  std::vector<double> normal_sums(3 * n, 0.0);
  std::size_t collapsed = 0;
  g.indices.reserve(3 * a.number_of_faces());
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
      const std::array<std::size_t, 3> t = { { a.corner_texture[begin], a.corner_texture[begin + k],
                                               a.corner_texture[begin + k + 1] } };
      for(std::size_t corner : t)
        g.indices.push_back(static_cast<std::uint32_t>(corner));
      // As written: v flipped.
      if(collapses_in_float({ { a.textures[t[0]].u, a.textures[t[1]].u, a.textures[t[2]].u } },
                            { { 1.0 - a.textures[t[0]].v, 1.0 - a.textures[t[1]].v, 1.0 - a.textures[t[2]].v } }))
        ++collapsed;
    }
  }
  if(collapsed > 0)
    throw Input_error("cannot write a glTF file: " + collapsed_in_float_message(collapsed) +
                      ", or write OBJ, which keeps double precision");
  g.normals.resize(3 * n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const double* s = &normal_sums[3 * i];
    const double length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if(length > 0 && std::isfinite(length))
      for(int d = 0; d < 3; ++d)
        g.normals[3 * i + d] = static_cast<float>(s[d] / length);
    else // degenerate faces only: any unit vector keeps the file valid
    {
      g.normals[3 * i] = 0.f; g.normals[3 * i + 1] = 0.f; g.normals[3 * i + 2] = 1.f;
    }
  }
}

// One buffer, four views and accessors, one mesh of one primitive, one
// node, one scene; throws Input_error past the 4 GiB of a GLB file.
inline tinygltf::Model glb_model(const Glb_arrays& g)
{
  const std::size_t n = g.texcoords.size() / 2;
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "CGAL::Disk_segmentation";

  tinygltf::Buffer buffer;
  struct View { std::size_t offset, length; };
  const View position_view = { buffer.data.size(), g.positions.size() * sizeof(float) };
  append_bytes(buffer.data, g.positions);
  const View normal_view = { buffer.data.size(), g.normals.size() * sizeof(float) };
  append_bytes(buffer.data, g.normals);
  const View texcoord_view = { buffer.data.size(), g.texcoords.size() * sizeof(float) };
  append_bytes(buffer.data, g.texcoords);
  const View index_view = { buffer.data.size(), g.indices.size() * sizeof(std::uint32_t) };
  append_bytes(buffer.data, g.indices);
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
  model.accessors[position_accessor].minValues = g.min_position;
  model.accessors[position_accessor].maxValues = g.max_position;
  const int normal_accessor = add_accessor(add_view(normal_view, TINYGLTF_TARGET_ARRAY_BUFFER),
                                           TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  const int texcoord_accessor = add_accessor(add_view(texcoord_view, TINYGLTF_TARGET_ARRAY_BUFFER),
                                             TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n);
  const int index_accessor = add_accessor(add_view(index_view, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                          g.indices.size());

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
  return model;
}

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_GLB_MODEL_H
