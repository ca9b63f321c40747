// Levenberg-Marquardt (see the header).
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/calibration/levenberg_marquardt.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hyperelastic
{
  namespace calibration
  {
    namespace
    {
      struct Evaluation
      {
        std::vector<double>              r;
        std::vector<std::vector<double>> J;
        double                           cost       = 0.;
        bool                             admissible = false;
      };

      Evaluation
      evaluate(const LeastSquaresProblem &problem, const std::vector<double> &x)
      {
        Evaluation e;
        e.admissible = problem.evaluate(x, e.r, e.J);
        if (e.admissible)
          for (const double r : e.r)
            e.cost += 0.5 * r * r;
        if (!std::isfinite(e.cost))
          e.admissible = false;
        return e;
      }

      /// The step of (J^T J + m diag(J^T J)) dx = -J^T r; empty if singular.
      std::vector<double>
      damped_step(const Evaluation &e, const double m)
      {
        const unsigned int         n = e.J.empty() ? 0 : e.J[0].size();
        dealii::FullMatrix<double> M(n, n);
        dealii::Vector<double>     rhs(n), dx(n);
        for (unsigned int k = 0; k < e.r.size(); ++k)
          for (unsigned int i = 0; i < n; ++i)
            {
              rhs[i] -= e.J[k][i] * e.r[k];
              for (unsigned int j = 0; j < n; ++j)
                M(i, j) += e.J[k][i] * e.J[k][j];
            }
        for (unsigned int i = 0; i < n; ++i)
          M(i, i) += m * std::max(M(i, i), 1e-30);
        try
          {
            M.gauss_jordan();
          }
        catch (...)
          {
            return {};
          }
        M.vmult(dx, rhs);
        return std::vector<double>(dx.begin(), dx.end());
      }
    } // namespace

    LeastSquaresResult
    levenberg_marquardt(const LeastSquaresProblem        &problem,
                        const std::vector<double>        &start,
                        const LevenbergMarquardtSettings &settings)
    {
      LeastSquaresResult result;
      result.x           = start;
      Evaluation current = evaluate(problem, start);
      if (!current.admissible)
        {
          result.cost = std::numeric_limits<double>::infinity();
          return result;
        }
      // Nielsen's damping update from the gain ratio rho (actual over
      // predicted fall of the cost).
      double       m = 1e-3, nu = 2.;
      unsigned int flat_steps = 0; // accepted steps in a row that gain ~0
      for (; result.iterations < settings.max_iterations; ++result.iterations)
        {
          const std::vector<double> dx = damped_step(current, m);
          if (dx.empty())
            {
              m *= nu;
              nu *= 2.;
              continue;
            }
          std::vector<double> trial  = result.x;
          double              change = 0.;
          for (unsigned int i = 0; i < dx.size(); ++i)
            {
              trial[i] += dx[i];
              change = std::max(change,
                                std::abs(dx[i]) /
                                  std::max(std::abs(result.x[i]), 1e-300));
            }
          // The model's fall -g.dx - |J dx|^2 / 2, g = J^T r.
          double predicted = 0.;
          for (unsigned int k = 0; k < current.r.size(); ++k)
            {
              double J_dx = 0.;
              for (unsigned int i = 0; i < dx.size(); ++i)
                J_dx += current.J[k][i] * dx[i];
              predicted -= current.r[k] * J_dx + 0.5 * J_dx * J_dx;
            }
          const Evaluation next = evaluate(problem, trial);
          const double     fall = current.cost - next.cost;
          const double     rho =
            next.admissible && predicted > 0. ? fall / predicted : -1.;
          if (rho > 0. || (next.admissible && fall == 0. && predicted <= 0.))
            {
              result.x = trial;
              current  = next;
              m *= std::max(1. / 3., 1. - std::pow(2. * rho - 1., 3));
              m          = std::max(m, 1e-15);
              nu         = 2.;
              flat_steps = fall <= settings.cost_tolerance * current.cost
                             ? flat_steps + 1
                             : 0;
              if (change <= settings.tolerance || flat_steps >= 3 ||
                  current.cost == 0.)
                {
                  result.converged = true;
                  break;
                }
            }
          else
            {
              m *= nu;
              nu *= 2.;
              if (change <= settings.tolerance || m > 1e16)
                {
                  result.converged = true;
                  break;
                }
            }
        }
      result.cost = current.cost;
      return result;
    }
  } // namespace calibration
} // namespace hyperelastic
