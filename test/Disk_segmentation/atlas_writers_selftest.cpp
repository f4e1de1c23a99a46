// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Self-test of the atlas writers (CGAL/Disk_segmentation/IO/): writes the OBJ, GLB and PNG atlas of a small
// hand-made mesh and reads them back. Exits with 0 when every check passes;
// its last line is "atlas_writers: N passed, M failed".

#include <CGAL/Disk_segmentation/IO/udim_tiles.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_GLB.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_OBJ.h>
#include <CGAL/Disk_segmentation/IO/write_atlas_PNG.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#if defined(__has_include)
#  if __has_include(<stb_image.h>)
#    include <stb_image.h>
#  else
#    include <stb/stb_image.h>
#  endif
#else
#  include <stb_image.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <locale>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_2 Point_2;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef Mesh::Halfedge_index Halfedge_index;
typedef Mesh::Property_map<Face_index, std::size_t> Patch_map;
typedef Mesh::Property_map<Halfedge_index, Point_2> UV_map;

int passed = 0, failed = 0;

void check(bool ok, const std::string& what)
{
  if(ok)
    ++passed;
  else
  {
    ++failed;
    std::cerr << "FAILED: " << what << std::endl;
  }
}

// A 3x3 grid of vertices over [0,1]^2 (slightly bent in z), split in 2x2
// quads and 8 triangles. The left column of quads is chart 0, mapped to
// u in [0.05, 0.45]; the right column is chart 1, mirrored into
// u in [0.55, 0.95] so that all its triangles are flipped. Faces alternate
// between the charts row by row. Vertex 0 of the mesh is removed before the
// writers run, so that indices in the files cannot be the mesh's indices.
struct Test_mesh
{
  Mesh mesh;
  Patch_map patch;
  UV_map uv;
};

const double xs[3] = { 0.0, 1.0 / 3.0, 1.0 };
const double ys[3] = { 0.0, 0.70710678118654757, 1.0 };

Point_2 chart_uv(std::size_t chart, const Point_3& p)
{
  const double v = 0.05 + 0.9 * p.y();
  if(chart == 0)
    return Point_2(0.05 + 0.4 * p.x() / xs[1], v);
  return Point_2(0.95 - 0.4 * (p.x() - xs[1]) / (1.0 - xs[1]), v);
}

void build(Test_mesh& t)
{
  Mesh& mesh = t.mesh;
  const Vertex_index removed = mesh.add_vertex(Point_3(9, 9, 9));
  Vertex_index grid[3][3];
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i)
      grid[i][j] = mesh.add_vertex(Point_3(xs[i], ys[j], xs[i] * ys[j] / 7.0));
  mesh.remove_vertex(removed);

  t.patch = mesh.add_property_map<Face_index, std::size_t>("f:patch", 0).first;
  t.uv = mesh.add_property_map<Halfedge_index, Point_2>("h:uv", Point_2(0, 0)).first;
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 2; ++i)
    {
      const Vertex_index a = grid[i][j], b = grid[i + 1][j], c = grid[i + 1][j + 1], d = grid[i][j + 1];
      for(const Face_index f : { mesh.add_face(a, b, c), mesh.add_face(a, c, d) })
      {
        if(f == Mesh::null_face())
        {
          std::cerr << "cannot build the test mesh" << std::endl;
          std::exit(2);
        }
        t.patch[f] = std::size_t(i);
        for(Halfedge_index h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
          t.uv[h] = chart_uv(std::size_t(i), mesh.point(mesh.target(h)));
      }
    }
}

// What every writer must reproduce: per face, the chart and the position and
// UV of each corner.
struct Corner
{
  Point_3 position;
  Point_2 uv;
};

std::vector<std::vector<Corner> > expected_corners(const Test_mesh& t)
{
  std::vector<std::vector<Corner> > faces;
  for(Face_index f : t.mesh.faces())
  {
    faces.emplace_back();
    for(Halfedge_index h : CGAL::halfedges_around_face(t.mesh.halfedge(f), t.mesh))
      faces.back().push_back({ t.mesh.point(t.mesh.target(h)), t.uv[h] });
  }
  return faces;
}

std::string read_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

template <typename Writer>
bool write_file(const std::string& path, Writer writer)
{
  std::ofstream out(path, std::ios::binary);
  try
  {
    writer(out);
  }
  catch(const std::exception& e)
  {
    std::cerr << "writing " << path << " threw: " << e.what() << std::endl;
    return false;
  }
  out.close();
  return bool(out);
}

