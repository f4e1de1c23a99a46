// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks of the types and values users pass: counts, patch maps and vertex
// points. Each check fails with one readable line (a static_assert or an
// Input_error naming the parameter) instead of a silent conversion or an
// error deep inside the package.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERS_PARAMETER_CHECKS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERS_PARAMETER_CHECKS_H

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/default_values.h>
#include <CGAL/Disk_segmentation/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <tuple>
#include <type_traits>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// A count parameter (number_of_seeds, number_of_subsamples,
// texture_resolution, texture_height, number_of_threads, max_chart_faces,
// max_number_of_charts, max_number_of_pages) as a std::size_t.
// A floating-point value would be truncated without a word, so it does not
// compile; a negative one would wrap around to a huge count, so it throws.
template <typename T>
std::size_t count_parameter(const T& value, const char* name)
{
  static_assert(std::is_integral<T>::value && !std::is_same<T, bool>::value,
                "CGAL::Disk_segmentation: count parameters (number_of_seeds, number_of_subsamples, "
                "texture_resolution, texture_height, number_of_threads, max_chart_faces, max_number_of_charts, max_number_of_pages) take an integer, not a "
                "floating-point or boolean value");
  if constexpr(std::is_signed<T>::value)
    if(value < 0)
      throw Input_error(std::string(name) + " must not be negative (got " + std::to_string(value) + ")");
  return static_cast<std::size_t>(value);
}

// The `crease_penalty` named parameter (`default_crease_penalty` when not
// given; 0 is the paper's geodesic distance): a finite number >= 0.
template <typename NamedParameters>
double crease_penalty_parameter(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double penalty = static_cast<double>(
    choose_parameter(get_parameter(np, Disk_segmentation::internal_np::crease_penalty), default_crease_penalty));
  if(!(penalty >= 0) || !(penalty <= (std::numeric_limits<double>::max)()))
    throw Input_error("crease_penalty must be a finite number >= 0 (got " + std::to_string(penalty) + ")");
  return penalty;
}

// The `number_of_threads` named parameter (0, TBB's choice, by default);
// counts above what an unsigned int holds mean "as many as there are".
template <typename NamedParameters>
unsigned int number_of_threads_parameter(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return static_cast<unsigned int>((std::min)(
    count_parameter(choose_parameter(get_parameter(np, Disk_segmentation::internal_np::number_of_threads), 0u),
                    "number_of_threads"),
    std::size_t((std::numeric_limits<unsigned int>::max)())));
}

// The `vertex_point_map` named parameter, or the mesh's own points.
template <typename TriangleMesh, typename NamedParameters>
auto vertex_point_map_parameter(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  return choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                          get_const_property_map(CGAL::vertex_point, tm));
}

// Patch ids are written and read as integers; a floating-point patch map
// would round them silently.
template <typename FacePatchMap>
struct Check_patch_map
{
  typedef typename boost::property_traits<FacePatchMap>::value_type Patch_id;
  static_assert(std::is_integral<Patch_id>::value && !std::is_same<Patch_id, bool>::value,
                "CGAL::Disk_segmentation: the value type of the face patch map must be an integer type "
                "(patch ids), e.g. std::size_t");
  static constexpr bool value = true;
};

// A map keyed by the wrong kind of descriptor (a UV map per vertex, a patch
// map per vertex) fails with one line below; the function then runs on a
// map of the right key that does nothing, so that no error follows from
// deep inside the package.
template <typename Descriptor, typename Map>
constexpr bool keyed_by = std::is_convertible<Descriptor, typename boost::property_traits<Map>::key_type>::value;

template <typename TriangleMesh, typename UVMap>
auto checked_uv_map(const UVMap& map)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  constexpr bool ok = keyed_by<halfedge_descriptor, UVMap>;
  static_assert(ok, "CGAL::Disk_segmentation: the UV map must have halfedge_descriptor as key type (one UV per "
                    "corner: uv_map[h] is the UV of target(h) in face(h)), not vertex_descriptor or face_descriptor");
  if constexpr(ok)
    return map;
  else
    return CGAL::Constant_property_map<halfedge_descriptor, typename boost::property_traits<UVMap>::value_type>();
}

