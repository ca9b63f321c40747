// The scene's Load stepping subsection: adaptive steps and cut-back.
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <vector>

#include <deal.II/base/parameter_handler.h>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  /// How the load factor advances ('Load stepping/Method').
  enum class LoadControl
  {
    load_control, ///< t prescribed per step, cut back on failure
    arc_length    ///< t an unknown, the step's length in (u, t) prescribed
  };

  struct LoadSteppingParameters
  {
    LoadControl method = LoadControl::load_control;
    /// Arc length: the run ends at the first converged step with t >= this
    /// (landed on it exactly) or after maximum_steps steps.
    double       maximum_load_factor  = 1.;
    unsigned int maximum_steps        = 200;
    bool         adaptive             = true;
    double       minimum_increment    = 1e-4;
    unsigned int easy_step_iterations = 6;
    /// 'Snap iterations': Newton's budget for a snap step's first, undamped
    /// solve (0: no snap steps).
    unsigned int snap_iterations = 20;
    /// 'Snap sub-step iterations': the Newton iterations of a snap step's
    /// sub-steps in all (SnapSequence; 0: none).
    unsigned int snap_sub_step_iterations = 400;
    /// A snap step is tried where a cut-back would take the increment
    /// below this fraction of the nominal one.
    static constexpr double snap_fraction = 1. / 16.;
    /// Start each load step after the first from the secant extrapolation
    /// of the last two converged states (if admissible).
    bool secant_predictor = false;
    /// 'Stop at load factors': load control lands a step exactly on each
    /// (strictly increasing, positive), whatever the cut-backs before.
    std::vector<double> stops;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };
} // namespace hyperelastic
