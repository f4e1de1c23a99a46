// The package's mesh readers (IO/internal/Mesh_readers.h, Ply_reader.h) and input
// file (IO/internal/Input_file.h): every format variant they accept gives the points
// and faces written out by hand here, in the file's order; every refusal is
// one line naming the line (or byte) and the token; inputs that are not
// regular files are refused without blocking, and no count is trusted
// beyond the bytes that back it.

#include <CGAL/Disk_segmentation/IO/read_triangle_mesh.h>

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 Point;
typedef std::vector<std::array<double, 3> > Points;
typedef std::vector<std::vector<std::size_t> > Faces;

struct Soup
{
  std::vector<Point> points;
  Faces faces;
};

Soup read(const std::string& bytes, const std::string& ext)
{
  Soup soup;
  CGAL::Disk_segmentation::IO::internal::read_polygon_soup_from(bytes, ext, "m." + ext, soup.points, soup.faces);
  return soup;
}

// The reader's message, or "accepted".
std::string refusal(const std::string& bytes, const std::string& ext)
{
  try
  {
    read(bytes, ext);
  }
  catch(const CGAL::Disk_segmentation::IO::File_error& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    return message;
  }
  return "accepted";
}

void expect_soup(const std::string& bytes, const std::string& ext, const Points& points, const Faces& faces)
{
  SCOPED_TRACE(ext + " file:\n" + bytes.substr(0, 400));
  Soup soup;
  try
  {
    soup = read(bytes, ext);
  }
  catch(const CGAL::Disk_segmentation::IO::File_error& e)
  {
    FAIL() << "refused: " << e.what();
  }
  ASSERT_EQ(soup.points.size(), points.size());
  for(std::size_t v = 0; v < points.size(); ++v)
    EXPECT_EQ(soup.points[v], Point(points[v][0], points[v][1], points[v][2])) << "vertex #" << v;
  EXPECT_EQ(soup.faces, faces);
}

#define EXPECT_REFUSED(bytes, ext, words) EXPECT_NE(refusal(bytes, ext).find(words), std::string::npos) \
  << "message: " << refusal(bytes, ext) << "\nexpected: " << (words)

// Binary files written value by value in either byte order.
struct Bytes
{
  bool big_endian = false;
  std::string data;

  template <typename T>
  Bytes& put(T value)
  {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    const std::uint16_t one = 1;
    const bool host_little = *reinterpret_cast<const char*>(&one) == 1;
    if(host_little == big_endian)
      std::reverse(b, b + sizeof(T));
    data.append(b, sizeof(T));
    return *this;
  }
  Bytes& text(const std::string& s)
  {
    data += s;
    return *this;
  }
};

const Points tetrahedron_points = { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } }, { { 0, 0, 1 } } };
const Faces tetrahedron_faces = { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } };
const std::string three_vertices_ply =
  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";

std::string temp_path(const std::string& name)
{
  return std::string(::testing::TempDir()) + "disk_uv_readers_" + name;
}

// Runs `f` in a child process that is killed after 10 s: a read that
// blocks fails the test instead of hanging it. Returns f's result, or -1.
int in_child(const std::function<int()>& f)
{
  const pid_t child = ::fork();
  if(child == 0)
  {
    ::alarm(10);
    int result = 3;
    try
    {
      result = f();
    }
    catch(...)
    {
    }
    ::_exit(result);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

TEST(Readers, OffVariants)
{
  const Faces triangle = { { 0, 1, 2 } };
  const Points points = { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } } };
  expect_soup("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "off", points, triangle);
  expect_soup("OFF 3 1 0\r\n# comment\r\n\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2", "off", points, triangle);
  expect_soup("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1e-400 0\t0 0 255 255\n3 0 1 2 0.5 0.5 0.5\n",
              "off", { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0, 0, 0 } } }, triangle);
  expect_soup("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", "off",
              { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 1, 1, 0 } }, { { 0, 1, 0 } } }, { { 0, 1, 2, 3 } });
}

