// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writers for the UV atlas of the disk_uv tool: a Wavefront OBJ with
// per-corner texture coordinates, a binary glTF 2.0 file (through
// tinygltf) and a PNG picture of the atlas layout (through stb).
//
// All three take a face graph `mesh`, a face property map `patch` (face ->
// chart id) and a per-corner halfedge property map `uv` (halfedge -> 2D
// point) where `get(uv, h)` is the UV of `target(h, mesh)` as seen from
// `face(h, mesh)`. All three write to a std::ostream, so that the caller can
// write to a temporary file and rename it.
//
// Requirements (link): libtinygltf (CMake target TinyGLTF::TinyGLTF) and
// libstb (pkg-config 'stb'). TINYGLTF_IMPLEMENTATION must NOT be defined:
// the implementation lives in the shared library.

#ifndef DISK_SEGMENTATION_EXAMPLES_ATLAS_WRITERS_H
#define DISK_SEGMENTATION_EXAMPLES_ATLAS_WRITERS_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/functional/hash.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <tiny_gltf.h>

#if defined(__has_include)
#  if __has_include(<stb_image_write.h>)
#    include <stb_image_write.h>
#  else
#    include <stb/stb_image_write.h>
#  endif
#else
#  include <stb_image_write.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <ios>
#include <limits>
#include <locale>
#include <ostream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace disk_uv {

// Color of chart `chart` in the atlas picture: hues spaced by the golden
// ratio, saturation and value alternating so that neighbors in the sequence
// differ. Hues stay within [30, 330] degrees, so that no chart looks like the
// pure red of flipped triangles; never white, never dark.
inline std::array<unsigned char, 3> chart_color(std::size_t chart)
{
  const double golden = std::fmod(double(chart) * 0.618033988749895, 1.0);
  const double hue = (30.0 + 300.0 * golden) / 60.0; // in sectors of 60 degrees
  const double s = (chart % 3 == 0) ? 0.55 : 0.75;
  const double v = (chart % 2 == 0) ? 0.95 : 0.8;
  const int sector = std::min(5, static_cast<int>(hue));
  const double f = hue - sector;
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  double r = v, g = t, b = p;
  switch(sector)
  {
    case 1: r = q; g = v; b = p; break;
    case 2: r = p; g = v; b = t; break;
    case 3: r = p; g = q; b = v; break;
    case 4: r = t; g = p; b = v; break;
    case 5: r = v; g = p; b = q; break;
    default: break;
  }
  return {{ static_cast<unsigned char>(r * 255 + 0.5), static_cast<unsigned char>(g * 255 + 0.5),
            static_cast<unsigned char>(b * 255 + 0.5) }};
}

namespace atlas_internal {

// One texture vertex: a mesh vertex seen from one chart at one UV position.
// With UVs continuous inside each chart, there is one per (vertex, chart)
// pair; a vertex that a chart sees at two different UVs (e.g. a chart whose
// border touches itself at that vertex) gets one per UV, so no corner ever
// gets a UV other than its own.
struct Texture_vertex
{
  std::size_t vertex; // index of the mesh vertex, in vertices(mesh) order
  std::size_t chart;
  double u, v;
};

struct Texture_vertex_key_hash
{
  std::size_t operator()(const Texture_vertex& t) const
  {
    std::size_t seed = 0;
    boost::hash_combine(seed, t.vertex);
    boost::hash_combine(seed, t.chart);
    boost::hash_combine(seed, t.u);
    boost::hash_combine(seed, t.v);
    return seed;
  }
};

struct Texture_vertex_key_equal
{
  bool operator()(const Texture_vertex& a, const Texture_vertex& b) const
  {
    return a.vertex == b.vertex && a.chart == b.chart && a.u == b.u && a.v == b.v;
  }
};

// The mesh flattened into arrays, in the mesh's vertex and face orders.
struct Atlas_corners
{
  std::vector<std::array<double, 3> > points;  // per mesh vertex
  std::vector<std::size_t> face_chart;          // per face
  std::vector<std::size_t> face_begin;          // per face + 1: first corner
  std::vector<std::size_t> corner_vertex;       // per corner: mesh vertex index
  std::vector<std::size_t> corner_texture;      // per corner: texture vertex index
  std::vector<Texture_vertex> textures;         // in order of first use

