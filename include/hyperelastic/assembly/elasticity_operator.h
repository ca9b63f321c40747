// The discrete problem as Newton sees it: the material part (an Assembler:
// the P1 kernel or the generic FEValues loops) plus the load terms. For a
// displacement u it gives the internal forces f_int(u), the load forces
// g(u, t) (terms independent of u evaluated once per load factor), the
// tangent d(f_int - g)/du and the total potential energy when every term
// has a potential.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/assembly/assembler.h>
#include <hyperelastic/assembly/energy_term.h>
#include <hyperelastic/assembly/term_capabilities.h>
#include <hyperelastic/base/tangent_projection_mode.h>
#include <hyperelastic/loads/boundary_conditions.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class ElasticityOperator
  {
  public:
    /// With @p fast_p1 (and a P1 element) the material part comes from the
    /// P1 kernel; otherwise, and for P2, from the generic FEValues loops.
    /// The load terms are made from @p boundary_conditions
    /// (create_load_terms()), which must outlive the operator.
    /// A non-null @p material_part (the mixed formulation's, stiffness
    /// warping's) replaces both.
    ElasticityOperator(const dealii::DoFHandler<dim>  &dof_handler,
                       const dealii::Mapping<dim>     &mapping,
                       const MaterialRegions<dim>     &material,
                       const BoundaryConditions<dim>  &boundary_conditions,
                       bool                            fast_p1       = true,
                       std::unique_ptr<Assembler<dim>> material_part = nullptr);
    ~ElasticityOperator();

    /// Whether the P1 kernel is in use.
    bool
    uses_p1_kernel() const
    {
      return p1 != nullptr;
    }

    /// A model with history (viscoelasticity): the next step (each attempt
    /// of it) lasts the physical time @p dt from the last accepted state.
    void
    begin_material_step(const double dt)
    {
      generic->begin_step(dt);
      if (p1)
        p1->begin_step(dt);
    }

    /// A model with history: the step ended at @p u (ghosted).
    void
    accept_material_step(const VectorType &u)
    {
      generic->accept_step(u);
      if (p1)
        p1->accept_step(u);
    }

    /// A model with history: the quadrature points' state (a checkpoint).
    std::vector<double>
    material_history() const
    {
      std::vector<double> state;
      generic->save_history(state);
      if (p1)
        p1->save_history(state);
      return state;
    }

    /// Restores what material_history() gave.
    void
    restore_material_history(const std::vector<double> &state)
    {
      std::size_t position = 0;
      generic->load_history(state, position);
      if (p1)
        p1->load_history(state, position);
    }

    /// The stored energy of each region (Assembler::region_energies()).
    std::vector<double>
    region_energies(const VectorType &u) const
    {
      return p1 ? p1->region_energies(u) : generic->region_energies(u);
    }

    /// Whether the material part and every load term have a potential: then
    /// the total potential energy exists, Newton's line search can use it,
    /// and the tangent is symmetric.
    bool
    is_conservative() const;

    /// Adds a term made elsewhere (the inertia of a time step, contact);
    /// the caller may keep a pointer to it to update its state. The term's
    /// opt-in capabilities (assembly/term_capabilities.h) are found here.
    void
    add_term(std::unique_ptr<EnergyTerm<dim>> term);

    /// The energy terms, in the order they were added (the scene's
    /// sections, then the time step's and contact's).
    const std::vector<std::unique_ptr<EnergyTerm<dim>>> &
    energy_terms() const
    {
      return terms;
    }

    /// Internal forces f_int(u) and load forces g(u, t), unconstrained (both
    /// compressed, owned entries only). u must have ghost entries. Returns
    /// an estimate of the round-off level of the l2 norm of f_int - g
    /// (round_off: residuals below it cannot be resolved) and the largest
    /// size of a load term's forces that cancel others in g (magnitude:
    /// inertia in a free fall; 0 without such a term).
    ForceSize
    assemble_forces(const VectorType &u,
                    const double      t,
                    VectorType       &internal,
                    VectorType       &external) const;

    /// Tangent K = d(f_int - g)/du and right-hand side -(f_int - g),
    /// condensed with @p constraints (whose inhomogeneities are imposed).
    /// With @p project_tangent, dP/dF at every quadrature point is projected
    /// to positive semi-definite first (projected Newton); load stiffnesses
    /// are added as they are.
    void
    assemble_system(
      const VectorType                        &u,
      const double                             t,
      const dealii::AffineConstraints<double> &constraints,
      MatrixType                              &matrix,
      VectorType                              &rhs,
      TangentProjection project_tangent = TangentProjection::none) const;

    /// Total potential energy (stored energy plus the potentials of the
    /// load terms; for a term without one, nothing is added) if
    /// @p with_energy, and the smallest J at the quadrature points
    /// (collective). +infinity where the model is undefined.
    EnergyEvaluation
    evaluate(const VectorType &u, const double t, bool with_energy) const;

    /// The smallest of the admissible-set terms' largest feasible steps
    /// from @p u along @p direction (1 if none limits it). Collective.
    double
    largest_feasible_step(const VectorType &u,
                          const VectorType &direction,
                          const double      t) const
    {
      double alpha = 1.;
      for (const AdmissibleSetTerm<dim> *term : admissible_sets)
        alpha = std::min(alpha, term->largest_feasible_step(u, direction, t));
      return alpha;
    }

    /// Whether a coupling term needs couplings the tangent's sparsity lacks
    /// (CouplingTerm::needs_new_couplings; every such term is asked).
    /// Collective.
    bool
    needs_new_couplings(const VectorType &u, const double t)
    {
      bool any = false;
      for (CouplingTerm<dim> *term : coupling_terms)
        any = term->needs_new_couplings(u, t) || any;
      return any;
    }

    /// Whether a term has a stiffness far above the elastic one on some
    /// dofs (StiffTerm).
    bool
    has_stiff_terms() const
    {
      return !stiff_terms.empty();
    }

    /// d f_int / dc_k of the material part for each constant of the model,
    /// where the material part has them (ConstantForces: the generic FEValues
    /// one of the displacement formulation, P1 or P2, and the mixed one)
    /// and no other term depends on the constants (none is stiff: contact's
    /// automatic barrier stiffness follows the moduli); empty otherwise.
    /// Collective.
    std::vector<VectorType>
    constant_forces(const VectorType &u, const VectorType &like) const;

    /// The owned dofs that the stiff terms' last stiffness wrote, in a set
    /// of @p n_dofs (StiffTerm::add_stiff_dofs over every such term).
    dealii::IndexSet
    stiff_dofs(const dealii::types::global_dof_index n_dofs) const
    {
      dealii::IndexSet dofs(n_dofs);
      for (const StiffTerm<dim> *term : stiff_terms)
        term->add_stiff_dofs(dofs);
      dofs.compress();
      return dofs;
    }

    /// Adds the coupling terms' couplings to @p pattern.
    void
    add_couplings(dealii::DynamicSparsityPattern &pattern) const
    {
      for (const CouplingTerm<dim> *term : coupling_terms)
        term->add_couplings(pattern);
    }

    /// The stepped terms' hooks (SteppedTerm::begin_step,
    /// extrapolate_lagged, set_end_state_map, project_trial,
    /// update_lagged), each over
    /// all such terms.
    /// Collective.
    void
    begin_step(const VectorType &u, const double t_start)
    {
      for (SteppedTerm<dim> *term : stepped_terms)
        term->begin_step(u, t_start);
    }
    void
    extrapolate_lagged(const VectorType &u_before, const double t_before)
    {
      for (SteppedTerm<dim> *term : stepped_terms)
        term->extrapolate_lagged(u_before, t_before);
    }
    void
    set_end_state_map(const double c, const double weight)
    {
      for (SteppedTerm<dim> *term : stepped_terms)
        term->set_end_state_map(c, weight);
    }
    void
    project_trial(const VectorType                        &u,
                  VectorType                              &trial,
                  const double                             t,
                  const dealii::AffineConstraints<double> &constraints) const
    {
      for (const SteppedTerm<dim> *term : stepped_terms)
        term->project_trial(u, trial, t, constraints);
    }
    LaggedUpdate
    update_lagged(const VectorType &u,
                  const double      t,
                  const LagMoment   moment,
                  const double      unbalanced_force)
    {
      LaggedUpdate outcome = LaggedUpdate::unchanged;
      for (SteppedTerm<dim> *term : stepped_terms)
        outcome = combine(outcome,
                          term->update_lagged(u, t, moment, unbalanced_force));
      return outcome;
    }

    /// The forces of the terms held at the end of the step (those that
    /// scale with set_end_state_map's weight: contact) at @p u (ghosted)
    /// and @p t, at weight 1 and the map c = 1 (compressed, owned entries);
    /// the map is left at (1, 1). Collective.
    void
    end_state_forces(const VectorType &u, double t, VectorType &forces);

    /// The moving admissible sets' hooks (MovingAdmissibleSetTerm::
    /// prepare_motion, advance), each over all such terms. Collective.
    bool
    prepare_motion(const double t)
    {
      bool any = false;
      for (MovingAdmissibleSetTerm<dim> *term : moving_sets)
        any = term->prepare_motion(t) || any;
      return any;
    }
    void
    advance(const double alpha, const double t)
    {
      for (MovingAdmissibleSetTerm<dim> *term : moving_sets)
        term->advance(alpha, t);
    }

    /// Total potential energy alone (collective).
    double
    total_energy(const VectorType &u, const double t) const
    {
      return evaluate(u, t, true).energy;
    }

  private:
    /// Growing models (materials/grown.h) evaluate at the load factor @p t
    /// (Assembler::set_load_factor; nothing for the other models).
    void
    follow_load_factor(const double t) const
    {
      generic->set_load_factor(t);
      if (p1)
        p1->set_load_factor(t);
    }

    /// The summed forces of the terms independent of u at load factor t,
    /// owned entries; computed once per load factor (collective).
    const VectorType &
    dead_forces(double t) const;

    /// external = g(u, t) of all terms (compressed); the terms' ForceSize
    /// (the largest magnitude, the summed round-off).
    ForceSize
    load_forces(const VectorType &u, double t, VectorType &external) const;

    const dealii::DoFHandler<dim> &dof_handler;
    /// Whether a material part was given (then there is no P1 kernel).
    const bool                                    replaced;
    std::unique_ptr<Assembler<dim>>               generic;
    std::unique_ptr<Assembler<dim>>               p1;
    std::vector<std::unique_ptr<EnergyTerm<dim>>> terms;
    bool                                          has_dead_terms = false;
    bool                                          has_live_terms = false;
    /// The terms with each opt-in capability, in the order of terms.
    std::vector<SteppedTerm<dim> *>             stepped_terms;
    std::vector<AdmissibleSetTerm<dim> *>       admissible_sets;
    std::vector<MovingAdmissibleSetTerm<dim> *> moving_sets;
    std::vector<CouplingTerm<dim> *>            coupling_terms;
    std::vector<const StiffTerm<dim> *>         stiff_terms;

    mutable VectorType dead_cache;
    mutable double dead_cache_time = std::numeric_limits<double>::quiet_NaN();
    /// Scratch for the load forces in assemble_system().
    mutable VectorType scratch;
  };
} // namespace hyperelastic
