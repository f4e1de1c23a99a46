// EXPECT: must be a parameterizer of CGAL::Disk_segmentation::Chart_mesh
// EXPECT-ONE-ERROR
// A parameterizer runs on the package's copy of a chart, not on the
// caller's mesh type.
#include <CGAL/Disk_segmentation/parameterize_patches.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include "common.h"

int main()
{
  Mesh m;
  std::map<Mesh::Face_index, std::size_t> ids;
  std::map<Mesh::Halfedge_index, K::Point_2> uv;
  DS::parameterize_patches(m, boost::make_assoc_property_map(ids), boost::make_assoc_property_map(uv),
                           DS::parameters::parameterizer(CGAL::Surface_mesh_parameterization::LSCM_parameterizer_3<
                                                         CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> >()));
}
