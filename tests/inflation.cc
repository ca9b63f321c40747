// Inflation of a thick hollow cylinder in plane strain (annulus 1 <= R <= 2,
// meshes/annulus_2d_N.msh): a follower pressure on the inner circle (a
// closed surface with uniform p: conservative) and the outer circle moved
// radially to R = 2.2. Asserts, for each model:
//   - the run is recognised as conservative: every Newton iteration after
//     the prescribed displacement is imposed uses the energy line search;
//   - Newton converges quadratically (exact tangent with the load
//     stiffness, direct solver: r_k+1 r_1 / r_k^2 <= 100 near the solution);
//   - the deformed inner radius (mean |x| of the inner vertices) agrees
//     with the radial ODE solution (tests/radial_inflation.h, converged to
//     1e-10) within the discretisation error, which decreases from the
//     coarse to the fine mesh at a rate of at least 1.5.
//
// Usage: mpirun -np N inflation MESH_FOLDER
#include <hyperelastic/problem/problem.h>

#include "support/dimension_main.h"
#include "support/radial_inflation.h"
#include "support/scene_text.h"

#include <cmath>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  constexpr double inner = 1., outer = 2., outer_deformed = 2.2, p = 0.3;

  std::string
  scene(const std::string &mesh, const std::string &model)
  {
    return subsection("Problem", entry("Dimension", "2")) +
           subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
           material_section(model,
                            entry("Young's modulus", "1") +
                              entry("Poisson's ratio", "0.3"),
                            lame_parameters(1. / 2.6, 0.3 / (1.3 * 0.4))) +
           cylinder_inflation_loading(p) +
           subsection("Newton",
                      entry("Max iterations", "30") +
                        entry("Absolute residual tolerance", "1e-15") +
                        entry("Relative residual tolerance", "1e-13") +
                        entry("Update tolerance", "1e-12") +
                        entry("Inexact Newton", "false") +
                        entry("Tangent", "exact")) +
           subsection("Linear solver", entry("Type", "direct")) +
           subsection("Output",
                      entry("Directory", "inflation_output") +
                        entry("Write VTU", "false") +
                        entry("Verbose", "false"));
  }

  /// Mean deformed radius of the vertices on the inner circle (id 1).
  double
  inner_radius(const Problem<2> &problem)
  {
    double sum = 0., count = 0.;
    for (const auto &cell : problem.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == 1)
            for (unsigned int v = 0; v < 2; ++v)
              {
                Point<2> x = cell->face(f)->vertex(v);
                for (unsigned int d = 0; d < 2; ++d)
                  x[d] +=
                    problem.solution()(cell->face(f)->vertex_dof_index(v, d));
                sum += x.norm();
                count += 1.;
              }
    return Utilities::MPI::sum(sum, MPI_COMM_WORLD) /
           Utilities::MPI::sum(count, MPI_COMM_WORLD);
  }

  void
  check(Checker &checker, const std::string &meshes)
  {
    for (const std::string model :
         {"neo-Hookean", "decoupled neo-Hookean", "Mooney-Rivlin"})
      {
        Parameters parameters;
        parameters.read_from_string(
          scene(meshes + "/annulus_2d_16.msh", model));
        const auto material = create_material<2>(parameters.material);
        const RadialInflation<2> reference(
          *material, inner, outer, p, outer_deformed, 20000);
        const RadialInflation<2> check_reference(
          *material, inner, outer, p, outer_deformed, 40000);
        const double r_exact = reference.inner_radius();
        checker.at_most(model + ": ODE reference r(A) converged",
                        std::abs(r_exact - check_reference.inner_radius()),
                        1e-10);

        std::vector<double> errors;
        for (const std::string n : {"16", "32"})
          {
            Parameters mesh_parameters;
            mesh_parameters.read_from_string(
              scene(meshes + "/annulus_2d_" + n + ".msh", model));
            Problem<2> problem(mesh_parameters, MPI_COMM_WORLD, false);
            problem.run();
            const std::string tag         = model + " N = " + n + ": ";
            unsigned int      energy_rows = 0, residual_rows = 0, pairs = 0;
            double            worst = 0.;
            for (const auto &s : problem.summaries())
              {
                std::vector<double> r;
                for (const auto &row : s.newton_history)
                  {
                    energy_rows += row.energy_tested;
                    residual_rows += std::isfinite(row.trial_residual);
                    r.push_back(row.residual);
                  }
                const double floor =
                  10. * *std::min_element(r.begin(), r.end());
                for (unsigned int k = 0; k + 1 < r.size(); ++k)
                  if (r[k] < 1e-3 * r[0] && r[k + 1] > floor)
                    {
                      ++pairs;
                      worst = std::max(worst, r[k + 1] * r[0] / (r[k] * r[k]));
                    }
              }
            checker.is_true(tag + "energy line search (conservative)",
                            energy_rows > 0 && residual_rows == 0);
            checker.at_least(tag + "residual pairs in the asymptotic range",
                             pairs,
                             1);
            checker.at_most(tag + "max r_k+1 r_1 / r_k^2", worst, 100.);
            errors.push_back(std::abs(inner_radius(problem) - r_exact));
            checker.at_most(tag + "|r(A) - ODE| / (r(A) - A)",
                            errors.back() / (r_exact - inner),
                            0.05);
          }
        checker.at_least(model + ": error rate N = 16 -> 32",
                         std::log2(errors[0] / errors[1]),
                         1.5);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  const std::string meshes     = argc > 1 ? argv[1] : "meshes";
  char             *dim_argv[] = {argv[0], const_cast<char *>("2"), nullptr};
  return run_checks_for_dimension(
    2,
    dim_argv,
    [&](Checker &checker, bool) { check(checker, meshes); },
    [](Checker &, bool) {});
}