TEST(Readers, OffRefusals)
{
  EXPECT_REFUSED("", "off", "(it is empty)");
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "off",
                 "(line 4: vertex #1 has a non-finite coordinate 'nan')");
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\n1e400 0 0\n0 1 0\n3 0 1 2\n", "off",
                 "(line 4: vertex #1 has a non-finite coordinate '1e400')");
  EXPECT_REFUSED("OFF\n100000000 1 0\n0 0 0\n", "off", "(line 2: 100000000 vertices and 1 faces do not fit in the 6 bytes");
  EXPECT_REFUSED("OFF\n3 1 0\n" + std::string(2000000, '1'), "off", "(line 3: longer than 1 MiB without a line break");
  EXPECT_REFUSED(std::string(2000000, '\0'), "off", "(line 1: longer than 1 MiB without a line break");
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n", "off",
                 "(line 6: face #0 does not start with its number of vertices");
  EXPECT_REFUSED("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "off", "(line 6: the file ends after 1 of its 2 faces)");
}

TEST(Readers, ObjVariants)
{
  const Points square = { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 1, 1, 0 } }, { { 0, 1, 0 } } };
  const Faces two_triangles = { { 0, 1, 2 }, { 0, 2, 3 } };
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  expect_soup(v + "f 1 2 3\nf 1 3 4\n", "obj", square, two_triangles);
  // Corners with texture and normal indices.
  expect_soup(v + "vt 0 0\nvn 0 0 1\nf 1/1 2/1 3/1\nf 1/1/1 3//1 4/1/1\n", "obj", square, two_triangles);
  // Negative indices count back from the last vertex so far.
  expect_soup(v + "f -4 -3 -2\nf -4 -2 -1\n", "obj", square, two_triangles);
  // Tabs, CRLF, comments, statements that do not change the soup.
  expect_soup("# square\r\nmtllib m.mtl\r\no square\r\nv\t0 0 0\r\nv 1\t0 0 # x\r\nv 1 1 0\t\r\nv 0 1 0\r\n"
              "vp 0.5\r\ng top\r\ns off\r\nusemtl red\r\nl 1 2\r\np 1\r\nf\t1\t2\t3\r\nf 1 3 4 # second\r\n",
              "obj", square, two_triangles);
  // A weight and vertex colors after the coordinates are ignored.
  expect_soup("v 0 0 0 1 0.5 0.5 0.5\nv 1 0 0 1.0\nv 1 1 0 0.1 0.2 0.3\nv 0 1 0\nf 1 2 3\nf 1 3 4\n", "obj", square,
              two_triangles);
  // A face may name a vertex defined after it; '\' continues a statement.
  expect_soup("f 1 2 3\nf 1 \\\n  3 \\\n 4\n" + v, "obj", square, two_triangles);
  // Polygons keep their size; the soup check or --triangulate deals with them.
  expect_soup(v + "f 1 2 3 4\n", "obj", square, { { 0, 1, 2, 3 } });
}

TEST(Readers, ObjRefusals)
{
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_REFUSED(v + "f 1 2 abc\n", "obj", "'m.obj' is not a valid .obj file (line 4: 'abc' is not a vertex index)");
  EXPECT_REFUSED(v + "f 1 2 1e23\n", "obj", "(line 4: '1e23' is not a vertex index)");
  EXPECT_REFUSED(v + "f 1 2 99999999999999999999999\n", "obj", "(line 4: index 99999999999999999999999 refers to no vertex");
  EXPECT_REFUSED(v + "v nan 0 0\nf 1 2 3\n", "obj", "(line 4: vertex #3 has a non-finite coordinate 'nan')");
  EXPECT_REFUSED(v + "v 0 1e400 0\nf 1 2 3\n", "obj", "(line 4: vertex #3 has a non-finite coordinate '1e400')");
  EXPECT_REFUSED(v + "v 0 0 1\nf 1 2 3\n\nf 1 2 -7\n", "obj", "(line 7: index -7 refers to no vertex (4 vertices so far))");
  EXPECT_REFUSED(v + "f 1 2 3\nf 1 2 9\nf 1 2 3\n", "obj", "(line 5: index 9 refers to no vertex (the file has 3 vertices))");
  EXPECT_REFUSED(v + "f 0 1 2\n", "obj", "(line 4: index 0 refers to no vertex (OBJ indices start at 1))");
  EXPECT_REFUSED(v + "f 1 2 3/\n", "obj", "(line 4: '3/' is not a face corner (v, v/vt, v/vt/vn or v//vn))");
  EXPECT_REFUSED(v + "f 1 2 3/x/1\n", "obj", "(line 4: '3/x/1' is not a face corner");
  EXPECT_REFUSED(v + "f\n", "obj", "(line 4: face #0 has no vertex)");
  EXPECT_REFUSED(v + "v 1 2\n", "obj", "(line 4: vertex #3 has fewer than three coordinates)");
  EXPECT_REFUSED(v + "v 1 2 3 red\n", "obj", "(line 4: 'red' is not a number)");
  EXPECT_REFUSED(v + "frob 1 2\n", "obj", "(line 4: unknown statement 'frob')");
  EXPECT_REFUSED(v, "obj", "(it has no face)");
  EXPECT_REFUSED("", "obj", "(it has no vertex and no face)");
  EXPECT_REFUSED(std::string(2000000, '\0'), "obj", "(line 1: longer than 1 MiB without a line break");
}

