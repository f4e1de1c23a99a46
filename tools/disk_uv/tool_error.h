// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The errors the disk_uv tool throws for a problem of its options or of an
// output file: the message is printed as the tool's one line. (Input files
// are read by the library, which throws IO::File_error.)

#ifndef DISK_UV_TOOL_ERROR_H
#define DISK_UV_TOOL_ERROR_H

#include <stdexcept>

namespace disk_uv {

// Exit status 1: the run failed.
struct Tool_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Exit status 2, as for any bad command line: a value or a combination of
// options that no input could make work.
struct Usage_error : Tool_error
{
  using Tool_error::Tool_error;
};

} // namespace disk_uv

#endif // DISK_UV_TOOL_ERROR_H
