// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PROGRESS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PROGRESS_H

#include <CGAL/Disk_segmentation/parameters.h>

#include <algorithm>
#include <functional>
#include <mutex>
#include <string>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

typedef std::function<void(const std::string&, std::size_t, std::size_t)> Progress_callback;

// Forwards progress to the user's callback, if any, one call at a time:
// charts finish on several threads.
class Progress
{
public:
  explicit Progress(Progress_callback callback) : callback_(std::move(callback)) {}

  template <typename NamedParameters>
  static Progress from(const NamedParameters& np)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    return Progress(choose_parameter(get_parameter(np, Disk_segmentation::internal_np::progress_callback),
                                     Progress_callback()));
  }

  void operator()(const std::string& stage, std::size_t done, std::size_t total)
  {
    if(!callback_)
      return;
    std::lock_guard<std::mutex> lock(mutex_);
    callback_(stage, done, total);
  }

  // Counts one more unit of `stage` done and reports it, at most `total`.
  void step(const std::string& stage, std::size_t total)
  {
    if(!callback_)
      return;
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = (std::min)(done_ + 1, total);
    callback_(stage, done_, total);
  }

private:
  Progress_callback callback_;
  std::mutex mutex_;
  std::size_t done_ = 0;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PROGRESS_H