TEST(Readers, PlyAscii)
{
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  expect_soup("ply\nformat ascii 1.0\ncomment made by hand\nobj_info none\nelement vertex 4\nproperty float x\n"
              "property float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\n"
              "end_header\n" + body, "ply", tetrahedron_points, tetrahedron_faces);
  // Faces first, other elements and properties (lists too) skipped, CRLF,
  // vertex_index, coordinates of integer types.
  expect_soup("ply\r\nformat ascii 1.0\r\nelement face 2\r\nproperty uchar flags\r\n"
              "property list ushort uint32 vertex_index\r\nproperty list uchar float texcoord\r\n"
              "element material 1\r\nproperty list int int ids\r\nelement vertex 4\r\nproperty int16 x\r\n"
              "property list uchar uchar tags\r\nproperty char y\r\nproperty double z\r\nproperty uchar red\r\n"
              "end_header\r\n7 3 0 1 2 2 0.5 0.5\r\n7 3 0 2 3 0\r\n3 -5 6 7\r\n0 0 0 0 9\r\n1 1 4 0 0 9\r\n"
              "1 0 1 0.0 9\r\n0 0 1 1e-400 9\r\n",
              "ply", { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 1, 1, 0 } }, { { 0, 1, 0 } } }, { { 0, 1, 2 }, { 0, 2, 3 } });
  // A float property rounds to float, as it does in CGAL's reader.
  Soup soup = read(three_vertices_ply + "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                   "0.1 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "ply");
  EXPECT_EQ(soup.points[0].x(), double(0.1f));
}

TEST(Readers, PlyBinaryAnyTypeEitherByteOrder)
{
  const char* types[][2] = { { "char", "int8" }, { "uchar", "uint8" }, { "short", "int16" }, { "ushort", "uint16" },
                             { "int", "int32" }, { "uint", "uint32" }, { "float", "float32" }, { "double", "float64" } };
  for(bool big_endian : { false, true })
    for(int t = 0; t < 8; ++t)
      for(int spelling = 0; spelling < 2; ++spelling)
      {
        const std::string type = types[t][spelling], count_type = types[(t + 3) % 6][1 - spelling];
        Bytes file;
        file.big_endian = big_endian;
        file.text(std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\nelement vertex 4\nproperty " + type + " x\nproperty " + type + " y\nproperty " + type +
                  " z\nproperty list uchar float extra\nelement face 4\nproperty list " + count_type + " " + type +
                  " vertex_indices\nproperty uchar red\nend_header\n");
        auto put = [&](double value, int type_index) {
          switch(type_index)
          {
            case 0: file.put(std::int8_t(value)); break;
            case 1: file.put(std::uint8_t(value)); break;
            case 2: file.put(std::int16_t(value)); break;
            case 3: file.put(std::uint16_t(value)); break;
            case 4: file.put(std::int32_t(value)); break;
            case 5: file.put(std::uint32_t(value)); break;
            case 6: file.put(float(value)); break;
            default: file.put(double(value));
          }
        };
        for(const auto& p : tetrahedron_points)
        {
          for(double c : p)
            put(c, t);
          file.put(std::uint8_t(1)).put(0.5f);
        }
        for(const auto& f : tetrahedron_faces)
        {
          put(3, (t + 3) % 6);
          for(std::size_t i : f)
            put(double(i), t);
          file.put(std::uint8_t(200));
        }
        SCOPED_TRACE(type + (big_endian ? ", big endian" : ", little endian"));
        expect_soup(file.data, "ply", tetrahedron_points, tetrahedron_faces);
      }
}

