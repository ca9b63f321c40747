// What only some energy terms have, as opt-in interfaces a term implements
// besides EnergyTerm (assembly/energy_term.h) when it has the capability:
// - SteppedTerm: state over a step (contact: the step's start positions, the
//   end-state map of implicit midpoint and Newmark, lagged friction);
// - AdmissibleSetTerm: a set the iterates must stay in (contact: no vertex
//   through an obstacle or through the boundary), with its largest feasible
//   step; MovingAdmissibleSetTerm: such a set that moves with t (obstacles
//   moving within a step) and is carried along by Newton's iterations;
// - CouplingTerm: couplings between dofs that the mesh's cells do not make
//   (self-contact pairs between distant parts of the boundary);
// - StiffTerm: a stiffness far above the elastic one on a few dofs (the
//   barrier between touching surfaces), which the linear solver's
//   preconditioner solves on exactly.
// ElasticityOperator::add_term finds them and calls each over the terms that
// have it.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hyperelastic/base/lagged_update.h>
#include <hyperelastic/base/linear_algebra.h>

namespace hyperelastic
{
  /// A term with state over a load or time step.
  template <int dim>
  class SteppedTerm
  {
  public:
    virtual ~SteppedTerm() = default;

    /// A step begins from the converged state @p u (owned entries are read)
    /// at @p t_start. Collective.
    virtual void
    begin_step(const VectorType &u, double t_start) = 0;

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
    set_end_state_map(double c, double weight) = 0;

    /// At the iterate @p u (ghosted), converged, within the solve or the
    /// step's predicted start (@p moment), where the residual on the free
    /// unknowns has the l2 norm @p unbalanced_force (0 at a prediction):
    /// updates the quantities the term lags behind the iterate (friction's
    /// normal forces and tangents); returns whether they changed enough
    /// that Newton must go on with them (updated) or too little to matter
    /// or not yet (see FrictionLagging). Collective.
    virtual LaggedUpdate
    update_lagged(const VectorType &u,
                  double            t,
                  LagMoment         moment,
                  double            unbalanced_force) = 0;

    /// After begin_step(), when the converged state before it is known:
    /// @p u_before (owned entries are read) at @p t_before < t_start. A
    /// term may start its lagged quantities at their value extrapolated
    /// from the two states to the step's end (friction's normal forces
    /// growing under a ramped load), so that the step needs fewer
    /// updates. Collective; nothing by default.
    virtual void
    extrapolate_lagged(const VectorType & /*u_before*/, double /*t_before*/)
    {}

    /// A trial point @p trial of Newton's line search from the iterate
    /// @p u (owned entries). A term whose potential has a kink that the
    /// step jumps over may move the trial back onto the kink (lagged
    /// friction: a sliding vertex whose slip the step reverses stops where
    /// the slip along its old direction is zero), so that the line search
    /// follows a projected path instead of shortening every vertex's step
    /// for one vertex's sake; dofs that @p constraints constrain are left
    /// alone. Collective; nothing by default.
    virtual void
    project_trial(
      const VectorType & /*u*/,
      VectorType & /*trial*/,
      double /*t*/,
      const dealii::AffineConstraints<double> & /*constraints*/) const
    {}
  };

  /// A term whose forces hold the iterates in an admissible set.
  template <int dim>
  class AdmissibleSetTerm
  {
  public:
    virtual ~AdmissibleSetTerm() = default;

    /// The largest step length alpha in (0, 1] for which u + alpha
    /// @p direction stays admissible (contact: no vertex reaches an
    /// obstacle); 1 if nothing limits it. @p u and @p direction: owned
    /// entries are read. Collective.
    virtual double
    largest_feasible_step(const VectorType &u,
                          const VectorType &direction,
                          double            t) const = 0;
  };

  /// An admissible set that moves with t (obstacles on their way): it does
  /// not jump to its place at t when a step begins; Newton's iterations
  /// carry it there as far as their feasible steps allow.
  template <int dim>
  class MovingAdmissibleSetTerm : public AdmissibleSetTerm<dim>
  {
  public:
    /// Prepares the iteration at load factor @p t: a set whose motion to
    /// its place at @p t is nothing (standing obstacles) is put there at
    /// once; returns whether it is still on its way. The linearization then
    /// carries the rest of the motion, the iteration is a predictor (no
    /// energy test) and largest_feasible_step() bounds the joint motion.
    /// Collective.
    virtual bool
    prepare_motion(double t) = 0;

    /// The last direction was taken with step length @p alpha: the set
    /// advances by that fraction of its remaining way to its place at @p t.
    virtual void
    advance(double alpha, double t) = 0;
  };

  /// A term whose stiffness couples dofs that the mesh's cells do not.
  template <int dim>
  class CouplingTerm
  {
  public:
    virtual ~CouplingTerm() = default;

    /// Whether the tangent needs couplings that its sparsity, last built
    /// with add_couplings(), lacks at @p u (ghosted). Collective.
    virtual bool
    needs_new_couplings(const VectorType &u, double t) = 0;

    /// Adds the couplings the term's stiffness writes (its owned rows) to
    /// @p pattern, with a margin so that a few iterates more fit in.
    virtual void
    add_couplings(dealii::DynamicSparsityPattern &pattern) const = 0;
  };

  /// A term whose stiffness on a few dofs is far above the elastic one.
  template <int dim>
  class StiffTerm
  {
  public:
    virtual ~StiffTerm() = default;

    /// Adds to @p dofs the owned dofs whose rows the last add_stiffness()
    /// wrote (contact: the vertices of the pairs within the barrier's
    /// reach and of friction's sliding pairs).
    virtual void
    add_stiff_dofs(dealii::IndexSet &dofs) const = 0;
  };
} // namespace hyperelastic
