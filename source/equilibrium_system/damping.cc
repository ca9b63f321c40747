// The equilibrium system's damping of snap sub-steps (DampedSystem): an
// energy term of the operator on the lumped mass of unit density.
#include <hyperelastic/dynamics/inertia.h>
#include <hyperelastic/equilibrium_system/equilibrium_system.h>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  EquilibriumSystem<dim>::set_damping(const double c)
  {
    if (!damping)
      {
        // The lumped mass of unit density (HRZ: diagonal, so its product
        // with ones is its diagonal) on the free displacement unknowns.
        const InertiaTerm<dim> mass(parts.dof_handler, 1., true);
        VectorType             ones(owned_dofs, comm), metric(owned_dofs, comm);
        ones = 1.;
        VectorType ones_ghosted(owned_dofs, relevant_dofs, comm);
        ones_ghosted = ones;
        mass.mass_product(ones_ghosted, metric);
        homogeneous_constraints.set_zero(metric);
        auto term = std::make_unique<SnapDamping<dim>>(metric);
        damping   = term.get();
        elasticity->add_term(std::move(term));
      }
    damping->set(c, u);
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::damping_force()
  {
    return damping ? damping->force_norm(u) : 0.;
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::damping_scale()
  {
    set_damping(0.);
    restore_converged_state();
    // At the converged state's own load factor (an obstacle at the next
    // one may be inside the body there).
    const double t      = current_load_factor;
    current_load_factor = converged.load_factor;
    assemble_tangent();
    current_load_factor = t;
    return damping->stiffness_ratio(tangent);
  }

  template void
  EquilibriumSystem<2>::set_damping(double);
  template double
  EquilibriumSystem<2>::damping_force();
  template double
  EquilibriumSystem<2>::damping_scale();
  template void
  EquilibriumSystem<3>::set_damping(double);
  template double
  EquilibriumSystem<3>::damping_force();
  template double
  EquilibriumSystem<3>::damping_scale();
} // namespace hyperelastic
