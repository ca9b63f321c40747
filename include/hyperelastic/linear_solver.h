// Linear solves with Trilinos: CG preconditioned by ML smoothed-aggregation
// AMG (with the rigid-body modes as near-null space), or a direct Amesos
// solver. Failures become ConvergenceFailure on every rank.
#pragma once

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hyperelastic/parameters.h>

#include <memory>
#include <vector>

namespace hyperelastic
{
  class LinearSolver
  {
  public:
    explicit LinearSolver(const LinearSolverParameters &parameters);

    /// The near-null space for AMG (column-major on the owned rows), and the
    /// number of unknowns per node ("PDE equations" for ML).
    void
    set_near_null_space(std::vector<double> modes,
                        unsigned int        n_modes,
                        unsigned int        n_components);

    /// Builds the preconditioner for @p A (the AMG hierarchy; nothing for a
    /// direct solver, which factorizes in solve()). Call before solve().
    void
    prepare(const dealii::TrilinosWrappers::SparseMatrix &A);

    /// Solves A x = b to the relative tolerance of the parameters. Returns the
    /// number of Krylov iterations (0 for a direct solve).
    unsigned int
    solve(const dealii::TrilinosWrappers::SparseMatrix &A,
          dealii::TrilinosWrappers::MPI::Vector        &x,
          const dealii::TrilinosWrappers::MPI::Vector  &b);

  private:
    const LinearSolverParameters              parameters;
    std::vector<double>                       null_space;
    unsigned int                              n_modes      = 0;
    unsigned int                              n_components = 1;
    dealii::TrilinosWrappers::PreconditionAMG amg;
  };
} // namespace hyperelastic
