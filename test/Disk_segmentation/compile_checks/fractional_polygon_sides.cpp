// EXPECT: takes an integer number of sides
#include <CGAL/Disk_segmentation/merge_disk_regions.h>
#include "common.h"

int main() { return DS::regular_polygon_threshold(4.5) > 0. ? 0 : 1; }
