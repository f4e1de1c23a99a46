// EXPECT: a named parameter that the package does not read
// EXPECT-ONE-ERROR
// A chain started from CGAL::parameters cannot take the package's
// number_of_seeds (CGAL 5.5 offers no way to add it), and its look-alike
// number_of_samples used to compile and be ignored.
#include <CGAL/Disk_segmentation/voronoi_fps_segmentation.h>
#include "common.h"

int main()
{
  Mesh m;
  std::map<Mesh::Face_index, int> ids;
  return int(DS::voronoi_fps_segmentation(m, boost::make_assoc_property_map(ids),
                                          CGAL::parameters::vertex_point_map(m.points()).number_of_samples(12)));
}
