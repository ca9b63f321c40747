// Runs a scene given as text on the ranks of MPI_COMM_WORLD, without
// printing, and hands back the problem for its summaries and solution.
#pragma once

#include <hyperelastic/problem/problem.h>

#include <memory>
#include <string>

namespace hyperelastic::testing
{
  template <int dim>
  std::unique_ptr<Problem<dim>>
  run_scene(const std::string &text)
  {
    Parameters parameters;
    parameters.read_from_string(text);
    auto problem =
      std::make_unique<Problem<dim>>(parameters, MPI_COMM_WORLD, false);
    problem->run();
    return problem;
  }
} // namespace hyperelastic::testing
