// The interface of a load term: one contribution g(u, t) to the nodal forces
// acting on the body, with its load stiffness -dg/du if it depends on u and
// its potential if it has one. ElasticityOperator sums the material part and
// the terms; Newton learns from it whether a total potential exists (energy
// line search) and whether the tangent is symmetric (CG or GMRES).
//
// A new kind of load is one class deriving from LoadTerm plus one line in
// create_load_terms() (loads/load_terms.cc).
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/linear_algebra.h>

#include <string>

namespace hyperelastic
{
  /// What Newton's convergence test must know of a term's nodal forces
  /// beyond their sum (LoadTerm::add_forces): a term whose forces cancel
  /// others in the sum (inertia against gravity in free fall) gives their
  /// size, for the relative residual test, and the round-off they carry
  /// (inertia: c M (u - w) from u and w far larger than their difference),
  /// for the noise floor. Both are l2 norms; 0: nothing to add.
  struct ForceSize
  {
    double magnitude = 0.;
    double round_off = 0.;
  };

  template <int dim>
  class LoadTerm
  {
  public:
    virtual ~LoadTerm() = default;

    /// The scene section that defines the term, for messages.
    virtual std::string
    name() const = 0;

    /// Whether the forces depend on the displacement (follower loads). Terms
    /// that do not are evaluated once per load factor, and their potential
    /// is minus their work, -g(t) . u.
    virtual bool
    depends_on_solution() const = 0;

    /// Whether the forces derive from a potential (always true for a term
    /// independent of u). A tangent of a conservative term is symmetric.
    virtual bool
    is_conservative() const
    {
      return !depends_on_solution();
    }

    /// Adds the nodal forces g(u, t) to @p forces (owned rows; entries
    /// added to other ranks' rows are sent by the caller's compress()). @p u
    /// has ghost entries. Throws InputError on every rank, naming the entry,
    /// if the load is not finite somewhere. Returns the forces' size and
    /// round-off where they matter (ForceSize; most terms: none). Collective.
    virtual ForceSize
    add_forces(const VectorType &u, double t, VectorType &forces) const = 0;

    /// Adds the load stiffness -dg/du to @p matrix, condensed with the
    /// Dirichlet @p constraints (constrained rows untouched, constrained
    /// columns moved to @p rhs with their prescribed values); the caller
    /// compresses both. Only called if depends_on_solution(). Collective.
    virtual void
    add_load_stiffness(const VectorType                        &u,
                       double                                   t,
                       const dealii::AffineConstraints<double> &constraints,
                       MatrixType                              &matrix,
                       VectorType                              &rhs) const
    {
      (void)u, (void)t, (void)constraints, (void)matrix, (void)rhs;
    }

    /// Whether the next add_load_stiffness() is to give a positive
    /// semi-definite stiffness (Newton's projected tangent, after the exact
    /// one gave no descent direction) or the exact one. Terms whose exact
    /// stiffness may be indefinite (self-contact pairs) follow it; the
    /// others ignore it.
    virtual void
    request_positive_semidefinite(bool positive_semidefinite)
    {
      (void)positive_semidefinite;
    }

    /// The potential V(u, t), with dV/du = -g: only called if
    /// depends_on_solution() and is_conservative(). Collective.
    virtual double
    potential(const VectorType &u, double t) const
    {
      (void)u, (void)t;
      return 0.;
    }

    /// The largest step length alpha in (0, 1] for which u + alpha
    /// @p direction stays admissible for this term (contact: no vertex
    /// reaches an obstacle); 1 if the term sets no limit. @p u and
    /// @p direction: owned entries are read. Collective.
    virtual double
    largest_feasible_step(const VectorType &u,
                          const VectorType &direction,
                          double            t) const
    {
      (void)u, (void)direction, (void)t;
      return 1.;
    }

    /// Whether the tangent needs couplings between dofs that the mesh's
    /// cells do not make (self-contact: distant parts of the boundary come
    /// close) and that its sparsity, last built with add_couplings(), lacks
    /// at @p u (ghosted). Collective.
    virtual bool
    needs_new_couplings(const VectorType &u, double t)
    {
      (void)u, (void)t;
      return false;
    }

    /// Adds the couplings the term's load stiffness writes (its owned rows)
    /// to @p pattern, with a margin so that a few iterates more fit in.
    virtual void
    add_couplings(dealii::DynamicSparsityPattern &pattern) const
    {
      (void)pattern;
    }

    // Step state. Terms whose admissible set moves with t (contact: the
    // obstacles' motion) or that lag quantities behind the iterate (contact:
    // friction's normal forces and tangents) keep it through these hooks;
    // the others ignore them.

    /// A step begins from the converged state @p u (owned entries are read)
    /// at @p t_start. Collective.
    virtual void
    begin_step(const VectorType &u, double t_start)
    {
      (void)u, (void)t_start;
    }

    /// The step's solved state u relates to its end state as u_end = u_n +
    /// @p c (u - u_n), at time t_end = t_n + c (t - t_n) (implicit
    /// midpoint: c = 2; 1 otherwise), from the u_n and t_n of begin_step().
    /// A term that must hold at the end of the step (contact: no vertex
    /// through an obstacle at the end state) evaluates itself there, with
    /// the potential @p weight V(u_end) / c (whose gradient in u is
    /// @p weight V'(u_end)). The weight is the scheme's: Newmark gives the
    /// contact force the whole step's impulse (weight 2, see
    /// dynamics/time_integrator.h), the others 1.
    virtual void
    set_end_state_map(double c, double weight)
    {
      (void)c, (void)weight;
    }

    /// Whether the term's admissible set has not reached its place at @p t
    /// yet (an obstacle on its way within the step). The linearization then
    /// carries the rest of the motion, the iteration is a predictor (no
    /// energy test) and largest_feasible_step() bounds the joint motion.
    /// Collective.
    virtual bool
    moving(double t)
    {
      (void)t;
      return false;
    }

    /// The last direction was taken with step length @p alpha: a moving
    /// admissible set advances by that fraction of its remaining way to t.
    virtual void
    advance(double alpha, double t)
    {
      (void)alpha, (void)t;
    }

    /// At a converged state @p u (ghosted): updates the lagged quantities;
    /// returns whether they changed enough that the step must be solved
    /// again. Collective.
    virtual bool
    update_lagged(const VectorType &u, double t)
    {
      (void)u, (void)t;
      return false;
    }
  };

  /// Throws InputError on every rank if the load of scene entry @p entry was
  /// not finite on some rank (@p bad_here on this one).
  inline void
  throw_if_load_not_finite(const bool         bad_here,
                           const std::string &entry,
                           const MPI_Comm     comm)
  {
    if (dealii::Utilities::MPI::max(bad_here ? 1 : 0, comm) != 0)
      throw InputError(
        "scene entry '" + entry +
        "' is not a finite number somewhere on the mesh (a division by zero, "
        "the logarithm of a negative number or similar)");
  }
} // namespace hyperelastic
