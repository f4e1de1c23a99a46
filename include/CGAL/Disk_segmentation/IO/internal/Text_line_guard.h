// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Watches the text of a mesh file while it is read, so that a file with a
// line longer than max_line_bytes (a gigabyte without a line break: a
// binary file under a text extension, a device) is refused as soon as that
// line passes the limit, not once the whole file is in memory. The readers
// refuse the same lines with the same message; this only refuses earlier.

#ifndef CGAL_DISK_SEGMENTATION_IO_INTERNAL_TEXT_LINE_GUARD_H
#define CGAL_DISK_SEGMENTATION_IO_INTERNAL_TEXT_LINE_GUARD_H

#include <CGAL/Disk_segmentation/IO/File_error.h>
#include <CGAL/Disk_segmentation/IO/internal/Mesh_readers.h>
#include <CGAL/Disk_segmentation/IO/internal/Text_scanner.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {
namespace internal {

class Text_line_guard
{
public:
  // The file `name` of format `ext` (lower case); `file_size` is its size
  // when known (a regular file), 0 otherwise.
  Text_line_guard(const std::string& name, const std::string& ext, std::uint64_t file_size)
    : name_(name), ext_(ext), file_size_(file_size)
  {
    if(ext == "ply")
      mode_ = Mode::ply_header;
    else if(ext == "stl")
      mode_ = file_size > 0 ? Mode::undecided : Mode::off;  // binary or not is told by the size
    else
      mode_ = Mode::text;
  }

  // Checks what was appended to `bytes` since the last call; throws
  // File_error at a line longer than max_line_bytes in the text part.
  void check(const std::string& bytes)
  {
    if(mode_ == Mode::undecided)
      decide_STL(bytes);
    while(mode_ == Mode::text || mode_ == Mode::ply_header)
    {
      const void* found = std::memchr(bytes.data() + checked_, '\n', bytes.size() - checked_);
      if(found == nullptr)
        break;
      const std::size_t end = std::size_t(static_cast<const char*>(found) - bytes.data());
      check_length(end - line_start_);
      if(mode_ == Mode::ply_header)
        read_PLY_header_line(std::string_view(bytes.data() + line_start_, end - line_start_));
      ++line_number_;
      line_start_ = checked_ = end + 1;
    }
    checked_ = bytes.size();
    if(mode_ == Mode::text || mode_ == Mode::ply_header)
      check_length(bytes.size() - line_start_);
  }

private:
  enum class Mode { undecided, text, ply_header, off };

  void check_length(std::size_t length) const
  {
    if(length > max_line_bytes)
      throw File_error("'" + name_ + "' is not a valid ." + ext_ + " file (line " + std::to_string(line_number_) +
                       ": longer than " + size_text(max_line_bytes) + " without a line break (not a text file?))");
  }

  // As read_STL_soup() tells them (is_ASCII_STL()), once the header is in.
  void decide_STL(const std::string& bytes)
  {
    if(bytes.size() < 84 && bytes.size() < file_size_)
      return;
    mode_ = is_ASCII_STL(bytes, file_size_) ? Mode::text : Mode::off;
  }

  // The header's lines up to end_header: the body is text when the format is ascii.
  void read_PLY_header_line(std::string_view line)
  {
    while(!line.empty() && is_blank(line.back()))
      line.remove_suffix(1);
    if(line.substr(0, 7) == "format " && line.find("ascii") != std::string_view::npos)
      ascii_ = true;
    else if(line == "end_header")
      mode_ = ascii_ ? Mode::text : Mode::off;
  }

  std::string name_, ext_;
  std::uint64_t file_size_;
  Mode mode_;
  bool ascii_ = false;
  std::size_t checked_ = 0, line_start_ = 0, line_number_ = 1;
};

} // namespace internal
} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_INTERNAL_TEXT_LINE_GUARD_H
