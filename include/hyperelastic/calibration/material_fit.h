// The fit of a model's constants to homogeneous test data: minimises
//   1/2 sum_tests w_t sum_points (N_model(state; c) - N_measured)^2
// with N_model the long-term response (calibration/homogeneous_test.h),
// times 1 + sum_j beta_j exp(-t / tau_j) for a relaxation test: with J = 1
// the overstress of the program's Prony series (materials/
// viscoelasticity.h) after a jump to a held stretch is beta_j exp(-t/tau_j)
// times the isochoric stress, and the isochoric and the full nominal stress
// are the same, the volumetric stress being a pressure. Absolute
// nominal-stress residuals, over the free values c (model_constants.h) by
// Levenberg-Marquardt with exact derivatives (the model's
// ConstantDerivatives through calibration/homogeneous_test.h), from the
// parameter file's values and Starts - 1 more starts scattered around them
// (each free value times a factor in [1/3, 3], the same on every rank). The
// model's own checks bound the constants: a rejected value is a rejected
// step.
#pragma once

#include <hyperelastic/calibration/levenberg_marquardt.h>
#include <hyperelastic/calibration/model_constants.h>
#include <hyperelastic/calibration/test_data.h>

#include <vector>

namespace hyperelastic
{
  namespace calibration
  {
    struct FitResult
    {
      std::vector<double> values;                ///< the free entries
      std::vector<double> standard_errors;       ///< from (J^T J)^-1 s^2
      double              cost             = 0.; ///< 1/2 the weighted squares
      unsigned int        starts_converged = 0;
      unsigned int        iterations       = 0; ///< over all starts
    };

    /// Levenberg-Marquardt on @p problem from @p origin and Starts - 1
    /// points around it (each value times a factor in [1/3, 3], the same
    /// sequence on every rank and run): the best, with standard errors.
    FitResult
    multi_start_fit(const LeastSquaresProblem &problem,
                    const std::vector<double> &origin,
                    unsigned int               starts);

    FitResult
    fit_material(const ModelConstants        &constants,
                 const std::vector<TestData> &data,
                 bool                         incompressible,
                 unsigned int                 starts);

    /// For drawing: each test's states at 101 points between its data's
    /// ends (uniaxial ... volumetric: over the first column; biaxial: per
    /// stress and first stretch, over the second; relaxation: over time).
    /// No measured values.
    std::vector<TestData>
    curve_states(const std::vector<TestData> &data);

    /// The model's value at every state of every test (NaN where it is
    /// undefined), with the Prony series @p prony for relaxation tests.
    std::vector<std::vector<double>>
    model_values(const Material<3>           &material,
                 const PronySeries           &prony,
                 const std::vector<TestData> &data,
                 bool                         incompressible);
  } // namespace calibration
} // namespace hyperelastic
