// The two-level P2 -> P1 preconditioner (TwoLevelPreconditioner, the
// default for P2 with CG + AMG):
// - prolongation: P maps the P1 interpolant of a linear vector field to its
//   P2 interpolant (1e-13; P2 interpolates linear fields exactly), 2D and
//   3D;
// - solve: the P2 twist of the bar converges to the same state as with ML
//   on the P2 matrix ('Linear solver/P2 preconditioner = AMG'; displacement
//   1e-9 relative, energy 1e-11) with at most 0.8 times its CG iterations,
//   and the run header names the two-level preconditioner;
// on the ranks of MPI_COMM_WORLD (ctest: 1 and 2).
//
// Usage: mpirun -np N two_level_preconditioner prolongation|solve
#include <deal.II/base/function.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/numerics/vector_tools.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>
#include <hyperelastic/solvers/two_level_preconditioner.h>

#include "support/checker.h"
#include "support/scene_text.h"

#include <iostream>

using namespace dealii;
using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  /// u_c(x) = c + 1 + sum_d (c + 2 d + 1) / 7 x_d: linear in every
  /// component.
  template <int dim>
  class LinearField : public Function<dim>
  {
  public:
    LinearField()
        : Function<dim>(dim)
    {
    }
    double
    value(const Point<dim> &x, const unsigned int c) const override
    {
      double v = c + 1.;
      for (unsigned int d = 0; d < dim; ++d)
        v += (c + 2. * d + 1.) / 7. * x[d];
      return v;
    }
  };

  template <int dim>
  void
  prolongation(Checker &check)
  {
    const std::string scene =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Finite element degree", "2")) +
      subsection("Mesh",
                 entry("Lower corner", dim == 2 ? "0, 0" : "0, 0, 0") +
                   entry("Upper corner", dim == 2 ? "2, 1" : "2, 1, 1") +
                   entry("Subdivisions", dim == 2 ? "6, 3" : "4, 2, 2")) +
      subsection("Output", entry("Write VTU", "false")) +
      dirichlet(1, 0, dim == 2 ? "x, y" : "x, y, z", dim == 2 ? "0; 0" : "0; 0; 0");
    Parameters parameters;
    parameters.read_from_string(scene);
    parameters.output.directory = "two_level_output";
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.setup();
    const DoFHandler<dim> &fine = problem.get_dof_handler();
    TwoLevelPreconditioner<dim> two_level(fine, 2);

    // The same P1 numbering as the preconditioner's own.
    DoFHandler<dim> coarse(fine.get_triangulation());
    coarse.distribute_dofs(FESystem<dim>(FE_SimplexP<dim>(1), dim));
    check.is_true("P1 level: " + std::to_string(coarse.n_dofs()) +
                    " unknowns, as the preconditioner's",
                  coarse.n_dofs() == two_level.n_coarse_dofs());
    const MappingFE<dim> mapping(FE_SimplexP<dim>(1));
    const MPI_Comm       comm = fine.get_communicator();
    VectorType coarse_values(coarse.locally_owned_dofs(), comm);
    VectorType fine_values(fine.locally_owned_dofs(), comm);
    VectorTools::interpolate(mapping, coarse, LinearField<dim>(), coarse_values);
    VectorTools::interpolate(mapping, fine, LinearField<dim>(), fine_values);
    VectorType prolonged(fine_values);
    two_level.prolongation().vmult(prolonged, coarse_values);
    prolonged -= fine_values;
    check.at_most(std::to_string(dim) +
                    "D: P (P1 interpolant) - P2 interpolant of a linear "
                    "field, relative",
                  prolonged.linfty_norm() / fine_values.linfty_norm(),
                  1e-13);
  }

  struct Run
  {
    VectorType   u;
    double       energy = 0.;
    unsigned int krylov = 0;
    std::string  solver;
  };

  Run
  twist(const std::string &preconditioner)
  {
    const std::string scene =
      bar_3d(3) + twist_loading() +
      subsection("Problem", entry("Finite element degree", "2")) +
      subsection("Newton",
                 entry("Inexact Newton", "false") +
                   entry("Relative residual tolerance", "1e-12")) +
      subsection("Linear solver",
                 entry("Relative tolerance", "1e-11") +
                   entry("P2 preconditioner", preconditioner));
    Parameters parameters;
    parameters.read_from_string(scene);
    parameters.output.directory = "two_level_output";
    Problem<3> problem(parameters, MPI_COMM_WORLD, false);
    problem.run();
    Run r;
    r.u      = problem.solution();
    r.energy = problem.summaries().back().energy;
    for (const auto &s : problem.summaries())
      r.krylov += s.linear_iterations;
    r.solver = problem.linear_solver_description();
    return r;
  }

  void
  solve(Checker &check)
  {
    const Run two_level = twist("two-level");
    const Run ml        = twist("AMG");
    VectorType difference = two_level.u;
    difference -= ml.u;
    check.at_most("P2 twist, two-level vs ML on P2: displacement, relative",
                  difference.linfty_norm() / ml.u.linfty_norm(),
                  1e-9);
    check.at_most("P2 twist, two-level vs ML on P2: energy, relative",
                  std::abs(two_level.energy - ml.energy) / std::abs(ml.energy),
                  1e-11);
    check.at_most("P2 twist: CG iterations, two-level / ML on P2 (" +
                    std::to_string(two_level.krylov) + " / " +
                    std::to_string(ml.krylov) + ")",
                  double(two_level.krylov) / ml.krylov,
                  0.8);
    check.is_true("run header names the two-level preconditioner: " +
                    two_level.solver,
                  two_level.solver.find("two-level") != std::string::npos &&
                    ml.solver.find("two-level") == std::string::npos);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker check(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const std::string which  = argc > 1 ? argv[1] : "";
  const int         status = run_and_report(
    [&]() {
      if (which == "prolongation")
        {
          prolongation<2>(check);
          prolongation<3>(check);
        }
      else if (which == "solve")
        solve(check);
      else
        throw InputError("unknown case '" + which + "'");
    },
    MPI_COMM_WORLD);
  return check.exit_code(status);
}
