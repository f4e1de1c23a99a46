// EXPECT-SUCCESS
// EXPECT-NOT-INCLUDED: Surface_mesh_parameterization
// EXPECT-NOT-INCLUDED: tbb/
// EXPECT-NOT-INCLUDED: Eigen/Sparse
// EXPECT-NOT-INCLUDED: Disk_segmentation/parameterize_patches.h
// EXPECT-NOT-INCLUDED: Disk_segmentation/pack_patches.h
// Segmentation alone does not pull in the parameterization, the sparse
// solvers or TBB (the umbrella header CGAL/Disk_segmentation.h does).
#include <CGAL/Disk_segmentation/segment_into_disks.h>
#include "common.h"

int main()
{
  Mesh m;
  std::map<Mesh::Face_index, std::size_t> ids;
  return int(DS::segment_into_disks(m, boost::make_assoc_property_map(ids)));
}
