// A unit square (cube) on symmetry rollers at x = 0, y = 0 (, z = 0) under a
// pressure p on the other faces deforms homogeneously, F = s I, so P1 and P2
// reproduce it at every node. Two loads of the same size give two different
// exact answers:
//   follower pressure (Cauchy stress sigma = -p I):  P_11(s I) = -p s^(dim-1)
//   dead traction -p N (nominal stress P = -p I):     P_11(s I) = -p
// (plane strain: F = diag(s, s, 1)). s is found here by bisection from the
// model's own P; the nodal displacements must equal (s - 1) X to 1e-9, and
// the two answers must differ. The loaded faces do not close the surface,
// so the follower run has no potential: it must use the residual line
// search and GMRES.
//
// Usage: mpirun -np N hydrostatic_pressure DIM
#include <hyperelastic/problem/problem.h>

#include "support/dimension_main.h"
#include "support/scene_text.h"

#include <cmath>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  constexpr double p = 0.2;

  std::string
  scene(const int dim, const std::string &model, const bool follower)
  {
    const bool  three = dim == 3;
    std::string loads;
    for (int d = 0; d < dim; ++d)
      {
        const std::string id = std::to_string(2 * d + 1);
        if (follower)
          loads += subsection("Pressure " + std::to_string(d + 1),
                              entry("Boundary id", id) +
                                entry("Pressure", std::to_string(p) + "*t"));
        else
          {
            std::string traction;
            for (int c = 0; c < dim; ++c)
              traction += (c > 0 ? "; " : "") +
                          (c == d ? "-" + std::to_string(p) + "*t" : "0");
            loads += subsection("Traction " + std::to_string(d + 1),
                                entry("Boundary id", id) +
                                  entry("Traction", traction));
          }
      }
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "1, 1, 1" : "1, 1") +
                        entry("Subdivisions", three ? "2, 2, 2" : "3, 3")) +
           material_section(model,
                            entry("Young's modulus", "1") +
                              entry("Poisson's ratio", "0.3"),
                            lame_parameters(1. / 2.6, 0.3 / (1.3 * 0.4))) +
           subsection("Loading", entry("Number of load steps", "2")) +
           dirichlet(1, 0, "x", "0") + dirichlet(2, 2, "y", "0") +
           (three ? dirichlet(3, 4, "z", "0") : std::string()) + loads +
           subsection("Newton",
                      entry("Relative residual tolerance", "1e-13") +
                        entry("Update tolerance", "1e-12")) +
           subsection("Linear solver", entry("Relative tolerance", "1e-12")) +
           subsection("Output",
                      entry("Directory", "hydrostatic_pressure_output") +
                        entry("Write VTU", "false") +
                        entry("Verbose", "false"));
  }

  /// The s of F = s I with P_11(s I) = target(s), by bisection in (0.2, 1].
  template <int dim, typename Target>
  double
  homogeneous_stretch(const Material<dim> &material, Target &&target)
  {
    double low = 0.2, high = 1.;
    for (int k = 0; k < 200; ++k)
      {
        const double         s = 0.5 * (low + high);
        const Tensor<2, dim> F = s * unit_symmetric_tensor<dim>();
        // Compression: P_11 grows with s; too compressed below the root.
        (material.first_piola_kirchhoff(F)[0][0] < target(s) ? low : high) = s;
      }
    return 0.5 * (low + high);
  }

  /// max over the vertices of |u - (s - 1) X|.
  template <int dim>
  double
  homogeneous_error(const Problem<dim> &problem, const double s)
  {
    double worst = 0.;
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            worst = std::max(worst,
                             std::abs(problem.solution()(
                                        cell->vertex_dof_index(v, d)) -
                                      (s - 1.) * cell->vertex(v)[d]));
    return Utilities::MPI::max(worst, MPI_COMM_WORLD);
  }

  template <int dim>
  void
  check(Checker &checker, const bool)
  {
    for (const std::string model :
         {"neo-Hookean", "decoupled neo-Hookean", "Mooney-Rivlin"})
      {
        std::array<double, 2> stretch = {{0., 0.}};
        for (const bool follower : {true, false})
          {
            Parameters parameters;
            parameters.read_from_string(scene(dim, model, follower));
            Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
            problem.run();
            const auto material =
              create_material<dim>(parameters.material);
            const double s =
              follower ? homogeneous_stretch(*material,
                                             [](const double s) {
                                               return -p * std::pow(s, dim - 1);
                                             })
                       : homogeneous_stretch(*material,
                                             [](const double) { return -p; });
            stretch[follower]     = s;
            const std::string tag = std::to_string(dim) + "D " + model +
                                    (follower ? " follower" : " dead") + ": ";
            checker.at_most(tag + "|u - (s-1) X| (s = " + std::to_string(s) +
                              ")",
                            homogeneous_error(problem, s),
                            1e-9);
            // Rows whose line search tested the energy / the residual.
            unsigned int energy_rows = 0, residual_rows = 0;
            for (const auto &step : problem.summaries())
              for (const auto &row : step.newton_history)
                {
                  energy_rows += row.energy_tested;
                  residual_rows += std::isfinite(row.trial_residual);
                }
            checker.is_true(tag + (follower ? "residual line search, GMRES"
                                            : "energy line search, CG"),
                            (follower
                               ? residual_rows > 0 && energy_rows == 0
                               : energy_rows > 0 && residual_rows == 0) &&
                              problem.linear_solver_description().find(
                                follower ? "GMRES" : "CG") == 0);
          }
        checker.at_least(std::to_string(dim) + "D " + model +
                           ": |s follower - s dead|",
                         std::abs(stretch[1] - stretch[0]),
                         1e-3);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_checks_for_dimension(argc, argv, check<2>, check<3>);
}
