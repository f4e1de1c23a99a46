// EXPECT: a parameterizer factory must be callable as const
// EXPECT-ONE-ERROR
// Charts call a factory from several threads at once: one that changes
// its own state (a mutable lambda) is refused with one line, not an error
// deep in SMP.
#include <CGAL/Disk_segmentation/parameterize_patches.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include "common.h"

int main()
{
  Mesh m;
  std::map<Mesh::Face_index, std::size_t> ids;
  std::map<Mesh::Halfedge_index, K::Point_2> uv;
  int made = 0;
  DS::parameterize_patches(m, boost::make_assoc_property_map(ids), boost::make_assoc_property_map(uv),
                           DS::parameters::parameterizer([made]() mutable {
                             ++made;
                             return CGAL::Surface_mesh_parameterization::LSCM_parameterizer_3<DS::Chart_mesh>();
                           }));
}
