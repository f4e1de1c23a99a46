// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A square RGB picture with the few drawing operations of the atlas picture.

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_RGB_IMAGE_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_RGB_IMAGE_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

// An RGB image, row 0 at the top.
class Rgb_image
{
public:
  typedef std::array<unsigned char, 3> Color;

  explicit Rgb_image(int size) : Rgb_image(size, size) {}
  Rgb_image(int width, int height)
    : width_(width), height_(height), pixels_(std::size_t(width) * std::size_t(height) * 3, 255)
  {}

  int width() const { return width_; }
  int height() const { return height_; }
  const unsigned char* data() const { return pixels_.data(); }

  void set(int x, int y, const Color& c)
  {
    if(x < 0 || y < 0 || x >= width_ || y >= height_)
      return;
    unsigned char* p = &pixels_[(std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3];
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
    const double min_x = std::max(-1.0, std::min({ a[0], b[0], c[0] }));
    const double max_x = std::min(double(width_) + 1.0, std::max({ a[0], b[0], c[0] }));
    const double min_y = std::max(-1.0, std::min({ a[1], b[1], c[1] }));
    const double max_y = std::min(double(height_) + 1.0, std::max({ a[1], b[1], c[1] }));
    const int i0 = std::max(0, int(std::ceil(min_x - 0.5)));
    const int i1 = std::min(width_ - 1, int(std::floor(max_x - 0.5)));
    const int j0 = std::max(0, int(std::ceil(min_y - 0.5)));
    const int j1 = std::min(height_ - 1, int(std::floor(max_y - 0.5)));
    // At most the image's pixels: the ranges are clamped to it.
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
    if(!(p[0] >= 0 && p[1] >= 0 && p[0] <= width_ && p[1] <= height_))
      return;
    set(std::min(width_ - 1, int(p[0])), std::min(height_ - 1, int(p[1])), color);
  }

  // Draws a 1-pixel line from a to b (pixel coordinates) with a DDA, after
  // clipping it to the image.
  void draw_line(std::array<double, 2> a, std::array<double, 2> b, const Color& color)
  {
    if(!clip(a, b))
      return;
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double length = std::max(std::fabs(dx), std::fabs(dy));
    // Clipped to the image, so at most about its longer side + 1 steps.
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

  // Liang-Barsky clipping of segment [a, b] to [0, width] x [0, height].
  bool clip(std::array<double, 2>& a, std::array<double, 2>& b) const
  {
    if(!std::isfinite(a[0]) || !std::isfinite(a[1]) || !std::isfinite(b[0]) || !std::isfinite(b[1]))
      return false;
    double t0 = 0, t1 = 1;
    const double d[2] = { b[0] - a[0], b[1] - a[1] };
    for(int axis = 0; axis < 2; ++axis)
    {
      const double p[2] = { -d[axis], d[axis] };
      const double q[2] = { a[axis], double(axis == 0 ? width_ : height_) - a[axis] };
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

  int width_, height_;
  std::vector<unsigned char> pixels_;
};

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_RGB_IMAGE_H
