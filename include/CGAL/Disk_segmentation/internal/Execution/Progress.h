// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Progress reports to the user's callback, one at a time from several
// threads, and the cancellation it may ask for.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_EXECUTION_PROGRESS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_EXECUTION_PROGRESS_H

#include <CGAL/Disk_segmentation/Cancelled.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <algorithm>
#include <functional>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Returns false to cancel.
typedef std::function<bool(const std::string&, std::size_t, std::size_t)> Progress_callback;

// The user's callback as one that may cancel: a callback whose result
// converts to bool cancels with `false`; any other result is ignored.
template <typename Callback>
Progress_callback as_cancellable(const Callback& callback)
{
  if constexpr(std::is_constructible<bool, const Callback&>::value)
    if(!static_cast<bool>(callback))  // an empty std::function
      return Progress_callback();
  typedef decltype(callback(std::declval<const std::string&>(), std::size_t(), std::size_t())) Result;
  if constexpr(std::is_constructible<bool, Result>::value)
    return [callback](const std::string& stage, std::size_t done, std::size_t total) {
      return static_cast<bool>(callback(stage, done, total));
    };
  else
    return [callback](const std::string& stage, std::size_t done, std::size_t total) {
      callback(stage, done, total);
      return true;
    };
}

// Forwards progress to the user's callback, if any, one call at a time:
// charts finish on several threads. When the callback asks to stop, this
// and every later call throw Cancelled, without calling it again.
class Progress
{
public:
  Progress() = default;
  explicit Progress(Progress_callback callback) : callback_(std::move(callback)) {}

  template <typename NamedParameters>
  static Progress from(const NamedParameters& np)
  {
    const auto& callback = CGAL::parameters::get_parameter(np, Disk_segmentation::internal_np::progress_callback);
    typedef std::decay_t<decltype(callback)> Callback;
    if constexpr(std::is_same<Callback, CGAL::internal_np::Param_not_found>::value)
      return Progress();
    else
      return Progress(as_cancellable(callback));
  }

  void operator()(const std::string& stage, std::size_t done, std::size_t total)
  {
    if(!callback_)
      return;
    std::lock_guard<std::mutex> lock(mutex_);
    report(stage, done, total);
  }

  // Counts one more unit of `stage` done and reports it, at most `total`.
  void step(const std::string& stage, std::size_t total)
  {
    if(!callback_)
      return;
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = (std::min)(done_ + 1, total);
    report(stage, done_, total);
  }

private:
  void report(const std::string& stage, std::size_t done, std::size_t total)
  {
    if(cancelled_ || !callback_(stage, done, total))
    {
      cancelled_ = true;
      throw Cancelled(stage);
    }
  }

  Progress_callback callback_;
  std::mutex mutex_;
  std::size_t done_ = 0;
  bool cancelled_ = false;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_EXECUTION_PROGRESS_H
