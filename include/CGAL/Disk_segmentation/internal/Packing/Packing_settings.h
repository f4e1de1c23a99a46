// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The packing's named parameters, read and checked once (packing_settings()),
// and what follows from them alone: the page's aspect, how many charts the
// padding leaves room for.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PACKING_SETTINGS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PACKING_SETTINGS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Packing_method.h>
#include <CGAL/Disk_segmentation/internal/Execution/Progress.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

struct Packing_settings
{
  Packing_method method;
  double resolution;  // the texture's width, in texels
  double height;      // its height
  double padding;     // in texels
  // Fixed texel density, charts spread over pages; 0: the largest common
  // scale that fits all charts on one page.
  double texels_per_unit = 0.;
  std::size_t max_pages = 1;
  unsigned int threads;  // 0: TBB's choice
  // Told of every trial layout, so that a cancellation stops a long
  // packing between two trials (it throws Cancelled); none if null.
  Progress* progress = nullptr;
};

// Trials of the tight packer reported to the progress callback: one for
// the rectangles, at most about eight for the profile packer and six for
// the raster packer.
constexpr std::size_t reported_packing_trials = 16;

inline void report_packing_trial(const Packing_settings& s, std::size_t& trial)
{
  if(s.progress != nullptr)
    (*s.progress)("packing", (std::min)(++trial, reported_packing_trials - 1), reported_packing_trials);
}

// The `texture_resolution` named parameter, as a count.
template <typename NamedParameters>
std::size_t texture_resolution_parameter(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::texture_resolution), default_texture_resolution),
    "texture_resolution");
}

template <typename NamedParameters>
Packing_settings packing_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  Packing_settings s;
  s.method = choose_parameter(get_parameter(np, Disk_segmentation::internal_np::packing_method),
                              Packing_method::TIGHT);
  if(s.method != Packing_method::TIGHT && s.method != Packing_method::GRID)
    throw Input_error("pack_patches: packing_method is not a Packing_method value");

  // Read through double so that a negative signed argument is caught rather
  // than wrapped around.
  s.resolution = static_cast<double>(texture_resolution_parameter(np));
  if(!(s.resolution >= 1.) || !std::isfinite(s.resolution))
    throw Input_error("pack_patches: texture_resolution must be at least 1");
  s.height = s.resolution;
  if(!is_default_parameter<NamedParameters, Disk_segmentation::internal_np::texture_height_t>::value)
  {
    s.height = static_cast<double>(count_parameter(
      choose_parameter(get_parameter(np, Disk_segmentation::internal_np::texture_height), default_texture_resolution), "texture_height"));
    if(!(s.height >= 1.))
      throw Input_error("pack_patches: texture_height must be at least 1");
    if(s.height != s.resolution && s.method != Packing_method::TIGHT)
      throw Input_error("pack_patches: a non-square texture (texture_height other than texture_resolution) needs "
                        "packing_method TIGHT (the grid's cells are square)");
  }

  s.padding = static_cast<double>(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::padding_in_texels), default_padding_in_texels));
  if(!(s.padding >= 0.) || !std::isfinite(s.padding))
    throw Input_error("pack_patches: padding_in_texels must be a finite number >= 0");
  if(!(2. * s.padding < (std::min)(s.resolution, s.height)))
    throw Input_error(std::string("pack_patches: padding_in_texels leaves no room: twice the padding must be "
                                  "less than ") + (s.height < s.resolution ? "texture_height" : "texture_resolution"));
  s.texels_per_unit = static_cast<double>(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::texels_per_unit), 0.));
  if(!(s.texels_per_unit >= 0.) || !std::isfinite(s.texels_per_unit))
    throw Input_error("pack_patches: texels_per_unit must be a finite number >= 0 (0: fit one page)");
  if(s.texels_per_unit > 0. && s.method != Packing_method::TIGHT)
    throw Input_error("pack_patches: texels_per_unit needs packing_method TIGHT (the grid scales every chart to "
                      "its cell)");
  s.max_pages = count_parameter(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::max_number_of_pages), default_max_number_of_pages),
    "max_number_of_pages");
  if(s.max_pages == 0)
    throw Input_error("pack_patches: max_number_of_pages must be at least 1");
  if(s.texels_per_unit == 0.)
    s.max_pages = 1;
  s.threads = number_of_threads_parameter(np);
  return s;
}

// The page's height over its width: in units of the width, a page is
// [0, 1] x [0, aspect].
inline double page_aspect(const Packing_settings& s) { return s.height / s.resolution; }

// "1024 texels" or "2048 x 1024 texels".
inline std::string texture_size(const Packing_settings& s)
{
  std::ostringstream text;
  text << s.resolution;
  if(s.height != s.resolution)
    text << " x " << s.height;
  text << " texels";
  return text.str();
}

// "1 page", "3 pages".
inline std::string pages_text(std::size_t pages)
{
  return std::to_string(pages) + (pages == 1 ? " page" : " pages");
}

// The most charts the padding leaves room for, at any scale. TIGHT: the
// rectangles, grown by the padding on their right and top and so larger
// than pad x pad, fill [pad, 1] x [pad, aspect]: fewer than
// ((1 - pad) / pad) ((aspect - pad) / pad) of them (an area bound: what the
// packer finds may be less). GRID: a cell of a c x c grid is (1 - pad) / c
// wide and keeps pad inside around a chart of positive size:
// c < (1 - pad) / pad.
inline double packing_capacity(const Packing_settings& s)
{
  const double pad = s.padding / s.resolution;
  if(!(pad > 0.))
    return std::numeric_limits<double>::infinity();
  const double across = (1. - pad) / pad;
  if(s.method == Packing_method::GRID)
  {
    const double columns = std::ceil(across) - 1.;
    return columns > 0. ? columns * columns : 0.;
  }
  return std::ceil(across * ((page_aspect(s) - pad) / pad)) - 1.;
}

// Throws when `number_of_charts` cannot be packed at any scale, before the
// work that would have found it out.
inline void check_packing_capacity(const Packing_settings& s, std::size_t number_of_charts)
{
  const double capacity = packing_capacity(s) * static_cast<double>(s.max_pages);
  if(static_cast<double>(number_of_charts) <= capacity)
    return;
  std::ostringstream message;
  message << "pack_patches: padding_in_texels (" << s.padding << ") is too large to place " << number_of_charts
          << " charts on a texture of " << texture_size(s) << " (texture_resolution): it leaves room for "
          << static_cast<std::size_t>(capacity) << " at most";
  if(s.max_pages > 1)
    message << " on " << pages_text(s.max_pages) << " (max_number_of_pages)";
  throw Input_error(message.str());
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PACKING_PACKING_SETTINGS_H
