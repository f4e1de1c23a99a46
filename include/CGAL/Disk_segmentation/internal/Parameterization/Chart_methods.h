// Copyright (c) 2026 The Disk_segmentation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The methods that parameterize a chart (ARAP, LSCM, the fixed-border
// ones, the user's parameterizer) behind one interface.

#ifndef CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_METHODS_H
#define CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_METHODS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Disk_segmentation/Chart_parameterizer.h>
#include <CGAL/Disk_segmentation/Input_error.h>
#include <CGAL/Disk_segmentation/Parameterization_method.h>
#include <CGAL/Disk_segmentation/internal/Mesh/Indexed_triangle_mesh.h>
#include <CGAL/Disk_segmentation/internal/Parameterization/Chart_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Disk_segmentation {
namespace internal {

// One way to parameterize a chart. The built-in methods and the user's
// parameterizer are all Chart_methods, so the code that chooses charts
// never names a method, and a new method is one more class.
class Chart_method
{
public:
  virtual ~Chart_method() = default;

  // What reports call it.
  virtual Parameterization_method id() const = 0;

  // A first try on the indexed chart, before it is copied into a
  // Chart_mesh (ARAP's own free-border start needs no copy): nullopt to go
  // on to parameterize_copy(), else what parameterize_chart_with() returns.
  virtual std::optional<std::string> parameterize_indexed(const Indexed_triangle_mesh&, Chart&,
                                                          std::vector<Index>& /* border_loop */,
                                                          bool& /* validated */, On_invalid_map,
                                                          Early_look*) const
  {
    return std::nullopt;
  }

  // Runs on `mesh`, the copy of `c` (same vertex numbering) whose border
  // holds `border`; leaves the UVs in `c.uv` and returns what went wrong
  // (empty on success). `validated`: whether the UVs were found valid.
  virtual std::string parameterize_copy(const Indexed_triangle_mesh& m, Chart& c, Chart_mesh& mesh,
                                        Chart_mesh::Halfedge_index border, const std::vector<Index>& border_loop,
                                        bool& validated, Early_look* look) const = 0;

  // Whether the method iterates from a start map, so that the union of two
  // solved charts may start from their two maps glued.
  virtual bool starts_from_a_map() const { return false; }

  // From `start` (one UV per local vertex); returns what went wrong, empty
  // if `c.uv` is now a valid map (it is unchanged otherwise).
  virtual std::string parameterize_from_map(const Indexed_triangle_mesh&, Chart&, Chart_uv /* start */,
                                            Early_look*) const
  {
    return "the method does not start from a map";
  }
};

// A method that runs a model of SMP's Parameterizer_3 on the chart's copy;
// `make()` gives the parameterizer of each chart. SMP's parameterizers
// share their solver among copies (Eigen_solver_traits holds it by
// shared_ptr), so copies of one object must not solve at once: with
// `take_turns`, solves run one at a time.
template <typename Make>
class Smp_chart_method : public Chart_method
{
public:
  Smp_chart_method(Parameterization_method id, Make make, bool take_turns)
    : id_(id), make_(std::move(make)), take_turns_(take_turns)
  {}

  Parameterization_method id() const override { return id_; }

  std::string parameterize_copy(const Indexed_triangle_mesh&, Chart& c, Chart_mesh& mesh,
                                Chart_mesh::Halfedge_index border, const std::vector<Index>&, bool&,
                                Early_look*) const override
  {
    if(!take_turns_)
      return solve(mesh, border, c);
    std::lock_guard<std::mutex> turn(turn_);
#ifdef CGAL_LINKED_WITH_TBB
    // Were the parameterizer to wait on TBB work of its own, this thread
    // could meanwhile take another chart and wait for the lock it holds.
    std::string problem;
    tbb::this_task_arena::isolate([&] { problem = solve(mesh, border, c); });
    return problem;
#else
    return solve(mesh, border, c);
#endif
  }

private:
  std::string solve(Chart_mesh& mesh, Chart_mesh::Halfedge_index border, Chart& c) const
  {
    try
    {
      return run_parameterizer(mesh, make_(), border, c);
    }
    catch(const std::exception& e)  // from the user's factory
    {
      return std::string("parameterizer threw: ") + e.what();
    }
  }

  Parameterization_method id_;
  Make make_;
  bool take_turns_;
  mutable std::mutex turn_;
};

template <typename Parameterizer>
struct Make_default
{
  Parameterizer operator()() const { return Parameterizer(); }
};

// The package's ARAP (see Local_global_arap.h for why not SMP's).
class Arap_chart_method : public Chart_method
{
public:
  Parameterization_method id() const override { return Parameterization_method::ARAP; }

  std::optional<std::string> parameterize_indexed(const Indexed_triangle_mesh& m, Chart& c,
                                                  std::vector<Index>& border_loop, bool& validated,
                                                  On_invalid_map on_invalid, Early_look* look) const override
  {
    if(c.triangles.size() < 2)
      return std::nullopt;
    if(arap_from_lscm(m, c, border_loop, look))
    {
      validated = true;
      return std::string();
    }
    if(on_invalid == On_invalid_map::report)
      return std::string("ARAP: the free-border LSCM start folds or overlaps and the iterations did not repair it");
    return std::nullopt;
  }

