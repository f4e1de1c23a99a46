// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_DISK_SEGMENTATION_PARAMETERIZATION_METHOD_H
#define CGAL_DISK_SEGMENTATION_PARAMETERIZATION_METHOD_H

#include <CGAL/Disk_segmentation/Input_error.h>

#include <string>

namespace CGAL {
namespace Disk_segmentation {

/// \ingroup PkgDiskSegmentationRef
/// The per-chart parameterization methods. The paper's three methods map
/// as: harmonic = `DISCRETE_CONFORMAL`, conformal = `LSCM`, ARAP = `ARAP`.
///
/// Whose code runs: `DISCRETE_CONFORMAL`, `LSCM`, `MEAN_VALUE` and `TUTTE`
/// are CGAL's Surface_mesh_parameterization parameterizers
/// (`Discrete_conformal_map_parameterizer_3`, `LSCM_parameterizer_3`,
/// `Mean_value_coordinates_parameterizer_3`,
/// `Barycentric_mapping_parameterizer_3`, the fixed-border ones with
/// `Circular_border_arc_length_parameterizer_3`), run on a copy of the
/// chart; the package gives the fixed-border ones a sparse LU factored once.
/// `ARAP` is the package's own: its start is its own free-border LSCM
/// (assembled directly, not SMP's), its iterations its own local/global
/// solver with one factorization (SMP's `ARAP_parameterizer_3` rebuilds and
/// refactors its system at every iteration); SMP's LSCM, mean value
/// and Tutte maps are only its fallback starts. Every method lays out a
/// chart of one triangle isometrically, without a solver.
enum class Parameterization_method
{
  /// Discrete conformal map (cotangent weights), border fixed on a circle by arc length.
  DISCRETE_CONFORMAL,
  /// Least squares conformal map, free border (two pinned vertices).
  LSCM,
  /// As-rigid-as-possible (Liu et al.\ 2008), free border: from the
  /// free-border LSCM map (from the mean value map, or Tutte's, when that
  /// fails), ten local/global iterations with a cotangent Laplacian
  /// factored once; if the last iterate is not a valid chart, they are run
  /// again keeping each only if the chart stays valid.
  ARAP,
  /// Mean value coordinates, border fixed on a circle: injective by construction.
  MEAN_VALUE,
  /// Tutte's barycentric map, border fixed on a circle: injective by construction.
  TUTTE,
  /// The user's parameterizer, given with the named parameter
  /// `parameterizer` (see `Chart_mesh`). Reports name it; it is never
  /// requested by value: `parameterization_method(CUSTOM)` throws `Input_error`.
  CUSTOM
};

/// \ingroup PkgDiskSegmentationRef
/// The short name of a method, as the command-line tool spells it:
/// `conformal`, `lscm`, `arap`, `mvc`, `tutte` (and `custom`). Constant time and memory.
inline std::string to_string(Parameterization_method m)
{
  switch(m)
  {
    case Parameterization_method::DISCRETE_CONFORMAL: return "conformal";
    case Parameterization_method::LSCM: return "lscm";
    case Parameterization_method::ARAP: return "arap";
    case Parameterization_method::MEAN_VALUE: return "mvc";
    case Parameterization_method::TUTTE: return "tutte";
    case Parameterization_method::CUSTOM: return "custom";
  }
  return "unknown";
}

/// \ingroup PkgDiskSegmentationRef
/// The built-in method named `name` (see `to_string()`); throws
/// `Input_error` for an unknown name and for `custom`, which only a
/// parameterizer object gives. Time and memory linear in the length of `name`.
inline Parameterization_method parameterization_method_from_string(const std::string& name)
{
  // The built-in methods are the enumerators before CUSTOM.
  for(int i = 0; i < int(Parameterization_method::CUSTOM); ++i)
    if(to_string(Parameterization_method(i)) == name)
      return Parameterization_method(i);
  throw Input_error("unknown parameterization method '" + name + "' (expected conformal, lscm, arap, mvc or tutte)");
}

} // namespace Disk_segmentation
} // namespace CGAL

#endif // CGAL_DISK_SEGMENTATION_PARAMETERIZATION_METHOD_H
