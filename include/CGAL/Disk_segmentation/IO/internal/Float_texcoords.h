// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether an atlas survives being written with 32-bit float UVs (glTF's,
// xatlas's arrays): a chart far smaller than the texture can lose its
// triangles to the rounding, and such a file must not be written as valid.

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_FLOAT_TEXCOORDS_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_FLOAT_TEXCOORDS_H

#include <array>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

// Twice the signed area of the UV triangle (u[k], v[k]), k = 0, 1, 2.
template <typename Real>
double uv_triangle_orientation(const std::array<Real, 3>& u, const std::array<Real, 3>& v)
{
  return (double(u[1]) - double(u[0])) * (double(v[2]) - double(v[0])) -
         (double(v[1]) - double(v[0])) * (double(u[2]) - double(u[0]));
}

// Whether the triangle, not degenerate in double, is degenerate or flipped
// once its UVs are rounded to float.
inline bool collapses_in_float(const std::array<double, 3>& u, const std::array<double, 3>& v)
{
  const double exact = uv_triangle_orientation(u, v);
  const std::array<float, 3> fu = { { float(u[0]), float(u[1]), float(u[2]) } };
  const std::array<float, 3> fv = { { float(v[0]), float(v[1]), float(v[2]) } };
  const double rounded = uv_triangle_orientation(fu, fv);
  return exact != 0. && !(exact > 0. ? rounded > 0. : rounded < 0.);
}

// The message of an atlas that cannot be written with float UVs.
inline std::string collapsed_in_float_message(std::size_t collapsed)
{
  return std::to_string(collapsed) + (collapsed == 1 ? " triangle" : " triangles") +
         " of the atlas would be degenerate or flipped in 32-bit float UVs: its charts are too small for float "
         "precision (raise texels_per_unit)";
}

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_FLOAT_TEXCOORDS_H
