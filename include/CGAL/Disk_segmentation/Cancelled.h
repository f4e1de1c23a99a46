// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_CANCELLED_H
#define CGAL_DISK_SEGMENTATION_CANCELLED_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// Thrown when the `progress_callback` named parameter returns `false`: the
/// caller asked the computation to stop. As with `Input_error`, the
/// function's output maps are left as they were. `stage()` says where the
/// computation was (`"segmentation"`, `"parameterization"`, `"packing"`).
class Cancelled : public std::runtime_error
{
public:
  explicit Cancelled(const std::string& stage)
    : std::runtime_error("cancelled by the progress callback during the " + stage), stage_(stage)
  {}

  const std::string& stage() const { return stage_; }

private:
  std::string stage_;
};

} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_CANCELLED_H
