// The equilibrium system's constraints beyond the Dirichlet conditions
// (SystemConstraint), looped over where the equations pass them: a solve's
// right-hand side and update, and the residuals and directions.
#include <hyperelastic/equilibrium_system/equilibrium_system.h>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  const VectorType &
  EquilibriumSystem<dim>::constrained_right_hand_side(const VectorType &b)
  {
    if (system_constraints.empty())
      return b;
    for (const auto &constraint : system_constraints)
      constraint->prepare_solve(u, tangent, b, force_scale);
    pinned_rhs = b;
    for (const auto &constraint : system_constraints)
      constraint->project_out(u, pinned_rhs);
    return pinned_rhs;
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::constrain_update(const double  tolerance,
                                           VectorType   &x,
                                           unsigned int &iterations)
  {
    for (const auto &constraint : system_constraints)
      constraint->constrain_update(
        u,
        [&](const VectorType &v, VectorType &z) {
          z = 0.;
          iterations += parts.linear_solver.solve(tangent, z, v, tolerance);
          homogeneous_constraints.distribute(z);
        },
        x);
  }

  template <int dim>
  void
  EquilibriumSystem<dim>::project_out(const VectorType &at, VectorType &v) const
  {
    for (const auto &constraint : system_constraints)
      constraint->project_out(at, v);
  }

  template const VectorType &
  EquilibriumSystem<2>::constrained_right_hand_side(const VectorType &);
  template void
  EquilibriumSystem<2>::constrain_update(double, VectorType &, unsigned int &);
  template void
  EquilibriumSystem<2>::project_out(const VectorType &, VectorType &) const;
  template const VectorType &
  EquilibriumSystem<3>::constrained_right_hand_side(const VectorType &);
  template void
  EquilibriumSystem<3>::constrain_update(double, VectorType &, unsigned int &);
  template void
  EquilibriumSystem<3>::project_out(const VectorType &, VectorType &) const;
} // namespace hyperelastic
