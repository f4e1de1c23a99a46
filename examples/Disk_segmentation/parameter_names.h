// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The names users give the package's parameters: the disk_uv tool's flags
// and the Python module's arguments. The library's errors name its own
// parameters (texture_resolution, padding_in_texels); both front ends
// reword them with this one table, so that a user reads the flag or the
// argument they typed.

#ifndef DISK_SEGMENTATION_EXAMPLES_PARAMETER_NAMES_H
#define DISK_SEGMENTATION_EXAMPLES_PARAMETER_NAMES_H

#include <array>
#include <cctype>
#include <string>

namespace disk_uv {

enum class Front_end { command_line, python };

struct Parameter_name
{
  const char* library;   // the named parameter
  const char* flag;      // disk_uv's option
  const char* argument;  // disk_uv.atlas()'s keyword
};

inline const std::array<Parameter_name, 19>& parameter_names()
{
  static const std::array<Parameter_name, 19> names = { {
    { "number_of_seeds", "-n/--seeds", "n (seeds)" },
    { "number_of_subsamples", "-k/--subsamples", "k (subsamples)" },
    { "merge_threshold", "--threshold", "threshold" },
    { "parameterization_method", "--method", "method" },
    { "packing_method", "--packer", "packer" },
    { "texture_resolution", "--resolution", "resolution" },
    { "texture_height", "--resolution (its height)", "resolution (its height)" },
    { "padding_in_texels", "--padding", "padding" },
    { "texels_per_unit", "--texels-per-unit", "texels_per_unit" },
    { "max_number_of_pages", "--max-pages", "max_pages" },
    { "number_of_threads", "--threads", "threads" },
    { "max_chart_faces", "--max-chart-faces", "max_chart_faces" },
    { "max_number_of_charts", "--max-charts", "max_charts" },
    { "max_angle_distortion", "--max-angle-distortion", "max_angle_distortion" },
    { "max_area_distortion", "--max-area-distortion", "max_area_distortion" },
    { "max_stretch_p95", "--max-stretch-p95", "max_stretch_p95" },
    { "max_stretch", "--max-stretch", "max_stretch" },
    { "max_area_scale", "--max-area-scale", "max_area_scale" },
    { "min_convexity", "--min-convexity", "min_convexity" },
  } };
  return names;
}

// `message` (an Input_error's) with every parameter named as `front_end`
// names it, and without the library function that checked it ("pack_patches:
// padding_in_texels (3) ..." -> "--padding (3) ..."). Whole identifiers only:
// max_stretch is not the start of max_stretch_p95.
inline std::string in_user_terms(std::string message, Front_end front_end)
{
  auto is_identifier_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  bool reworded = false;
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
    if(function_name)
      message.erase(0, colon + 2);
  }
  return message;
}

} // namespace disk_uv

#endif // DISK_SEGMENTATION_EXAMPLES_PARAMETER_NAMES_H