TEST(Readers, PlyRefusals)
{
  const std::string face_header = "element face 1\nproperty list char int vertex_indices\nend_header\n";
  EXPECT_REFUSED("ply\nformat ascii\nend_header\n", "ply", "(line 2: expected 'format ascii 1.0'");
  EXPECT_REFUSED("ply\nformat binary_middle_endian 1.0\nend_header\n", "ply",
                 "(line 2: unknown format 'binary_middle_endian'");
  EXPECT_REFUSED("ply\nformat ascii 2.0\nend_header\n", "ply", "(line 2: unsupported PLY version '2.0'");
  EXPECT_REFUSED("PLY\n", "ply", "(line 1: the file does not start with a 'ply' line)");
  EXPECT_REFUSED(three_vertices_ply + face_header + "0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n", "ply",
                 "(line 13: face #0: the list 'vertex_indices' has the length '-1', a negative count)");
  EXPECT_REFUSED(three_vertices_ply + face_header + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "ply",
                 "(line 13: face #0 has the index '-1', which is not a vertex index)");
  EXPECT_REFUSED(three_vertices_ply + face_header + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "ply",
                 "(line 11: vertex #1 has a non-finite coordinate 'nan')");
  EXPECT_REFUSED(three_vertices_ply + face_header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", "ply",
                 "(line 14: data after the last element");
  EXPECT_REFUSED(three_vertices_ply + face_header + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "ply",
                 "(line 13: face #0: the list 'vertex_indices' declares 3 entries, more than the 4 bytes left");
  EXPECT_REFUSED(three_vertices_ply + face_header + "0 0 0\n1 0 0\n0 1 0\n3 000 111\n", "ply",
                 "(line 13: the file ends in face #0)");
  EXPECT_REFUSED(three_vertices_ply + "element face 1\nproperty list uchar uchar vertex_indices\nend_header\n"
                 "0 0 0\n1 0 0\n0 1 0\n3 0 1 256\n", "ply", "(line 13: face #0: '256' is not a uchar");
  EXPECT_REFUSED(three_vertices_ply + "element face 1000000000\nproperty list uchar int vertex_indices\nend_header\n"
                 "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "ply",
                 "(line 7: 1000000000 items of element 'face' do not fit in the 26 bytes after the header)");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n", "ply",
                 "(line 3: a property comes before any element)");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n", "ply",
                 "(line 4: unknown property type 'float128')");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n", "ply",
                 "(line 3: element 'vertex' has no scalar property 'y')");
  EXPECT_REFUSED(three_vertices_ply + "element face 0\nproperty list uchar int indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
                 "ply", "(line 7: element 'face' has no list property 'vertex_indices' (or 'vertex_index'))");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement vertex 1\n", "ply", "(the header has no end_header line)");
  EXPECT_REFUSED("ply\nformat ascii 1.0\n" + std::string(1 << 21, '\n'), "ply",
                 "(no end_header line in its first 1 MiB)");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nmaterial 1\n", "ply", "(line 3: unknown header keyword 'material')");

  // Binary: a list longer than the bytes left is refused before it is allocated.
  const std::string binary_header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                                    "property float y\nproperty float z\nelement face 1\n"
                                    "property list uint int vertex_indices\nend_header\n";
  Bytes file;
  file.text(binary_header);
  for(int i = 0; i < 9; ++i)
    file.put(0.f);
  file.put(std::uint32_t(1000000000)).text(std::string(900, '\0'));
  EXPECT_REFUSED(file.data, "ply", "(byte " + std::to_string(binary_header.size() + 36) +
                                     ": face #0: the list 'vertex_indices' declares 1000000000 entries, "
                                     "more than the 900 bytes left in the file hold)");
  // The counts fit the minimum sizes, but the first list takes the bytes
  // the second face needed.
  std::string two_faces = binary_header;
  two_faces.replace(two_faces.find("face 1"), 6, "face 2");
  Bytes short_file;
  short_file.text(two_faces);
  for(int i = 0; i < 9; ++i)
    short_file.put(0.f);
  short_file.put(std::uint32_t(3)).put(0).put(1).put(2);
  EXPECT_REFUSED(short_file.data, "ply",
                 "(byte " + std::to_string(two_faces.size() + 52) + ": the file ends in face #1)");
  Bytes nan_vertex;
  nan_vertex.text(binary_header).put(0.f).put(0.f).put(0.f).put(std::nanf("")).put(0.f).put(0.f);
  nan_vertex.put(0.f).put(1.f).put(0.f).put(std::uint32_t(3)).put(0).put(1).put(2);
  EXPECT_REFUSED(nan_vertex.data, "ply", "(byte " + std::to_string(binary_header.size() + 12) +
                                           ": vertex #1 has a non-finite coordinate 'nan')");

  // Nothing but our one line: CGAL's reader printed to std::cerr.
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  refusal("ply\nformat ascii\nend_header\n", "ply");
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

