// The main() of a test program whose first argument is the dimension: MPI
// set up, the checks of that dimension run with one Checker, exceptions
// turned into messages on every rank, and the exit status.
#pragma once

#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>

#include "checker.h"

#include <cstdlib>
#include <string>
#include <vector>

namespace hyperelastic::testing
{
  /// The models whose energy is rotation invariant (all but linear
  /// elasticity).
  inline const std::vector<std::string> &
  nonlinear_models()
  {
    static const std::vector<std::string> names = {"St. Venant-Kirchhoff",
                                                   "corotational",
                                                   "neo-Hookean",
                                                   "stable neo-Hookean",
                                                   "decoupled neo-Hookean"};
    return names;
  }

  /// Runs @p check_2d or @p check_3d (each called as (checker, print)) by
  /// the first argument; DIM defaults to 3.
  template <typename Check2D, typename Check3D>
  int
  run_checks_for_dimension(int argc, char **argv, Check2D &&check_2d, Check3D &&check_3d)
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const bool print = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const int  dim   = argc > 1 ? std::atoi(argv[1]) : 3;
    Checker    checker(print);
    const int  status = run_and_report(
      [&]() {
        if (dim != 2 && dim != 3)
          throw InputError("the first argument must be the dimension, 2 or 3");
        if (dim == 2)
          check_2d(checker, print);
        else
          check_3d(checker, print);
      },
      MPI_COMM_WORLD);
    return checker.exit_code(status);
  }
} // namespace hyperelastic::testing
