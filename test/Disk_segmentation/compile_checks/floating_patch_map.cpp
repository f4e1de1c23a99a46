// EXPECT: value type of the face patch map must be an integer type
// Patch ids in a double map would be rounded silently.
#include <CGAL/Disk_segmentation/voronoi_fps_segmentation.h>
#include "common.h"

int main()
{
  Mesh m;
  std::map<Mesh::Face_index, double> ids;
  return int(DS::voronoi_fps_segmentation(m, boost::make_assoc_property_map(ids)));
}