namespace {

std::string binary_STL(const std::string& header, const std::vector<std::array<float, 9> >& triangles)
{
  Bytes file;
  file.text(header + std::string(80 - header.size(), ' ')).put(std::uint32_t(triangles.size()));
  for(const auto& t : triangles)
  {
    file.put(0.f).put(0.f).put(1.f);
    for(float c : t)
      file.put(c);
    file.put(std::uint16_t(0));
  }
  return file.data;
}

} // namespace

TEST(Readers, StlVariants)
{
  // Identical points are one vertex, numbered in order of first
  // appearance; -0.0 and 0.0 are the same point (the first one is kept).
  const std::vector<std::array<float, 9> > triangles = {
    { { -0.f, 0, 0, 1, 0, 0, 0, 1, 0 } }, { { 1, 0, 0, 1, 1, 0, 0, 1, 0 } }, { { 0, 0, 0, 0, 0, 1, 1, 0, 0 } } };
  const Points points = { { { -0., 0, 0 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } }, { { 1, 1, 0 } }, { { 0, 0, 1 } } };
  const Faces faces = { { 0, 1, 2 }, { 1, 3, 2 }, { 0, 4, 1 } };
  expect_soup(binary_STL("binary", triangles), "stl", points, faces);
  EXPECT_TRUE(std::signbit(CGAL::to_double(read(binary_STL("binary", triangles), "stl").points[0].x())));
  // Binary writers may start the header with 'solid': the size decides.
  expect_soup(binary_STL("solid exported by a binary writer", triangles), "stl", points, faces);
  expect_soup(binary_STL("binary", triangles) + "padding", "stl", points, faces);

  const std::string ascii =
    "solid one\n  facet normal 0 0 1\n    outer loop\n      vertex -0 0 0\n      vertex 1 0 0\n"
    "      vertex 0 1 0\n    endloop\n  endfacet\nendsolid one\n"
    "solid two\r\nfacet normal nan nan nan\r\nouter loop\r\nvertex 1 0 0\r\nvertex 1 1 0\r\nvertex 0 1 0\r\n"
    "endloop\r\nendfacet\r\nfacet normal 0 0 1 outer loop vertex 0 0 0 vertex 0 0 1 vertex 1 0 0 endloop endfacet\r\n"
    "endsolid two\r\n";
  expect_soup(ascii, "stl", points, faces);
}

TEST(Readers, StlRefusals)
{
  const std::vector<std::array<float, 9> > one = { { { 0, 0, 0, 1, 0, 0, 0, 1, 0 } } };
  std::string more = binary_STL("binary", one);
  more[80] = 3;
  EXPECT_REFUSED(more, "stl", "(binary: its header declares 3 triangles, but its 134 bytes hold at most 1)");
  EXPECT_REFUSED(std::string(40, 'x'), "stl", "it does not start with 'solid' and its 40 bytes are too few for a binary STL");
  EXPECT_REFUSED(binary_STL("binary", { { { 0, 0, 0, 1, std::nanf(""), 0, 0, 1, 0 } } }), "stl",
                 "(binary, byte 84: triangle #0 has a non-finite coordinate)");
  const std::string facet = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n";
  EXPECT_REFUSED(facet + "vertex 1 1 0\nendloop\nendfacet\nendsolid\n", "stl",
                 "(line 7: facet #0 has more than 3 vertices (STL facets are triangles))");
  EXPECT_REFUSED(facet, "stl", "(line 6: the file ends in facet #0)");
  EXPECT_REFUSED(facet + "endloop\nendfacet\n", "stl", "(line 8: the file ends inside a solid (no 'endsolid'))");
  EXPECT_REFUSED("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 inf 0\n", "stl",
                 "(line 5: facet #0 has a non-finite coordinate 'inf')");
  EXPECT_REFUSED("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\n", "stl",
                 "(line 4: 'zero' is not a number (in facet #0))");
  EXPECT_REFUSED("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nendloop\n", "stl",
                 "(line 5: facet #0 has 1 vertices, then 'endloop' (STL facets are triangles))");
  EXPECT_REFUSED("solid s\nendsolid s\n", "stl", "(it has no facet)");
  EXPECT_REFUSED("solid s\nfacet normal 0 0 1\nloop\n", "stl", "(line 3: expected 'outer' in facet #0, found 'loop')");
  EXPECT_REFUSED(" \n\t", "stl", "(it is empty)");
}

