// The block preconditioner of the mixed formulation's saddle-point tangent
//   [ A  B^T ] [du]   [r_u]
//   [ B  -C  ] [dp] = [r_p]
// (A: displacement block, B: pressure coupling, C >= 0: pressure block):
// block lower-triangular,
//   P^-1 r = ( y_u = AMG(A) r_u ,  y_p = S^-1 (B y_u - r_p) ),
// with one ML V-cycle on A (rigid-body modes as near-null space) and the
// diagonal S = (1/mu) M_p + diag(C), M_p the lumped pressure mass: (1/mu) M_p
// is spectrally equivalent to B A^-1 B^T uniformly in kappa/mu (for
// Stokes-like problems) and diag(C) carries the compressibility U*''(p) M,
// the stabilisation and MINI's condensed bubble, so GMRES iterations do not
// grow with kappa.
// The unknowns are not renumbered: the blocks are the rows of each kind.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_CrsMatrix.h>
#include <memory>
#include <vector>

namespace hyperelastic
{
  class SaddlePointPreconditioner
  {
  public:
    /// @p owned: this rank's rows; @p pressure: the pressure unknowns among
    /// (at least) the locally relevant ones; @p shear_schur: (1/mu) (M_p)_ii
    /// (lumped) for the owned pressure rows, in increasing index order.
    SaddlePointPreconditioner(const dealii::IndexSet &owned,
                              const dealii::IndexSet &pressure,
                              std::vector<double>     shear_schur,
                              MPI_Comm                comm);

    /// Copies the displacement block A of @p matrix (for AMG), takes C_ii
    /// from its pressure block and keeps a reference to @p matrix (B y_u).
    void
    extract_displacement_block(
      const dealii::TrilinosWrappers::SparseMatrix &matrix);

    const Epetra_CrsMatrix &
    displacement_block() const
    {
      return *block;
    }

    /// The rows of the displacement unknowns of @p modes (column-major over
    /// the owned rows, @p n_modes columns).
    std::vector<double>
    displacement_rows(const std::vector<double> &modes,
                      unsigned int               n_modes) const;

    /// Uses @p amg (built on displacement_block()) from now on.
    void
    set_amg(const dealii::TrilinosWrappers::PreconditionAMG &amg)
    {
      this->amg = &amg;
    }

    void
    vmult(dealii::TrilinosWrappers::MPI::Vector       &dst,
          const dealii::TrilinosWrappers::MPI::Vector &src) const;

  private:
    /// Local row indices of the displacement and pressure unknowns.
    std::vector<unsigned int>                        u_rows, p_rows;
    dealii::IndexSet                                 owned, pressure, owned_u;
    std::vector<double>                              shear_schur, schur_inverse;
    MPI_Comm                                         comm;
    std::unique_ptr<Epetra_CrsMatrix>                block;
    const dealii::TrilinosWrappers::SparseMatrix    *matrix = nullptr;
    const dealii::TrilinosWrappers::PreconditionAMG *amg    = nullptr;
    mutable dealii::TrilinosWrappers::MPI::Vector    r_u, y_u, full, product;
  };
} // namespace hyperelastic
