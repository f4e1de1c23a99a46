// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Jacobian of one triangle's map from 3D to UV and its singular
// values: what every distortion measure is made of.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_TRIANGLE_DISTORTION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_TRIANGLE_DISTORTION_H

#include <array>
#include <cmath>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The linear map of one triangle from 3D to UV (Atlas_quality's definition):
// the 3D triangle is laid in an orthonormal frame of its plane
// (x0 = (0,0), x1 = (|p1 - p0|, 0), x2 by projection) and J solves
// J [x1 - x0, x2 - x0] = [u1 - u0, u2 - u0].
struct Triangle_jacobian
{
  double area_3d = 0;              // area of the 3D triangle
  double determinant = 0;          // det J: UV area / 3D area, negative if flipped
  double sigma_max = 0, sigma_min = 0;  // singular values of J

  bool valid() const { return area_3d > 0 && std::isfinite(determinant); }
};

inline Triangle_jacobian triangle_jacobian(const std::array<double, 3>& p0, const std::array<double, 3>& p1,
                                           const std::array<double, 3>& p2, const std::array<double, 2>& u0,
                                           const std::array<double, 2>& u1, const std::array<double, 2>& u2)
{
  Triangle_jacobian t;
  const double e1[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
  const double e2[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
  const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  if(!(l1 > 0))
    return t;
  const double x2 = (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1;
  const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2], cz = e1[0] * e2[1] - e1[1] * e2[0];
  const double y2 = std::sqrt(cx * cx + cy * cy + cz * cz) / l1;  // >= 0: the frame keeps the 3D winding
  t.area_3d = 0.5 * l1 * y2;
  if(!(y2 > 0))
    return t;

  // J = [a b; c d] = [du1 du2] * inverse([l1 x2; 0 y2]).
  const double du1x = u1[0] - u0[0], du1y = u1[1] - u0[1];
  const double du2x = u2[0] - u0[0], du2y = u2[1] - u0[1];
  const double a = du1x / l1, c = du1y / l1;
  const double b = (du2x - a * x2) / y2, d = (du2y - c * x2) / y2;
  t.determinant = a * d - b * c;

  // Singular values of a 2x2 matrix in closed form.
  const double e = (a + d) / 2, f = (a - d) / 2, g = (c + b) / 2, h = (c - b) / 2;
  const double q = std::sqrt(e * e + h * h), r = std::sqrt(f * f + g * g);
  t.sigma_max = q + r;
  t.sigma_min = std::abs(q - r);
  return t;
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_TRIANGLE_DISTORTION_H
