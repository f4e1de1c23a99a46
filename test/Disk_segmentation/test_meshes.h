// Test support: deterministic triangle-mesh generators (as polygon soups) and
// conversion of a soup into any CGAL MutableFaceGraph.
//
// This file is deliberately independent of the Disk_segmentation library: it
// must not include any <CGAL/Disk_segmentation/...> header.
//
// Conventions shared by every generator:
//  * every triangle is listed counter-clockwise as seen from the side its
//    normal points to; closed surfaces have outward normals, planar meshes
//    lie in the plane z = 0 with normals along +z;
//  * every point is used by at least one triangle (no isolated vertices);
//  * no triangle is degenerate (three distinct, non-collinear points);
//  * the soup describes a manifold, consistently oriented mesh, i.e.
//    CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh() holds;
//  * output is a pure function of the arguments (no randomness).

#ifndef DISK_SEGMENTATION_TEST_SUPPORT_TEST_MESHES_H
#define DISK_SEGMENTATION_TEST_SUPPORT_TEST_MESHES_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_support {

struct Soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
};

namespace soup_detail {

inline double pi() { return 3.14159265358979323846; }

inline void require(bool condition, const char* message)
{
  if(!condition)
    throw std::invalid_argument(message);
}

inline std::size_t add_point(Soup& s, double x, double y, double z)
{
  s.points.push_back(std::array<double, 3>{{x, y, z}});
  return s.points.size() - 1;
}

inline void add_triangle(Soup& s, std::size_t a, std::size_t b, std::size_t c)
{
  s.triangles.push_back(std::array<std::size_t, 3>{{a, b, c}});
}

// Quad a,b,c,d given counter-clockwise as seen from the side of its normal;
// split along the diagonal a-c.
inline void add_quad(Soup& s, std::size_t a, std::size_t b, std::size_t c, std::size_t d)
{
  add_triangle(s, a, b, c);
  add_triangle(s, a, c, d);
}

// Appends `part` to `s`, translated by (dx, dy, dz).
inline void append(Soup& s, const Soup& part, double dx, double dy, double dz)
{
  const std::size_t offset = s.points.size();
  for(const std::array<double, 3>& p : part.points)
    add_point(s, p[0] + dx, p[1] + dy, p[2] + dz);
  for(const std::array<std::size_t, 3>& t : part.triangles)
    add_triangle(s, t[0] + offset, t[1] + offset, t[2] + offset);
}

} // namespace soup_detail