  std::size_t number_of_faces() const { return face_chart.size(); }
  std::size_t face_size(std::size_t f) const { return face_begin[f + 1] - face_begin[f]; }
};

template <typename Mesh, typename Patch_map, typename UV_map>
Atlas_corners flatten(const Mesh& mesh, const Patch_map& patch, const UV_map& uv)
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  Atlas_corners a;
  const auto vpm = get(CGAL::vertex_point, mesh);
  std::unordered_map<vertex_descriptor, std::size_t, boost::hash<vertex_descriptor> > vertex_index;
  for(vertex_descriptor v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    vertex_index.emplace(v, a.points.size());
    a.points.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
  }

  std::unordered_map<Texture_vertex, std::size_t, Texture_vertex_key_hash, Texture_vertex_key_equal> texture_index;
  a.face_begin.push_back(0);
  for(face_descriptor f : faces(mesh))
  {
    const std::size_t chart = static_cast<std::size_t>(get(patch, f));
    a.face_chart.push_back(chart);
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const std::size_t vi = vertex_index.at(target(h, mesh));
      const auto& t = get(uv, h);
      const Texture_vertex key = { vi, chart, CGAL::to_double(t.x()), CGAL::to_double(t.y()) };
      const auto inserted = texture_index.emplace(key, a.textures.size());
      if(inserted.second)
        a.textures.push_back(key);
      a.corner_vertex.push_back(vi);
      a.corner_texture.push_back(inserted.first->second);
    }
    a.face_begin.push_back(a.corner_vertex.size());
  }
  return a;
}

// Restores the formatting state of a stream when leaving a scope.
class Stream_state_saver
{
public:
  explicit Stream_state_saver(std::ostream& out)
    : out_(out), flags_(out.flags()), precision_(out.precision()), locale_(out.getloc())
  {}
  ~Stream_state_saver()
  {
    out_.flags(flags_);
    out_.precision(precision_);
    out_.imbue(locale_);
  }
  Stream_state_saver(const Stream_state_saver&) = delete;
  Stream_state_saver& operator=(const Stream_state_saver&) = delete;

private:
  std::ostream& out_;
  std::ios_base::fmtflags flags_;
  std::streamsize precision_;
  std::locale locale_;
};

template <typename T>
void append_bytes(std::vector<unsigned char>& buffer, const std::vector<T>& values)
{
  const std::size_t bytes = values.size() * sizeof(T);
  const std::size_t offset = buffer.size();
  buffer.resize(offset + bytes);
  if(bytes != 0)
    std::memcpy(buffer.data() + offset, values.data(), bytes);
}

// An RGB image, row 0 at the top.
class Rgb_image
{
public:
  typedef std::array<unsigned char, 3> Color;

  explicit Rgb_image(int size) : size_(size), pixels_(std::size_t(size) * std::size_t(size) * 3, 255) {}

  int size() const { return size_; }
  const unsigned char* data() const { return pixels_.data(); }

  void set(int x, int y, const Color& c)
  {
    if(x < 0 || y < 0 || x >= size_ || y >= size_)
      return;
    unsigned char* p = &pixels_[(std::size_t(y) * std::size_t(size_) + std::size_t(x)) * 3];
    p[0] = c[0]; p[1] = c[1]; p[2] = c[2];
  }

