// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_IO_FILE_ERROR_H
#define CGAL_DISK_SEGMENTATION_IO_FILE_ERROR_H

#include <stdexcept>

namespace CGAL {
namespace Disk_segmentation {
namespace IO {

/// \ingroup PkgDiskSegmentationIO
/// Thrown by `read_triangle_mesh()` for a file that cannot be used: missing,
/// unreadable, of an unknown format, malformed, or not a manifold,
/// consistently oriented triangle mesh. `what()` is one line that names the
/// file and, where there is one, the line, token or element at fault.
class File_error : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

} // namespace IO
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_IO_FILE_ERROR_H
