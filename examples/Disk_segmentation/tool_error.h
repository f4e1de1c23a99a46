// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The error every part of the disk_uv tool throws for a problem of the
// user's files or options: its message is printed as the tool's one line.

#ifndef DISK_SEGMENTATION_EXAMPLES_TOOL_ERROR_H
#define DISK_SEGMENTATION_EXAMPLES_TOOL_ERROR_H

#include <stdexcept>

namespace disk_uv {

struct Tool_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

} // namespace disk_uv

#endif // DISK_SEGMENTATION_EXAMPLES_TOOL_ERROR_H