  // Fills the pixels whose centers lie in the triangle (a, b, c), given in
  // pixel coordinates (x to the right, y down, pixel (i, j) covers
  // [i, i+1] x [j, j+1]); centers on an edge count as inside.
  void fill_triangle(const std::array<double, 2>& a, const std::array<double, 2>& b,
                     const std::array<double, 2>& c, const Color& color)
  {
    const double area = edge(a, b, c);
    if(!(area != 0) || !std::isfinite(area))
      return;
    const double sign = area > 0 ? 1.0 : -1.0;
    const double lim = double(size_) + 1.0;
    const double min_x = std::max(-1.0, std::min({ a[0], b[0], c[0] }));
    const double max_x = std::min(lim, std::max({ a[0], b[0], c[0] }));
    const double min_y = std::max(-1.0, std::min({ a[1], b[1], c[1] }));
    const double max_y = std::min(lim, std::max({ a[1], b[1], c[1] }));
    const int i0 = std::max(0, int(std::ceil(min_x - 0.5)));
    const int i1 = std::min(size_ - 1, int(std::floor(max_x - 0.5)));
    const int j0 = std::max(0, int(std::ceil(min_y - 0.5)));
    const int j1 = std::min(size_ - 1, int(std::floor(max_y - 0.5)));
    // At most size_^2 pixels: the ranges are clamped to the image.
    for(int j = j0; j <= j1; ++j)
      for(int i = i0; i <= i1; ++i)
      {
        const std::array<double, 2> p = {{ i + 0.5, j + 0.5 }};
        if(sign * edge(a, b, p) >= 0 && sign * edge(b, c, p) >= 0 && sign * edge(c, a, p) >= 0)
          set(i, j, color);
      }
  }

  // Sets the pixel that contains point p (pixel coordinates); a point on the
  // right or bottom border of the image belongs to the last pixel.
  void set_at(const std::array<double, 2>& p, const Color& color)
  {
    if(!(p[0] >= 0 && p[1] >= 0 && p[0] <= size_ && p[1] <= size_))
      return;
    set(std::min(size_ - 1, int(p[0])), std::min(size_ - 1, int(p[1])), color);
  }

  // Draws a 1-pixel line from a to b (pixel coordinates) with a DDA, after
  // clipping it to the image.
  void draw_line(std::array<double, 2> a, std::array<double, 2> b, const Color& color)
  {
    if(!clip(a, b))
      return;
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double length = std::max(std::fabs(dx), std::fabs(dy));
    // Clipped to [0, size]^2, so at most about size + 1 steps.
    const long steps = std::max(1L, long(std::ceil(length)));
    for(long k = 0; k <= steps; ++k)
    {
      const double t = double(k) / double(steps);
      set_at({{ a[0] + t * dx, a[1] + t * dy }}, color);
    }
  }

private:
  static double edge(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& p)
  {
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
  }

  // Liang-Barsky clipping of segment [a, b] to [0, size]^2.
  bool clip(std::array<double, 2>& a, std::array<double, 2>& b) const
  {
    if(!std::isfinite(a[0]) || !std::isfinite(a[1]) || !std::isfinite(b[0]) || !std::isfinite(b[1]))
      return false;
    double t0 = 0, t1 = 1;
    const double d[2] = { b[0] - a[0], b[1] - a[1] };
    for(int axis = 0; axis < 2; ++axis)
    {
      const double p[2] = { -d[axis], d[axis] };
      const double q[2] = { a[axis], double(size_) - a[axis] };
      for(int k = 0; k < 2; ++k)
      {
        if(p[k] == 0)
        {
          if(q[k] < 0)
            return false;
        }
        else
        {
          const double r = q[k] / p[k];
          if(p[k] < 0)
            t0 = std::max(t0, r);
          else
            t1 = std::min(t1, r);
        }
      }
    }
    if(t0 > t1)
      return false;
    const std::array<double, 2> a0 = a;
    a = {{ a0[0] + t0 * d[0], a0[1] + t0 * d[1] }};
    b = {{ a0[0] + t1 * d[0], a0[1] + t1 * d[1] }};
    return true;
  }

  int size_;
  std::vector<unsigned char> pixels_;
};

inline void write_to_ostream(void* context, void* data, int size)
{
  static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), std::streamsize(size));
}

} // namespace atlas_internal

