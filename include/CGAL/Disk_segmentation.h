// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Umbrella header of the Disk_segmentation package.

#ifndef CGAL_DISK_SEGMENTATION_H
#define CGAL_DISK_SEGMENTATION_H

#include <CGAL/Disk_segmentation/Cancelled.h>
#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/parameters.h>
#include <CGAL/Disk_segmentation/topology.h>
#include <CGAL/Disk_segmentation/voronoi_fps_segmentation.h>
#include <CGAL/Disk_segmentation/refine_to_topological_disks.h>
#include <CGAL/Disk_segmentation/Merge_tree.h>
#include <CGAL/Disk_segmentation/regular_polygon_threshold.h>
#include <CGAL/Disk_segmentation/merge_disk_regions.h>
#include <CGAL/Disk_segmentation/segment_into_disks.h>
#include <CGAL/Disk_segmentation/Chart_parameterizer.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/Distortion_bound.h>
#include <CGAL/Disk_segmentation/Parameterization_report.h>
#include <CGAL/Disk_segmentation/parameterize_patches.h>
#include <CGAL/Disk_segmentation/Packing_method.h>
#include <CGAL/Disk_segmentation/Packing_report.h>
#include <CGAL/Disk_segmentation/pack_patches.h>
#include <CGAL/Disk_segmentation/patch_faces.h>
#include <CGAL/Disk_segmentation/Atlas_report.h>
#include <CGAL/Disk_segmentation/uv_atlas.h>
#include <CGAL/Disk_segmentation/uv_atlas_of_meshes.h>
#include <CGAL/Disk_segmentation/Distortion_statistics.h>
#include <CGAL/Disk_segmentation/atlas_quality.h>

#endif // CGAL_DISK_SEGMENTATION_H
