// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PATCH_FACES_H
#define CGAL_DISK_SEGMENTATION_PATCH_FACES_H

#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/internal/Parameters/Parameter_checks.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
///
/// Lists the faces of every patch: element `p` of the result holds the faces
/// whose patch id is `p`, in the order of `faces(tm)`. This is the input of a
/// per-patch loop, e.g. to give each patch to \cgal's
/// `Surface_mesh_parameterization` through `CGAL::Face_filtered_graph` (see
/// the example `parameterize_with_smp.cpp` in the manual).
///
/// @tparam FaceListGraph a model of `FaceListGraph`
/// @tparam FacePatchMap a model of `ReadablePropertyMap` with
///         `boost::graph_traits<FaceListGraph>::%face_descriptor` as key
///         type and an integral value type (patch ids)
///
/// @return one vector per patch id from 0 to the largest id found; a patch
///         id that no face has gives an empty vector
///
/// @throws Input_error if a patch id is negative
///
/// Complexity: \f$ O(F + P) \f$ time and memory for `F` faces and `P` patches.
template <typename FaceListGraph, typename FacePatchMap>
std::vector<std::vector<typename boost::graph_traits<FaceListGraph>::face_descriptor> >
patch_faces(const FaceListGraph& tm, FacePatchMap face_patch_map)
{
  static_assert(internal::Check_patch_map<FacePatchMap>::value, "");
  typedef typename boost::property_traits<FacePatchMap>::value_type Patch_id;
  std::vector<std::vector<typename boost::graph_traits<FaceListGraph>::face_descriptor> > result;
  for(auto f : faces(tm))
  {
    const Patch_id id = get(face_patch_map, f);
    if constexpr(std::is_signed<Patch_id>::value)
      if(id < 0)
        throw Input_error("patch_faces: negative patch id " + std::to_string(id));
    const std::size_t p = static_cast<std::size_t>(id);
    if(p >= result.size())
      result.resize(p + 1);
    result[p].push_back(f);
  }
  return result;
}

} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_PATCH_FACES_H
