// The material part plus the load terms.
#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/assembly/generic_assembler.h>
#include <hyperelastic/assembly/p1_assembler.h>
#include <hyperelastic/loads/load_terms.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  ElasticityOperator<dim>::ElasticityOperator(
    const DoFHandler<dim>          &dof_handler,
    const Mapping<dim>             &mapping,
    const MaterialRegions<dim>     &material,
    const BoundaryConditions<dim>  &boundary_conditions,
    const bool                      fast_p1,
    std::unique_ptr<Assembler<dim>> material_part)
      : dof_handler(dof_handler)
      , replaced(material_part != nullptr)
      , generic(material_part
                  ? std::move(material_part)
                  : std::make_unique<GenericAssembler<dim>>(dof_handler,
                                                            mapping,
                                                            material))
  {
    for (auto &term :
         create_load_terms(boundary_conditions, dof_handler, mapping))
      add_term(std::move(term));
    if (!replaced && fast_p1 && dof_handler.get_fe().degree == 1 &&
        dof_handler.get_fe().n_components() == dim)
      {
        auto kernel = std::make_unique<P1Assembler<dim>>(dof_handler, material);
        if (kernel->usable())
          p1 = std::move(kernel);
      }
  }

  template <int dim>
  std::vector<VectorType>
  ElasticityOperator<dim>::constant_forces(const VectorType &u,
                                           const VectorType &like) const
  {
    const auto *material_part =
      dynamic_cast<const ConstantForces<dim> *>(generic.get());
    if (!material_part || has_stiff_terms())
      return {};
    return material_part->constant_forces(u, like);
  }

  template <int dim>
  ElasticityOperator<dim>::~ElasticityOperator() = default;

  template <int dim>
  void
  ElasticityOperator<dim>::add_term(std::unique_ptr<EnergyTerm<dim>> term)
  {
    (term->kind() == TermKind::dead ? has_dead_terms : has_live_terms) = true;
    EnergyTerm<dim> *added = term.get();
    if (auto *stepped = dynamic_cast<SteppedTerm<dim> *>(added))
      stepped_terms.push_back(stepped);
    if (auto *admissible = dynamic_cast<AdmissibleSetTerm<dim> *>(added))
      admissible_sets.push_back(admissible);
    if (auto *moving = dynamic_cast<MovingAdmissibleSetTerm<dim> *>(added))
      moving_sets.push_back(moving);
    if (auto *coupling = dynamic_cast<CouplingTerm<dim> *>(added))
      coupling_terms.push_back(coupling);
    if (auto *stiff = dynamic_cast<StiffTerm<dim> *>(added))
      stiff_terms.push_back(stiff);
    terms.push_back(std::move(term));
  }

  template <int dim>
  bool
  ElasticityOperator<dim>::is_conservative() const
  {
    if (!generic->is_conservative())
      return false;
    for (const auto &term : terms)
      if (term->kind() == TermKind::non_conservative)
        return false;
    return true;
  }

  template <int dim>
  const VectorType &
  ElasticityOperator<dim>::dead_forces(const double t) const
  {
    if (t == dead_cache_time)
      return dead_cache;
    dead_cache.reinit(dof_handler.locally_owned_dofs(),
                      dof_handler.get_communicator());
    for (const auto &term : terms)
      if (term->kind() == TermKind::dead)
        term->add_forces(dead_cache, t, dead_cache);
    dead_cache.compress(VectorOperation::add);
    dead_cache_time = t;
    return dead_cache;
  }

  template <int dim>
  ForceSize
  ElasticityOperator<dim>::load_forces(const VectorType &u,
                                       const double      t,
                                       VectorType       &external) const
  {
    if (has_dead_terms)
      external = dead_forces(t);
    else
      external = 0.;
    ForceSize size;
    if (!has_live_terms)
      return size;
    for (const auto &term : terms)
      if (term->kind() != TermKind::dead)
        {
          const ForceSize s = term->add_forces(u, t, external);
          size.magnitude    = std::max(size.magnitude, s.magnitude);
          size.round_off += s.round_off;
        }
    external.compress(VectorOperation::add);
    return size;
  }

  template <int dim>
  ForceSize
  ElasticityOperator<dim>::assemble_forces(const VectorType &u,
                                           const double      t,
                                           VectorType       &internal,
                                           VectorType       &external) const
  {
    follow_load_factor(t);
    const double noise = (p1 ? *p1 : *generic).internal_forces(u, internal);
    ForceSize    size  = load_forces(u, t, external);
    size.round_off += noise;
    return size;
  }

  template <int dim>
  void
  ElasticityOperator<dim>::end_state_forces(const VectorType &u,
                                            const double      t,
                                            VectorType       &forces)
  {
    // The difference between the load forces with and without those terms.
    VectorType without(forces);
    set_end_state_map(1., 0.);
    load_forces(u, t, without);
    set_end_state_map(1., 1.);
    load_forces(u, t, forces);
    forces -= without;
  }

  template <int dim>
  void
  ElasticityOperator<dim>::assemble_system(
    const VectorType                &u,
    const double                     t,
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      &rhs,
    const TangentProjection          project_tangent) const
  {
    follow_load_factor(t);
    // The kernel declines (on all ranks) constraints other than Dirichlet
    // and matrices without its node-block sparsity.
    if (!(p1 && p1->system(u, constraints, project_tangent, matrix, rhs)))
      generic->system(u, constraints, project_tangent, matrix, rhs);
    if (terms.empty())
      return;
    // The load forces act on the free rows only; a constrained row already
    // reads d du_r = d g_r.
    scratch.reinit(dof_handler.locally_owned_dofs(),
                   dof_handler.get_communicator());
    load_forces(u, t, scratch);
    constraints.set_zero(scratch);
    rhs += scratch;
    if (!has_live_terms)
      return;
    for (const auto &term : terms)
      if (term->kind() != TermKind::dead)
        term->add_stiffness(u, t, project_tangent, constraints, matrix, rhs);
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
  }

  template <int dim>
  EnergyEvaluation
  ElasticityOperator<dim>::evaluate(const VectorType &u,
                                    const double      t,
                                    const bool        with_energy) const
  {
    follow_load_factor(t);
    EnergyEvaluation result =
      (p1 ? *p1 : *generic).stored_energy(u, with_energy);
    if (!with_energy || terms.empty())
      return result;
    // The potentials of the loads, with their round-off (of the size of
    // the terms, as for the stored energy).
    constexpr double round_off = 1e-13;
    const MPI_Comm   comm      = dof_handler.get_communicator();
    if (has_dead_terms)
      {
        // Forces independent of u: the potential is minus their work.
        const double work =
          Utilities::MPI::sum(local_owned_dot(u, dead_forces(t)), comm);
        result.energy -= work;
        result.noise += round_off * std::abs(work);
      }
    for (const auto &term : terms)
      if (term->kind() == TermKind::conservative)
        {
          const double potential = term->energy(u, t);
          result.energy += potential;
          result.noise += round_off * std::abs(potential);
        }
    return result;
  }

  template class ElasticityOperator<2>;
  template class ElasticityOperator<3>;
} // namespace hyperelastic
