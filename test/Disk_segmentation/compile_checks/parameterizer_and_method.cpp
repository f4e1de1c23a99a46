// EXPECT: give parameterization_method or parameterizer, not both
// EXPECT-ONE-ERROR
// The built-in method and a parameterizer object cannot both decide.
#include <CGAL/Disk_segmentation/parameterize_patches.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include "common.h"

int main()
{
  Mesh m;
  std::map<Mesh::Face_index, std::size_t> ids;
  std::map<Mesh::Halfedge_index, K::Point_2> uv;
  DS::parameterize_patches(m, boost::make_assoc_property_map(ids), boost::make_assoc_property_map(uv),
                           DS::parameters::parameterization_method(DS::Parameterization_method::ARAP)
                             .parameterizer(CGAL::Surface_mesh_parameterization::LSCM_parameterizer_3<DS::Chart_mesh>()));
}
