// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The disk_uv tool's strict readers of OFF, OBJ, STL and GOCAD TS polygon
// soups (PLY: Ply_reader.h), parsing a file held in memory. Each keeps the
// file's vertex and face order, allocates no more than the file's bytes can
// fill, and throws a File_error naming the line (or byte) and the token at
// fault. Non-finite coordinates are refused here, where the line is known.

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_MESH_READERS_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_MESH_READERS_H

#include <CGAL/Disk_segmentation/IO/internal/Ply_reader.h>
#include <CGAL/Disk_segmentation/IO/internal/Text_scanner.h>
#include <CGAL/Disk_segmentation/IO/File_error.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

typedef std::vector<std::vector<std::size_t> > Polygons;

// Reads an ASCII OFF file (OFF, COFF, NOFF, CNOFF, STOFF...: the values
// after a vertex's three coordinates and after a face's indices, such as
// colors and normals, are ignored), one vertex or face per line. Our own
// reader: CGAL 5.5's converts a negative face size to an unsigned integer
// (undefined behavior, found by the fuzzer), and on a 2.2M-face file the
// whole read (parse, check, build the mesh) drops from 4.0 s to 2.4 s.
template <typename Point>
void read_OFF_soup(std::string_view text, const std::string& name, std::vector<Point>& points, Polygons& polygons)
{
  Text_scanner in(text, name, "off");
  std::vector<std::string_view> tokens;
  if(!in.next_tokens(tokens))
    in.fail_file("it is empty");
  const std::string_view keyword = tokens[0];
  if(keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF")
    in.fail("the file does not start with an OFF keyword");
  if(keyword.find_first_of("4n") != std::string_view::npos)  // 4OFF, nOFF: other dimensions
    in.fail("only 3D OFF files are supported");
  std::size_t first_count = 1;
  if(tokens.size() >= 2 && tokens[1] == "BINARY")
    in.fail("binary OFF is not supported; convert it to ASCII");
  if(tokens.size() == 1)
  {
    if(!in.next_tokens(tokens))
      in.fail("the vertex and face counts are missing");
    first_count = 0;
  }
  std::size_t number_of_vertices = 0, number_of_faces = 0;
  if(tokens.size() < first_count + 2 || !parse_index(tokens[first_count], number_of_vertices) ||
     !parse_index(tokens[first_count + 1], number_of_faces))
    in.fail("expected the numbers of vertices and faces");

  // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 2 ("0\n");
  // the last line may lack its line break.
  const std::size_t left = in.bytes_left();
  if(number_of_vertices > left || number_of_faces > left ||
     6 * number_of_vertices + 2 * number_of_faces > left + 1)
    in.fail(std::to_string(number_of_vertices) + " vertices and " + std::to_string(number_of_faces) +
            " faces do not fit in the " + std::to_string(left) + " bytes after this line");

  points.reserve(points.size() + number_of_vertices);
  polygons.reserve(polygons.size() + number_of_faces);
  double xyz[3];
  for(std::size_t v = 0; v < number_of_vertices; ++v)
  {
    if(!in.next_tokens(tokens))
      in.fail("the file ends after " + std::to_string(v) + " of its " + std::to_string(number_of_vertices) +
              " vertices");
    if(tokens.size() < 3 || !parse_number(tokens[0], xyz[0]) ||
       !parse_number(tokens[1], xyz[1]) || !parse_number(tokens[2], xyz[2]))
      in.fail("vertex #" + std::to_string(v) + " does not start with three numbers");
    for(int i = 0; i < 3; ++i)
      if(!std::isfinite(xyz[i]))
        in.fail("vertex #" + std::to_string(v) + " has a non-finite coordinate " + quote_token(tokens[i]));
    points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }
  for(std::size_t f = 0; f < number_of_faces; ++f)
  {
    if(!in.next_tokens(tokens))
      in.fail("the file ends after " + std::to_string(f) + " of its " + std::to_string(number_of_faces) + " faces");
    std::size_t size = 0;
    if(!parse_index(tokens[0], size) || size > tokens.size() - 1)
      in.fail("face #" + std::to_string(f) + " does not start with its number of vertices followed by as many indices");
    std::vector<std::size_t> polygon(size);
    for(std::size_t i = 0; i < size; ++i)
      if(!parse_index(tokens[i + 1], polygon[i]))
        in.fail("face #" + std::to_string(f) + " has an index that is not a non-negative integer");
    polygons.push_back(std::move(polygon));
  }
}


// OBJ statements that do not change the polygon soup: texture coordinates,
// normals, groups, materials, lines, points, free-form geometry.
inline bool is_ignored_OBJ_statement(std::string_view keyword)
{
  static const char* const ignored[] = {
    "vt", "vn", "vp", "l", "p", "o", "g", "s", "mg", "usemtl", "mtllib", "maplib", "usemap", "bevel", "lod",
    "ctech", "c_interp", "d_interp", "stech", "shadow_obj", "trace_obj", "cstype", "deg", "step", "bmat", "con",
    "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "bsp", "bzp", "cdc", "cdp", "res",
    // accepted by CGAL 5.5's reader, so kept
    "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2", "q0_2", "q1_2", "curv2d_2" };
  for(const char* statement : ignored)
    if(keyword == statement)
      return true;
  return false;
}

// A statement ending with '\' (and no comment) continues on the next line.
inline bool continues_on_next_line(std::string_view line)
{
  if(line.find('#') != std::string_view::npos)
    return false;
  while(!line.empty() && is_blank(line.back()))
    line.remove_suffix(1);
  return !line.empty() && line.back() == '\\';
}


// Reads a Wavefront OBJ file: `v x y z [w] [colors]` and `f` lines whose
// corners are `v`, `v/vt`, `v/vt/vn` or `v//vn`, indices from 1 or negative
// (relative to the vertices so far); other statements are ignored, unknown
// ones refused.
template <typename Point>
void read_OBJ_soup(std::string_view text, const std::string& name, std::vector<Point>& points, Polygons& polygons)
{
  Text_scanner in(text, name, "obj");
  std::vector<std::string_view> tokens;
  std::string joined;
  const std::size_t vertices_before = points.size();
  // Positive indices may refer to vertices defined later: checked at the end.
  long long largest_index = 0;
  std::size_t largest_index_line = 0;
  // Each pass takes a line, the inner loop one more per continued line.
  while(in.next_line())
  {
    const std::size_t line_number = in.line_number();
    std::string_view statement = in.line();
    if(continues_on_next_line(statement))
    {
      joined.clear();
      while(continues_on_next_line(statement))
      {
        joined.append(statement.data(), statement.find_last_of('\\')).push_back(' ');
        if(joined.size() > max_line_bytes)
          in.fail_at(line_number, "a statement continued over lines is longer than " +
                                    size_text(max_line_bytes));
        if(!in.next_line())
          break;
        statement = in.line();
      }
      if(!continues_on_next_line(statement))
        joined.append(statement.data(), statement.size());
      statement = joined;
    }
    split_tokens(statement, tokens);
    if(tokens.empty())
      continue;
    const std::string_view keyword = tokens[0];
    auto vertex_name = [&] { return "vertex #" + std::to_string(points.size() - vertices_before); };
    if(keyword == "v")
    {
      if(tokens.size() < 4)
        in.fail_at(line_number, vertex_name() + " has fewer than three coordinates");
      double xyz[3] = { 0, 0, 0 };
      for(std::size_t i = 1; i < tokens.size(); ++i)
      {
        double value = 0;
        if(!parse_number(tokens[i], value))
          in.fail_at(line_number, quote_token(tokens[i]) + " is not a number");
        if(i <= 3 && !std::isfinite(value))
          in.fail_at(line_number, vertex_name() + " has a non-finite coordinate " + quote_token(tokens[i]));
        if(i <= 3)
          xyz[i - 1] = value;
      }
      points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    else if(keyword == "f")
    {
      std::vector<std::size_t> polygon;
      polygon.reserve(tokens.size() - 1);
      for(std::size_t i = 1; i < tokens.size(); ++i)
      {
        const std::string_view corner = tokens[i];
        const std::size_t slash = corner.find('/');
        const std::string_view vertex = corner.substr(0, slash);
        if(slash != std::string_view::npos)
        {
          // v/vt, v/vt/vn or v//vn: the other indices are not used, but must be indices.
          const std::string_view others = corner.substr(slash + 1);
          const std::size_t second = others.find('/');
          const std::string_view texture = others.substr(0, second);
          const std::string_view normal = second == std::string_view::npos ? std::string_view() : others.substr(second + 1);
          long long unused = 0;
          bool overflow = false;
          const bool texture_ok = texture.empty() ? second != std::string_view::npos && !normal.empty()
                                                  : parse_integer(texture, unused, overflow);
          const bool normal_ok = second == std::string_view::npos || parse_integer(normal, unused, overflow);
          if(!texture_ok || !normal_ok)
            in.fail_at(line_number, quote_token(corner) + " is not a face corner (v, v/vt, v/vt/vn or v//vn)");
        }
        long long index = 0;
        bool overflow = false;
        if(!parse_integer(vertex, index, overflow))
        {
          if(overflow)
            in.fail_at(line_number, "index " + std::string(vertex) + " refers to no vertex");
          in.fail_at(line_number, quote_token(vertex) + " is not a vertex index");
        }
        const long long so_far = static_cast<long long>(points.size() - vertices_before);
        if(index == 0)
          in.fail_at(line_number, "index 0 refers to no vertex (OBJ indices start at 1)");
        if(index < 0 && -index > so_far)
          in.fail_at(line_number, "index " + std::to_string(index) + " refers to no vertex (" +
                                    std::to_string(so_far) + " vertices so far)");
        if(index > largest_index)
        {
          largest_index = index;
          largest_index_line = line_number;
        }
        polygon.push_back(vertices_before + std::size_t(index > 0 ? index - 1 : so_far + index));
      }
      if(polygon.empty())
        in.fail_at(line_number, "face #" + std::to_string(polygons.size()) + " has no vertex");
      polygons.push_back(std::move(polygon));
    }
    else if(!is_ignored_OBJ_statement(keyword))
      in.fail_at(line_number, "unknown statement " + quote_token(keyword));
  }
  const std::size_t vertices = points.size() - vertices_before;
  if(largest_index > static_cast<long long>(vertices))
    in.fail_at(largest_index_line, "index " + std::to_string(largest_index) + " refers to no vertex (the file has " +
                                     std::to_string(vertices) + " vertices)");
  if(polygons.empty())
    in.fail_file(vertices == 0 ? "it has no vertex and no face" : "it has no face");
}


// Gives each distinct point the index of its first appearance, as CGAL's
// STL reader does with a std::map of points: -0.0 and 0.0 are one point
// (NaN is refused before it gets here).
template <typename Point>
class Point_merger
{
public:
  std::size_t index_of(const std::array<double, 3>& xyz, std::vector<Point>& points)
  {
    const std::array<double, 3> key = { { xyz[0] + 0.0, xyz[1] + 0.0, xyz[2] + 0.0 } };  // -0.0 + 0.0 is 0.0
    const auto inserted = index_.emplace(key, points.size());
    if(inserted.second)
      points.emplace_back(xyz[0], xyz[1], xyz[2]);
    return inserted.first->second;
  }

private:
  struct Hash
  {
    std::size_t operator()(const std::array<double, 3>& p) const
    {
      std::size_t h = 0;
      for(double c : p)
      {
        std::uint64_t bits;
        std::memcpy(&bits, &c, sizeof(bits));
        h = (h ^ std::size_t(bits)) * 1099511628211ull;
      }
      return h;
    }
  };
  std::unordered_map<std::array<double, 3>, std::size_t, Hash> index_;
};

inline std::uint32_t little_endian_uint32(const char* bytes)
{
  const unsigned char* b = reinterpret_cast<const unsigned char*>(bytes);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

inline float little_endian_float(const char* bytes)
{
  const std::uint32_t bits = little_endian_uint32(bytes);
  float value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

// Whether an STL file of `file_size` bytes that starts with `head` (at
// least its first 84 bytes, or all of it) is ASCII: it starts with 'solid'
// and a blank (after blank lines), unless its size is exactly the one its
// binary header declares (some binary writers start the header with 'solid').
inline bool is_ASCII_STL(std::string_view head, std::uint64_t file_size)
{
  std::size_t start = 0;
  while(start < head.size() && (is_blank(head[start]) || head[start] == '\n'))
    ++start;
  const std::string_view word = head.substr(start, 6);
  const bool starts_with_solid =
    word.substr(0, 5) == "solid" && (word.size() == 5 || is_blank(word[5]) || word[5] == '\n');
  const bool binary_size =
    head.size() >= 84 && file_size == 84 + 50 * std::uint64_t(little_endian_uint32(head.data() + 80));
  return starts_with_solid && !binary_size;
}

template <typename Point>
void read_binary_STL(std::string_view bytes, const std::string& name, std::vector<Point>& points, Polygons& polygons)
{
  auto fail = [&](const std::string& why) {
    throw File_error("'" + name + "' is not a valid .stl file (" + why + ")");
  };
  if(bytes.size() < 84)
    fail("it does not start with 'solid' and its " + std::to_string(bytes.size()) +
         " bytes are too few for a binary STL (an 84-byte header and 50 bytes per triangle)");
  const std::uint64_t triangles = little_endian_uint32(bytes.data() + 80);
  if(84 + 50 * triangles > bytes.size())
    fail("binary: its header declares " + std::to_string(triangles) + " triangles, but its " +
         std::to_string(bytes.size()) + " bytes hold at most " + std::to_string((bytes.size() - 84) / 50));
  if(triangles == 0)
    fail("binary: it has no triangle");
  Point_merger<Point> merger;
  polygons.reserve(polygons.size() + triangles);
  for(std::uint64_t t = 0; t < triangles; ++t)
  {
    const char* triangle = bytes.data() + 84 + 50 * t;
    std::vector<std::size_t> corners(3);
    for(int c = 0; c < 3; ++c)
    {
      std::array<double, 3> xyz;
      for(int i = 0; i < 3; ++i)
      {
        xyz[i] = little_endian_float(triangle + 12 * (c + 1) + 4 * i);
        if(!std::isfinite(xyz[i]))
          fail("binary, byte " + std::to_string(84 + 50 * t) + ": triangle #" + std::to_string(t) +
               " has a non-finite coordinate");
      }
      corners[c] = merger.index_of(xyz, points);
    }
    polygons.push_back(std::move(corners));
  }
}

template <typename Point>
void read_ASCII_STL(std::string_view text, const std::string& name, std::vector<Point>& points, Polygons& polygons)
{
  Text_scanner in(text, name, "stl");
  Point_merger<Point> merger;
  std::string_view token;
  auto facet = [&] { return "facet #" + std::to_string(polygons.size()); };
  // The next token of the current facet, which must be `keyword` if given.
  auto next_in_facet = [&](const char* keyword) {
    if(!in.next_token(token))
      in.fail("the file ends in " + facet());
    if(keyword != nullptr && token != keyword)
      in.fail("expected '" + std::string(keyword) + "' in " + facet() + ", found " + quote_token(token));
  };
  auto number = [&] {
    double value = 0;
    next_in_facet(nullptr);
    if(!parse_number(token, value))
      in.fail(quote_token(token) + " is not a number (in " + facet() + ")");
    return value;
  };
  std::size_t solids = 0;
  // Every pass of both loops takes at least one token, or throws.
  while(in.next_token(token))
  {
    if(token != "solid")
      in.fail("expected 'solid', found " + quote_token(token));
    ++solids;
    in.skip_rest_of_line();  // the solid's name
    for(;;)
    {
      if(!in.next_token(token))
        in.fail("the file ends inside a solid (no 'endsolid')");
      if(token == "endsolid")
        break;
      if(token != "facet")
        in.fail("expected 'facet' or 'endsolid', found " + quote_token(token));
      next_in_facet("normal");
      for(int i = 0; i < 3; ++i)
        number();  // any value: some writers give degenerate facets a NaN normal
      next_in_facet("outer");
      next_in_facet("loop");
      std::vector<std::size_t> corners(3);
      for(int c = 0; c < 3; ++c)
      {
        next_in_facet(nullptr);
        if(token != "vertex")
          in.fail(facet() + " has " + std::to_string(c) + " vertices, then " + quote_token(token) +
                  " (STL facets are triangles)");
        std::array<double, 3> xyz;
        for(int i = 0; i < 3; ++i)
        {
          xyz[i] = number();
          if(!std::isfinite(xyz[i]))
            in.fail(facet() + " has a non-finite coordinate " + quote_token(token));
        }
        corners[c] = merger.index_of(xyz, points);
      }
      next_in_facet(nullptr);
      if(token == "vertex")
        in.fail(facet() + " has more than 3 vertices (STL facets are triangles)");
      if(token != "endloop")
        in.fail("expected 'endloop' in " + facet() + ", found " + quote_token(token));
      next_in_facet("endfacet");
      polygons.push_back(std::move(corners));
    }
    in.skip_rest_of_line();  // the solid's name again
  }
  if(solids == 0)
    in.fail_file("it is empty");
  if(polygons.empty())
    in.fail_file("it has no facet");
}


// Reads an STL file, binary or ASCII. Identical points are merged into one
// vertex, numbered in order of first appearance (as CGAL's reader does:
// STL lists each triangle's three points). A file is ASCII when it starts
// with 'solid' and a blank, unless its size is exactly the one its binary
// header declares (some binary writers start the header with 'solid').
template <typename Point>
void read_STL_soup(std::string_view bytes, const std::string& name, std::vector<Point>& points, Polygons& polygons)
{
  std::size_t start = 0;
  while(start < bytes.size() && (is_blank(bytes[start]) || bytes[start] == '\n'))
    ++start;
  if(start == bytes.size())
    throw File_error("'" + name + "' is not a valid .stl file (it is empty)");
  if(is_ASCII_STL(bytes, bytes.size()))
    read_ASCII_STL(bytes, name, points, polygons);
  else
    read_binary_STL(bytes, name, points, polygons);
}

// Reads a GOCAD TSurf (.ts) file: the VRTX/PVRTX (id x y z), ATOM/PATOM
// (id, id of the vertex it repeats) and TRGL (three ids) lines after a
// TFACE line, up to END; several objects may follow each other. Other lines
// (header, properties, borders) do not change the soup.
template <typename Point>
void read_TS_soup(std::string_view text, const std::string& name, std::vector<Point>& points, Polygons& polygons)
{
  Text_scanner in(text, name, "ts");
  std::vector<std::string_view> tokens;
  struct Triangle
  {
    long long ids[3];
    std::size_t line;
  };
  std::unordered_map<long long, std::size_t> vertex_of_id;
  std::vector<Triangle> triangles;
  bool in_faces = false;
  std::size_t objects = 0;
  auto id_at = [&](std::size_t i, const char* what) {
    long long id = 0;
    bool overflow = false;
    if(i >= tokens.size() || !parse_integer(tokens[i], id, overflow))
      in.fail(std::string(what) + (i < tokens.size() ? ": " + quote_token(tokens[i]) + " is not an id" : " is missing"));
    return id;
  };
  auto define = [&](long long id, std::size_t vertex) {
    if(!vertex_of_id.emplace(id, vertex).second)
      in.fail("vertex id " + std::to_string(id) + " is defined twice");
  };
  // Each pass takes a line.
  while(in.next_tokens(tokens, '\0'))
  {
    const std::string_view keyword = tokens[0];
    if(!in_faces)
    {
      if(keyword == "TFACE")
      {
        in_faces = true;
        ++objects;
      }
      continue;
    }
    if(keyword == "VRTX" || keyword == "PVRTX")
    {
      const long long id = id_at(1, "the vertex id");
      double xyz[3];
      for(int i = 0; i < 3; ++i)
      {
        if(std::size_t(i + 2) >= tokens.size() || !parse_number(tokens[i + 2], xyz[i]))
          in.fail("vertex #" + std::to_string(points.size()) + " does not have three coordinates after its id");
        if(!std::isfinite(xyz[i]))
          in.fail("vertex #" + std::to_string(points.size()) + " has a non-finite coordinate " +
                  quote_token(tokens[i + 2]));
      }
      define(id, points.size());
      points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    else if(keyword == "ATOM" || keyword == "PATOM")
    {
      const long long id = id_at(1, "the atom id");
      const auto repeated = vertex_of_id.find(id_at(2, "the id of the atom's vertex"));
      if(repeated == vertex_of_id.end())
        in.fail("the atom repeats vertex id " + std::string(tokens[2]) + ", which no VRTX line before defines");
      define(id, repeated->second);
    }
    else if(keyword == "TRGL")
      triangles.push_back({ { id_at(1, "the triangle's first id"), id_at(2, "the triangle's second id"),
                              id_at(3, "the triangle's third id") }, in.line_number() });
    else if(keyword == "END")
    {
      // Triangles may name vertices defined after them, within their object.
      for(const Triangle& t : triangles)
      {
        std::vector<std::size_t> corners(3);
        for(int c = 0; c < 3; ++c)
        {
          const auto found = vertex_of_id.find(t.ids[c]);
          if(found == vertex_of_id.end())
            in.fail_at(t.line, "the triangle refers to vertex id " + std::to_string(t.ids[c]) +
                                 ", which no VRTX line defines");
          corners[c] = found->second;
        }
        polygons.push_back(std::move(corners));
      }
      triangles.clear();
      vertex_of_id.clear();
      in_faces = false;
    }
    else if(keyword == "GOCAD")
      in.fail("a new GOCAD object starts before the END of the previous one");
  }
  if(in_faces)
    in.fail_file("the file ends without the END line of its last object");
  if(objects == 0)
    in.fail_file("it has no TFACE section");
  if(polygons.empty())
    in.fail_file("it has no triangle");
}

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_MESH_READERS_H
