// An exact solve on a few unknowns whose couplings are far stiffer than the
// rest of the tangent (touching surfaces held apart by a barrier), around
// the preconditioner M of the whole tangent A. With S = R^T A_SS^-1 R, the
// restriction R to the stiff unknowns S, one application is
//   z = S r;  z += M (r - A z);  z += S (r - A z),
// so that I - B A = (I - S A)(I - M A)(I - S A). I - S A is the A-orthogonal
// projector off the subspace, and B A = (I - P) + P M A P in A's inner
// product: B is symmetric positive definite whenever M is, and CG can use it.
// Smoothed aggregation built from the rigid-body modes of the elastic
// operator cannot represent a stiffness of 1e4 or more times the elastic
// one between a few unknowns: the exact solve takes those modes off it.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/base/linear_algebra.h>

#include <functional>

namespace hyperelastic
{
  class StiffSubspaceCorrection
  {
  public:
    /// Extracts A_SS from @p A for the owned unknowns @p stiff (each rank
    /// its own), gathers it on every rank and factorizes it with UMFPACK.
    /// Collective; an empty subspace on every rank leaves the correction
    /// inactive.
    void
    initialize(const MatrixType &A, const dealii::IndexSet &stiff);

    /// Whether initialize() found a subspace to solve on.
    bool
    active() const
    {
      return n_global > 0;
    }

    /// The size of the subspace over all ranks.
    dealii::types::global_dof_index
    size() const
    {
      return n_global;
    }

    /// z = B r as above, with @p M the preconditioner of the whole
    /// tangent (z = M r). Collective.
    void
    vmult(VectorType                                                  &z,
          const VectorType                                            &r,
          const std::function<void(VectorType &, const VectorType &)> &M) const;

  private:
    /// x += R^T A_SS^-1 R b.
    void
    add_correction(VectorType &x, const VectorType &b) const;

    const MatrixType               *matrix = nullptr;
    dealii::IndexSet                stiff;
    dealii::types::global_dof_index n_global = 0;
    /// How many stiff unknowns each rank owns, and where its own begin in
    /// the block's numbering (ranks in order).
    std::vector<int> counts, offsets;
    /// A_SS on every rank (it is small), and its factorization: a solve
    /// gathers the right-hand side instead of sending the block around.
    dealii::SparsityPattern        pattern;
    dealii::SparseMatrix<double>   block;
    dealii::SparseDirectUMFPACK    factorization;
    mutable dealii::Vector<double> block_vector;
    /// Work vectors of vmult().
    mutable VectorType residual, product;
  };
} // namespace hyperelastic
