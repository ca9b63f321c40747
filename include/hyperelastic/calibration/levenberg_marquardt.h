// Levenberg-Marquardt for small nonlinear least-squares problems,
//   minimise 1/2 |r(x)|^2,
// with exact Jacobians from the caller: each iteration solves
//   (J^T J + m diag(J^T J)) dx = -J^T r,
// accepts the step if the cost falls (m shrinks) and rejects it otherwise
// (m grows). Admissibility (bounds, a model's own checks) is the caller's
// evaluate() returning false: the step is rejected like a rise in cost.
// Nothing here knows about materials.
#pragma once

#include <functional>
#include <vector>

namespace hyperelastic
{
  namespace calibration
  {
    struct LeastSquaresProblem
    {
      /// r(x) and J = dr/dx (rows: residuals); false where x is not
      /// admissible (r and J are then ignored).
      std::function<bool(const std::vector<double>        &x,
                         std::vector<double>              &r,
                         std::vector<std::vector<double>> &J)>
        evaluate;
    };

    struct LeastSquaresResult
    {
      std::vector<double> x;
      double              cost       = 0.; ///< 1/2 |r|^2
      unsigned int        iterations = 0;
      bool                converged  = false;
    };

    struct LevenbergMarquardtSettings
    {
      unsigned int max_iterations = 300;
      /// Stop when a step changes no unknown by more than this relative
      /// amount,
      double tolerance = 1e-13;
      /// or when three accepted steps in a row lower the cost by less than
      /// this fraction of it.
      double cost_tolerance = 1e-10;
    };

    /// From @p start, which must be admissible (otherwise the result has
    /// iterations 0, converged false and an infinite cost).
    LeastSquaresResult
    levenberg_marquardt(const LeastSquaresProblem        &problem,
                        const std::vector<double>        &start,
                        const LevenbergMarquardtSettings &settings = {});
  } // namespace calibration
} // namespace hyperelastic
