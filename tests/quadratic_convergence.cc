// Quadratic convergence of Newton's method (stress-tests.md case 9): with the
// exact tangent and exact linear solves (Amesos KLU, inexact Newton off), the
// residuals r_k of the two load steps of a twisted (3D) or bent (2D) and
// pulled bar must fall as r_{k+1} <= C r_k^2 near the solution. Ratio test:
// for every pair of successive residuals near the solution (r_k below 1e-3
// of the step's first residual r_1) and clear of round-off, the scaled ratio
// r_{k+1} r_1 / r_k^2 must stay below 100, and there must be at least one
// such pair. The table with the ratios and the observed order
// log(r_{k+1} / r_k) / log(r_k / r_{k-1}) is printed. Every nonlinear
// model, P1 and P2.
//
// Usage: mpirun -np N quadratic_convergence DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_text.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  /// Bound on r_k+1 r_1 / r_k^2 (quadratic convergence: about C r_1 with
  /// C the Lipschitz constant of the tangent; observed 0.02-30). Linear
  /// convergence with factor c gives c r_1 / r_k, above 100 for any c > 0.1
  /// once r_k < 1e-3 r_1, and growing as r_k falls.
  constexpr double ratio_bound = 100.;

  std::string
  scene(const int dim, const std::string &model, const unsigned int degree)
  {
    const bool three = dim == 3;
    return small_bar(dim, degree) +
           material_section(model,
                            entry("Young's modulus", "1") +
                              entry("Poisson's ratio", "0.3"),
                            LameParameters::from_young_poisson(1., 0.3)) +
           subsection("Loading",
                      entry("Number of load steps", "2") +
                        entry("Constants", "a = 1.0") +
                        entry("Body force",
                              three ? "0; 0; -0.05*t" : "0; -0.05*t")) +
           dirichlet(1,
                     0,
                     three ? "x, y, z" : "x, y",
                     three ? "0; 0; 0" : "0; 0") +
           dirichlet(2,
                     1,
                     three ? "x, y, z" : "x, y",
                     three
                       ? "0.3*t; (cos(a*t) - 1)*(y - 0.5) - sin(a*t)*(z - 0.5);"
                         " sin(a*t)*(y - 0.5) + (cos(a*t) - 1)*(z - 0.5)"
                       : "0.3*t; 1.0*t") +
           subsection("Newton",
                      entry("Max iterations", "30") +
                        entry("Absolute residual tolerance", "1e-15") +
                        entry("Relative residual tolerance", "1e-14") +
                        entry("Update tolerance", "1e-13") +
                        entry("Inexact Newton", "false") +
                        // No projected fallback: every iteration exact.
                        entry("Tangent", "exact")) +
           subsection("Linear solver", entry("Type", "direct")) +
           subsection("Output",
                      entry("Directory", "quadratic_convergence_output") +
                        entry("Write VTU", "false") +
                        entry("Verbose", "false"));
  }

  template <int dim>
  void
  check(Checker &checker, const bool print)
  {
    for (const std::string &model : nonlinear_models())
      for (const unsigned int degree : {1u, 2u})
        {
          Parameters parameters;
          parameters.read_from_string(scene(dim, model, degree));
          Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
          problem.run();
          const std::string tag = std::to_string(dim) + "D " + model + " P" +
                                  std::to_string(degree) + " ";
          unsigned int      pairs = 0;
          double            worst = 0.;
          for (const auto &s : problem.summaries())
            {
              std::vector<double> r;
              for (const auto &row : s.newton_history)
                r.push_back(row.residual);
              if (print)
                {
                  std::cout << tag << "load step " << s.step << ":\n"
                            << "   k      residual  r_k r_1/r_(k-1)^2   order\n";
                  for (unsigned int k = 0; k < r.size(); ++k)
                    {
                      std::cout << std::setw(4) << k + 1 << std::scientific
                                << std::setprecision(3) << std::setw(14) << r[k];
                      if (k > 0)
                        std::cout << std::setw(16) << r[k] * r[0] / (r[k - 1] * r[k - 1]);
                      if (k > 1)
                        std::cout << std::fixed << std::setprecision(2) << std::setw(8)
                                  << std::log(r[k] / r[k - 1]) / std::log(r[k - 1] / r[k - 2]);
                      std::cout << std::defaultfloat << '\n';
                    }
                }
              // Pairs (r_k, r_k+1) near the solution (r_k below 1e-3 r_1)
              // and clear of round-off (r_k+1 above 10 times the smallest
              // residual of the step, where Newton stopped).
              const double floor = 10. * *std::min_element(r.begin(), r.end());
              for (unsigned int k = 0; k + 1 < r.size(); ++k)
                if (r[k] < 1e-3 * r[0] && r[k + 1] > floor)
                  {
                    ++pairs;
                    worst = std::max(worst, r[k + 1] * r[0] / (r[k] * r[k]));
                  }
            }
          checker.at_least(tag + "residual pairs in the asymptotic range", pairs, 1);
          checker.at_most(tag + "max r_k+1 r_1 / r_k^2", worst, ratio_bound);
        }
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_checks_for_dimension(argc, argv, check<2>, check<3>);
}
