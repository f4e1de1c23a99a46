// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INPUT_ERROR_H
#define CGAL_DISK_SEGMENTATION_INPUT_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// Thrown by every function of the package when its input mesh or one of its
/// parameters cannot be processed (empty mesh, non-triangle face,
/// non-finite coordinate, out-of-range parameter, ...).
/// `what()` names the problem and, where there is one, the first offending
/// element.
///
/// These checks run in release builds too: a bad input must never crash or
/// loop, whatever `NDEBUG` says.
class Input_error : public std::invalid_argument
{
public:
  explicit Input_error(const std::string& message)
    : std::invalid_argument(message)
  {}
};

} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INPUT_ERROR_H
