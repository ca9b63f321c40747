// Path independence (stress-tests.md case 10): a hyperelastic body under
// dead loads has a final state that does not depend on how the load was
// applied. A clamped bar whose far end is pulled and pushed sideways, under
// gravity and a traction on its top face (y = 1 in 2D, z = 1 in 3D), is solved in one load step and in ten:
// displacements (every unknown), energy and reactions must agree to 1e-8
// relative. The one-step run must really be one Newton solve from the
// reference state (no cut-back).
//
// Usage: mpirun -np N path_independence DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_text.h"

#include <cmath>
#include <iostream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  std::string
  scene(const int dim, const std::string &model, const unsigned int steps)
  {
    const bool three = dim == 3;
    return small_bar(dim, 1) +
           material_section(model,
                            entry("Young's modulus", "1") +
                              entry("Poisson's ratio", "0.3"),
                            LameParameters::from_young_poisson(1., 0.3)) +
           subsection("Loading",
                      entry("Number of load steps", std::to_string(steps)) +
                        entry("Body force",
                              three ? "0; 0; -0.02*t" : "0; -0.02*t")) +
           dirichlet(1,
                     0,
                     three ? "x, y, z" : "x, y",
                     three ? "0; 0; 0" : "0; 0") +
           dirichlet(2,
                     1,
                     three ? "x, y, z" : "x, y",
                     three ? "0.3*t; 0.2*t; 0.1*t" : "0.3*t; 0.2*t") +
           subsection("Traction 1",
                      entry("Boundary id", three ? "5" : "3") +
                        entry("Traction",
                              three ? "0.01*t; 0; 0" : "0.01*t; 0")) +
           tight_solver("cg") +
           subsection("Output",
                      entry("Directory", "path_independence_output") +
                        entry("Write VTU", "false") +
                        entry("Verbose", "false"));
  }

  struct State
  {
    VectorType             u;
    std::vector<double>    reactions;
    double                 energy = 0.;
    unsigned int           steps = 0, cut_backs = 0;
  };

  template <int dim>
  State
  solve(const std::string &model, const unsigned int steps)
  {
    Parameters parameters;
    parameters.read_from_string(scene(dim, model, steps));
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.run();
    State state;
    state.u      = problem.solution();
    state.energy = problem.summaries().back().energy;
    state.steps  = problem.summaries().size();
    for (const auto &s : problem.summaries())
      state.cut_backs += s.cut_backs;
    for (const auto &[id, force] : problem.summaries().back().reactions)
      for (unsigned int d = 0; d < dim; ++d)
        state.reactions.push_back(force[d]);
    return state;
  }

  template <int dim>
  void
  check(Checker &checker, bool)
  {
    for (const std::string &model : nonlinear_models())
      {
        const State       one = solve<dim>(model, 1), ten = solve<dim>(model, 10);
        const std::string tag = std::to_string(dim) + "D " + model + ": ";
        checker.is_true(tag + "one load step, no cut-back",
                        one.steps == 1 && one.cut_backs == 0);
        VectorType difference = one.u;
        difference -= ten.u;
        checker.at_most(tag + "max |u_1 - u_10| / max |u_10|",
                        difference.linfty_norm() / ten.u.linfty_norm(),
                        1e-8);
        checker.at_most(tag + "energy, relative",
                        std::abs(one.energy - ten.energy) / std::abs(ten.energy),
                        1e-8);
        double largest = 0., worst = 0.;
        for (unsigned int i = 0; i < ten.reactions.size(); ++i)
          {
            largest = std::max(largest, std::abs(ten.reactions[i]));
            worst   = std::max(worst, std::abs(one.reactions[i] - ten.reactions[i]));
          }
        checker.at_most(tag + "reactions, relative to the largest", worst / largest, 1e-8);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_checks_for_dimension(argc, argv, check<2>, check<3>);
}
