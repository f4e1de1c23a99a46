// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Runs a parameterizer of CGAL's Surface_mesh_parameterization on a chart's
// mesh, with the circle border and the sparse LU the fixed-border ones use.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_SMP_PARAMETERIZERS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_SMP_PARAMETERIZERS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Chart_parameterizer.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_sparse_matrix.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <exception>
#include <string>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// The border of the fixed-border methods: a circle, by arc length.
typedef CGAL::Surface_mesh_parameterization::Circular_border_arc_length_parameterizer_3<Chart_mesh> Circle_border;

// Solver traits for SMP's fixed-border methods: a direct sparse LU instead
// of the default BiCGSTAB with incomplete LU (measured 20% faster on a
// 75k-face chart, and it cannot fail to converge), factored once for the
// two systems (u and v) that share one matrix, where Eigen_solver_traits
// would factor it twice.
class Factor_once_sparse_lu
  : public CGAL::Eigen_solver_traits<
      Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> > >
{
  typedef CGAL::Eigen_solver_traits<
    Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> > > Base;

public:
  using Base::linear_solver;

  bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D)
  {
    D = 1;
    const auto& a = A.eigen_object();
    const double checksum = a.coeffs().sum();
    if(&a != factored_ || a.nonZeros() != factored_non_zeros_ || checksum != factored_checksum_)
    {
      solver().compute(a);
      if(solver().info() != Eigen::Success)
      {
        factored_ = nullptr;
        return false;
      }
      factored_ = &a;
      factored_non_zeros_ = a.nonZeros();
      factored_checksum_ = checksum;
    }
    X = solver().solve(B);
    return solver().info() == Eigen::Success;
  }

private:
  const void* factored_ = nullptr;
  Eigen::Index factored_non_zeros_ = 0;
  double factored_checksum_ = 0;
};

template <typename Parameterizer>
std::string run_parameterizer(Chart_mesh& mesh, Parameterizer parameterizer,
                              Chart_mesh::Halfedge_index border, Chart& c)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Point_2;
  auto uv = mesh.add_property_map<Chart_mesh::Vertex_index, Point_2>("v:uv", Point_2(0, 0)).first;
  SMP::Error_code status;
  try
  {
    status = SMP::parameterize(mesh, parameterizer, border, uv);
  }
  catch(const std::exception& e)
  {
    mesh.remove_property_map(uv);
    return std::string("parameterizer threw: ") + e.what();
  }
  // A user's parameterizer gets the mesh by reference: one that added or
  // removed vertices would have its UVs read out of place.
  if(mesh.number_of_vertices() != c.uv.size() || mesh.has_garbage())
  {
    mesh.remove_property_map(uv);
    return "the parameterizer changed the chart's mesh";
  }
  for(Chart_mesh::Vertex_index v : mesh.vertices())
    c.uv[std::size_t(v)] = {{ uv[v].x(), uv[v].y() }};
  mesh.remove_property_map(uv);
  if(status != SMP::OK)
    return SMP::get_error_message(status);
  return std::string();
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_SMP_PARAMETERIZERS_H
