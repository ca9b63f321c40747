// The follower pressure's load stiffness and potential against finite
// differences, on the ranks of MPI_COMM_WORLD, P1 and P2, 2D and 3D:
//   1. a non-uniform pressure p = 1 + x y + t on one face of a box (an open
//      surface: no potential): the assembled tangent of the whole operator
//      (material + load stiffness) against central differences of the
//      assembled residual f_int - g, relative error < 1e-6; and the load
//      stiffness alone is not symmetric;
//   2. a uniform pressure on the whole boundary (closed): the term reports
//      itself conservative, dV/du . v from differences of its potential
//      equals -g . v (relative 1e-6), and the assembled tangent is
//      symmetric (|K - K^T| / |K| < 1e-10).
//
// Usage: mpirun -np N follower_pressure_fd
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/loads/boundary_conditions.h>

#include "support/box_discretisation.h"
#include "support/checker.h"
#include "support/random_vector.h"

#include <string>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  constexpr types::boundary_id whole_boundary = 7;

  template <int dim>
  struct Setup
  {
    Setup(const unsigned int degree, const bool closed)
        : box(2., 2, 2, degree, MPI_COMM_WORLD)
    {
      if (closed)
        // One id for the whole boundary (ids are local to each rank's
        // cells; every rank relabels its own and its ghosts).
        for (const auto &cell : box.tria.active_cell_iterators())
          if (!cell->is_artificial())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                cell->face(f)->set_boundary_id(whole_boundary);
      LoadingParameters loading;
      if (closed)
        loading.boundary_loads.push_back(
          {"Pressure", whole_boundary, {"0.7*t"}, "Pressure 1", ""});
      else
        loading.boundary_loads.push_back(
          {"Pressure", 1, {"1 + x*y + t"}, "Pressure 1", ""});
      std::set<types::boundary_id> ids = box.boundary_ids;
      ids.insert(whole_boundary);
      bc = std::make_unique<BoundaryConditions<dim>>(loading, ids);
      LameParameters lame;
      lame.mu     = 1.;
      lame.lambda = 2.;
      material    = create_material<dim>("neo-Hookean", lame);
      op          = std::make_unique<ElasticityOperator<dim>>(box.dof_handler,
                                                     box.mapping,
                                                     *material,
                                                     *bc);
    }

    VectorType
    owned() const
    {
      return VectorType(box.owned, box.comm);
    }

    VectorType
    ghosted(const VectorType &v) const
    {
      VectorType g(box.owned, box.relevant, box.comm);
      g = v;
      return g;
    }

    BoxDiscretisation<dim>                   box;
    std::unique_ptr<BoundaryConditions<dim>> bc;
    std::unique_ptr<Material<dim>>           material;
    std::unique_ptr<ElasticityOperator<dim>> op;
  };

  /// f_int(u) - g(u) at t = 0.5.
  template <int dim>
  VectorType
  residual(const Setup<dim> &s, const VectorType &u)
  {
    VectorType internal = s.owned(), external = s.owned();
    s.op->assemble_forces(s.ghosted(u), 0.5, internal, external);
    internal -= external;
    return internal;
  }

  /// |K - K^T| / |K| in the Frobenius norm, from products with random
  /// vectors: max over a few w, v of |w.Kv - v.Kw| / (|K v| |w|).
  double
  asymmetry(const MatrixType &K, VectorType v, VectorType w)
  {
    double     worst = 0.;
    VectorType Kv(v), Kw(w);
    for (unsigned int k = 0; k < 3; ++k)
      {
        fill_random(v, 1., 20 + k);
        fill_random(w, 1., 30 + k);
        K.vmult(Kv, v);
        K.vmult(Kw, w);
        worst =
          std::max(worst,
                   std::abs(w * Kv - v * Kw) / (Kv.l2_norm() * w.l2_norm()));
      }
    return worst;
  }

  template <int dim>
  void
  check_open(Checker &check, const unsigned int degree)
  {
    const Setup<dim>  s(degree, false);
    const std::string what = "open surface P" + std::to_string(degree) + " " +
                             std::to_string(dim) + "D: ";
    check.is_true(what + "not conservative", !s.op->is_conservative());

    MatrixType K;
    s.box.reinit_matrix(K);
    AffineConstraints<double> none(s.box.relevant);
    none.close();
    VectorType u = s.owned(), rhs = s.owned();
    fill_random(u, 0.05, 1);
    s.op->assemble_system(s.ghosted(u), 0.5, none, K, rhs);

    double worst = 0.;
    for (unsigned int direction = 0; direction < 3; ++direction)
      {
        VectorType v = s.owned(), Kv = s.owned();
        fill_random(v, 1., 10 + direction);
        K.vmult(Kv, v);
        const double h    = 1e-6;
        VectorType   plus = u, minus = u;
        plus.add(h, v);
        minus.add(-h, v);
        VectorType difference = residual(s, plus);
        difference -= residual(s, minus);
        difference /= 2. * h;
        difference -= Kv;
        worst = std::max(worst, difference.l2_norm() / Kv.l2_norm());
      }
    check.at_most(what + "tangent vs FD of residual", worst, 1e-6);

    // The load stiffness alone: K of the operator minus the material part.
    MatrixType K_material;
    s.box.reinit_matrix(K_material);
    LoadingParameters             no_loads;
    const BoundaryConditions<dim> bare(no_loads, s.box.boundary_ids);
    const ElasticityOperator<dim> material_only(s.box.dof_handler,
                                                s.box.mapping,
                                                *s.material,
                                                bare);
    material_only.assemble_system(s.ghosted(u), 0.5, none, K_material, rhs);
    K.add(-1., K_material);
    check.at_least(what + "load stiffness not symmetric",
                   asymmetry(K, s.owned(), s.owned()),
                   1e-3);
  }

  template <int dim>
  void
  check_closed(Checker &check, const unsigned int degree)
  {
    const Setup<dim>  s(degree, true);
    const std::string what = "closed surface P" + std::to_string(degree) + " " +
                             std::to_string(dim) + "D: ";
    check.is_true(what + "conservative", s.op->is_conservative());

    VectorType u = s.owned();
    fill_random(u, 0.05, 2);
    const auto &term = *s.op->energy_terms().front();
    VectorType  g    = s.owned();
    term.add_forces(s.ghosted(u), 0.5, g);
    g.compress(VectorOperation::add);
    double worst = 0.;
    for (unsigned int direction = 0; direction < 3; ++direction)
      {
        VectorType v = s.owned();
        fill_random(v, 1., 40 + direction);
        const double h    = 1e-6;
        VectorType   plus = u, minus = u;
        plus.add(h, v);
        minus.add(-h, v);
        const double dV = (term.energy(s.ghosted(plus), 0.5) -
                           term.energy(s.ghosted(minus), 0.5)) /
                          (2. * h);
        worst = std::max(worst, std::abs(dV + g * v) / std::abs(g * v));
      }
    check.at_most(what + "dV/du vs -g", worst, 1e-6);

    MatrixType K;
    s.box.reinit_matrix(K);
    AffineConstraints<double> none(s.box.relevant);
    none.close();
    VectorType rhs = s.owned();
    s.op->assemble_system(s.ghosted(u), 0.5, none, K, rhs);
    check.at_most(what + "tangent symmetric",
                  asymmetry(K, s.owned(), s.owned()),
                  1e-10);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker   check(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const int status = run_and_report(
    [&]() {
      for (const unsigned int degree : {1u, 2u})
        {
          check_open<2>(check, degree);
          check_open<3>(check, degree);
          check_closed<2>(check, degree);
          check_closed<3>(check, degree);
        }
    },
    MPI_COMM_WORLD);
  return check.exit_code(status);
}
