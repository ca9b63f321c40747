// The scene's Linear solver subsection: CG with AMG or a direct solver.
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  enum class LinearSolverType
  {
    cg_amg,
    direct
  };

  struct LinearSolverParameters
  {
    LinearSolverType type                  = LinearSolverType::cg_amg;
    double           relative_tolerance    = 1e-8;
    unsigned int     max_iterations        = 1000;
    std::string      direct_solver         = "Amesos_Klu";
    double           aggregation_threshold = 1e-4;
    unsigned int     smoother_sweeps       = 1;
    /// ML's smoothed aggregation; false: plain aggregation (prolongator
    /// damping 0).
    bool smoothed_aggregation = true;
    /// The AMG hierarchy is rebuilt once CG needs more than this factor
    /// times the iterations (per decade of residual reduction) of the first
    /// solve with the current hierarchy; 0: rebuilt for every solve.
    double amg_rebuild_growth = 1.5;
    /// Refresh a hierarchy for a new tangent on the aggregates of its first
    /// build (ML's ReComputePreconditioner) instead of aggregating anew.
    bool amg_reuse_aggregates = false;
    /// P2 displacement tangents with CG + AMG: the two-level P2 -> P1
    /// preconditioner (TwoLevelPreconditioner) instead of ML on the P2
    /// matrix.
    bool p2_two_level = true;
    /// 'Exact solve on stiff couplings'.
    bool stiff_couplings_solve = false;
    /// 'AMG for contrast': auto (on for regions whose stiffnesses differ
    /// by more than contrast_threshold), on or off. On: ML's
    /// energy-minimizing prolongators and an aggregation threshold of at
    /// least contrast_aggregation_threshold.
    enum class Contrast
    {
      automatic,
      on,
      off
    } amg_for_contrast = Contrast::automatic;
    static constexpr double contrast_threshold             = 10.;
    static constexpr double contrast_aggregation_threshold = 0.01;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };
} // namespace hyperelastic
