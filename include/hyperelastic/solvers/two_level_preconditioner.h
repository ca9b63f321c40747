// A two-level preconditioner for P2 displacement tangents: Chebyshev
// smoothing (Jacobi-preconditioned) on the P2 matrix A and ML smoothed-
// aggregation AMG on the Galerkin P1 operator P^T A P, where P interpolates
// the P1 field of the same mesh into P2 (vertex values, edge midpoints the
// average of their two vertices). One symmetric V-cycle: pre-smooth, coarse
// correction, post-smooth, so CG can use it.
//
// The linear solver's preconditioner for P2 with CG + AMG ('Linear solver/
// P2 preconditioner = two-level', the default): measured against ML on the
// P2 matrix directly (hyperelastic_benchmark --p2-preconditioner,
// benchmarks/setup), it needs a fifth of the set-up time and about half
// the iterations.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hyperelastic/solvers/tangent_preconditioner.h>

#include <vector>

namespace hyperelastic
{
  template <int dim>
  class TwoLevelPreconditioner : public TangentPreconditioner
  {
  public:
    using Matrix = MatrixType;
    using Vector = VectorType;

    /// @p fine: the P2 vector field (FE_SimplexP(2)^dim); the P1 field,
    /// its rigid-body modes and P are built here. @p smoother_degree: the
    /// Chebyshev degree of each smoothing.
    TwoLevelPreconditioner(const dealii::DoFHandler<dim> &fine,
                           unsigned int                   smoother_degree);

    /// Builds the coarse operator P^T A P, its AMG hierarchy and the
    /// smoother for @p A (which must outlive the use of this object).
    void
    initialize(const Matrix &A) override;

    /// x = B^-1 b: one V-cycle from x = 0.
    void
    vmult(Vector &x, const Vector &b) const override;

    std::string
    description() const override;

    /// Unknowns of the coarse (P1) level.
    dealii::types::global_dof_index
    n_coarse_dofs() const
    {
      return coarse.n_dofs();
    }

    /// The interpolation P1 -> P2 (rows: P2 unknowns).
    const Matrix &
    prolongation() const
    {
      return P;
    }

  private:
    /// Jacobi: x = D^-1 b (deal.II's DiagonalMatrix cannot be sized for
    /// a distributed Trilinos vector inside the Chebyshev set-up).
    struct InverseDiagonal
    {
      Vector values;
      void
      vmult(Vector &x, const Vector &b) const
      {
        x = b;
        x.scale(values);
      }
    };
    using Smoother =
      dealii::PreconditionChebyshev<Matrix, Vector, InverseDiagonal>;

    dealii::DoFHandler<dim>           coarse;
    const unsigned int                smoother_degree;
    Matrix                            P;
    Matrix                            coarse_matrix;
    std::vector<double>               coarse_modes;
    dealii::TrilinosWrappers::PreconditionAMG amg;
    Smoother                          smoother;
    const Matrix                     *A = nullptr;
    mutable Vector                    residual, correction;
    mutable Vector                    coarse_residual, coarse_correction;
  };
} // namespace hyperelastic