// ---- OBJ --------------------------------------------------------------------

struct Obj
{
  std::vector<std::array<double, 3> > v;
  std::vector<std::array<double, 2> > vt;
  std::vector<std::vector<std::array<long, 2> > > f; // 1-based (v, vt) per corner
  std::vector<std::string> groups;
  std::vector<std::size_t> group_first_face;
  bool ok = true;
};

Obj parse_obj(const std::string& text)
{
  Obj obj;
  std::istringstream in(text);
  in.imbue(std::locale::classic());
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream ls(line);
    ls.imbue(std::locale::classic());
    std::string tag;
    if(!(ls >> tag) || tag[0] == '#')
      continue;
    if(tag == "v")
    {
      std::array<double, 3> p;
      if(!(ls >> p[0] >> p[1] >> p[2]))
        obj.ok = false;
      obj.v.push_back(p);
    }
    else if(tag == "vt")
    {
      std::array<double, 2> p;
      if(!(ls >> p[0] >> p[1]))
        obj.ok = false;
      obj.vt.push_back(p);
    }
    else if(tag == "g")
    {
      std::string name;
      ls >> name;
      obj.groups.push_back(name);
      obj.group_first_face.push_back(obj.f.size());
    }
    else if(tag == "f")
    {
      obj.f.emplace_back();
      std::string corner;
      while(ls >> corner)
      {
        const std::size_t slash = corner.find('/');
        if(slash == std::string::npos || corner.find('/', slash + 1) != std::string::npos)
        {
          obj.ok = false;
          continue;
        }
        char* end = nullptr;
        const long vi = std::strtol(corner.c_str(), &end, 10);
        const long ti = std::strtol(corner.c_str() + slash + 1, &end, 10);
        obj.f.back().push_back({{ vi, ti }});
      }
    }
    else
      obj.ok = false;
  }
  return obj;
}

void test_obj(const Test_mesh& t, const std::string& path, std::size_t expected_texture_vertices)
{
  const std::string text = read_file(path);
  const Obj obj = parse_obj(text);
  check(obj.ok, "OBJ: every line parses");
  check(obj.v.size() == t.mesh.number_of_vertices(), "OBJ: one 'v' per vertex");
  std::size_t i = 0;
  bool same_points = true;
  for(Vertex_index v : t.mesh.vertices())
  {
    const Point_3& p = t.mesh.point(v);
    same_points = same_points && i < obj.v.size() && obj.v[i][0] == p.x() && obj.v[i][1] == p.y() &&
                  obj.v[i][2] == p.z();
    ++i;
  }
  check(same_points, "OBJ: vertex positions in vertex order, exact");
  check(obj.vt.size() == expected_texture_vertices,
        "OBJ: " + std::to_string(expected_texture_vertices) + " 'vt' (got " + std::to_string(obj.vt.size()) + ")");

  // Faces grouped by chart, by increasing id, in mesh order within a chart.
  std::vector<std::pair<std::size_t, std::size_t> > chart_and_face;  // chart, index in faces()
  for(Face_index fd : t.mesh.faces())
    chart_and_face.emplace_back(std::size_t(t.patch[fd]), chart_and_face.size());
  std::sort(chart_and_face.begin(), chart_and_face.end());
  const std::vector<std::vector<Corner> > faces = expected_corners(t);
  check(obj.f.size() == faces.size(), "OBJ: same face count");
  bool same_corners = obj.f.size() == faces.size();
  for(std::size_t line = 0; same_corners && line < faces.size(); ++line)
  {
    const std::size_t f = chart_and_face[line].second;
    same_corners = obj.f[line].size() == faces[f].size();
    for(std::size_t k = 0; same_corners && k < faces[f].size(); ++k)
    {
      const long vi = obj.f[line][k][0] - 1, ti = obj.f[line][k][1] - 1;
      same_corners = vi >= 0 && ti >= 0 && std::size_t(vi) < obj.v.size() && std::size_t(ti) < obj.vt.size();
      if(!same_corners)
        break;
      const Corner& c = faces[f][k];
      same_corners = obj.v[vi][0] == c.position.x() && obj.v[vi][1] == c.position.y() &&
                     obj.v[vi][2] == c.position.z() && obj.vt[ti][0] == c.uv.x() && obj.vt[ti][1] == c.uv.y();
    }
  }
  check(same_corners, "OBJ: per-corner positions and UVs, grouped by chart, exact");

  // Groups: one per chart, before its first face.
  std::vector<std::string> groups;
  std::vector<std::size_t> first_faces;
  for(std::size_t line = 0; line < chart_and_face.size(); ++line)
    if(line == 0 || chart_and_face[line].first != chart_and_face[line - 1].first)
    {
      groups.push_back("chart_" + std::to_string(chart_and_face[line].first));
      first_faces.push_back(line);
    }
  check(obj.groups == groups && obj.group_first_face == first_faces,
        "OBJ: one 'g chart_<id>' line per chart (" + std::to_string(obj.groups.size()) + " groups for " +
          std::to_string(groups.size()) + " charts)");
}

