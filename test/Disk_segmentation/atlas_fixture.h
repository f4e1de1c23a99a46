// Shared by the atlas tests: an atlas computed on a Surface_mesh with its
// patch and UV maps, and its check by the independent checkers.

#ifndef DISK_SEGMENTATION_TEST_SUPPORT_ATLAS_FIXTURE_H
#define DISK_SEGMENTATION_TEST_SUPPORT_ATLAS_FIXTURE_H

#include "independent_atlas.h"
#include "independent_topology.h"

#include <CGAL/Disk_segmentation.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

namespace test_support {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Atlas_kernel;
typedef CGAL::Surface_mesh<Atlas_kernel::Point_3> Atlas_mesh;

struct Atlas
{
  Atlas_mesh::Property_map<Atlas_mesh::Face_index, std::size_t> patch;
  Atlas_mesh::Property_map<Atlas_mesh::Halfedge_index, Atlas_kernel::Point_2> uv;
  CGAL::Disk_segmentation::Atlas_report report;
};

// uv_atlas() with `np`, writing into new property maps of `tm`.
template <typename NamedParameters>
Atlas make_atlas(Atlas_mesh& tm, const NamedParameters& np)
{
  Atlas a;
  a.patch = tm.add_property_map<Atlas_mesh::Face_index, std::size_t>("f:test_patch", 0).first;
  a.uv = tm.add_property_map<Atlas_mesh::Halfedge_index, Atlas_kernel::Point_2>(
           "h:test_uv", Atlas_kernel::Point_2(0, 0)).first;
  a.report = CGAL::Disk_segmentation::uv_atlas(tm, a.uv, np.face_patch_map(a.patch));
  return a;
}

// Every chart a disk, the report's chart count right, a valid atlas (no
// flip, no overlap, simple borders, texel coverage at `resolution`).
inline void expect_valid_atlas(const Atlas_mesh& tm, const Atlas& a, unsigned resolution = 1024)
{
  const Partition_report partition = check_disk_partition(tm, a.patch);
  EXPECT_TRUE(partition.ok) << partition.problem;
  EXPECT_EQ(partition.number_of_patches, a.report.number_of_charts);
  const Atlas_report atlas = check_atlas(tm, a.patch, a.uv, resolution);
  EXPECT_TRUE(atlas.ok()) << atlas.summary();
  EXPECT_EQ(a.report.parameterization.number_of_invalid_charts, 0u);
}

inline constexpr CGAL::Disk_segmentation::Parameterization_method all_parameterization_methods[] = {
  CGAL::Disk_segmentation::Parameterization_method::DISCRETE_CONFORMAL,
  CGAL::Disk_segmentation::Parameterization_method::LSCM,
  CGAL::Disk_segmentation::Parameterization_method::ARAP,
  CGAL::Disk_segmentation::Parameterization_method::MEAN_VALUE,
  CGAL::Disk_segmentation::Parameterization_method::TUTTE };

} // namespace test_support

#endif // DISK_SEGMENTATION_TEST_SUPPORT_ATLAS_FIXTURE_H
