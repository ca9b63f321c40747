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
        double                           cost = 0.;
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
        const unsigned int          n = e.J.empty() ? 0 : e.J[0].size();
        dealii::FullMatrix<double>  M(n, n);
        dealii::Vector<double>      rhs(n), dx(n);
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
      result.x          = start;
      Evaluation current = evaluate(problem, start);
      if (!current.admissible)
        {
          result.cost = std::numeric_limits<double>::infinity();
          return result;
        }
      double       m          = 1e-3;
      unsigned int flat_steps = 0; // accepted steps in a row that gain ~0
      for (; result.iterations < settings.max_iterations; ++result.iterations)
        {
          const std::vector<double> dx = damped_step(current, m);
          if (dx.empty())
            {
              m *= 10.;
              continue;
            }
          std::vector<double> trial = result.x;
          double              change = 0.;
          for (unsigned int i = 0; i < dx.size(); ++i)
            {
              trial[i] += dx[i];
              change = std::max(change,
                                std::abs(dx[i]) /
                                  std::max(std::abs(result.x[i]), 1.));
            }
          const Evaluation next = evaluate(problem, trial);
          if (next.admissible && next.cost <= current.cost)
            {
              const double fall = current.cost - next.cost;
              result.x          = trial;
              current           = next;
              m                 = std::max(m / 3., 1e-12);
              flat_steps = fall <= settings.tolerance * current.cost ?
                             flat_steps + 1 :
                             0;
              if (change <= settings.tolerance || flat_steps >= 3 ||
                  current.cost == 0.)
                {
                  result.converged = true;
                  break;
                }
            }
          else
            {
              m *= 4.;
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
