// The core interface of an energy term: one contribution to the total
// potential (or, for a term without one, to the nodal forces) besides the
// material's stored energy. Dead loads, follower pressures, point loads,
// inertia, stiffness damping and contact barriers are all terms;
// ElasticityOperator sums them with the material part. Newton learns from
// the terms' kinds whether a total potential exists (energy line search) and
// whether the tangent is symmetric (CG or GMRES).
//
// The core has five methods: a name, a kind, the value, the gradient (as
// forces) and the Hessian (as a stiffness, with the projection mode as an
// argument). A term that also has step state, an admissible set or
// couplings beyond the mesh's implements the opt-in interfaces of
// assembly/term_capabilities.h; the core knows nothing of them.
//
// A new kind of load is one class deriving from EnergyTerm (or DeadTerm)
// plus one line in create_load_terms() (loads/load_terms.cc).
#pragma once

#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/base/tangent_projection_mode.h>

#include <string>

namespace hyperelastic
{
  /// What Newton's convergence test must know of a term's nodal forces
  /// beyond their sum (EnergyTerm::add_forces): a term whose forces cancel
  /// others in the sum (inertia against gravity in free fall) gives their
  /// size, for the relative residual test, and the round-off they carry
  /// (inertia: c M (u - w) from u and w far larger than their difference),
  /// for the noise floor. Both are l2 norms; 0: nothing to add.
  struct ForceSize
  {
    double magnitude = 0.;
    double round_off = 0.;
  };

  /// How a term's forces depend on the displacement.
  enum class TermKind
  {
    /// Independent of u: evaluated once per load factor; its potential is
    /// minus its work, -g(t) . u, and its stiffness is zero.
    dead,
    /// Depends on u and derives from a potential V (dV/du = -g): its
    /// stiffness is symmetric.
    conservative,
    /// Depends on u without a potential (a follower load on a free
    /// boundary): no total energy, a non-symmetric tangent.
    non_conservative
  };

  template <int dim>
  class EnergyTerm
  {
  public:
    virtual ~EnergyTerm() = default;

    /// The scene section that defines the term, for messages and the
    /// header's list of terms.
    virtual std::string
    name() const = 0;

    /// How the forces depend on u (TermKind).
    virtual TermKind
    kind() const = 0;

    /// The potential V(u, t), with dV/du = -g: only called for a
    /// conservative term. +infinity where the state is not admissible
    /// (contact: a vertex through an obstacle). Collective.
    virtual double
    energy(const VectorType &u, double t) const = 0;

    /// Adds the nodal forces g(u, t) to @p forces (owned rows; entries
    /// added to other ranks' rows are sent by the caller's compress()). @p u
    /// has ghost entries. Throws InputError on every rank, naming the entry,
    /// if the load is not finite somewhere. Returns the forces' size and
    /// round-off where they matter (ForceSize; most terms: none). Collective.
    virtual ForceSize
    add_forces(const VectorType &u, double t, VectorType &forces) const = 0;

    /// Adds the stiffness -dg/du to @p matrix, condensed with the Dirichlet
    /// @p constraints (constrained rows untouched, constrained columns moved
    /// to @p rhs with their prescribed values); the caller compresses both.
    /// @p projection is Newton's choice for the tangent: a term whose exact
    /// stiffness may be indefinite (self-contact pairs) projects it to
    /// positive semi-definite for TangentProjection::every_point; the others
    /// add their stiffness as it is. Not called for a dead term. Collective.
    virtual void
    add_stiffness(const VectorType                        &u,
                  double                                   t,
                  TangentProjection                        projection,
                  const dealii::AffineConstraints<double> &constraints,
                  MatrixType                              &matrix,
                  VectorType                              &rhs) const = 0;
  };

  /// The base of the terms independent of u (TermKind::dead): their
  /// potential is -g(t) . u, which the operator forms from their forces,
  /// and they have no stiffness; only name() and add_forces() are theirs.
  template <int dim>
  class DeadTerm : public EnergyTerm<dim>
  {
  public:
    TermKind
    kind() const final
    {
      return TermKind::dead;
    }

    /// Not called: the operator forms -g(t) . u.
    double
    energy(const VectorType &, double) const final
    {
      return 0.;
    }

    /// Not called: a dead term has no stiffness.
    void
    add_stiffness(const VectorType &,
                  double,
                  TangentProjection,
                  const dealii::AffineConstraints<double> &,
                  MatrixType &,
                  VectorType &) const final
    {}
  };
} // namespace hyperelastic
