// The rigid motions of the bodies no Dirichlet condition holds, in a
// quasi-static scene where contact holds them (a body squeezed between two
// plates). Where a support resists a rigid motion (a plate normal to it,
// friction) the tangent is regular along it; where none does (a frictionless
// plate along its plane, a rotation about its normal) the tangent is
// singular along it and the equilibrium is unique only up to that motion.
// Newton then solves with the tangent made regular by a small multiple of
// the identity on the body's unknowns, beta = 1e-8 of the mean diagonal
// (no spring stays in the answer: the residual is the true one).
//
// The unresisted motions are pinned: the body keeps the position it
// started from along them. At each linearization they are found among the
// eigenvectors of the tangent restricted to the body's rigid motions (taken
// at the current positions, orthonormal): those whose eigenvalue is below
// 1e-2 of the largest one (or below 1e-6 of the mean diagonal; negative
// ones too: a motion along which the energy curves down is not held either)
// and along which the net force is below 1e-4 of the forces' size (with
// friction: below 1e-6 of the mean diagonal and 1e-10 of the forces). A
// support that only nearly resists (a block on a deformed, slightly tilted
// face: restricted eigenvalues 1e-4 of the resisted ones, a net force 1e-7
// of the forces) would otherwise let the body creep along a valley with no
// equilibrium near; the linearized rotations of a stressed body, and the
// barrier's forces between nearly aligned features, even make the
// restricted tangent indefinite there. Newton's update is the minimizer of
// its quadratic model among the updates without a component along the
// pinned motions (the tangent's couplings between those motions and the
// deformation accounted for, by one extra solve per pinned motion), so the
// energy line search sees a consistent direction; the residual is measured
// without its components along them (their force is the pin's reaction,
// like a Dirichlet condition's: zero where the supports are flat).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/constraints/system_constraint.h>
#include <hyperelastic/solvers/rigid_body_modes.h>

#include <array>
#include <functional>
#include <set>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class UnheldRigidMotions : public SystemConstraint
  {
  public:
    /// The bodies of the mesh without a boundary face among
    /// @p dirichlet_ids and the owned nodes of each. With @p frictional
    /// contact, only the motions the tangent does not resist at all
    /// (eigenvalue below 1e-6 of the mean diagonal, a force along them
    /// below 1e-10 of the forces' size) are pinned: friction's stiffness
    /// along the contact surfaces, however small against the normal one,
    /// is a support. Collective.
    UnheldRigidMotions(
      const dealii::Mapping<dim>                 &mapping,
      const dealii::DoFHandler<dim>              &dof_handler,
      const std::set<dealii::types::boundary_id> &dirichlet_ids,
      bool                                        frictional = false);

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
    regularize(MatrixType &tangent) override;

    /// Finds the unresisted rigid motions of each unheld body at the
    /// positions X + @p u from the (regularized) @p tangent, with the force
    /// @p rhs along them below 1e-4 of @p force_scale (the size of the
    /// forces), and keeps them as the pinned ones. Returns their number
    /// over all bodies. Collective.
    unsigned int
    pin_unresisted(const VectorType &u,
                   const MatrixType &tangent,
                   const VectorType &rhs,
                   double            force_scale);

    /// Turns @p update, the solution of tangent update = rhs, into the
    /// solution among the updates without a component along the pinned
    /// motions (at X + @p u): update - Z (V^T Z)^{-1} V^T update with
    /// Z = tangent^{-1} V, each column by @p solve (x = tangent^{-1} b).
    /// Collective.
    void
    constrain_update(
      const VectorType                                            &u,
      const std::function<void(const VectorType &, VectorType &)> &solve,
      VectorType &update) const override;

    // SystemConstraint: the unresisted motions pinned before a solve, and
    // removed from a residual, right-hand side or direction.
    void
    prepare_solve(const VectorType &u,
                  const MatrixType &tangent,
                  const VectorType &rhs,
                  double            force_scale) override
    {
      pin_unresisted(u, tangent, rhs, force_scale);
    }
    void
    project_out(const VectorType &u, VectorType &v) const override
    {
      project_out_pinned(u, v);
    }

    /// Removes from @p v its components along the pinned motions at
    /// X + @p u (owned entries suffice) and returns the norm of what it
    /// removed. Collective.
    double
    project_out_pinned(const VectorType &u, VectorType &v) const;

    /// How many motions are pinned over all bodies (the same on every
    /// rank).
    unsigned int
    n_pinned() const;

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
      /// The pinned motions, as coefficients of the orthonormal rigid
      /// motions of motions().
      std::vector<std::array<double, n_rigid_body_modes<dim>>> pinned;
    };

    /// Where the supports lie along the axes (each of the pinned span's
    /// dimensions holds one of the orthonormal rigid motions @p r, the
    /// translations along x, y, z and the rotations about them, to 0.99 of
    /// its norm squared), pins those pure motions instead of the
    /// eigenvectors: the tangent's couplings (a lateral force that grows
    /// with the pressing) mix the eigenvectors slightly with the resisted
    /// motions, so that the pins' reactions would have a small component
    /// along them (a plate's force not quite equal to the clamp's).
    void
    snap_to_axes(UnheldBody                    &body,
                 const std::vector<VectorType> &r,
                 const VectorType              &rhs,
                 double                         force_scale) const;

    /// The pinned motions of all bodies at X + u, orthonormal.
    std::vector<VectorType>
    pinned_motions(const VectorType &u) const;

    /// The body's rigid motions at the positions X + u, orthonormal.
    std::vector<VectorType>
    motions(const UnheldBody &body, const VectorType &u) const;

    bool                    frictional;
    MPI_Comm                comm;
    dealii::IndexSet        owned;
    std::vector<UnheldBody> bodies;
  };
} // namespace hyperelastic
