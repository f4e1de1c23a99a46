// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Refines regions into topological disks by Voronoi splits (the paper's
// Algorithm 1), at a cost that depends on the regions' sizes only.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_REGION_REFINEMENT_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_REGION_REFINEMENT_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/internal/Mesh/Face_partition.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Region_topology.h>
#include <CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The paper's Algorithm 1 on an indexed mesh. `regions` lists the faces of
// each region in increasing order (empty regions are ignored); returns the
// refined regions, each in increasing order, sorted by smallest face (the
// canonical numbering). Costs depend on the regions' sizes only, not on the
// mesh's, so that splitting one chart of a large mesh stays cheap.
//
// Termination: a region that is a disk is final. A region of at most k faces
// is split into single faces, which are disks. A region R of more than k
// faces is re-sampled with at least k >= 2 seeds, all distinct faces of R;
// each seed keeps at least itself (its distance 0 is never strictly
// lowered), so every sub-region has fewer faces than R. Sizes strictly
// decrease along every chain of re-sampling, so the worklist empties after
// at most |R| - 1 splits below each region.
inline std::vector<std::vector<Index> > refine_region_list(Region_topology& topology,
                                                           Voronoi_fps& fps,
                                                           std::vector<std::vector<Index> > regions,
                                                           std::size_t k)
{
  std::vector<std::vector<Index> > refined;
  std::vector<std::vector<Index> > worklist;
  for(std::vector<Index>& region : regions)
  {
    if(region.empty())
      continue;
    if(topology.is_disk(region))
      refined.push_back(std::move(region));
    else
      worklist.push_back(std::move(region));
  }

  // Ends: see Termination above.
  while(!worklist.empty())
  {
    std::vector<Index> region = std::move(worklist.back());
    worklist.pop_back();
    if(region.size() <= k || topology.mesh().at_one_point(region))
    {
      for(Index f : region)
        refined.push_back(std::vector<Index>(1, f));
      continue;
    }

    const std::vector<Index> seeds = fps.run(region, k);
    CGAL_assertion(seeds.size() >= 2);
    std::vector<std::vector<Index> > cells(seeds.size());
    for(std::size_t k = 0; k < region.size(); ++k)
      cells[fps.cells()[k]].push_back(region[k]);  // stays sorted: region is
    for(std::vector<Index>& cell : cells)
    {
      CGAL_assertion(!cell.empty() && cell.size() < region.size());
      if(topology.is_disk(cell))
        refined.push_back(std::move(cell));
      else
        worklist.push_back(std::move(cell));
    }
  }
  std::sort(refined.begin(), refined.end(),
            [](const std::vector<Index>& a, const std::vector<Index>& b) { return a.front() < b.front(); });
  return refined;
}

// refine_region_list() as face labels of the whole mesh (faces outside
// every region get `no_index`); returns the number of refined regions.
inline std::size_t refine_regions(const Indexed_triangle_mesh& m,
                                  Voronoi_fps& fps,
                                  std::vector<std::vector<Index> > regions,
                                  std::size_t k,
                                  std::vector<Index>& labels)
{
  Region_topology topology(m);
  const std::vector<std::vector<Index> > refined = refine_region_list(topology, fps, std::move(regions), k);
  labels.assign(m.number_of_faces(), no_index);
  for(std::size_t r = 0; r < refined.size(); ++r)
    for(Index f : refined[r])
      labels[f] = static_cast<Index>(r);
  return refined.size();
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_SEGMENTATION_REGION_REFINEMENT_H
