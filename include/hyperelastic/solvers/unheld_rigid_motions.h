// The rigid motions of the bodies no Dirichlet condition holds, in a
// quasi-static scene where contact holds them (a body squeezed between two
// plates). Where a support resists a rigid motion (a plate normal to it,
// friction) the tangent is regular along it; where none does (a frictionless
// plate along its plane, a rotation about its normal) the tangent is
// singular along it and the equilibrium is unique only up to that motion.
// Newton then solves with the tangent made regular by a small multiple of
// the identity on the body's unknowns, beta = 1e-8 of the mean diagonal:
// the residual is unchanged, so the converged state is exactly an
// equilibrium (no spring stays in the answer). From each update it removes
// the unresisted motions: the eigenvectors of the tangent restricted to the
// body's rigid motions (taken at the current positions, orthonormal) whose
// eigenvalues are below 1e-6 of the mean diagonal in magnitude and along
// which the residual is below a tenth of Newton's residual target or
// round-off. The body
// thus keeps the position it started from along the motions nothing
// resists; a net force along such a motion (a contact surface slightly
// tilted) still moves it, by Newton's step, until the force balances.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/solvers/rigid_body_modes.h>

#include <array>
#include <set>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class UnheldRigidMotions
  {
  public:
    /// The bodies of the mesh without a boundary face among
    /// @p dirichlet_ids and the owned nodes of each. Collective.
    UnheldRigidMotions(const dealii::Mapping<dim>                 &mapping,
                       const dealii::DoFHandler<dim>              &dof_handler,
                       const std::set<dealii::types::boundary_id> &dirichlet_ids);

    /// Whether the mesh has no unheld body (the same on every rank).
    bool
    empty() const
    {
      return bodies.empty();
    }

    /// Adds beta to the diagonal of @p tangent on each unheld body's
    /// displacement unknowns (and remembers beta and the tangent's scale).
    /// Collective.
    void
    regularize(MatrixType &tangent);

    /// Removes from @p update (the solution of tangent update = @p rhs)
    /// the rigid motions of the unheld bodies that the (regularized)
    /// @p tangent does not resist and along which @p rhs has a force
    /// below a tenth of Newton's @p residual_target or 1e-10 of
    /// @p force_scale (the size of the forces), the rigid motions taken
    /// at the positions X + @p u (owned entries suffice). Returns how many
    /// motions it removed over all bodies. Collective.
    unsigned int
    remove_unresisted(const VectorType &u,
                      const MatrixType &tangent,
                      const VectorType &rhs,
                      double            residual_target,
                      double            force_scale,
                      VectorType       &update) const;

  private:
    static constexpr unsigned int n_modes = n_rigid_body_modes<dim>;

    /// A node of an unheld body whose unknowns this rank owns.
    struct Node
    {
      dealii::Point<dim>                               X;
      std::array<dealii::types::global_dof_index, dim> dofs;
    };

    struct UnheldBody
    {
      std::vector<Node> nodes;
      /// The regularization added, and the mean diagonal of the tangent
      /// on the body's unknowns (the scale of "not resisted").
      double beta  = 0.;
      double scale = 0.;
    };

    /// The body's rigid motions at the positions X + u, orthonormal.
    std::vector<VectorType>
    motions(const UnheldBody &body, const VectorType &u) const;

    MPI_Comm                comm;
    dealii::IndexSet        owned;
    std::vector<UnheldBody> bodies;
  };
} // namespace hyperelastic
