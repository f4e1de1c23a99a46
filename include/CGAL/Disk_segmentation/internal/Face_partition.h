// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_FACE_PARTITION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_FACE_PARTITION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Indexed_triangle_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Groups faces by label: one region per distinct label, regions ordered by
// their smallest face, faces of a region in increasing order.
template <typename Label>
std::vector<std::vector<Index> > group_faces_by_label(const std::vector<Label>& labels)
{
  std::vector<std::vector<Index> > regions;
  std::unordered_map<Label, Index> region_of_label;
  for(Index f = 0; f < labels.size(); ++f)
  {
    auto it = region_of_label.emplace(labels[f], static_cast<Index>(regions.size())).first;
    if(it->second == regions.size())
      regions.emplace_back();
    regions[it->second].push_back(f);
  }
  return regions;
}

// Renumbers labels 0..P-1 in order of each label's smallest face: the
// canonical numbering, independent of how the labels were produced. Returns P.
// Faces labeled `no_index` (outside every region) keep that label and are
// not counted.
inline std::size_t make_canonical(std::vector<Index>& labels)
{
  std::unordered_map<Index, Index> canonical;
  for(Index& l : labels)
    if(l != no_index)
      l = canonical.emplace(l, static_cast<Index>(canonical.size())).first->second;
  return canonical.size();
}

template <typename FaceHandles, typename FacePatchMap>
std::vector<std::size_t> read_face_labels(const FaceHandles& face_handles, const FacePatchMap& face_patch_map)
{
  std::vector<std::size_t> labels;
  labels.reserve(face_handles.size());
  for(const auto& f : face_handles)
    labels.push_back(static_cast<std::size_t>(get(face_patch_map, f)));
  return labels;
}

template <typename FaceHandles, typename FacePatchMap>
void write_face_labels(const FaceHandles& face_handles, const std::vector<Index>& labels,
                       FacePatchMap& face_patch_map)
{
  typedef typename boost::property_traits<FacePatchMap>::value_type Id;
  for(std::size_t f = 0; f < face_handles.size(); ++f)
    put(face_patch_map, face_handles[f], static_cast<Id>(labels[f]));
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_FACE_PARTITION_H