// ---- GLB --------------------------------------------------------------------

template <typename T>
std::vector<T> accessor_values(const tinygltf::Model& model, int index, int components)
{
  std::vector<T> values;
  if(index < 0 || std::size_t(index) >= model.accessors.size())
    return values;
  const tinygltf::Accessor& accessor = model.accessors[index];
  if(accessor.bufferView < 0 || std::size_t(accessor.bufferView) >= model.bufferViews.size())
    return values;
  const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
  const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
  const int stride = accessor.ByteStride(view);
  if(stride <= 0)
    return values;
  const std::size_t start = view.byteOffset + accessor.byteOffset;
  if(accessor.count > 0 &&
     start + (accessor.count - 1) * std::size_t(stride) + components * sizeof(T) > data.size())
    return values;
  values.resize(accessor.count * components);
  for(std::size_t i = 0; i < accessor.count; ++i)
    std::memcpy(&values[i * components], &data[start + i * std::size_t(stride)], components * sizeof(T));
  return values;
}

void test_glb(const Test_mesh& t, const std::string& path, std::size_t expected_vertices)
{
  const std::string bytes = read_file(path);
  std::uint32_t header[3] = { 0, 0, 0 };
  if(bytes.size() >= 12)
    std::memcpy(header, bytes.data(), 12);
  check(bytes.compare(0, 4, "glTF") == 0 && header[1] == 2 && header[2] == bytes.size() && bytes.size() % 4 == 0,
        "GLB: header magic, version 2 and total length");

  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  const bool loaded = loader.LoadBinaryFromFile(&model, &err, &warn, path);
  check(loaded, "GLB: loads with tinygltf (" + err + warn + ")");
  if(!loaded)
    return;
  check(model.asset.version == "2.0", "GLB: asset version 2.0");
  check(model.meshes.size() == 1 && model.meshes[0].primitives.size() == 1, "GLB: one mesh, one primitive");
  if(model.meshes.size() != 1 || model.meshes[0].primitives.size() != 1)
    return;
  check(model.scenes.size() == 1 && model.defaultScene == 0 && model.nodes.size() == 1 && model.nodes[0].mesh == 0,
        "GLB: one scene with one node showing the mesh");
  const tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
  check(primitive.mode == TINYGLTF_MODE_TRIANGLES, "GLB: TRIANGLES");
  auto attribute = [&primitive](const char* name) {
    const auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
  };
  const int position_index = attribute("POSITION"), normal_index = attribute("NORMAL"),
            texcoord_index = attribute("TEXCOORD_0");
  check(position_index >= 0 && texcoord_index >= 0 && normal_index >= 0 && primitive.indices >= 0,
        "GLB: POSITION, NORMAL, TEXCOORD_0 and indices");
  if(position_index < 0 || texcoord_index < 0 || normal_index < 0 || primitive.indices < 0)
    return;

  const tinygltf::Accessor& position = model.accessors[position_index];
  const tinygltf::Accessor& texcoord = model.accessors[texcoord_index];
  const tinygltf::Accessor& indices = model.accessors[primitive.indices];
  check(position.count == expected_vertices && texcoord.count == expected_vertices &&
          model.accessors[normal_index].count == expected_vertices,
        "GLB: " + std::to_string(expected_vertices) + " vertices (got " + std::to_string(position.count) + ")");
  check(position.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT && position.type == TINYGLTF_TYPE_VEC3 &&
          texcoord.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT && texcoord.type == TINYGLTF_TYPE_VEC2,
        "GLB: float3 positions and float2 texture coordinates");
  check(indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT && indices.type == TINYGLTF_TYPE_SCALAR &&
          indices.count == 3 * t.mesh.number_of_faces(),
        "GLB: UNSIGNED_INT indices, 3 per face");

  const std::vector<float> positions = accessor_values<float>(model, position_index, 3);
  const std::vector<float> normals = accessor_values<float>(model, normal_index, 3);
  const std::vector<float> texcoords = accessor_values<float>(model, texcoord_index, 2);
  const std::vector<std::uint32_t> index_values = accessor_values<std::uint32_t>(model, primitive.indices, 1);
  if(positions.size() != 3 * expected_vertices || normals.size() != 3 * expected_vertices ||
     texcoords.size() != 2 * expected_vertices || index_values.size() != 3 * t.mesh.number_of_faces())
  {
    check(false, "GLB: accessor data within the buffer");
    return;
  }

  bool min_max = position.minValues.size() == 3 && position.maxValues.size() == 3;
  for(int k = 0; min_max && k < 3; ++k)
  {
    float lo = positions[k], hi = positions[k];
    for(std::size_t i = 0; i < expected_vertices; ++i)
    {
      lo = std::min(lo, positions[3 * i + k]);
      hi = std::max(hi, positions[3 * i + k]);
    }
    min_max = position.minValues[k] == double(lo) && position.maxValues[k] == double(hi);
  }
  check(min_max, "GLB: POSITION min and max are those of the data");

  bool unit_normals = true;
  for(std::size_t i = 0; i < expected_vertices; ++i)
  {
    const double x = normals[3 * i], y = normals[3 * i + 1], z = normals[3 * i + 2];
    unit_normals = unit_normals && std::fabs(std::sqrt(x * x + y * y + z * z) - 1.0) < 1e-5 && z > 0.9;
  }
  check(unit_normals, "GLB: unit normals pointing up");

  const std::vector<std::vector<Corner> > faces = expected_corners(t);
  bool same_corners = true;
  for(std::size_t f = 0; same_corners && f < faces.size(); ++f)
    for(std::size_t k = 0; same_corners && k < 3; ++k)
    {
      const std::uint32_t i = index_values[3 * f + k];
      if(i >= expected_vertices)
      {
        same_corners = false;
        break;
      }
      const Corner& c = faces[f][k];
      same_corners = positions[3 * i] == float(c.position.x()) && positions[3 * i + 1] == float(c.position.y()) &&
                     positions[3 * i + 2] == float(c.position.z()) && texcoords[2 * i] == float(c.uv.x()) &&
                     texcoords[2 * i + 1] == float(1.0 - c.uv.y());
    }
  check(same_corners, "GLB: per-corner positions and TEXCOORD_0 = (u, 1 - v), in face order");
}