TEST(Readers, TsVariants)
{
  // Ids from 1 or 0, PVRTX with properties, an ATOM repeating a vertex,
  // a triangle naming a vertex defined after it, two objects.
  expect_soup("GOCAD TSurf 1\nHEADER {\nname:two\n}\nTFACE\nVRTX 1 0 0 0\r\nPVRTX 2 1 0 0 5.5\nVRTX 3 0 1 0\n"
              "ATOM 4 1\nTRGL 1 2 3\nTRGL 2 4 3\nBSTONE 1\nEND\nGOCAD TSurf 1\nTFACE\nVRTX 0 5 5 5\nVRTX 1 6 5 5\n"
              "TRGL 0 1 2\nVRTX 2 5 6 5\nEND\n",
              "ts",
              { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } }, { { 5, 5, 5 } }, { { 6, 5, 5 } }, { { 5, 6, 5 } } },
              { { 0, 1, 2 }, { 1, 0, 2 }, { 3, 4, 5 } });
}

TEST(Readers, TsRefusals)
{
  const std::string start = "GOCAD TSurf 1\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\n";
  EXPECT_REFUSED(start + "TRGL 1 2 3\nEND\n", "ts", "(line 5: the triangle refers to vertex id 3, which no VRTX line defines)");
  EXPECT_REFUSED(start + "VRTX 3 0 1 0\nTRGL 1 2 3\n", "ts", "(the file ends without the END line of its last object)");
  EXPECT_REFUSED(start + "VRTX 2 0 1 0\n", "ts", "(line 5: vertex id 2 is defined twice)");
  EXPECT_REFUSED(start + "VRTX 3 0 nan 0\n", "ts", "(line 5: vertex #2 has a non-finite coordinate 'nan')");
  EXPECT_REFUSED(start + "TRGL 1 2 x\n", "ts", "(line 5: the triangle's third id: 'x' is not an id)");
  EXPECT_REFUSED("GOCAD TSurf 1\nHEADER {\n}\n", "ts", "(it has no TFACE section)");
}

TEST(Readers, InputFileRefusesWhatIsNotARegularFile)
{
  // Regular files are read whole.
  const std::string path = temp_path("regular.off");
  std::ofstream(path, std::ios::binary) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(CGAL::Disk_segmentation::IO::internal::read_input_file(path, false, 10).size(), 36u);

  auto message = [](const std::string& p, bool allow, std::uint64_t limit) {
    try
    {
      CGAL::Disk_segmentation::IO::internal::read_input_file(p, allow, limit);
    }
    catch(const CGAL::Disk_segmentation::IO::File_error& e)
    {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("/dev/zero", false, std::uint64_t(4) << 30),
            "'/dev/zero' is not a regular file (it is a character device); --allow-special-input reads it, up to 4 GiB");
  EXPECT_EQ(message("/dev/zero", true, 1 << 20),
            "'/dev/zero' is longer than the limit of 1 MiB for an input that is not a regular file");
  EXPECT_EQ(message(::testing::TempDir(), false, 10), "'" + std::string(::testing::TempDir()) + "' is a directory, not a mesh file");
  EXPECT_NE(message(temp_path("missing.off"), false, 10).find("cannot open"), std::string::npos);

  // Through the tool's reader, the extension naming the format.
  const std::string zero = temp_path("zero.off");
  std::remove(zero.c_str());
  ASSERT_EQ(::symlink("/dev/zero", zero.c_str()), 0);
  CGAL::Surface_mesh<Point> mesh;
  try
  {
    CGAL::Disk_segmentation::IO::read_triangle_mesh(zero, mesh);
    ADD_FAILURE() << "/dev/zero read as a mesh";
  }
  catch(const CGAL::Disk_segmentation::IO::File_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("is not a regular file (it is a character device)"), std::string::npos) << e.what();
  }
  std::remove(zero.c_str());
}

