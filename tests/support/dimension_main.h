// The main() of a test program whose first argument is the dimension: MPI
// set up, the checks of that dimension run with one Checker, exceptions
// turned into messages on every rank, and the exit status.
#pragma once

#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/material_registry.h>

#include "checker.h"

#include <cstdlib>
#include <string>
#include <vector>

namespace hyperelastic::testing
{
  /// The registered finite-strain models (!is_linear: all but linear
  /// elasticity, the one model that is not rotation invariant), in
  /// registration order.
  inline std::vector<std::string>
  nonlinear_models()
  {
    std::vector<std::string> names;
    for (const MaterialModel &model : material_models())
      if (!model.is_linear)
        names.push_back(model.name);
    return names;
  }

  /// Every registered model, in registration order.
  inline std::vector<std::string>
  all_models()
  {
    std::vector<std::string> names;
    for (const MaterialModel &model : material_models())
      names.push_back(model.name);
    return names;
  }

  /// MPI set up, DIM read from argument @p dim_position (default 3; 2 or 3,
  /// else an input error), @p run(dim, checker, print) with one Checker
  /// (print: on rank 0), exceptions turned into messages on every rank;
  /// returns the exit status.
  template <typename Run>
  int
  run_for_dimension(int argc, char **argv, const int dim_position, Run &&run)
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const bool print = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const int  dim   = argc > dim_position ? std::atoi(argv[dim_position]) : 3;
    Checker    checker(print);
    const int  status = run_and_report(
      [&]() {
        if (dim != 2 && dim != 3)
          throw InputError(std::string("the ") +
                           (dim_position == 1 ? "first" : "second") +
                           " argument must be the dimension, 2 or 3");
        run(dim, checker, print);
      },
      MPI_COMM_WORLD);
    return checker.exit_code(status);
  }

  /// Runs @p check_2d or @p check_3d (each called as (checker, print)) by
  /// the first argument; DIM defaults to 3.
  template <typename Check2D, typename Check3D>
  int
  run_checks_for_dimension(int argc, char **argv, Check2D &&check_2d, Check3D &&check_3d)
  {
    return run_for_dimension(argc, argv, 1, [&](const int dim, Checker &checker, const bool print) {
      if (dim == 2)
        check_2d(checker, print);
      else
        check_3d(checker, print);
    });
  }

  /// For test programs called as 'PROGRAM CASE DIM': runs
  /// @p run_2d(case, checker) or @p run_3d(case, checker) by DIM (default
  /// 3); CASE defaults to @p default_case.
  template <typename Run2D, typename Run3D>
  int
  run_case_for_dimension(int                argc,
                         char             **argv,
                         const std::string &default_case,
                         Run2D            &&run_2d,
                         Run3D            &&run_3d)
  {
    const std::string which = argc > 1 ? argv[1] : default_case;
    return run_for_dimension(argc, argv, 2, [&](const int dim, Checker &checker, bool) {
      if (dim == 2)
        run_2d(which, checker);
      else
        run_3d(which, checker);
    });
  }
} // namespace hyperelastic::testing