// ---- PNG --------------------------------------------------------------------

std::uint32_t big_endian(const std::string& bytes, std::size_t at)
{
  std::uint32_t value = 0;
  for(std::size_t k = 0; k < 4; ++k)
    value = (value << 8) | static_cast<unsigned char>(bytes[at + k]);
  return value;
}

void test_png(const Test_mesh& t, const std::string& path, int resolution)
{
  const std::string bytes = read_file(path);
  static const unsigned char signature[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
  const bool header = bytes.size() > 33 && std::memcmp(bytes.data(), signature, 8) == 0 &&
                      bytes.compare(12, 4, "IHDR") == 0;
  check(header, "PNG: signature and IHDR chunk");
  if(!header)
    return;
  check(big_endian(bytes, 16) == std::uint32_t(resolution) && big_endian(bytes, 20) == std::uint32_t(resolution),
        "PNG: IHDR width and height are the resolution");
  check(bytes[24] == 8 && bytes[25] == 2, "PNG: 8-bit RGB");

  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &width, &height, &channels, 3);
  check(pixels != nullptr && width == resolution && height == resolution && channels == 3, "PNG: decodes as RGB");
  if(pixels == nullptr)
    return;
  // The pixel whose center is nearest to (u, v); row 0 is v = 1.
  auto at = [&](double u, double v) {
    const int x = std::min(resolution - 1, int(u * resolution));
    const int y = std::min(resolution - 1, int((1.0 - v) * resolution));
    const unsigned char* p = pixels + 3 * (std::size_t(y) * std::size_t(resolution) + std::size_t(x));
    return std::array<unsigned char, 3>{{ p[0], p[1], p[2] }};
  };
  typedef std::array<unsigned char, 3> Rgb;
  const Rgb white = {{ 255, 255, 255 }}, red = {{ 255, 0, 0 }}, dark = {{ 24, 24, 24 }};
  check(at(0.01, 0.01) == white && at(0.99, 0.99) == white && at(0.5, 0.5) == white,
        "PNG: white outside the charts");
  check(at(0.75, 0.3) == red && at(0.62, 0.8) == red, "PNG: flipped chart 1 is red");
  check(at(0.25, 0.3) == CGAL::Disk_segmentation::IO::chart_color(0) && at(0.3, 0.8) == CGAL::Disk_segmentation::IO::chart_color(0),
        "PNG: chart 0 has its color");
  check(CGAL::Disk_segmentation::IO::chart_color(0) != white && CGAL::Disk_segmentation::IO::chart_color(0) != red && CGAL::Disk_segmentation::IO::chart_color(1) != red &&
          CGAL::Disk_segmentation::IO::chart_color(0) != CGAL::Disk_segmentation::IO::chart_color(1),
        "PNG: chart colors differ from each other, white and red");
  check(at(0.05, 0.5) == dark && at(0.45, 0.3) == dark && at(0.25, 0.05) == dark,
        "PNG: chart 0 borders (boundary and seam) are dark lines");
  // Vertical line u = 1/3 of the 3D grid is inside chart 0: no border there.
  check(at(0.25, 0.5) == CGAL::Disk_segmentation::IO::chart_color(0), "PNG: no line across the inside of a chart");
  (void)t;
  stbi_image_free(pixels);
}

} // namespace

