// EquilibriumSystem::solve_transposed_tangent(): the adjoint solve of a fit
// through a scene (Problem::reaction_sensitivities) when the tangent is not
// symmetric. The condensed tangent has zero rows and columns on the
// constrained unknowns but their diagonal, so its transpose is the
// transpose of the free block with the same diagonal.
#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/equilibrium_system/equilibrium_system.h>

#include <stdexcept>

namespace hyperelastic
{
  template <int dim>
  unsigned int
  EquilibriumSystem<dim>::solve_transposed_tangent(const VectorType &b,
                                                   VectorType       &x)
  {
    if (has_system_constraints())
      throw std::logic_error("solve_transposed_tangent: not with system "
                             "constraints");
    MatrixType transposed;
    transpose(tangent, transposed);
    VectorType rhs(b);
    homogeneous_constraints.set_zero(rhs);
    x = 0.;
    dealii::TimerOutput::Scope scope(parts.timer, "linear solve");
    // A hierarchy for K^T, and one built anew for the next tangent: the
    // kept one must not outlive the matrix it was built on (also when the
    // solve throws).
    LinearSolver &solver = parts.linear_solver;
    solver.forget_preconditioner();
    struct Forget
    {
      LinearSolver &solver;
      ~Forget()
      {
        solver.forget_preconditioner();
      }
    } forget{solver};
    solver.prepare(transposed);
    const unsigned int iterations = solver.solve(
      transposed, x, rhs, parts.linear_solver_parameters.relative_tolerance);
    homogeneous_constraints.distribute(x);
    return iterations;
  }

  template unsigned int
  EquilibriumSystem<2>::solve_transposed_tangent(const VectorType &,
                                                 VectorType &);
  template unsigned int
  EquilibriumSystem<3>::solve_transposed_tangent(const VectorType &,
                                                 VectorType &);
} // namespace hyperelastic
