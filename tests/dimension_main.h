// The main() of a test program whose first argument is the dimension: MPI
// set up, the checks of that dimension run with one Checker, exceptions
// turned into messages on every rank, and the exit status.
#pragma once

#include <deal.II/base/mpi.h>

#include <hyperelastic/error_handling.h>

#include "checker.h"

#include <cstdlib>
#include <functional>

namespace hyperelastic::testing
{
  /// @p checks(dim, checker, print) runs the checks; DIM defaults to 3.
  inline int
  run_checks_for_dimension(int                                             argc,
                           char                                          **argv,
                           const std::function<void(int, Checker &, bool)> &checks)
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const bool print = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const int  dim   = argc > 1 ? std::atoi(argv[1]) : 3;
    Checker    checker(print);
    const int  status = run_and_report(
      [&]() {
        if (dim != 2 && dim != 3)
          throw InputError("the first argument must be the dimension, 2 or 3");
        checks(dim, checker, print);
      },
      MPI_COMM_WORLD);
    return checker.exit_code(status);
  }
} // namespace hyperelastic::testing