int main()
{
  char folder_template[] = "/tmp/atlas_writers_XXXXXX";
  const char* folder_name = ::mkdtemp(folder_template);
  if(folder_name == nullptr)
  {
    std::cerr << "cannot create a temporary folder" << std::endl;
    std::cout << "atlas_writers: 0 passed, 1 failed" << std::endl;
    return 1;
  }
  const std::string folder = folder_name;
  std::vector<std::string> files;

  Test_mesh t;
  build(t);
  check(t.mesh.number_of_vertices() == 9 && t.mesh.number_of_faces() == 8 && t.mesh.has_garbage(),
        "test mesh: 9 vertices, 8 faces, one removed vertex");

  // 6 (vertex, chart) pairs per chart: the 3 seam vertices are duplicated.
  const std::string obj_path = folder + "/atlas.obj", glb_path = folder + "/atlas.glb",
                    png_path = folder + "/atlas.png";
  files.insert(files.end(), { obj_path, glb_path, png_path });
  check(write_file(obj_path, [&](std::ostream& out) { CGAL::Disk_segmentation::IO::write_atlas_OBJ(out, t.mesh, t.patch, t.uv); }),
        "OBJ: writes");
  test_obj(t, obj_path, 12);
  check(write_file(glb_path, [&](std::ostream& out) { CGAL::Disk_segmentation::IO::write_atlas_GLB(out, t.mesh, t.patch, t.uv); }),
        "GLB: writes");
  test_glb(t, glb_path, 12);
  const int resolution = 64;
  check(write_file(png_path, [&](std::ostream& out) { CGAL::Disk_segmentation::IO::write_atlas_PNG(out, t.mesh, t.patch, t.uv, resolution); }),
        "PNG: writes");
  test_png(t, png_path, resolution);

  // The writers leave the stream's formatting as they found it.
  {
    std::ostringstream out;
    out.precision(4);
    CGAL::Disk_segmentation::IO::write_atlas_OBJ(out, t.mesh, t.patch, t.uv);
    out.str("");
    out << 1.0 / 3.0;
    check(out.str() == "0.3333", "OBJ: the stream's precision is restored");
  }

  // A corner whose UV differs from the other corners of its vertex in the same
  // chart keeps its own UV: one more texture vertex, corners still exact.
  {
    Test_mesh u;
    build(u);
    const Face_index first = *u.mesh.faces().begin();
    const Halfedge_index h = u.mesh.halfedge(first);
    u.uv[h] = Point_2(u.uv[h].x() + 0.001, u.uv[h].y());
    const std::string path = folder + "/discontinuous.obj", glb = folder + "/discontinuous.glb";
    files.insert(files.end(), { path, glb });
    check(write_file(path, [&](std::ostream& out) { CGAL::Disk_segmentation::IO::write_atlas_OBJ(out, u.mesh, u.patch, u.uv); }),
          "OBJ (discontinuous UVs): writes");
    test_obj(u, path, 13);
    check(write_file(glb, [&](std::ostream& out) { CGAL::Disk_segmentation::IO::write_atlas_GLB(out, u.mesh, u.patch, u.uv); }),
          "GLB (discontinuous UVs): writes");
    test_glb(u, glb, 13);
  }

  // Errors.
  {
    Mesh empty;
    Patch_map patch = empty.add_property_map<Face_index, std::size_t>("f:patch", 0).first;
    UV_map uv = empty.add_property_map<Halfedge_index, Point_2>("h:uv", Point_2(0, 0)).first;
    std::ostringstream out;
    bool threw = false;
    try { CGAL::Disk_segmentation::IO::write_atlas_GLB(out, empty, patch, uv); }
    catch(const CGAL::Disk_segmentation::Input_error&) { threw = true; }
    check(threw, "GLB: an empty mesh throws Input_error");
    threw = false;
    try { CGAL::Disk_segmentation::IO::write_atlas_PNG(out, t.mesh, t.patch, t.uv, 0); }
    catch(const CGAL::Disk_segmentation::Input_error&) { threw = true; }
    check(threw, "PNG: resolution 0 throws Input_error");
    std::ostringstream png;
    CGAL::Disk_segmentation::IO::write_atlas_PNG(png, empty, patch, uv, 8);
    check(png.str().compare(1, 3, "PNG") == 0, "PNG: an empty mesh gives a white picture");
  }

  // Charts so small that 32-bit floats cannot hold their triangles (valid
  // in doubles): the GLB writer refuses them and writes no byte.
  {
    Test_mesh tiny;
    build(tiny);
    for(Halfedge_index h : tiny.mesh.halfedges())
      if(!tiny.mesh.is_border(h))
        tiny.uv[h] = Point_2(0.5 + 1e-12 * tiny.uv[h].x(), 0.5 + 1e-12 * tiny.uv[h].y());
    std::ostringstream out;
    std::string message;
    try { CGAL::Disk_segmentation::IO::write_atlas_GLB(out, tiny.mesh, tiny.patch, tiny.uv); }
    catch(const CGAL::Disk_segmentation::Input_error& e) { message = e.what(); }
    check(message.find("degenerate or flipped in 32-bit float UVs") != std::string::npos && out.str().empty(),
          "GLB: triangles that float UVs collapse throw before writing (" + message + ")");
    // As small at (0, 1), which glTF's flipped v writes near 0: floats hold
    // them, so they are written.
    Test_mesh held;
    build(held);
    for(Halfedge_index h : held.mesh.halfedges())
      if(!held.mesh.is_border(h))
        held.uv[h] = Point_2(1e-12 * held.uv[h].x(), 1. - 1e-12 * held.uv[h].y());
    std::ostringstream kept;
    message.clear();
    try { CGAL::Disk_segmentation::IO::write_atlas_GLB(kept, held.mesh, held.patch, held.uv); }
    catch(const CGAL::Disk_segmentation::Input_error& e) { message = e.what(); }
    check(message.empty() && kept.str().compare(0, 4, "glTF") == 0, "GLB: tiny UVs that floats hold are written");
  }

  // UDIM tiles stop at 1999: a page beyond it is refused, the UVs untouched.
  {
    Test_mesh pages;
    build(pages);
    std::vector<std::size_t> page_of_chart = { 0, CGAL::Disk_segmentation::IO::max_udim_pages - 1 };
    CGAL::Disk_segmentation::IO::move_pages_to_udim_tiles(pages.mesh, pages.patch, pages.uv, page_of_chart);
    check(CGAL::Disk_segmentation::IO::udim_tile(page_of_chart[1]) == 1999, "UDIM: the last page is tile 1999");
    Test_mesh beyond;
    build(beyond);
    const Halfedge_index h = beyond.mesh.halfedge(*beyond.mesh.faces().begin());
    const Point_2 before = beyond.uv[h];
    bool threw = false;
    try
    {
      CGAL::Disk_segmentation::IO::move_pages_to_udim_tiles(beyond.mesh, beyond.patch, beyond.uv,
                                                           { 0, CGAL::Disk_segmentation::IO::max_udim_pages });
    }
    catch(const CGAL::Disk_segmentation::Input_error&) { threw = true; }
    check(threw && beyond.uv[h] == before, "UDIM: a page beyond tile 1999 throws and moves no UV");
  }

  if(failed == 0)
  {
    for(const std::string& f : files)
      std::remove(f.c_str());
    ::rmdir(folder.c_str());
  }
  else
    std::cerr << "files kept in " << folder << std::endl;

  std::cout << "atlas_writers: " << passed << " passed, " << failed << " failed" << std::endl;
  return failed == 0 ? 0 : 1;
}
