// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Named parameters of the Disk_segmentation package.
//
// CGAL 5.5 stamps its chaining builders (`.vertex_point_map(...)`, ...) out of
// one list and offers no hook to add names, so the package keeps its own
// parameter pack type that derives from `CGAL::Named_function_parameters`,
// re-stamps CGAL's builders and adds the package's. CGAL's lookup helpers
// (`get_parameter`, `choose_parameter`, `is_default_parameter`) work on it
// unchanged because they only see the base class.

#ifndef CGAL_DISK_SEGMENTATION_PARAMETERS_H
#define CGAL_DISK_SEGMENTATION_PARAMETERS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/default_values.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Disk_segmentation {

namespace internal_np {

// Tags of the package's own named parameters.
#define CGAL_DISK_SEGMENTATION_PARAMETER(name, flag, argument) enum name##_t { name };
#include <CGAL/Disk_segmentation/parameters_interface.h>
#undef CGAL_DISK_SEGMENTATION_PARAMETER

} // namespace internal_np

/// \ingroup PkgDiskSegmentationRef
/// Named parameter pack of the package. It behaves like
/// `CGAL::Named_function_parameters` (and is one), and also offers the
/// package's own parameters, so that CGAL's and the package's parameters
/// chain in any order, e.g.
/// `parameters::number_of_seeds(20).vertex_point_map(vpm).merge_threshold(0.6)`.
/// The parameters are listed on the page \ref PkgDiskSegmentationNamedParameters.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters
  : public CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> CGAL_base;
  typedef typename CGAL_base::base base;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : CGAL_base() {}
  Named_function_parameters(const T& v) : CGAL_base(v) {}
  Named_function_parameters(const T& v, const Base& b) : CGAL_base(v, b) {}

#define CGAL_add_named_parameter(X, Y, Z)                                         \
  template <typename K>                                                           \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const    \
  {                                                                               \
    return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this);   \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_DISK_SEGMENTATION_ADD_PARAMETER(X, Z)                                \
  template <typename K>                                                           \
  Named_function_parameters<K, internal_np::X, self> Z(const K& k) const          \
  {                                                                               \
    return Named_function_parameters<K, internal_np::X, self>(k, *this);         \
  }
#define CGAL_DISK_SEGMENTATION_PARAMETER(name, flag, argument) CGAL_DISK_SEGMENTATION_ADD_PARAMETER(name##_t, name)
#include <CGAL/Disk_segmentation/parameters_interface.h>
#undef CGAL_DISK_SEGMENTATION_PARAMETER
#undef CGAL_DISK_SEGMENTATION_ADD_PARAMETER
};

namespace parameters {

typedef Named_function_parameters<bool, CGAL::internal_np::all_default_t>
  Default_named_parameters;

// `default_values()` and the builders below are documented on the manual's
// page PkgDiskSegmentationNamedParameters and under "Named Parameters" in
// every function that reads them, not as free functions of the reference.
/// \cond SKIP_IN_MANUAL
/// An empty parameter pack: every parameter takes its default value.
inline Default_named_parameters default_values()
{
  return Default_named_parameters();
}

#define CGAL_add_named_parameter(X, Y, Z)                                         \
  template <typename K>                                                           \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& k)                \
  {                                                                               \
    return Named_function_parameters<K, CGAL::internal_np::X>(k);                 \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_DISK_SEGMENTATION_ADD_PARAMETER(X, Z)                                \
  template <typename K>                                                           \
  Named_function_parameters<K, internal_np::X> Z(const K& k)                      \
  {                                                                               \
    return Named_function_parameters<K, internal_np::X>(k);                       \
  }
// The interface's parameters here, the testing ones below.
#define CGAL_DISK_SEGMENTATION_PARAMETER(name, flag, argument) CGAL_DISK_SEGMENTATION_ADD_PARAMETER(name##_t, name)
#define CGAL_DISK_SEGMENTATION_TESTING_PARAMETER(name)
#include <CGAL/Disk_segmentation/parameters_interface.h>
#undef CGAL_DISK_SEGMENTATION_TESTING_PARAMETER
#undef CGAL_DISK_SEGMENTATION_PARAMETER
/// \endcond

// Parameters for the package's tests and benchmarks, not part of its
// interface (they may change without notice): the face used as the first
// farthest-point seed of its component, and whether parameterize_patches()
// refuses patches that are not topological disks (`false` parameterizes
// them anyway, as a baseline that ignores topology).
namespace testing {
#define CGAL_DISK_SEGMENTATION_PARAMETER(name, flag, argument)
#define CGAL_DISK_SEGMENTATION_TESTING_PARAMETER(name) CGAL_DISK_SEGMENTATION_ADD_PARAMETER(name##_t, name)
#include <CGAL/Disk_segmentation/parameters_interface.h>
#undef CGAL_DISK_SEGMENTATION_TESTING_PARAMETER
#undef CGAL_DISK_SEGMENTATION_PARAMETER
} // namespace testing
#undef CGAL_DISK_SEGMENTATION_ADD_PARAMETER

} // namespace parameters

} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_PARAMETERS_H
