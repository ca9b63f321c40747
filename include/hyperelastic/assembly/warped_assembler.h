// Stiffness warping (Müller, Dorsey, McMillan, Jordan and Cutler 2002), the
// material part of 'Material/Model = stiffness warping': the linear elastic
// stiffness K, assembled once at rest, warped at every state by one rotation
// per vertex,
//   A_i = sum over the edges (i, j) of (x_j - x_i)(X_j - X_i)^T,
//   R_i = the rotation of the polar decomposition of A_i (proper, det = +1),
//   f_i = R_i sum_j K_ij (R_i^T (x_j - x_i) - (X_j - X_i)),
// which equals Müller's R_i sum_j K_ij (R_i^T x_j - X_j) because the rows of
// K sum to zero (K annihilates translations) and is free of the round-off of
// absolute positions. Tangent: the warped stiffness R_i K_ij R_i^T (dR/dx
// ignored, as in Müller's semi-implicit step), not symmetric. The forces
// have no potential: Newton's line search uses the residual merit. The
// "energy" this part reports (output, total energy in the CSV) and the smallest
// J come from the element-rotation corotational model with the same
// constants, which the program also uses for the cell stresses.
//
// P1 displacement only (one rotation per vertex). Rows are assembled where
// they are owned, from the rank's ghost layer (every edge of an owned vertex
// lies on an owned or ghost cell): no communication but the ghosted u.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/assembly/assembler.h>
#include <hyperelastic/assembly/generic_assembler.h>

#include <array>
#include <memory>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class WarpedAssembler : public Assembler<dim>
  {
  public:
    /// @p material: the model of each cell (corotational, whose
    /// small-strain moduli give the rest stiffness K, each region its own);
    /// the models must outlive the assembler.
    WarpedAssembler(const dealii::DoFHandler<dim> &dof_handler,
                    const dealii::Mapping<dim>    &mapping,
                    const MaterialRegions<dim>    &material);
    ~WarpedAssembler() override;

    double
    internal_forces(const VectorType &u, VectorType &internal) const override;

    /// Handles Dirichlet constraints (a constrained row reads
    /// K_rr du_r = K_rr g_r); @p project_tangent has no meaning here and is
    /// ignored. Always true.
    bool
    system(const VectorType                        &u,
           const dealii::AffineConstraints<double> &constraints,
           TangentProjection                        project_tangent,
           MatrixType                              &matrix,
           VectorType                              &rhs) const override;

    /// The corotational energy (see the top of this file) and smallest J.
    EnergyEvaluation
    stored_energy(const VectorType &u, bool with_energy) const override;

    /// The corotational energy of each region's cells (as stored_energy()).
    std::vector<double>
    region_energies(const VectorType &u) const override
    {
      return corotational.region_energies(u);
    }

    /// The warped forces are not the gradient of an energy.
    bool
    is_conservative() const override
    {
      return false;
    }

    /// The rotation R_i of every owned vertex at @p u (ghosted), in the
    /// order of the owned vertices; for tests.
    std::vector<Tensor<2, dim>>
    vertex_rotations(const VectorType &u) const;

  private:
    /// A vertex of the rank's owned or ghost cells.
    struct Vertex
    {
      dealii::Point<dim>                               X;
      std::array<dealii::types::global_dof_index, dim> dofs;
    };
    /// An owned vertex's row: its neighbours (itself included) with the
    /// blocks K_ij, in CSR form over owned_vertices.
    struct Rows
    {
      std::vector<unsigned int>   owned_vertices; ///< into vertices
      std::vector<unsigned int>   start;          ///< size n_owned + 1
      std::vector<unsigned int>   neighbour;      ///< into vertices
      std::vector<Tensor<2, dim>> block;          ///< K_ij
      std::vector<unsigned int>   diagonal;       ///< position of K_ii
    };

    /// R_i of owned vertex r (the rotation of A_i; the identity where A_i
    /// vanishes), and the relative positions x_j - x_i of its neighbours.
    Tensor<2, dim>
    rotation(unsigned int                 r,
             const VectorType            &u,
             std::vector<Tensor<1, dim>> &dx) const;

    /// f_i of owned vertex r with rotation @p R and relative positions
    /// @p dx (from rotation()); @p magnitude: sum |K_ij| |dx_j|, the size of
    /// its terms (round-off estimate).
    Tensor<1, dim>
    force(unsigned int                       r,
          const Tensor<2, dim>              &R,
          const std::vector<Tensor<1, dim>> &dx,
          double                            &magnitude) const;

    const dealii::DoFHandler<dim> &dof_handler;
    GenericAssembler<dim>          corotational;
    std::vector<Vertex>            vertices;
    Rows                           rows;
  };
} // namespace hyperelastic