// Unit sphere centred at the origin. `n_lat` >= 2 latitude bands, `n_lon` >= 3
// meridians. The poles are single vertices (fans of n_lon triangles); the
// bands in between are split quads.
// #vertices = 2 + (n_lat-1)*n_lon, #triangles = 2*n_lon*(n_lat-1).
// Point 0 is the north pole (0,0,1), the last point is the south pole.
// When n_lat is even, a ring of vertices lies exactly on the equator z = 0.
inline Soup uv_sphere(int n_lat, int n_lon)
{
  using namespace soup_detail;
  require(n_lat >= 2, "uv_sphere: n_lat must be >= 2");
  require(n_lon >= 3, "uv_sphere: n_lon must be >= 3");
  Soup s;
  const std::size_t north = add_point(s, 0., 0., 1.);
  // ring k (1 <= k <= n_lat-1) vertex j has index 1 + (k-1)*n_lon + j
  for(int k = 1; k < n_lat; ++k)
  {
    const double theta = pi() * k / n_lat;
    for(int j = 0; j < n_lon; ++j)
    {
      const double phi = 2. * pi() * j / n_lon;
      add_point(s, std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  }
  const std::size_t south = add_point(s, 0., 0., -1.);

  auto ring = [n_lon](int k, int j) -> std::size_t {
    return std::size_t(1 + (k - 1) * n_lon + (j % n_lon));
  };
  // Going "south" (increasing theta) then "east" (increasing phi) is
  // counter-clockwise seen from outside, since e_theta x e_phi = e_r.
  for(int j = 0; j < n_lon; ++j)
    add_triangle(s, north, ring(1, j), ring(1, j + 1));
  for(int k = 1; k + 1 < n_lat; ++k)
    for(int j = 0; j < n_lon; ++j)
      add_quad(s, ring(k, j), ring(k + 1, j), ring(k + 1, j + 1), ring(k, j + 1));
  for(int j = 0; j < n_lon; ++j)
    add_triangle(s, ring(n_lat - 1, j), south, ring(n_lat - 1, j + 1));
  return s;
}

// Torus around the z axis: major radius R, minor radius r (0 < r < R).
// n_major >= 3 samples around the z axis, n_minor >= 3 around the tube.
// #vertices = n_major*n_minor, #triangles = 2*n_major*n_minor.
inline Soup torus(int n_major, int n_minor, double R = 1.0, double r = 0.35)
{
  using namespace soup_detail;
  require(n_major >= 3, "torus: n_major must be >= 3");
  require(n_minor >= 3, "torus: n_minor must be >= 3");
  require(r > 0. && r < R, "torus: need 0 < r < R");
  Soup s;
  for(int i = 0; i < n_major; ++i)
  {
    const double u = 2. * pi() * i / n_major;
    for(int j = 0; j < n_minor; ++j)
    {
      const double v = 2. * pi() * j / n_minor;
      const double rho = R + r * std::cos(v);
      add_point(s, rho * std::cos(u), rho * std::sin(u), r * std::sin(v));
    }
  }
  auto id = [n_major, n_minor](int i, int j) -> std::size_t {
    return std::size_t((i % n_major) * n_minor + (j % n_minor));
  };
  // d/du x d/dv points outward.
  for(int i = 0; i < n_major; ++i)
    for(int j = 0; j < n_minor; ++j)
      add_quad(s, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return s;
}

// Closed orientable surface of genus `genus` (>= 0): the boundary of a thick
// plate of (2*genus+1) x 3 unit blocks, one block thick, from which the blocks
// (2k+1, 1), k = 0..genus-1, are removed (square through-holes). Every unit
// block face is subdivided into resolution x resolution squares, each split in
// two triangles. Coordinates: x in [0, 2g+1], y in [0, 3], z in [0, 1].
// #triangles = resolution^2 * (36*genus + 28)   (e.g. genus 3, resolution 3: 1224)
// Euler characteristic 2 - 2*genus; connected.
inline Soup genus_surface(int genus, int resolution)
{
  using namespace soup_detail;
  require(genus >= 0, "genus_surface: genus must be >= 0");
  require(resolution >= 1, "genus_surface: resolution must be >= 1");
  const int res = resolution;
  const int W = (2 * genus + 1) * res; // fine cells along x
  const int H = 3 * res;               // fine cells along y
  const int T = res;                   // fine layers along z

  auto filled = [&](int x, int y) -> bool {
    if(x < 0 || y < 0 || x >= W || y >= H)
      return false;
    const int bx = x / res, by = y / res;
    if(by == 1 && (bx % 2) == 1) // hole blocks (1,1), (3,1), ..., (2g-1,1)
      return false;
    return true;
  };

  Soup s;
  std::map<std::array<int, 3>, std::size_t> lattice;
  auto vid = [&](int x, int y, int z) -> std::size_t {
    const std::array<int, 3> key{{x, y, z}};
    auto it = lattice.find(key);
    if(it != lattice.end())
      return it->second;
    const std::size_t i = add_point(s, double(x) / res, double(y) / res, double(z) / res);
    lattice.emplace(key, i);
    return i;
  };

  for(int y = 0; y < H; ++y)
    for(int x = 0; x < W; ++x)
    {
      if(!filled(x, y))
        continue;
      // top (normal +z) and bottom (normal -z)
      add_quad(s, vid(x, y, T), vid(x + 1, y, T), vid(x + 1, y + 1, T), vid(x, y + 1, T));
      add_quad(s, vid(x, y, 0), vid(x, y + 1, 0), vid(x + 1, y + 1, 0), vid(x + 1, y, 0));
      // side walls, where the neighbouring column is empty
      for(int k = 0; k < T; ++k)
      {
        if(!filled(x + 1, y)) // normal +x, wall at X = x+1
          add_quad(s, vid(x + 1, y, k), vid(x + 1, y + 1, k), vid(x + 1, y + 1, k + 1), vid(x + 1, y, k + 1));
        if(!filled(x - 1, y)) // normal -x, wall at X = x
          add_quad(s, vid(x, y, k), vid(x, y, k + 1), vid(x, y + 1, k + 1), vid(x, y + 1, k));
        if(!filled(x, y + 1)) // normal +y, wall at Y = y+1
          add_quad(s, vid(x, y + 1, k), vid(x, y + 1, k + 1), vid(x + 1, y + 1, k + 1), vid(x + 1, y + 1, k));
        if(!filled(x, y - 1)) // normal -y, wall at Y = y
          add_quad(s, vid(x, y, k), vid(x + 1, y, k), vid(x + 1, y, k + 1), vid(x, y, k + 1));
      }
    }
  return s;
}

// Open tube of radius 1 around the z axis, z in [0, 1]: n_around >= 3
// vertices per ring, n_height >= 1 bands (n_height+1 rings). Normals point
// away from the axis. Two boundary loops (z = 0 and z = 1), Euler char. 0.
// #vertices = n_around*(n_height+1), #triangles = 2*n_around*n_height.
inline Soup cylinder(int n_around, int n_height)
{
  using namespace soup_detail;
  require(n_around >= 3, "cylinder: n_around must be >= 3");
  require(n_height >= 1, "cylinder: n_height must be >= 1");
  Soup s;
  for(int h = 0; h <= n_height; ++h)
    for(int i = 0; i < n_around; ++i)
    {
      const double phi = 2. * pi() * i / n_around;
      add_point(s, std::cos(phi), std::sin(phi), double(h) / n_height);
    }
  auto id = [n_around](int i, int h) -> std::size_t {
    return std::size_t(h * n_around + (i % n_around));
  };
  // e_phi x e_z = e_rho (outward)
  for(int h = 0; h < n_height; ++h)
    for(int i = 0; i < n_around; ++i)
      add_quad(s, id(i, h), id(i + 1, h), id(i + 1, h + 1), id(i, h + 1));
  return s;
}

// Planar unit disk in z = 0 (normal +z): a centre vertex (index 0) and
// n_rings >= 1 concentric rings of n_around >= 3 vertices each.
// #vertices = 1 + n_rings*n_around, #triangles = n_around*(2*n_rings - 1).
inline Soup disk(int n_rings, int n_around)
{
  using namespace soup_detail;
  require(n_rings >= 1, "disk: n_rings must be >= 1");
  require(n_around >= 3, "disk: n_around must be >= 3");
  Soup s;
  const std::size_t centre = add_point(s, 0., 0., 0.);
  for(int k = 1; k <= n_rings; ++k)
  {
    const double radius = double(k) / n_rings;
    for(int j = 0; j < n_around; ++j)
    {
      const double phi = 2. * pi() * j / n_around;
      add_point(s, radius * std::cos(phi), radius * std::sin(phi), 0.);
    }
  }
  auto ring = [n_around](int k, int j) -> std::size_t {
    return std::size_t(1 + (k - 1) * n_around + (j % n_around));
  };
  for(int j = 0; j < n_around; ++j)
    add_triangle(s, centre, ring(1, j), ring(1, j + 1));
  // e_rho x e_phi = e_z
  for(int k = 1; k < n_rings; ++k)
    for(int j = 0; j < n_around; ++j)
      add_quad(s, ring(k, j), ring(k + 1, j), ring(k + 1, j + 1), ring(k, j + 1));
  return s;
}

// Planar grid of nx x ny unit squares in z = 0 (normal +z), point (i, j) at
// index j*(nx+1) + i, each square split along its (i,j)-(i+1,j+1) diagonal.
// `holes` squares are removed; a hole square never shares a vertex with
// another hole or with the outer border, so the result is a manifold planar
// mesh with 1 + holes boundary loops and Euler characteristic 1 - holes.
// Candidate hole squares are (2a+1, 2b+1), a < (nx-1)/2, b < (ny-1)/2; the
// holes are spread evenly over them. Throws std::invalid_argument if there is
// not enough room. Square (i, j) becomes triangles 2q and 2q+1 where q is the
// rank of (i, j) among the kept squares in row-major (j, then i) order.
inline Soup grid_with_holes(int nx, int ny, int holes)
{
  using namespace soup_detail;
  require(nx >= 1 && ny >= 1, "grid_with_holes: nx and ny must be >= 1");
  require(holes >= 0, "grid_with_holes: holes must be >= 0");
  const int slots_x = (nx - 1) / 2;
  const int slots_y = (ny - 1) / 2;
  const long n_slots = long(slots_x) * long(slots_y);
  require(holes <= n_slots, "grid_with_holes: too many holes for this grid size");

  std::vector<char> removed(std::size_t(nx) * std::size_t(ny), 0);
  for(int h = 0; h < holes; ++h)
  {
    const long slot = (long(h) * n_slots) / holes; // strictly increasing in h
    const int a = int(slot % slots_x), b = int(slot / slots_x);
    removed[std::size_t(2 * b + 1) * std::size_t(nx) + std::size_t(2 * a + 1)] = 1;
  }

  Soup s;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
      add_point(s, double(i), double(j), 0.);
  auto id = [nx](int i, int j) -> std::size_t { return std::size_t(j) * std::size_t(nx + 1) + std::size_t(i); };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
      if(!removed[std::size_t(j) * std::size_t(nx) + std::size_t(i)])
        add_quad(s, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return s;
}

// `copies` (>= 1) disjoint closed components along the x axis, spaced by 4:
// even copies are uv_sphere(4, 8) (26 points, 48 triangles),
// odd copies are torus(8, 6) (48 points, 96 triangles).
// Component k uses a contiguous block of points and of triangles.
inline Soup disconnected(int copies)
{
  using namespace soup_detail;
  require(copies >= 1, "disconnected: copies must be >= 1");
  const Soup sphere = uv_sphere(4, 8);
  const Soup ring = torus(8, 6);
  Soup s;
  for(int k = 0; k < copies; ++k)
    append(s, (k % 2 == 0) ? sphere : ring, 4. * k, 0., 0.);
  return s;
}

// One triangle (0,0,0), (1,0,0), (0,1,0), normal +z.
inline Soup single_triangle()
{
  using namespace soup_detail;
  Soup s;
  add_point(s, 0., 0., 0.);
  add_point(s, 1., 0., 0.);
  add_point(s, 0., 1., 0.);
  add_triangle(s, 0, 1, 2);
  return s;
}

// Long planar strip in z = 0 (normal +z): n >= 1 cells of length 1 and width
// `width` in a row along x (overall size n x width), each cell split in two
// triangles, 2n triangles in all. Point (i, 0) has index 2i, point
// (i, width) has index 2i+1. Every vertex is on the boundary.
inline Soup thin_strip(int n, double width = 0.1)
{
  using namespace soup_detail;
  require(n >= 1, "thin_strip: n must be >= 1");
  require(width > 0., "thin_strip: width must be > 0");
  Soup s;
  for(int i = 0; i <= n; ++i)
  {
    add_point(s, double(i), 0., 0.);
    add_point(s, double(i), width, 0.);
  }
  for(int i = 0; i < n; ++i)
  {
    const std::size_t b0 = 2 * std::size_t(i), t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
    add_quad(s, b0, b1, t1, t0);
  }
  return s;
}

// Builds `out` (cleared first) from the soup with
// CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh().
// Afterwards, in the iteration order of vertices(out) / faces(out), vertex i
// has point s.points[i] and face i is s.triangles[i] (same cyclic vertex
// order). This is verified; std::runtime_error is thrown if the soup is not a
// valid polygon mesh or if the order was not preserved.
// Works with CGAL::Surface_mesh<Point_3> and CGAL::Polyhedron_3<K>.
template <class Mesh>
void to_mesh(const Soup& s, Mesh& out)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;

  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(s.triangles))
    throw std::runtime_error("to_mesh: the soup is not a valid oriented manifold polygon mesh");
  for(const std::array<std::size_t, 3>& t : s.triangles)
    for(std::size_t i : t)
      if(i >= s.points.size())
        throw std::runtime_error("to_mesh: triangle refers to a missing point");

  CGAL::clear(out);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.triangles, out);

  // Verify the order.
  std::map<vertex_descriptor, std::size_t> index;
  for(vertex_descriptor v : vertices(out))
    index.emplace(v, index.size());
  if(index.size() != s.points.size())
    throw std::runtime_error("to_mesh: vertex count differs from the soup");
  {
    std::size_t i = 0;
    for(vertex_descriptor v : vertices(out))
    {
      const auto& p = get(CGAL::vertex_point, out, v);
      const std::array<double, 3>& q = s.points[i++];
      if(double(p.x()) != q[0] || double(p.y()) != q[1] || double(p.z()) != q[2])
        throw std::runtime_error("to_mesh: vertex order not preserved");
    }
  }
  std::size_t fi = 0;
  for(face_descriptor f : faces(out))
  {
    if(fi >= s.triangles.size())
      throw std::runtime_error("to_mesh: more faces than triangles");
    std::vector<std::size_t> cycle;
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, out), out))
      cycle.push_back(index.at(v));
    const std::array<std::size_t, 3>& t = s.triangles[fi++];
    bool same = false;
    if(cycle.size() == 3)
      for(int r = 0; r < 3 && !same; ++r)
        same = (cycle[std::size_t(r)] == t[0] && cycle[std::size_t((r + 1) % 3)] == t[1] &&
                cycle[std::size_t((r + 2) % 3)] == t[2]);
    if(!same)
      throw std::runtime_error("to_mesh: face order or orientation not preserved");
  }
  if(fi != s.triangles.size())
    throw std::runtime_error("to_mesh: fewer faces than triangles");
}

} // namespace test_support

#endif // DISK_SEGMENTATION_TEST_SUPPORT_TEST_MESHES_H
