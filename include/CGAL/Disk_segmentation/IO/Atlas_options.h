// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The options of the front ends (the disk_uv tool, the Python module) and
// their one mapping to the library's named parameters: both fill an
// `Atlas_options` from what the user typed and get the same checked
// parameter chain; errors come back in the names the user typed.

#ifndef CGAL_DISK_SEGMENTATION_IO_ATLAS_OPTIONS_H
#define CGAL_DISK_SEGMENTATION_IO_ATLAS_OPTIONS_H

#include <CGAL/Disk_segmentation/Distortion_bound.h>
#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/default_values.h>
#include <CGAL/Disk_segmentation/IO/udim_tiles.h>
#include <CGAL/Disk_segmentation/uv_atlas.h>

#include <array>
#include <cctype>
#include <charconv>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {

/// \ingroup PkgDiskSegmentationIO
/// What a front end lets its user choose, with the library's defaults;
/// `atlas_parameters()` turns it into the named parameters of `uv_atlas()`.
struct Atlas_options
{
  std::size_t number_of_seeds = default_number_of_seeds;
  std::size_t number_of_subsamples = default_number_of_subsamples;
  double merge_threshold = regular_polygon_threshold(default_merge_threshold_sides);
  /// Longer dual arcs across bent edges (see `parameters::crease_penalty()`; 0: the paper's distance).
  double crease_penalty = default_crease_penalty;
  /// A name `parameterization_method_from_string()` reads.
  std::string method = to_string(default_parameterization_method);
  /// "tight" or "grid" (see `packing_method_from_string()`).
  std::string packer = "tight";
  unsigned int texture_width = default_texture_resolution;
  unsigned int texture_height = default_texture_resolution;
  double padding_in_texels = default_padding_in_texels;
  /// 0: the largest density that fits one page.
  double texels_per_unit = 0;
  std::size_t max_number_of_pages = default_max_number_of_pages;
  Distortion_bound bound;
  /// No distortion or convexity bound at all (the paper's charts).
  bool unbounded = false;
  /// Keep the saw teeth of chart borders (no smoothing, no straightening).
  bool rough_borders = false;
  std::size_t max_chart_faces = default_max_chart_faces;
  /// 0: no chart budget.
  std::size_t max_number_of_charts = 0;
  /// 0: all cores.
  unsigned int number_of_threads = 0;
  bool use_fallback = true;
};

/// \ingroup PkgDiskSegmentationIO
/// The packing method named `name`: "tight" or "grid".
/// \throws Input_error for any other name
inline Packing_method packing_method_from_string(const std::string& name)
{
  if(name == "tight")
    return Packing_method::TIGHT;
  if(name == "grid")
    return Packing_method::GRID;
  throw Input_error("unknown packer '" + name + "' (expected tight or grid)");
}

/// \ingroup PkgDiskSegmentationIO
/// Reads a texture size written "N" (a square texture) or "WxH"
/// (non-negative integers that fit an `unsigned int`); `false`, with
/// `width` and `height` untouched, if `text` is neither.
inline bool parse_texture_size(const std::string& text, unsigned int& width, unsigned int& height)
{
  const std::size_t x = text.find('x');
  const std::string sides[2] = { text.substr(0, x), x == std::string::npos ? text : text.substr(x + 1) };
  unsigned int values[2] = { 0, 0 };
  for(int k = 0; k < 2; ++k)
  {
    const std::string& side = sides[k];
    const auto result = std::from_chars(side.data(), side.data() + side.size(), values[k]);
    if(side.empty() || side.find_first_not_of("0123456789") != std::string::npos || result.ec != std::errc())
      return false;
  }
  width = values[0];
  height = values[1];
  return true;
}