  std::string parameterize_copy(const Indexed_triangle_mesh& m, Chart& c, Chart_mesh& mesh,
                                Chart_mesh::Halfedge_index border, const std::vector<Index>& border_loop,
                                bool& validated, Early_look* look) const override
  {
    return arap_from_other_starts(m, c, mesh, border, border_loop, validated, look);
  }

  // The maps of two charts glued are close to their union's ARAP optimum.
  // (Not for the pieces of a parameterized chart: from its map restricted
  // to them, local/global iterations converge slowly, 30 iterations to
  // reach the charts an LSCM start gives in 10.)
  bool starts_from_a_map() const override { return true; }

  std::string parameterize_from_map(const Indexed_triangle_mesh& m, Chart& c, Chart_uv start,
                                    Early_look* look) const override
  {
    const std::vector<Index> border =
      (c.triangles.size() < 2 || start.size() != c.vertices.size()) ? std::vector<Index>() : chart_border_loop(c);
    if(border.empty() || !arap_from(c, border, chart_geometry(m, c), std::move(start), look))
      return "ARAP: the start glued from the two charts' maps folds or overlaps and the iterations did not repair it";
    return std::string();
  }
};

// The built-in method `method`; throws Input_error for CUSTOM and for a
// value out of the enumeration.
inline const Chart_method& built_in_chart_method(Parameterization_method method)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef Factor_once_sparse_lu Solver;
  typedef SMP::Discrete_conformal_map_parameterizer_3<Chart_mesh, Circle_border, Solver> Conformal;
  typedef SMP::LSCM_parameterizer_3<Chart_mesh> Lscm;
  typedef SMP::Mean_value_coordinates_parameterizer_3<Chart_mesh, Circle_border, Solver> Mean_value;
  typedef SMP::Barycentric_mapping_parameterizer_3<Chart_mesh, Circle_border, Solver> Tutte;
  // A fresh parameterizer per chart: no shared solver, no turns.
  static const Smp_chart_method<Make_default<Conformal> > conformal(Parameterization_method::DISCRETE_CONFORMAL, {},
                                                                     false);
  static const Smp_chart_method<Make_default<Lscm> > lscm(Parameterization_method::LSCM, {}, false);
  static const Arap_chart_method arap;
  static const Smp_chart_method<Make_default<Mean_value> > mean_value(Parameterization_method::MEAN_VALUE, {}, false);
  static const Smp_chart_method<Make_default<Tutte> > tutte(Parameterization_method::TUTTE, {}, false);
  switch(method)
  {
    case Parameterization_method::DISCRETE_CONFORMAL: return conformal;
    case Parameterization_method::LSCM: return lscm;
    case Parameterization_method::ARAP: return arap;
    case Parameterization_method::MEAN_VALUE: return mean_value;
    case Parameterization_method::TUTTE: return tutte;
    case Parameterization_method::CUSTOM:
      throw Input_error("parameterization_method: CUSTOM names a parameterizer object in reports; pass the object "
                        "with the named parameter parameterizer instead");
  }
  throw Input_error("parameterization_method: unknown value " + std::to_string(int(method)));
}

// A parameterizer's declared mesh (SMP's parameterizers name it
// Triangle_mesh) must be Chart_mesh; a class that declares none is taken
// on trust.
template <typename Parameterizer, typename = void>
struct works_on_chart_mesh : std::true_type
{};

template <typename Parameterizer>
struct works_on_chart_mesh<Parameterizer, std::void_t<typename Parameterizer::Triangle_mesh> >
  : std::is_same<typename Parameterizer::Triangle_mesh, Chart_mesh>
{};

// The user's `parameterizer` named parameter as a method: a factory is
// called for each chart; an object is copied for each chart and its copies
// take turns (see Smp_chart_method).
template <typename Parameterizer>
std::shared_ptr<const Chart_method> user_chart_method(const Parameterizer& parameterizer)
{
  // Charts call a factory from several threads at once.
  static_assert(std::is_invocable_v<const Parameterizer&> || !std::is_invocable_v<Parameterizer&>,
                "CGAL::Disk_segmentation: a parameterizer factory must be callable as const (not a mutable "
                "lambda): it is called from several threads at once");
  if constexpr(std::is_invocable_v<const Parameterizer&>)
  {
    typedef std::decay_t<std::invoke_result_t<const Parameterizer&> > Made;
    static_assert(works_on_chart_mesh<Made>::value,
                  "CGAL::Disk_segmentation: the parameterizer factory must return a parameterizer of "
                  "CGAL::Disk_segmentation::Chart_mesh");
    return std::make_shared<Smp_chart_method<Parameterizer> >(Parameterization_method::CUSTOM, parameterizer, false);
  }
  else
  {
    static_assert(works_on_chart_mesh<Parameterizer>::value,
                  "CGAL::Disk_segmentation: the parameterizer must be a parameterizer of "
                  "CGAL::Disk_segmentation::Chart_mesh, e.g. "
                  "Surface_mesh_parameterization::Discrete_authalic_parameterizer_3<Chart_mesh>");
    auto copy = [parameterizer] { return parameterizer; };
    return std::make_shared<Smp_chart_method<decltype(copy)> >(Parameterization_method::CUSTOM, copy, true);
  }
}

} // namespace internal
} // namespace Disk_segmentation
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_DISK_SEGMENTATION_INTERNAL_PARAMETERIZATION_CHART_METHODS_H
