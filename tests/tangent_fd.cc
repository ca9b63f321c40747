// The assembled tangent against finite differences of the assembled internal
// forces: for a random displacement field u and random directions v,
//   || K(u) v - (f_int(u + h v) - f_int(u - h v)) / (2 h) || / || K(u) v ||
// must be below 1e-6, for P1 and P2, 2D and 3D, every nonlinear model, on
// the ranks of MPI_COMM_WORLD.
//
// Usage: mpirun -np N tangent_fd
#include <deal.II/base/mpi.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/material_registry.h>

#include "support/box_discretisation.h"
#include "support/checker.h"
#include "support/random_vector.h"

#include <string>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  template <int dim>
  double
  worst_error(const std::string &model, const unsigned int degree)
  {
    const MPI_Comm               comm = MPI_COMM_WORLD;
    const BoxDiscretisation<dim> box(2., 2, 2, degree, comm);
    const IndexSet              &owned = box.owned, &relevant = box.relevant;

    LameParameters lame;
    lame.mu             = 1.;
    lame.lambda         = 2.;
    const auto material = create_material<dim>(model, lame);
    // Loads do not enter the tangent; a traction checks they stay out of it.
    LoadingParameters loading;
    loading.boundary_loads.push_back(
      {"Traction", 1, std::vector<std::string>(dim, "0.3*t"), "Traction 1", ""});
    const BoundaryConditions<dim> bc(loading, box.boundary_ids);
    const ElasticityOperator<dim> op(box.dof_handler, box.mapping, *material, bc);

    MatrixType K;
    box.reinit_matrix(K);
    AffineConstraints<double> none(relevant);
    none.close();

    VectorType u(owned, comm), v(owned, comm), Kv(owned, comm),
      rhs(owned, comm), f_plus(owned, comm), f_minus(owned, comm),
      external(owned, comm);
    VectorType u_ghosted(owned, relevant, comm);
    fill_random(u, 0.05, 1);
    u_ghosted = u;
    op.assemble_system(u_ghosted, 1., none, K, rhs);

    double worst = 0.;
    for (unsigned int direction = 0; direction < 3; ++direction)
      {
        fill_random(v, 1., 10 + direction);
        K.vmult(Kv, v);
        const double h = 1e-6;
        VectorType   w(owned, comm);
        w = u;
        w.add(h, v);
        u_ghosted = w;
        op.assemble_forces(u_ghosted, 1., f_plus, external);
        w.add(-2. * h, v);
        u_ghosted = w;
        op.assemble_forces(u_ghosted, 1., f_minus, external);
        f_plus -= f_minus;
        f_plus /= 2. * h;
        f_plus -= Kv;
        worst = std::max(worst, f_plus.l2_norm() / Kv.l2_norm());
      }
    return worst;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker   check(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const int status = run_and_report(
    [&]() {
      // Every finite-strain model of the registry (linear elasticity's
      // tangent is the constant C, checked in material_test).
      for (const MaterialModel &registered : material_models())
        {
          if (registered.is_linear)
            continue;
          const std::string &model = registered.name;
          for (const unsigned int degree : {1u, 2u})
            for (const int dim : {2, 3})
              check.at_most(model + " P" + std::to_string(degree) + " " +
                              std::to_string(dim) + "D",
                            dim == 2 ? worst_error<2>(model, degree)
                                     : worst_error<3>(model, degree),
                            1e-6);
        }
    },
    MPI_COMM_WORLD);
  return check.exit_code(status);
}
