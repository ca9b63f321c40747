// Convergence rates against the manufactured finite-strain solution of
// manufactured_motion.h (a 90-degree rotation of a smoothly deformed body,
// body force -Div P from the model's own dP/dF, exact displacement on the
// whole boundary). The errors of u_h in L2 and in the H1 seminorm are
// computed on meshes n, 2n, 4n, and the rates from the last two must be
// p + 1 (L2) and p (H1) within 0.15.
//
// Usage: mpirun -np N manufactured_solution DIM MODEL [DEGREE]
//   without DEGREE both P1 and P2 are checked.
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/numerics/vector_tools.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/manufactured_motion.h"
#include "support/scene_text.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  struct Errors
  {
    unsigned int n, dofs, newton;
    double       l2, h1;
  };

  template <int dim>
  Errors
  solve(const std::string &model, const unsigned int degree, const unsigned int n)
  {
    const bool        three = dim == 3;
    const std::string N     = std::to_string(n);
    std::string       text =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Finite element degree", std::to_string(degree))) +
      subsection("Mesh",
                 entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                   entry("Upper corner", three ? "1, 1, 1" : "1, 1") +
                   entry("Subdivisions",
                         three ? N + ", " + N + ", " + N : N + ", " + N)) +
      material_section(model,
                       entry("Elastic constants", "Lame") +
                         entry("Shear modulus", "1") +
                         entry("Lame lambda", "1.5"),
                       lame_parameters(1., 1.5)) +
      subsection("Loading", entry("Number of load steps", "4")) +
      tight_solver("cg") +
      // Plain Newton: the test is about the discretisation, and the energy
      // line search has nothing to gain near the solution.
      subsection("Newton", entry("Line search", "false")) +
      subsection("Output",
                 entry("Write VTU", "false") + entry("Verbose", "false") +
                   entry("Directory", "manufactured_output"));
    // Placeholders on every side, replaced by the exact displacement below.
    for (unsigned int id = 0; id < 2 * dim; ++id)
      text += dirichlet(id + 1, id, three ? "x, y, z" : "x, y", three ? "0; 0; 0" : "0; 0");

    Parameters parameters;
    parameters.read_from_string(text);
    const auto   material = create_material<dim>(parameters.material);
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.set_load_editor([&](BoundaryConditions<dim> &bc) {
      for (auto &d : bc.dirichlet)
        d.displacement = std::make_unique<ExactDisplacement<dim>>();
      bc.body_force = std::make_unique<ManufacturedBodyForce<dim>>(*material);
    });
    problem.run();

    const DoFHandler<dim>   &dof_handler = problem.get_dof_handler();
    const MappingFE<dim>     mapping(FE_SimplexP<dim>(1));
    const QGaussSimplex<dim> quadrature(degree + 2);
    ExactDisplacement<dim>   exact;
    exact.set_time(1.);
    Errors errors{n, static_cast<unsigned int>(dof_handler.n_dofs()), 0, 0., 0.};
    for (const auto &s : problem.summaries())
      errors.newton += s.newton_iterations;
    Vector<double> cellwise(dof_handler.get_triangulation().n_active_cells());
    for (const auto norm : {VectorTools::L2_norm, VectorTools::H1_seminorm})
      {
        VectorTools::integrate_difference(
          mapping, dof_handler, problem.solution(), exact, cellwise, quadrature, norm);
        (norm == VectorTools::L2_norm ? errors.l2 : errors.h1) =
          VectorTools::compute_global_error(dof_handler.get_triangulation(), cellwise, norm);
      }
    return errors;
  }

  template <int dim>
  void
  check_rates(const std::string &model, const unsigned int degree, Checker &checker, const bool print)
  {
    // Coarsest mesh of the three, chosen so that the finest one is in the
    // asymptotic range and small enough for ctest.
    const unsigned int  n0 = dim == 2 ? 4 : (degree == 1 ? 4 : 2);
    std::vector<Errors> rows;
    for (unsigned int n = n0; n <= 4 * n0; n *= 2)
      rows.push_back(solve<dim>(model, degree, n));
    if (print)
      {
        std::cout << dim << "D " << model << ", P" << degree << ":\n"
                  << "     n    unknowns  Newton      L2 error  rate      H1 error  rate\n";
        for (unsigned int i = 0; i < rows.size(); ++i)
          {
            std::cout << std::setw(6) << rows[i].n << std::setw(12) << rows[i].dofs
                      << std::setw(8) << rows[i].newton << std::scientific << std::setprecision(4)
                      << std::setw(14) << rows[i].l2;
            if (i > 0)
              std::cout << std::fixed << std::setprecision(2) << std::setw(6)
                        << std::log2(rows[i - 1].l2 / rows[i].l2);
            else
              std::cout << std::setw(6) << "";
            std::cout << std::scientific << std::setprecision(4) << std::setw(14) << rows[i].h1;
            if (i > 0)
              std::cout << std::fixed << std::setprecision(2) << std::setw(6)
                        << std::log2(rows[i - 1].h1 / rows[i].h1);
            std::cout << std::defaultfloat << '\n';
          }
      }
    const Errors      &a = rows[rows.size() - 2], &b = rows.back();
    const std::string  tag = std::to_string(dim) + "D P" + std::to_string(degree) + " ";
    const double       l2_rate = std::log2(a.l2 / b.l2), h1_rate = std::log2(a.h1 / b.h1);
    checker.at_most(tag + "|L2 rate - " + std::to_string(degree + 1) + "|",
                    std::abs(l2_rate - (degree + 1.)),
                    0.15);
    checker.at_most(tag + "|H1 rate - " + std::to_string(degree) + "|",
                    std::abs(h1_rate - degree),
                    0.15);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool print = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if (argc < 3)
    {
      if (print)
        std::cerr << "usage: manufactured_solution DIM MODEL [DEGREE]\n";
      return 1;
    }
  const int         dim   = std::stoi(argv[1]);
  const std::string model = argv[2];
  Checker           checker(print);
  const int         status = run_and_report(
    [&]() {
      for (unsigned int degree = 1; degree <= 2; ++degree)
        if (argc < 4 || std::stoi(argv[3]) == static_cast<int>(degree))
          {
            if (dim == 2)
              check_rates<2>(model, degree, checker, print);
            else
              check_rates<3>(model, degree, checker, print);
          }
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
