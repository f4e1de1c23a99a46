// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A look at an early ARAP iterate of a chart: whether the iterations left
// are needed, so that a chart clearly good or clearly hopeless stops early.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_ARAP_EARLY_LOOK_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_ARAP_EARLY_LOOK_H

#include <CGAL/Disk_segmentation/internal/Parameterization/Chart.h>

#include <functional>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// What a look at an early ARAP iterate of a chart says of the iterations
// left.
enum class Early_verdict
{
  iterate_on,   // they are needed
  good_enough,  // the iterate already meets what the chart must meet: stop there if it is valid
  hopeless      // it is so far from it that they would not bring it there: stop
};

// A verdict, with the measure it was drawn from (Split_rule: the chart's
// excess), so that the chart need not be measured again.
struct Early_judgement
{
  Early_verdict verdict = Early_verdict::iterate_on;
  double measure = 0.;
};

// Judges chart `c` under the ARAP iterate `uv` after
// arap_early_look_iterations iterations (see Split_rule::early_verdict()).
// Most charts that meet the bound after all iterations already meet it
// there, and most that miss it by far already miss it by far.
typedef std::function<Early_judgement(const Chart&, const Chart_uv&)> Arap_early_look;
constexpr int arap_early_look_iterations = 2;

// The early look of one chart's parameterization: the judge (none: all
// iterations), and its judgement of the map the chart ends with when the
// look ended the iterations on it (else `iterate_on`).
struct Early_look
{
  const Arap_early_look* judge = nullptr;
  Early_judgement ended;
};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_ARAP_EARLY_LOOK_H