// Wavefront OBJ with per-corner texture coordinates: one 'v' per mesh vertex
// in vertices(mesh) order, one 'vt' per (vertex, chart) pair, faces
// 'f v/vt ...' in faces(mesh) order, and a 'g chart_<id>' line whenever the
// chart changes between consecutive faces. Numbers are written with
// max_digits10 significant digits, so they read back exactly.
template <typename Mesh, typename Patch_map, typename UV_map>
void write_obj(std::ostream& out, const Mesh& mesh, const Patch_map& patch, const UV_map& uv)
{
  const atlas_internal::Atlas_corners a = atlas_internal::flatten(mesh, patch, uv);
  atlas_internal::Stream_state_saver saver(out);
  out.imbue(std::locale::classic());
  out.unsetf(std::ios_base::floatfield);
  out.precision(std::numeric_limits<double>::max_digits10);

  out << "# UV atlas written by disk_uv: " << a.points.size() << " vertices, " << a.textures.size()
      << " texture coordinates, " << a.number_of_faces() << " faces\n";
  for(const std::array<double, 3>& p : a.points)
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const atlas_internal::Texture_vertex& t : a.textures)
    out << "vt " << t.u << ' ' << t.v << '\n';
  for(std::size_t f = 0; f < a.number_of_faces(); ++f)
  {
    if(f == 0 || a.face_chart[f] != a.face_chart[f - 1])
      out << "g chart_" << a.face_chart[f] << '\n';
    out << 'f';
    for(std::size_t c = a.face_begin[f]; c < a.face_begin[f + 1]; ++c)
      out << ' ' << a.corner_vertex[c] + 1 << '/' << a.corner_texture[c] + 1;
    out << '\n';
  }
}

