// The fast P1 kernel against the generic FEValues assembly it replaces: for
// a random displacement, with inhomogeneous Dirichlet conditions on two
// faces, a traction and a body force,
//   internal forces, external forces, the condensed tangent (applied to
//   random vectors), the right-hand side, the total energy and min J
// must agree to round-off (1e-12 relative), in 2D and 3D, for every model,
// with and without the projected tangent, on the ranks of MPI_COMM_WORLD.
//
// Usage: mpirun -np N p1_kernel
#include <deal.II/base/mpi.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/material_registry.h>

#include "support/box_discretisation.h"
#include "support/checker.h"
#include "support/random_vector.h"

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  double
  relative_difference(VectorType a, VectorType b)
  {
    a -= b;
    return a.l2_norm() / std::max(b.l2_norm(), 1e-300);
  }

  template <int dim>
  void
  compare(const std::string &model, const bool projected, Checker &check)
  {
    const MPI_Comm               comm = MPI_COMM_WORLD;
    const BoxDiscretisation<dim> box(3., 7, 3, 1, comm);
    const IndexSet              &owned = box.owned, &relevant = box.relevant;
    const TangentProjection      projection =
      projected ? TangentProjection::every_point : TangentProjection::none;
    const DoFHandler<dim> &dof_handler = box.dof_handler;
    const MappingFE<dim>  &mapping     = box.mapping;

    LameParameters lame;
    lame.mu                    = 1.;
    lame.lambda                = 3.;
    const auto        material = create_material<dim>(model, lame);
    LoadingParameters loading;
    const std::string xyz[] = {"x", "y", "z"};
    // Clamped and moved at x = 0, only the x component moved at x = 3.
    DirichletCondition left{0, {}, {}, "Dirichlet 1", {}, ""};
    for (unsigned int d = 0; d < dim; ++d)
      {
        left.components.push_back(d);
        left.expressions.push_back("0.1*t*sin(" + xyz[(d + 1) % dim] + "+" +
                                   std::to_string(d) + ")");
      }
    loading.dirichlet.push_back(left);
    loading.dirichlet.push_back({1, {0}, {"0.4*t"}, "Dirichlet 2", {}, ""});
    loading.boundary_loads.push_back(
      {"Traction", 2, std::vector<std::string>(dim, "0.3*t*x"), "Traction 1", ""});
    loading.body_force = std::vector<std::string>(dim, "-0.2*t");
    const BoundaryConditions<dim> bc(loading, box.boundary_ids);
    const ElasticityOperator<dim> fast(dof_handler, mapping, *material, bc);
    const ElasticityOperator<dim> generic(
      dof_handler, mapping, *material, bc, false);
    check.is_true(std::to_string(dim) + "D: the kernel is in use",
                  fast.uses_p1_kernel() && !generic.uses_p1_kernel());

    MatrixType K_fast, K_generic;
    box.reinit_matrix(K_fast);
    box.reinit_matrix(K_generic);

    VectorType u(owned, comm), u_ghosted(owned, relevant, comm);
    fill_random(u, 0.05, 1);
    u_ghosted                   = u;
    const double              t = 0.7;
    AffineConstraints<double> constraints;
    bc.make_constraints(
      mapping, dof_handler, relevant, t, u_ghosted, false, constraints);

    // Relative difference on the unconstrained rows.
    const auto free_difference = [&](VectorType a, VectorType b) {
      constraints.set_zero(a);
      constraints.set_zero(b);
      return relative_difference(a, b);
    };
    const std::string tag = std::to_string(dim) + "D " + model +
                            (projected ? " projected" : "") + ": ";
    VectorType f_fast(owned, comm), f_generic(owned, comm), e_fast(owned, comm),
      e_generic(owned, comm);
    fast.assemble_forces(u_ghosted, t, f_fast, e_fast);
    generic.assemble_forces(u_ghosted, t, f_generic, e_generic);
    check.at_most(tag + "internal forces",
                  relative_difference(f_fast, f_generic),
                  1e-12);
    check.at_most(tag + "external forces",
                  relative_difference(e_fast, e_generic),
                  1e-12);

    VectorType rhs_fast(owned, comm), rhs_generic(owned, comm);
    // Twice: the second call reuses the positions found in the first.
    for (unsigned int repeat = 0; repeat < 2; ++repeat)
      {
        fast.assemble_system(
          u_ghosted, t, constraints, K_fast, rhs_fast, projection);
        generic.assemble_system(
          u_ghosted, t, constraints, K_generic, rhs_generic, projection);
        // Constrained rows: only their diagonal scale may differ.
        check.at_most(tag + "right-hand side, call " +
                        std::to_string(repeat + 1),
                      free_difference(rhs_fast, rhs_generic),
                      1e-12);
      }
    double worst = 0.;
    for (unsigned int direction = 0; direction < 3; ++direction)
      {
        VectorType v(owned, comm), Kv_fast(owned, comm),
          Kv_generic(owned, comm);
        fill_random(v, 1., 10 + direction);
        K_fast.vmult(Kv_fast, v);
        K_generic.vmult(Kv_generic, v);
        worst = std::max(worst, free_difference(Kv_fast, Kv_generic));
      }
    check.at_most(tag + "tangent times random vectors", worst, 1e-12);

    const EnergyEvaluation a = fast.evaluate(u_ghosted, t, true);
    const EnergyEvaluation b = generic.evaluate(u_ghosted, t, true);
    check.at_most(tag + "total energy",
                  std::abs(a.energy - b.energy) / std::abs(b.energy),
                  1e-12);
    check.at_most(tag + "min J", std::abs(a.min_J - b.min_J), 1e-14);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker   check(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const int status = run_and_report(
    [&]() {
      for (const MaterialModel &registered : material_models())
        {
          const std::string &model = registered.name;
          compare<2>(model, false, check);
          compare<3>(model, false, check);
        }
      compare<3>("neo-Hookean", true, check);
    },
    MPI_COMM_WORLD);
  return check.exit_code(status);
}
