// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Face labels as a partition: the faces of each label, and the canonical
// numbering of the labels (by smallest face).

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_MESH_FACE_PARTITION_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_MESH_FACE_PARTITION_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// Calls `visit(r)` for each label in order, where r is the label's rank
// among the distinct labels by first appearance, or `no_index` for a label
// that `is_skipped`. Labels below twice the count (patch ids, region ids:
// the usual case) are ranked through a table, others through a hash map,
// which was 1.4 % of the pipeline's time. `visit` may overwrite the label
// it is given.
template <typename Label, typename IsSkipped, typename Visit>
void rank_labels_by_first_appearance(const std::vector<Label>& labels, const IsSkipped& is_skipped,
                                     const Visit& visit)
{
  Index next = 0;
  auto visit_all = [&](const auto& rank_of) {
    for(const Label& l : labels)
      visit(is_skipped(l) ? no_index : rank_of(l));
  };
  const std::size_t table_size = 2 * labels.size();
  bool dense = true;
  for(const Label& l : labels)
    if(!is_skipped(l) && !(static_cast<std::size_t>(l) < table_size))
      dense = false;
  if(dense)
  {
    std::vector<Index> rank(table_size, no_index);
    visit_all([&](const Label& l) {
      Index& r = rank[static_cast<std::size_t>(l)];
      if(r == no_index)
        r = next++;
      return r;
    });
    return;
  }
  std::unordered_map<Label, Index> rank;
  visit_all([&](const Label& l) {
    const auto inserted = rank.emplace(l, next);
    if(inserted.second)
      ++next;
    return inserted.first->second;
  });
}

// Groups faces by label: one region per distinct label, regions ordered by
// their smallest face, faces of a region in increasing order.
template <typename Label>
std::vector<std::vector<Index> > group_faces_by_label(const std::vector<Label>& labels)
{
  std::vector<std::vector<Index> > regions;
  Index f = 0;
  rank_labels_by_first_appearance(labels, [](const Label&) { return false; }, [&](Index region) {
    if(region == regions.size())
      regions.emplace_back();
    regions[region].push_back(f++);
  });
  return regions;
}

// Renumbers labels 0..P-1 in order of each label's smallest face: the
// canonical numbering, independent of how the labels were produced. Returns P.
// Faces labeled `no_index` (outside every region) keep that label and are
// not counted.
inline std::size_t make_canonical(std::vector<Index>& labels)
{
  std::size_t count = 0;
  std::size_t f = 0;
  rank_labels_by_first_appearance(labels, [](Index l) { return l == no_index; }, [&](Index rank) {
    labels[f++] = rank;
    if(rank != no_index)
      count = (std::max)(count, std::size_t(rank) + 1);
  });
  return count;
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

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_MESH_FACE_PARTITION_H