// Binary glTF 2.0: one mesh with one TRIANGLES primitive whose vertices are
// the (vertex, chart) pairs, with attributes POSITION, NORMAL (area-weighted
// over the faces of the chart around the vertex), TEXCOORD_0 (u, 1 - v) and
// UNSIGNED_INT indices, faces in faces(mesh) order (polygons are split in
// fans). Throws std::runtime_error on failure.
template <typename Mesh, typename Patch_map, typename UV_map>
void write_glb(std::ostream& out, const Mesh& mesh, const Patch_map& patch, const UV_map& uv)
{
  const atlas_internal::Atlas_corners a = atlas_internal::flatten(mesh, patch, uv);
  if(a.number_of_faces() == 0)
    throw std::runtime_error("cannot write a glTF file of a mesh without faces");
  if(a.textures.size() >= std::size_t(std::numeric_limits<std::uint32_t>::max()))
    throw std::runtime_error("too many vertices for a glTF file");

  const std::size_t n = a.textures.size();
  std::vector<float> positions(3 * n), normals(3 * n), texcoords(2 * n);
  std::vector<double> normal_sums(3 * n, 0.0);
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * a.number_of_faces());

  for(std::size_t i = 0; i < n; ++i)
  {
    const atlas_internal::Texture_vertex& t = a.textures[i];
    const std::array<double, 3>& p = a.points[t.vertex];
    for(int k = 0; k < 3; ++k)
    {
      if(!std::isfinite(p[k]))
        throw std::runtime_error("cannot write a glTF file: vertex #" + std::to_string(t.vertex) +
                                 " has a non-finite coordinate");
      positions[3 * i + k] = static_cast<float>(p[k]);
    }
    if(!std::isfinite(t.u) || !std::isfinite(t.v))
      throw std::runtime_error("cannot write a glTF file: a corner of vertex #" + std::to_string(t.vertex) +
                               " has a non-finite UV");
    texcoords[2 * i] = static_cast<float>(t.u);
    texcoords[2 * i + 1] = static_cast<float>(1.0 - t.v);
  }

  for(std::size_t f = 0; f < a.number_of_faces(); ++f)
  {
    const std::size_t begin = a.face_begin[f], size = a.face_size(f);
    if(size < 3)
      throw std::runtime_error("cannot write a glTF file: face #" + std::to_string(f) + " has fewer than 3 corners");
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
  model.asset.generator = "disk_uv";

  tinygltf::Buffer buffer;
  struct View { std::size_t offset, length; };
  const View position_view = { buffer.data.size(), positions.size() * sizeof(float) };
  atlas_internal::append_bytes(buffer.data, positions);
  const View normal_view = { buffer.data.size(), normals.size() * sizeof(float) };
  atlas_internal::append_bytes(buffer.data, normals);
  const View texcoord_view = { buffer.data.size(), texcoords.size() * sizeof(float) };
  atlas_internal::append_bytes(buffer.data, texcoords);
  const View index_view = { buffer.data.size(), indices.size() * sizeof(std::uint32_t) };
  atlas_internal::append_bytes(buffer.data, indices);
  if(buffer.data.size() > std::size_t(std::numeric_limits<std::uint32_t>::max()) - 64)
    throw std::runtime_error("cannot write a glTF file: the mesh is too large for a GLB file");
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

// Larger pictures would need over 800 MB of pixels.
constexpr unsigned max_atlas_png_resolution = 16384;

// The atlas layout as an RGB PNG of resolution x resolution pixels, v axis up
// (row 0 is v = 1): white background, the faces of each chart filled with
// chart_color(chart), chart borders (edges between two charts, and boundary
// edges) drawn as dark 1-pixel lines, and faces whose UV orientation is
// negative filled in pure red (255, 0, 0), drawn last (and at least the pixel
// of their centroid) so that no fold goes unseen. Pixels are filled when
// their center is in a triangle. Throws std::runtime_error on failure.
template <typename Mesh, typename Patch_map, typename UV_map>
void write_atlas_png(std::ostream& out, const Mesh& mesh, const Patch_map& patch, const UV_map& uv,
                     unsigned resolution)
{
  typedef boost::graph_traits<Mesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef std::array<double, 2> P2;

  if(resolution == 0 || resolution > max_atlas_png_resolution)
    throw std::runtime_error("the atlas resolution must be between 1 and " +
                             std::to_string(max_atlas_png_resolution) + " pixels, not " +
                             std::to_string(resolution));
  const int size = static_cast<int>(resolution);
  atlas_internal::Rgb_image image(size);
  const atlas_internal::Rgb_image::Color red = {{ 255, 0, 0 }};
  const atlas_internal::Rgb_image::Color dark = {{ 24, 24, 24 }};

  auto pixel = [size](const P2& t) { return P2{{ t[0] * size, (1.0 - t[1]) * size }}; };
  auto uv_at = [&uv](halfedge_descriptor h) {
    const auto& t = get(uv, h);
    return P2{{ CGAL::to_double(t.x()), CGAL::to_double(t.y()) }};
  };

  std::vector<std::vector<P2> > flipped; // the fan triangles with negative UV area, in pixels
  std::vector<P2> corners;
  for(face_descriptor f : faces(mesh))
  {
    corners.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      corners.push_back(uv_at(h));
    const atlas_internal::Rgb_image::Color color = chart_color(static_cast<std::size_t>(get(patch, f)));
    for(std::size_t k = 1; k + 1 < corners.size(); ++k)
    {
      const P2& a = corners[0];
      const P2& b = corners[k];
      const P2& c = corners[k + 1];
      const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      if(area < 0)
        flipped.push_back({ pixel(a), pixel(b), pixel(c) });
      else
        image.fill_triangle(pixel(a), pixel(b), pixel(c), color);
    }
  }

  for(face_descriptor f : faces(mesh))
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const halfedge_descriptor o = opposite(h, mesh);
      if(is_border(o, mesh) || get(patch, face(o, mesh)) != get(patch, f))
        image.draw_line(pixel(uv_at(prev(h, mesh))), pixel(uv_at(h)), dark);
    }

  for(const std::vector<P2>& t : flipped)
  {
    image.fill_triangle(t[0], t[1], t[2], red);
    image.set_at({{ (t[0][0] + t[1][0] + t[2][0]) / 3, (t[0][1] + t[1][1] + t[2][1]) / 3 }}, red);
  }

  if(stbi_write_png_to_func(&atlas_internal::write_to_ostream, &out, size, size, 3, image.data(), size * 3) == 0)
    throw std::runtime_error("stb failed to encode the atlas PNG");
  if(!out)
    throw std::runtime_error("error while writing the atlas PNG");
}

} // namespace disk_uv

#endif // DISK_SEGMENTATION_EXAMPLES_ATLAS_WRITERS_H
