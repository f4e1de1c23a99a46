// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a front end tells its user about a packing that wastes its texture:
// one wording and one threshold for disk_uv and the Python module, which
// print or raise the text; options are named as the user typed them.

#ifndef CGAL_DISK_SEGMENTATION_IO_PACKING_WARNINGS_H
#define CGAL_DISK_SEGMENTATION_IO_PACKING_WARNINGS_H

#include <CGAL/Disk_segmentation/IO/Atlas_options.h>

#include <cstddef>
#include <cstdio>
#include <cstring>
#include <string>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {

/// \ingroup PkgDiskSegmentationIO
/// The share of its pages that the charts cover below which a packing is
/// called sparse: the padding, fixed in texels, then takes most of the
/// texture (many charts on a small one), or the pages are larger than the
/// requested density needs.
constexpr double sparse_packing_efficiency = 0.25;

namespace internal {

// The option that sets the named parameter `library`, as `front_end` names it.
inline std::string option_name(const char* library, Front_end front_end)
{
  for(const Parameter_name& name : parameter_names())
    if(std::strcmp(name.library, library) == 0)
      return front_end == Front_end::command_line ? name.flag : name.argument;
  return library;
}

// That option given `value`: "--padding 2" on the command line, "padding=2" in Python.
inline std::string option_setting(const char* library, const std::string& value, Front_end front_end)
{
  return option_name(library, front_end) + (front_end == Front_end::command_line ? " " : "=") + value;
}

// printf's %g and %.1f, as the front ends have always written numbers.
inline std::string formatted(const char* format, double value)
{
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

} // namespace internal

/// \ingroup PkgDiskSegmentationIO
/// The warning for a sparse packing (efficiency below
/// `sparse_packing_efficiency`), or an empty string when there is none.
/// With a requested density (`texels_per_unit > 0`) the pages are larger
/// than it needs; else the padding around each of the `charts` charts takes
/// the texture. `resolution` is the texture size as the user gave it,
/// `pages` the number of pages; options are named as `front_end` names them.
inline std::string sparse_packing_warning(double efficiency, std::size_t pages, std::size_t charts,
                                          const std::string& resolution, double padding, double texels_per_unit,
                                          Front_end front_end)
{
  using internal::formatted;
  using internal::option_name;
  using internal::option_setting;
  // Not `efficiency >= ...`: a NaN efficiency warns of nothing.
  if(!(efficiency < sparse_packing_efficiency))
    return std::string();
  const std::string covered = "the charts cover only " + formatted("%.1f", 100 * efficiency) + "% of ";
  const std::string size = option_name("texture_resolution", front_end);
  if(texels_per_unit > 0)
  {
    const std::string density = option_name("texels_per_unit", front_end);
    return covered + (pages == 1 ? std::string("the page") : "the " + std::to_string(pages) + " pages") +
           " on the mean at " + option_setting("texels_per_unit", formatted("%g", texels_per_unit), front_end) +
           " (a page of " + option_setting("texture_resolution", resolution, front_end) +
           " texels holds more: lower " + size + " or raise " + density + ")";
  }
  return covered + "the texture: at " + option_setting("texture_resolution", resolution, front_end) + ", " +
         option_setting("padding_in_texels", formatted("%g", padding), front_end) + " texels around each of " +
         std::to_string(charts) + " charts takes the rest (raise " + size + ", lower " +
         option_name("padding_in_texels", front_end) + " or set " + option_name("max_number_of_charts", front_end) +
         ")";
}

/// \ingroup PkgDiskSegmentationIO
/// The warning that `tiny` of the `charts` charts are smaller than one
/// texel (`Packing_report::number_of_charts_below_a_texel`), so that they
/// get no texel of their own, or an empty string when `tiny` is 0.
/// Arguments as for `sparse_packing_warning()`.
inline std::string charts_below_a_texel_warning(std::size_t tiny, std::size_t charts, const std::string& resolution,
                                                double texels_per_unit, Front_end front_end)
{
  if(tiny == 0)
    return std::string();
  return std::to_string(tiny) + " of " + std::to_string(charts) + " charts are smaller than one texel of a " +
         internal::option_setting("texture_resolution", resolution, front_end) + " texture" +
         (texels_per_unit > 0 ? " at this " + internal::option_name("texels_per_unit", front_end) : std::string()) +
         ": they get no texel of their own";
}

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_PACKING_WARNINGS_H
