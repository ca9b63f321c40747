// The scene's Load stepping subsection: adaptive steps and cut-back.
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  struct LoadSteppingParameters
  {
    bool         adaptive             = true;
    double       minimum_increment    = 1e-4;
    unsigned int easy_step_iterations = 6;
    /// Start each load step after the first from the secant extrapolation
    /// of the last two converged states (if admissible).
    bool secant_predictor = false;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };
} // namespace hyperelastic
