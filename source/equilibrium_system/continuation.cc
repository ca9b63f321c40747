// The equilibrium system's states (u, t) set from outside
// (ContinuationSystem) and the tangent's solves at them (TangentSystem):
// arc length's corrector and the stiffness along the load path.
#include <deal.II/base/mpi.h>

#include <hyperelastic/equilibrium_system/equilibrium_system.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  EquilibriumSystem<dim>::set_state(const VectorType &v, const double t)
  {
    current_load_factor = t;
    u                   = v;
    u_ghosted           = u;
    // The prescribed entries at their values at t: the constraints of the
    // increment from the current values, applied to a zero vector, give it.
    parts.boundary_conditions.make_constraints(parts.mapping,
                                               parts.dof_handler,
                                               relevant_dofs,
                                               t,
                                               u_ghosted,
                                               false,
                                               increment_constraints);
    VectorType increment(owned_dofs, comm);
    increment_constraints.distribute(increment);
    u += increment;
    u_ghosted = u;
  }

  template <int dim>
  ResidualNorms
  EquilibriumSystem<dim>::free_residual(VectorType &r)
  {
    const ResidualNorms norms = residual_norms();
    r                         = residual;
    homogeneous_constraints.set_zero(r);
    project_out(u_ghosted, r);
    return norms;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::load_derivative(VectorType &r_t)
  {
    // Central differences in t at fixed free unknowns (exact to round-off
    // for loads linear in t).
    const VectorType at(u);
    const double     t = current_load_factor;
    const double     h = 1e-6 * std::max(1., std::abs(t));
    double           noise;
    set_state(at, t + h);
    free_residual_norm(noise);
    r_t = residual;
    set_state(at, t - h);
    free_residual_norm(noise);
    r_t -= residual;
    r_t *= 0.5 / h;
    homogeneous_constraints.set_zero(r_t);
    set_state(at, t);
    free_residual_norm(noise);
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::assemble_tangent()
  {
    TimerOutput::Scope scope(parts.timer, "assembly");
    active_constraints = &homogeneous_constraints;
    assemble_linearization_into(homogeneous_constraints,
                                tangent,
                                rhs,
                                TangentProjection::none);
  }

  template <int dim>
  unsigned int
  EquilibriumSystem<dim>::solve_tangent(const VectorType &b, VectorType &x)
  {
    {
      TimerOutput::Scope scope(parts.timer, "preconditioner setup");
      parts.linear_solver.prepare(tangent);
    }
    TimerOutput::Scope scope(parts.timer, "linear solve");
    x                             = 0.;
    const unsigned int iterations = parts.linear_solver.solve(
      tangent,
      x,
      constrained_right_hand_side(b),
      parts.linear_solver_parameters.relative_tolerance);
    homogeneous_constraints.distribute(x);
    unsigned int constraint_iterations = 0;
    constrain_update(parts.linear_solver_parameters.relative_tolerance,
                     x,
                     constraint_iterations);
    return iterations + constraint_iterations;
  }

  template <int dim>
  double
  EquilibriumSystem<dim>::path_product(const VectorType &a,
                                       const VectorType &b) const
  {
    if (displacement_mask.size() == 0)
      return a * b;
    VectorType masked(a);
    masked.scale(displacement_mask);
    return masked * b;
  }

  template void
  EquilibriumSystem<2>::set_state(const VectorType &, double);
  template ResidualNorms
  EquilibriumSystem<2>::free_residual(VectorType &);
  template void
  EquilibriumSystem<2>::load_derivative(VectorType &);
  template void
  EquilibriumSystem<2>::assemble_tangent();
  template unsigned int
  EquilibriumSystem<2>::solve_tangent(const VectorType &, VectorType &);
  template double
  EquilibriumSystem<2>::path_product(const VectorType &,
                                     const VectorType &) const;
  template void
  EquilibriumSystem<3>::set_state(const VectorType &, double);
  template ResidualNorms
  EquilibriumSystem<3>::free_residual(VectorType &);
  template void
  EquilibriumSystem<3>::load_derivative(VectorType &);
  template void
  EquilibriumSystem<3>::assemble_tangent();
  template unsigned int
  EquilibriumSystem<3>::solve_tangent(const VectorType &, VectorType &);
  template double
  EquilibriumSystem<3>::path_product(const VectorType &,
                                     const VectorType &) const;
} // namespace hyperelastic