template <typename TriangleMesh, typename FacePatchMap>
auto checked_patch_map(const FacePatchMap& map)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  constexpr bool ok = keyed_by<face_descriptor, FacePatchMap>;
  static_assert(ok, "CGAL::Disk_segmentation: the face patch map must have face_descriptor as key type (one "
                    "patch id per face), not vertex_descriptor or halfedge_descriptor");
  if constexpr(ok)
    return map;
  else
    return CGAL::Constant_property_map<face_descriptor, std::size_t>();
}

// face_polygon_map and face_material_map: one value per face.
template <typename TriangleMesh, typename FaceMap>
auto checked_face_group_map(const FaceMap& map)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  constexpr bool ok = keyed_by<face_descriptor, FaceMap>;
  static_assert(ok, "CGAL::Disk_segmentation: face_polygon_map and face_material_map must have face_descriptor "
                    "as key type (one polygon or material per face)");
  if constexpr(ok)
    return map;
  else
    return CGAL::Constant_property_map<face_descriptor, std::size_t>();
}

// A CGAL point (Kernel::Point_3 or any type with its kernel as `R`, which is
// what CGAL::Kernel_traits reads): coordinates are read through its kernel.
template <typename Point, typename = void>
struct is_kernel_point : std::false_type
{};

template <typename Point>
struct is_kernel_point<Point, std::void_t<typename Point::R>> : std::true_type
{};

// The tags of the named parameters that some function of the package reads:
// all of its own and the CGAL ones it takes.
typedef std::tuple<
#define CGAL_DISK_SEGMENTATION_PARAMETER(name, flag, argument) Disk_segmentation::internal_np::name##_t,
#include <CGAL/Disk_segmentation/parameters_interface.h>
#undef CGAL_DISK_SEGMENTATION_PARAMETER
  CGAL::internal_np::vertex_point_t, CGAL::internal_np::geom_traits_t, CGAL::internal_np::face_index_t,
  CGAL::internal_np::vertex_index_t, CGAL::internal_np::random_seed_t, CGAL::internal_np::face_patch_t,
  CGAL::internal_np::all_default_t>
  Read_parameter_tags;

template <typename Tag, typename Tags>
struct is_read_parameter;

template <typename Tag, typename... Tags>
struct is_read_parameter<Tag, std::tuple<Tags...>> : std::bool_constant<(std::is_same<Tag, Tags>::value || ...)>
{};

// Instantiated for a parameter that no function of the package reads: such
// a parameter would be ignored without a word (e.g. CGAL's
// `number_of_samples` where `number_of_seeds` was meant).
template <typename Tag, bool read = is_read_parameter<Tag, Read_parameter_tags>::value>
struct Unread_named_parameter
{
  static_assert(read,
                "CGAL::Disk_segmentation: a named parameter that the package does not read (its tag is the "
                "first template argument of Unread_named_parameter); chain the package's parameters from "
                "CGAL::Disk_segmentation::parameters, e.g. CGAL::Disk_segmentation::parameters::"
                "number_of_seeds(12).vertex_point_map(vpm)");
  static constexpr bool value = true;  // the static_assert above is the one error
};

// Checks every parameter of a chain (the package's parameter type or
// CGAL's), outermost first.
template <typename NamedParameters>
struct Check_named_parameters
{
  static constexpr bool value = true;
};

template <typename T, typename Tag, typename Base>
struct Check_named_parameters<CGAL::Named_function_parameters<T, Tag, Base>>
{
  static constexpr bool value = Unread_named_parameter<Tag>::value && Check_named_parameters<Base>::value;
};

template <typename T, typename Tag, typename Base>
struct Check_named_parameters<Disk_segmentation::Named_function_parameters<T, Tag, Base>>
  : Check_named_parameters<CGAL::Named_function_parameters<T, Tag, Base>>
{};

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERS_PARAMETER_CHECKS_H