TEST(Readers, InputFileNeverBlocksOnAFifo)
{
  const std::string fifo = temp_path("fifo.off");
  std::remove(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Without a writer: refused at once (opening it would block).
  EXPECT_EQ(in_child([&] {
              try
              {
                CGAL::Disk_segmentation::IO::internal::read_input_file(fifo, false, 1 << 20);
              }
              catch(const CGAL::Disk_segmentation::IO::File_error& e)
              {
                return std::string(e.what()).find("is not a regular file (it is a FIFO)") != std::string::npos ? 0 : 1;
              }
              return 2;
            }),
            0);
  // Allowed, with a writer: read to its end.
  const std::string mesh = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(in_child([&] {
              std::thread writer([&] {
                const int fd = ::open(fifo.c_str(), O_WRONLY);
                if(fd >= 0 && ::write(fd, mesh.data(), mesh.size()) == ssize_t(mesh.size()))
                  ::close(fd);
              });
              const std::string bytes = CGAL::Disk_segmentation::IO::internal::read_input_file(fifo, true, 1 << 20);
              writer.join();
              return bytes == mesh ? 0 : 1;
            }),
            0);
  std::remove(fifo.c_str());
}

namespace {

typedef CGAL::Surface_mesh<Point> Surface;

// The first difference between two meshes built from one soup, or "".
// Inner vertices may keep any of their incoming halfedges.
std::string structure_difference(const Surface& a, const Surface& b)
{
  if(a.number_of_vertices() != b.number_of_vertices() || a.number_of_halfedges() != b.number_of_halfedges() ||
     a.number_of_faces() != b.number_of_faces())
    return "different sizes";
  for(Surface::Halfedge_index h : a.halfedges())
    if(a.target(h) != b.target(h) || a.next(h) != b.next(h) || a.opposite(h) != b.opposite(h) ||
       a.face(h) != b.face(h))
      return "halfedge " + std::to_string(std::size_t(h));
  for(Surface::Face_index f : a.faces())
    if(a.halfedge(f) != b.halfedge(f))
      return "halfedge of face " + std::to_string(std::size_t(f));
  for(Surface::Vertex_index v : a.vertices())
  {
    if(a.point(v) != b.point(v))
      return "point of vertex " + std::to_string(std::size_t(v));
    const Surface::Halfedge_index ha = a.halfedge(v), hb = b.halfedge(v);
    if(ha == Surface::null_halfedge() || hb == Surface::null_halfedge())
    {
      if(ha != hb)
        return "halfedge of isolated vertex " + std::to_string(std::size_t(v));
      continue;
    }
    if(a.target(ha) != v || b.target(hb) != v || a.is_border(ha) != b.is_border(hb) ||
       (a.is_border(ha) && ha != hb))
      return "halfedge of vertex " + std::to_string(std::size_t(v));
  }
  return "";
}

// A fan of n triangles around `apex` (a new vertex at `height` if none),
// closed unless `open`, which leaves out its last triangle.
void add_fan(Soup& soup, std::size_t n, double height, std::size_t apex = std::size_t(-1), bool open = false)
{
  if(apex == std::size_t(-1))
  {
    apex = soup.points.size();
    soup.points.emplace_back(0., 0., height);
  }
  const std::size_t ring = soup.points.size();
  for(std::size_t i = 0; i < n; ++i)
    soup.points.emplace_back(std::cos(6.283185307179586 * double(i) / double(n)),
                             std::sin(6.283185307179586 * double(i) / double(n)), height - 1.);
  for(std::size_t i = 0; i + (open ? 1 : 0) < n; ++i)
    soup.faces.push_back({ apex, ring + i, ring + (i + 1) % n });
}

} // namespace

// The reader's mesh builder (linear at any valence) builds what CGAL's
// polygon_soup_to_polygon_mesh() builds, halfedge for halfedge.
TEST(Readers, CheckedSoupBuildsTheMeshCgalBuilds)
{
  std::vector<std::pair<std::string, Soup> > soups;
  for(const char* name : { "elephant.off", "elephant-with-holes.off", "blobby_3cc.off", "knot1.off" })
  {
    std::ifstream in(std::string(DISK_SEGMENTATION_TEST_DATA_DIR) + "/" + name, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    soups.emplace_back(name, read(bytes, "off"));
  }
  Soup fans;
  add_fan(fans, 3000, 0.3);   // open, one vertex of valence 3000
  add_fan(fans, 7, 1.);
  fans.points.emplace_back(5., 5., 5.);  // an isolated vertex
  soups.emplace_back("fans", fans);

  for(auto& named : soups)
  {
    SCOPED_TRACE(named.first);
    Soup& soup = named.second;
    ASSERT_EQ(CGAL::Disk_segmentation::IO::internal::triangle_soup_problem(soup.points, soup.faces), "");
    Surface ours, cgal;
    CGAL::Disk_segmentation::IO::internal::checked_triangle_soup_to_mesh(soup.points, soup.faces, ours);
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.faces, cgal);
    EXPECT_EQ(structure_difference(ours, cgal), "");
    // CGAL's check counts an isolated vertex as invalid.
    if(named.first != "fans")
      EXPECT_TRUE(CGAL::is_valid_polygon_mesh(ours, true));
    EXPECT_EQ(CGAL::is_valid_polygon_mesh(ours), CGAL::is_valid_polygon_mesh(cgal));
  }
}

// A pinched vertex, which CGAL's builder refuses, is kept: the package cuts
// it itself, and knows then that its fans are one vertex of the file (a copy
// made on reading hid that, and a patch could hold two of its fans).
TEST(Readers, CheckedSoupKeepsPinchedVertices)
{
  std::vector<std::pair<std::string, Soup> > soups;
  Soup cones;  // touching at their tips: two closed fans
  add_fan(cones, 5, 1.);
  add_fan(cones, 6, -1., 0);
  soups.emplace_back("two cones", cones);
  Soup open;  // two open fans and a closed one: two borders through the apex
  add_fan(open, 5, 1., std::size_t(-1), true);
  add_fan(open, 6, -1., 0, true);
  add_fan(open, 4, 3., 0);
  soups.emplace_back("open fans", open);

  for(auto& named : soups)
  {
    SCOPED_TRACE(named.first);
    const Soup& soup = named.second;
    const std::size_t points = soup.points.size(), fans = named.first == "two cones" ? 2 : 3;
    std::size_t extra_fans = 0;
    ASSERT_NE(CGAL::Disk_segmentation::IO::internal::triangle_soup_problem(soup.points, soup.faces), "");
    ASSERT_EQ(CGAL::Disk_segmentation::IO::internal::triangle_soup_problem(soup.points, soup.faces, &extra_fans), "");
    EXPECT_EQ(extra_fans, fans - 1);
    EXPECT_EQ(soup.points.size(), points);
    Surface ours;
    CGAL::Disk_segmentation::IO::internal::checked_triangle_soup_to_mesh(soup.points, soup.faces, ours);
    ASSERT_EQ(ours.number_of_vertices(), points);
    // Around the apex the halfedges stay in one fan, as CGAL's own repair
    // expects: it gives each other fan a vertex and leaves a valid mesh.
    std::size_t faces_at_apex = 0, faces_around = 0, borders_around = 0;
    for(const std::vector<std::size_t>& face : soup.faces)
      faces_at_apex += face[0] == 0 ? 1 : 0;
    for(Surface::Halfedge_index h : CGAL::halfedges_around_target(ours.halfedge(Surface::Vertex_index(0)), ours))
      ++(ours.is_border(h) ? borders_around : faces_around);
    EXPECT_LT(faces_around, faces_at_apex - 3);
    EXPECT_LE(borders_around, 1u);
    EXPECT_FALSE(CGAL::is_valid_polygon_mesh(ours));
    EXPECT_EQ(CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(ours), fans - 1);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(ours));
    EXPECT_EQ(ours.number_of_vertices(), points + fans - 1);
  }
}
