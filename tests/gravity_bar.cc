// Body force against an exact solution: a linear-elastic bar with nu = 0 on
// a roller at x = 0, loaded along its axis by a uniform body force b per unit
// reference volume, has P11 = b (L - x) and u_x = b / E (L x - x^2 / 2), a
// quadratic field that P2 elements reproduce exactly. Checked to 1e-8: the
// tip displacement b L^2 / (2 E), the roller reaction -b L A and the total
// potential energy -b^2 L^3 A / (6 E).
//
// Usage: mpirun -np N gravity_bar DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_text.h"

#include <cmath>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  constexpr double L = 3., E = 2., b = 0.1, area = 1.;

  template <int dim>
  void
  run(Checker &checker)
  {
    const bool        three = dim == 3;
    const std::string text =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Finite element degree", "2")) +
      subsection("Mesh",
                 entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                   entry("Upper corner", three ? "3, 1, 1" : "3, 1") +
                   entry("Subdivisions", three ? "3, 1, 1" : "3, 1")) +
      subsection("Material",
                 entry("Model", "linear elastic") +
                   entry("Young's modulus", "2") +
                   entry("Poisson's ratio", "0")) +
      subsection("Loading",
                 entry("Number of load steps", "1") +
                   entry("Body force", three ? "0.1*t; 0; 0" : "0.1*t; 0")) +
      dirichlet(1, 0, "x", "0") + dirichlet(2, 2, "y", "0") +
      (three ? dirichlet(3, 4, "z", "0") : std::string()) + tight_solver("cg") +
      subsection("Output",
                 entry("Directory", "gravity_bar_output") +
                   entry("Base name", "gravity_" + std::to_string(dim) + "d") +
                   entry("Write VTU", "false") + entry("Verbose", "false"));
    Parameters parameters;
    parameters.read_from_string(text);
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.run();
    const StepSummary<dim> &s = problem.summaries().back();

    struct Check
    {
      std::string name;
      double      computed, exact;
    };
    const std::vector<Check> checks = {
      {"tip displacement", s.deformed_max[0] - L, b * L * L / (2. * E)},
      {"roller reaction x", s.reactions[0].second[0], -b * L * area},
      {"total potential energy",
       s.energy,
       -b * b * L * L * L * area / (6. * E)}};
    for (const auto &c : checks)
      checker.close(std::to_string(dim) + "D " + c.name,
                    c.computed,
                    c.exact,
                    std::abs(c.exact),
                    1e-8);
  }
} // namespace

int
main(int argc, char *argv[])
{
  return run_checks_for_dimension(
    argc,
    argv,
    [](Checker &checker, bool) { run<2>(checker); },
    [](Checker &checker, bool) { run<3>(checker); });
}
