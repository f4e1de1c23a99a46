// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_PNG_H
#define CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_PNG_H

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/IO/internal/Atlas_corners.h>
#include <CGAL/Disk_segmentation/IO/internal/Rgb_image.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

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
#include <cstddef>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {

/// \ingroup PkgDiskSegmentationIO
/// The color of chart `chart` in `write_atlas_PNG()`'s picture: hues spaced
/// by the golden ratio and kept within [30, 330] degrees (never the pure red
/// of flipped faces), saturation and value alternating so that consecutive
/// ids differ; never white, never dark.
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

/// \ingroup PkgDiskSegmentationIO
/// The largest side of `write_atlas_PNG()`'s picture: larger ones would
/// need over 800 MB of pixels.
constexpr unsigned int max_atlas_png_resolution = 16384;

/// \ingroup PkgDiskSegmentationIO
///
/// `write_atlas_PNG()` drawing only the faces of `face_range` (of those, the
/// ones in `tile`), for instance those of one page (`faces_of_pages()`):
/// the pictures of `P` pages then take \f$ O(F + P R^2) \f$ time, not
/// \f$ O(P F + P R^2) \f$.
///
/// @tparam FaceRange a range of `face_descriptor`
template <typename TriangleMesh, typename FaceRange, typename FacePatchMap, typename UVMap>
void write_atlas_PNG_of_faces(std::ostream& out, const TriangleMesh& mesh, const FaceRange& face_range,
                              FacePatchMap patch, UVMap uv, unsigned int resolution, unsigned int height = 0,
                              unsigned int tile = 1001)
{
  static_assert(CGAL::Disk_segmentation::internal::Check_patch_map<FacePatchMap>::value, "");
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;
  typedef std::array<double, 2> P2;

  if(height == 0)
    height = resolution;
  for(unsigned int side : { resolution, height })
    if(side == 0 || side > max_atlas_png_resolution)
      throw Input_error("the atlas resolution must be between 1 and " + std::to_string(max_atlas_png_resolution) +
                        " pixels, not " + std::to_string(side));
  const int width = static_cast<int>(resolution), rows = static_cast<int>(height);
  internal::Rgb_image image(width, rows);
  const internal::Rgb_image::Color red = {{ 255, 0, 0 }};
  const internal::Rgb_image::Color dark = {{ 24, 24, 24 }};

  if(tile < 1001)
    throw Input_error("the UDIM tile must be 1001 or above, not " + std::to_string(tile));
  const double tile_u = double((tile - 1001) % 10), tile_v = double((tile - 1001) / 10);
  auto pixel = [width, rows](const P2& t) { return P2{{ t[0] * width, (1.0 - t[1]) * rows }}; };
  auto uv_at = [&](halfedge_descriptor h) {
    const auto& t = get(uv, h);
    return P2{{ CGAL::to_double(t.x()) - tile_u, CGAL::to_double(t.y()) - tile_v }};
  };
  // Whether the face is drawn: its UV centroid is in the tile.
  auto in_tile = [&](face_descriptor f) {
    if(tile == 1001)
      return true;
    P2 sum{{ 0., 0. }};
    double n = 0.;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const P2 t = uv_at(h);
      sum[0] += t[0];
      sum[1] += t[1];
      n += 1.;
    }
    return sum[0] >= 0. && sum[0] < n && sum[1] >= 0. && sum[1] < n;
  };

  std::vector<std::vector<P2> > flipped; // the fan triangles with negative UV area, in pixels
  std::vector<P2> corners;
  for(face_descriptor f : face_range)
  {
    if(!in_tile(f))
      continue;
    corners.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      corners.push_back(uv_at(h));
    const internal::Rgb_image::Color color = chart_color(static_cast<std::size_t>(get(patch, f)));
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

  for(face_descriptor f : face_range)
  {
    if(!in_tile(f))
      continue;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const halfedge_descriptor o = opposite(h, mesh);
      if(is_border(o, mesh) || get(patch, face(o, mesh)) != get(patch, f))
        image.draw_line(pixel(uv_at(prev(h, mesh))), pixel(uv_at(h)), dark);
    }
  }

  for(const std::vector<P2>& t : flipped)
  {
    image.fill_triangle(t[0], t[1], t[2], red);
    image.set_at({{ (t[0][0] + t[1][0] + t[2][0]) / 3, (t[0][1] + t[1][1] + t[2][1]) / 3 }}, red);
  }

  if(stbi_write_png_to_func(&internal::write_to_ostream, &out, width, rows, 3, image.data(), width * 3) == 0)
    throw std::runtime_error("stb failed to encode the atlas PNG");
  if(!out)
    throw std::runtime_error("error while writing the atlas PNG");
}

/// \ingroup PkgDiskSegmentationIO
///
/// Draws the atlas layout as an RGB PNG picture of `resolution` x
/// `height` pixels (`resolution` x `resolution` when `height` is 0),
/// \f$ v \f$ up (row 0 is \f$ v = 1 \f$): white
/// background, the faces of each chart filled with `chart_color()` of its
/// id, chart borders (edges between two charts and mesh borders) as dark
/// 1-pixel lines, and faces whose UV orientation is negative in pure red,
/// drawn last (at least the pixel of their centroid) so that no fold goes
/// unseen. A pixel is filled when its center is in a triangle.
///
/// Needs stb (Debian's `libstb-dev`, pkg-config `stb`, which also provides
/// the compiled implementation): include this header only where it is
/// available.
///
/// @tparam TriangleMesh, FacePatchMap, UVMap as in `write_atlas_OBJ()`
///
/// @throws Input_error if `resolution` or `height` is above `max_atlas_png_resolution`, `resolution` is 0,
///         or `tile` is below 1001
/// @throws std::runtime_error if stb or the stream fails
///
/// With `tile` (a UDIM tile number, `1001 + i + 10 j` for the square
/// \f$ [i, i+1] \times [j, j+1] \f$, `0 <= i < 10`), only the faces whose
/// UV centroid lies in that square are drawn, moved to \f$ [0,1]^2 \f$: one
/// picture per page of an atlas whose pages are laid out as UDIM tiles.
///
/// Complexity: \f$ O(F + R^2) \f$ time and \f$ O(R^2) \f$ memory for `F`
/// faces and resolution `R`.
template <typename TriangleMesh, typename FacePatchMap, typename UVMap>
void write_atlas_PNG(std::ostream& out, const TriangleMesh& mesh, FacePatchMap patch, UVMap uv,
                     unsigned int resolution, unsigned int height = 0, unsigned int tile = 1001)
{
  write_atlas_PNG_of_faces(out, mesh, faces(mesh), patch, uv, resolution, height, tile);
}

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_WRITE_ATLAS_PNG_H
