// Fast assembly for linear simplices (P1), the hot loop of every P1 scene.
//
// For P1 the deformation gradient is constant per cell: with the gradients
// g_a of the hat functions (the rows of Dm^-1, computed once from the
// reference vertices) F = I + sum_a u_a (x) g_a, the internal force of node a
// is |T| P(F) g_a and the element tangent is
//   K_ab[i][k] = |T| sum_JL dP_iJ/dF_kL g_a[J] g_b[L].
// No FEValues, no quadrature loop, no local-to-global index translation in
// the loop: the gradients, volumes and vector indices are computed once, and
// the positions of each node pair's 3x3 (2x2) block in the rows of the
// Trilinos matrix are found once per matrix.
//
// Each rank computes every cell that touches one of its rows (its own and
// its ghost cells) and writes only its own rows ("owner computes"): no
// values cross ranks during assembly. Dirichlet constraints are eliminated
// on the fly (constrained rows get only a diagonal, constrained columns move
// to the right-hand side), as AffineConstraints would.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>

#include <hyperelastic/assembly/assembler.h>
#include <hyperelastic/assembly/point_materials.h>

#include <array>
#include <vector>

class Epetra_CrsMatrix;

namespace hyperelastic
{
  template <int dim>
  class P1Assembler : public Assembler<dim>
  {
  public:
    static constexpr unsigned int n_nodes = dim + 1;

    /// Precomputes the geometry of the locally owned and ghost cells. The
    /// element must be FE_SimplexP(1)^dim; check usable() afterwards.
    P1Assembler(const dealii::DoFHandler<dim> &dof_handler,
                const MaterialRegions<dim>    &material);

    /// False if the dof layout is not the one this assembler relies on (the
    /// dim dofs of a vertex numbered consecutively, contiguous ownership).
    /// The same on all ranks.
    bool
    usable() const
    {
      return layout_ok;
    }

    double
    internal_forces(const VectorType &u, VectorType &internal) const override;

    /// Declines (returns false on all ranks) constraints other than
    /// Dirichlet ones and a matrix without the node-block sparsity it needs
    /// (one built without constraints).
    bool
    system(const VectorType                        &u,
           const dealii::AffineConstraints<double> &constraints,
           TangentProjection                        project_tangent,
           MatrixType                              &matrix,
           VectorType                              &rhs) const override;

    EnergyEvaluation
    stored_energy(const VectorType &u, bool with_energy) const override;

    std::vector<double>
    region_energies(const VectorType &u) const override;

    /// Every cell this rank sees (its own and its ghosts) writes its
    /// state: both compute the same F.
    void
    accept_step(const VectorType &u) override;

  protected:
    const PointMaterials<dim> *
    point_materials() const override
    {
      return &materials;
    }

  private:
    struct Cell
    {
      /// Index in a ghosted vector's local array of each node's first dof.
      std::array<unsigned int, n_nodes> node;
      /// Index among the owned rows of each node's first dof; -1 if the node
      /// belongs to another rank.
      std::array<int, n_nodes> row;
      /// Gradients of the hat functions in the reference configuration.
      std::array<dealii::Tensor<1, dim>, n_nodes> grad;
      double                                      volume;
      /// Locally owned (counted in energies); writes_rows: has a node
      /// whose rows this rank owns (contributes to forces and tangent).
      bool         owned;
      bool         writes_rows;
      unsigned int active_index;
    };

    /// K[a][b][i][k]: the dim x dim block of nodes a and b.
    using ElementMatrix = double[n_nodes][n_nodes][dim][dim];

    /// The element tangent |T| g_a . dP/dF . g_b of every node pair.
    void
    element_matrix(const Cell               &cell,
                   const StressTangent<dim> &A,
                   ElementMatrix            &K) const;

    /// F = I + sum_a u_a (x) g_a.
    dealii::Tensor<2, dim>
    deformation_gradient(const Cell &cell, const double *u) const;

    /// The local array of a vector with the locally relevant dofs as ghosts.
    const double *
    ghosted_values(const VectorType &u) const;

    /// The prescribed value of every ghosted dof into prescribed_ghosted
    /// (NaN where free). False on every rank if some rank cannot write the
    /// rows itself (block positions not found, or constraints other than
    /// Dirichlet ones).
    bool
    gather_prescribed_values(
      const dealii::AffineConstraints<double> &constraints) const;

    /// Adds the rows of cell @p ci (stress @p P, element tangent @p K) to
    /// the matrix's CRS arrays (@p offsets, @p values) and to the right-hand
    /// side @p b: the columns of prescribed dofs (@p prescribed, NaN where
    /// free) go to the right-hand side; a prescribed row only sizes its
    /// diagonal (constrained_diagonal).
    void
    add_cell_rows(unsigned int                  ci,
                  const dealii::Tensor<2, dim> &P,
                  const ElementMatrix          &K,
                  const double                 *prescribed,
                  const int                    *offsets,
                  double                       *values,
                  double                       *b) const;

    /// Finds the positions of each cell's node blocks in @p matrix.
    bool
    find_block_positions(const MatrixType &matrix) const;

    /// Throws ConvergenceFailure on all ranks if @p error is set anywhere,
    /// naming the cell.
    void
    report(const std::string &error, unsigned int cell) const;

    const dealii::DoFHandler<dim> &dof_handler;
    const MaterialRegions<dim>     material;
    /// The model at each cell (one point per P1 cell).
    const PointMaterials<dim>       materials;
    dealii::IndexSet                relevant;
    std::vector<Cell>               cells;
    bool                            layout_ok   = false;
    dealii::types::global_dof_index first_owned = 0;
    unsigned int                    n_owned     = 0;
    unsigned int                    n_ghosted   = 0;
    /// Offset of the owned entries inside a ghosted vector's local array.
    unsigned int owned_offset_in_ghosted = 0;

    /// Per cell, the position of node b's columns in the rows of node a,
    /// relative to the start of the row (for rows this rank owns); valid
    /// for the matrix whose Epetra object is block_matrix.
    mutable std::vector<std::array<unsigned int, n_nodes * n_nodes>>
                                    block_position;
    mutable const Epetra_CrsMatrix *block_matrix = nullptr;
    mutable bool                    block_ok     = false;
    /// Position of the diagonal entry of each owned row.
    mutable std::vector<unsigned int> diagonal_position;
    /// Scratch: the prescribed value of each owned and ghosted dof (NaN if
    /// free), and the diagonal collected for constrained rows.
    mutable VectorType          prescribed_owned;
    mutable VectorType          prescribed_ghosted;
    mutable std::vector<double> constrained_diagonal;
  };
} // namespace hyperelastic