/// \ingroup PkgDiskSegmentationIO
/// The named parameters of `uv_atlas()` (and `uv_atlas_of_meshes()`) that
/// `options` stand for, checked by `check_uv_atlas_parameters()`, and
/// `max_number_of_pages` at most `max_udim_pages` (the front ends write
/// pages as UDIM tiles). Maps and a progress callback are added by the
/// caller. Needs no mesh: a front end calls it before it reads any.
/// \throws Input_error naming the first bad option by its parameter's name
/// (see `in_user_terms()`)
inline auto atlas_parameters(const Atlas_options& options)
{
  if(options.max_number_of_pages > max_udim_pages)
    throw Input_error("max_number_of_pages must be at most " + std::to_string(max_udim_pages) +
                      ": pages are written as the UDIM tiles 1001 to 1999, where common readers stop");
  Parameterization_method method;
  try
  {
    method = parameterization_method_from_string(options.method);
  }
  catch(const Input_error& e)
  {
    throw Input_error(std::string("parameterization_method: ") + e.what());
  }
  Packing_method packer;
  try
  {
    packer = packing_method_from_string(options.packer);
  }
  catch(const Input_error& e)
  {
    throw Input_error(std::string("packing_method: ") + e.what());
  }
  const double inf = std::numeric_limits<double>::infinity();
  const bool unbounded = options.unbounded;
  const Distortion_bound& bound = options.bound;
  const std::size_t max_charts =
    options.max_number_of_charts == 0 ? Disk_segmentation::internal::no_chart_budget : options.max_number_of_charts;
  const auto settings =
    parameters::number_of_seeds(options.number_of_seeds).number_of_subsamples(options.number_of_subsamples)
      .merge_threshold(options.merge_threshold).crease_penalty(options.crease_penalty)
      .parameterization_method(method).use_fallback(options.use_fallback)
      .max_angle_distortion(unbounded ? inf : bound.max_angle_distortion)
      .max_area_distortion(unbounded ? inf : bound.max_area_distortion)
      .max_stretch(unbounded ? inf : bound.max_stretch).max_area_scale(unbounded ? inf : bound.max_area_scale)
      .max_stretch_p95(unbounded ? inf : bound.max_stretch_p95)
      .min_convexity(unbounded ? 0. : bound.min_convexity)
      .smooth_borders(!options.rough_borders)
      .straighten_borders(!options.rough_borders)
      .max_chart_faces(options.max_chart_faces).max_number_of_charts(max_charts)
      .packing_method(packer)
      .texture_resolution(options.texture_width).texture_height(options.texture_height)
      .padding_in_texels(options.padding_in_texels).texels_per_unit(options.texels_per_unit)
      .max_number_of_pages(options.max_number_of_pages).number_of_threads(options.number_of_threads);
  check_uv_atlas_parameters(settings);
  return settings;
}

/// \ingroup PkgDiskSegmentationIO
/// Who the user typed the options to.
enum class Front_end { command_line, python };

/// \ingroup PkgDiskSegmentationIO
/// One named parameter as the library, the disk_uv tool and the Python
/// module name it.
struct Parameter_name
{
  const char* library;   // the named parameter
  const char* flag;      // disk_uv's option
  const char* argument;  // disk_uv.atlas()'s keyword
};

/// \ingroup PkgDiskSegmentationIO
/// Every parameter a front end sets, with its three names (those of
/// `parameters_interface.h` that have a front-end option).
inline const std::vector<Parameter_name>& parameter_names()
{
  static const std::vector<Parameter_name> names = [] {
    const Parameter_name all[] = {
#define CGAL_DISK_SEGMENTATION_PARAMETER(name, flag, argument) { #name, flag, argument },
#include <CGAL/Disk_segmentation/parameters_interface.h>
#undef CGAL_DISK_SEGMENTATION_PARAMETER
    };
    std::vector<Parameter_name> set;
    for(const Parameter_name& name : all)
      if(*name.flag != '\0')
        set.push_back(name);
    return set;
  }();
  return names;
}

/// \ingroup PkgDiskSegmentationIO
/// `message` (an `Input_error`'s) with every parameter named as `front_end`
/// names it, and without the library function that checked it ("pack_patches:
/// padding_in_texels (3) ..." -> "--padding (3) ..."). Whole identifiers only:
/// max_stretch is not the start of max_stretch_p95.
inline std::string in_user_terms(std::string message, Front_end front_end)
{
  auto is_identifier_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  bool reworded = false;
  // A value named as the front end spells it ("packing_method TIGHT" -> "--packer tight").
  static const std::array<Parameter_name, 2> values = { {
    { "packing_method TIGHT", "--packer tight", "packer='tight'" },
    { "packing_method GRID", "--packer grid", "packer='grid'" },
  } };
  for(const Parameter_name& value : values)
    for(std::size_t at = message.find(value.library); at != std::string::npos; at = message.find(value.library, at))
    {
      const std::string user = front_end == Front_end::command_line ? value.flag : value.argument;
      message.replace(at, std::string(value.library).size(), user);
      at += user.size();
      reworded = true;
    }
  for(const Parameter_name& name : parameter_names())
  {
    const std::string library = name.library;
    const std::string user = front_end == Front_end::command_line ? name.flag : name.argument;
    for(std::size_t at = message.find(library); at != std::string::npos; at = message.find(library, at))
    {
      const std::size_t end = at + library.size();
      if((at > 0 && is_identifier_char(message[at - 1])) || (end < message.size() && is_identifier_char(message[end])))
      {
        at = end;
        continue;
      }
      message.replace(at, library.size(), user);
      at += user.size();
      reworded = true;
    }
  }
  // The checking function's name, "pack_patches: ", means nothing to them.
  const std::size_t colon = message.find(": ");
  if(reworded && colon != std::string::npos && colon > 0)
  {
    bool function_name = true;
    for(std::size_t i = 0; i < colon; ++i)
      function_name = function_name && (std::islower(static_cast<unsigned char>(message[i])) || message[i] == '_');
    // "method: ..." names the user's argument, not a function.
    for(const Parameter_name& name : parameter_names())
      function_name = function_name && message.compare(0, colon, front_end == Front_end::command_line
                                                                    ? name.flag : name.argument) != 0;
    if(function_name)
      message.erase(0, colon + 2);
  }
  return message;
}

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_ATLAS_OPTIONS_H
