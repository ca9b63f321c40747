// Quasi-static bodies held only by contact (Contact III, issue 43): no
// Dirichlet condition holds them; the solver removes the rigid motions no
// support resists.
//   plates DIM   a unit block between a floor and a plate pressing it 20 %,
//                no Dirichlet condition at all. Frictionless: the plate's
//                force is the homogeneous uniaxial one within the bound of
//                the compression test (dF/da d_hat), and the block's free
//                rigid motion (mean in-plane displacement; in 3D also the
//                mean rotation about the pressing axis) is zero to
//                round-off. With mu =
//                0.5 on both: the run completes, the plate's and the
//                floor's forces balance (every component, 1e-8), and the
//                steps after the first two take at most 2.5 times the
//                frictionless Newton iterations.
//   stacked DIM MESH  a unit block on a clamped long one
//                (meshes/block_on_block_DIMd.msh), pressed 30 % by a plate,
//                frictionless, all defaults: the upper block is held
//                vertically only by contact. The run completes, the plate's
//                force equals the clamp's reaction (1e-6), and every step's
//                contact_min_distance is positive.
//   ball 3 MESH  a coarse ball of radius 1 (meshes/ball_coarse_3d.msh)
//                squeezed frictionless between a floor and a plate by 0.2
//                in 4 load steps, no Dirichlet condition (the example
//                squeezed_ball_3d without friction): the run completes,
//                the plates' forces are equal and opposite (1e-8), and the
//                ball's mean displacement along x and y stays at round-off
//                (1e-12): it does not slide. Its mean rotations are only
//                reported: it still rolls (0.37 rad about y on this mesh).
// Usage: mpirun -np N contact_held CASE DIM [MESH]
#include <deal.II/base/mpi.h>

#include "support/analytic_bar.h"
#include "support/dimension_main.h"
#include "support/owned_vertices.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <cmath>
#include <string>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  const char *const axes[3] = {"x", "y", "z"};

  /// A unit block of neo-Hookean (E = 1, nu = 0.3), 4 x 4 (2D) or 2 x 2 x 2
  /// (3D) boxes, between a floor (Obstacle 1) and a plate (Obstacle 2),
  /// each d_hat / 2 away, the plate moving down by @p squash over 5 load
  /// steps; friction coefficient @p mu on both; no Dirichlet condition.
  template <int dim>
  std::string
  block_held_by_plates(const double d_hat, const double squash, const double mu)
  {
    // Frictionless: tight tolerances (round-off limited answers); with
    // friction the default ones.
    const bool        three = dim == 3;
    const std::string gap = number(0.5 * d_hat), top = number(1. + 0.5 * d_hat);
    const std::string down = three ? "0, 0, " : "0, ";
    const std::string friction = entry("Friction coefficient", number(mu));
    return unit_block(dim) +
           subsection("Loading", entry("Number of load steps", "5")) +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false")) +
           subsection(
             "Contact",
             entry("Barrier distance", number(d_hat)) +
               subsection("Obstacle 1",
                          entry("Type", "plane") +
                            entry("Point", down + "-" + gap) +
                            entry("Normal", three ? "0, 0, 1" : "0, 1") +
                            friction) +
               subsection("Obstacle 2",
                          entry("Type", "plane") + entry("Point", down + top) +
                            entry("Normal", three ? "0, 0, -1" : "0, -1") +
                            entry("Motion",
                                  three ? "0; 0; -" + number(squash) + "*t"
                                        : "0; -" + number(squash) + "*t") +
                            friction)) +
           (mu > 0. ? subsection("Linear solver", entry("Type", "direct"))
                    : tight_solver("direct"));
  }

  /// The mean displacement of the block's nodes along each axis and its
  /// mean rotation about the last axis (sum of (X - c) x u over the sum of
  /// |X - c|^2 in the plane normal to it), from the solution. Collective.
  template <int dim>
  std::array<double, dim + 1>
  rigid_part(const Problem<dim> &problem)
  {
    const auto &dof_handler = problem.get_dof_handler();
    const auto &u           = problem.solution();
    std::array<double, dim + 1> sums{};
    double                      count = 0., inertia = 0.;
    testing::for_each_owned_vertex(
      dof_handler, [&](const auto &cell, const unsigned int v) {
        const dealii::Point<dim> X = cell->vertex(v);
        double                   ux[dim];
        for (unsigned int d = 0; d < dim; ++d)
          ux[d] = u(cell->vertex_dof_index(v, d)), sums[d] += ux[d];
        // About the block's centre (0.5, 0.5): (X - c) x u.
        const double x = X[0] - 0.5, y = X[1] - 0.5;
        sums[dim] += x * ux[1] - y * ux[0];
        inertia += x * x + y * y;
        count += 1.;
      });
    count   = dealii::Utilities::MPI::sum(count, MPI_COMM_WORLD);
    inertia = dealii::Utilities::MPI::sum(inertia, MPI_COMM_WORLD);
    for (unsigned int d = 0; d <= dim; ++d)
      sums[d] = dealii::Utilities::MPI::sum(sums[d], MPI_COMM_WORLD) /
                (d < dim ? count : inertia);
    return sums;
  }

  template <int dim>
  void
  plates(Checker &checker)
  {
    const double      d_hat = 1e-3, squash = 0.2;
    const std::string up    = axes[dim - 1];
    const std::string tag   = std::to_string(dim) + "D block held by plates: ";
    // Newton iterations of the steps after the first two (friction's
    // normal forces are extrapolated from two converged states).
    const auto later_iterations = [](const auto &summaries,
                                     const unsigned int first = 3) {
      double sum = 0.;
      for (const auto &row : summaries)
        if (row.step >= first)
          sum += column(row, "newton_iterations");
      return sum;
    };
    double frictionless_iterations = 0., frictionless_all = 0.;
    {
      const auto problem =
        run_scene<dim>(block_held_by_plates<dim>(d_hat, squash, 0.));
      frictionless_iterations = later_iterations(problem->summaries());
      frictionless_all        = later_iterations(problem->summaries(), 1);
      const auto  &last        = problem->summaries().back();
      const double floor_force = column(last, "contact_force_1_" + up);
      const double plate_force = column(last, "contact_force_2_" + up);
      // mu = 1/2.6, lambda = 0.3 / (1.3 * 0.4) for E = 1, nu = 0.3.
      const double mu = 1. / 2.6, lambda = 0.3 / (1.3 * 0.4);
      const auto   at = [&](const double a) {
        return uniaxial("neo-Hookean", dim, a, mu, lambda).P11;
      };
      const double slope = (at(1. - squash + 1e-6) - at(1. - squash - 1e-6)) /
                           2e-6;
      checker.close(tag + "frictionless: floor force = -plate force",
                    floor_force,
                    -plate_force,
                    std::abs(plate_force),
                    1e-8);
      checker.at_most(tag +
                        "frictionless: |floor force - homogeneous uniaxial "
                        "force| / (dF/da d_hat)",
                      std::abs(floor_force + at(1. - squash)) /
                        (std::abs(slope) * d_hat),
                      1.);
      const auto rigid = rigid_part(*problem);
      for (unsigned int d = 0; d + 1 < dim; ++d)
        checker.at_most(tag + "frictionless: |mean displacement along " +
                          axes[d] + "| (in-plane translation)",
                        std::abs(rigid[d]),
                        1e-12);
      // In 3D the spin about the pressing axis is free too (in 2D the
      // plates resist the in-plane rotation).
      if (dim == 3)
        checker.at_most(tag + "frictionless: |mean rotation about z|",
                        std::abs(rigid[dim]),
                        1e-12);
      checker.above(tag + "frictionless: smallest contact_min_distance",
                    smallest(problem->summaries(), "contact_min_distance"),
                    0.);
    }
    {
      const auto problem =
        run_scene<dim>(block_held_by_plates<dim>(d_hat, squash, 0.5));
      const auto &last = problem->summaries().back();
      checker.close(tag + "mu = 0.5: completed to t",
                    last.load_factor,
                    1.,
                    1.,
                    1e-12);
      const double scale =
        std::abs(column(last, "contact_force_2_" + up));
      for (unsigned int d = 0; d < dim; ++d)
        checker.at_most(tag + "mu = 0.5: |floor + plate force| along " +
                          axes[d] + " / |plate force|",
                        std::abs(column(last, std::string("contact_force_1_") +
                                                axes[d]) +
                                 column(last, std::string("contact_force_2_") +
                                                axes[d])) /
                          scale,
                        1e-8);
      // Lagging updates within Newton's iterations (issue 43, item 5):
      // friction costs about one solve a step, not one per update
      // (measured 1.58 in 2D, 2.08 in 3D before the normal forces followed
      // the iterates; each update re-solving the step
      // from its converged state cost 3 to 4.6 times in
      // benchmarks/friction).
      const double with_friction = later_iterations(problem->summaries());
      checker.at_most(tag + "mu = 0.5: Newton iterations of steps 3-5 / "
                            "frictionless ones",
                      with_friction / frictionless_iterations,
                      2.5);
      // With the normal forces following Newton's iterates after each full
      // step, the 2D block meets issue 43's target (measured 1.42; 3D
      // 2.17, its steps 3-5 still paid a converged-state update each; 2.00
      // since the updates go on after one without change).
      if (dim == 2)
        checker.at_most(tag + "mu = 0.5: Newton iterations of steps 3-5 / "
                              "frictionless ones (issue 43's target)",
                        with_friction / frictionless_iterations,
                        1.5);
      // All steps, the first contact's too: large normal-force changes
      // taken within the solve (not deferred to the converged state) and
      // the line search's projected path (measured 1.64 in 2D, 1.88 in
      // 3D on 1 rank; 1.56 and 1.72 with the forcing terms of one set of
      // equations after an update).
      checker.at_most(tag + "mu = 0.5: Newton iterations of all steps / "
                            "frictionless ones",
                      later_iterations(problem->summaries(), 1) /
                        frictionless_all,
                      dim == 2 ? 1.8 : 2.1);
    }
  }

  template <int dim>
  void
  stacked(Checker &checker, const std::string &mesh)
  {
    const bool        three = dim == 3;
    const std::string up    = axes[dim - 1];
    const std::string tag   = std::to_string(dim) + "D stacked blocks: ";
    // The upper block's top is at 1.50501; the plate starts 1e-3 above it
    // and presses it 30 %.
    const std::string lead = three ? "0, 0, " : "0, ";
    const std::string scene =
      subsection("Problem", entry("Dimension", std::to_string(dim))) +
      subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
      subsection("Material",
                 entry("Model", "neo-Hookean") + entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0.3")) +
      subsection("Loading", entry("Number of load steps", "6")) +
      dirichlet(1, 1, three ? "x, y, z" : "x, y", three ? "0; 0; 0" : "0; 0") +
      subsection("Output",
                 entry("Write VTU", "false") + entry("Verbose", "false")) +
      subsection("Contact",
                 entry("Self contact", "true") +
                   subsection("Obstacle 1",
                              entry("Type", "plane") +
                                entry("Point", lead + "1.50601") +
                                entry("Normal", three ? "0, 0, -1" : "0, -1") +
                                entry("Motion",
                                      three ? "0; 0; -0.3*t" : "0; -0.3*t")));
    const auto  problem = run_scene<dim>(scene);
    const auto &s       = problem->summaries();
    const auto &last    = s.back();
    checker.close(tag + "completed to t", last.load_factor, 1., 1., 1e-12);
    const double plate    = column(last, "contact_force_1_" + up);
    const double reaction = column(last, "reaction_1_" + up);
    // The plate's and the clamp's forces on the bodies balance.
    checker.close(tag + "plate force = -clamp reaction (along " + up + ")",
                  plate,
                  -reaction,
                  std::abs(plate),
                  1e-6);
    checker.above(tag + "plate force magnitude", std::abs(plate), 1e-3);
    checker.above(tag + "smallest contact_min_distance over the steps",
                  smallest(s, "contact_min_distance"),
                  0.);
  }
  /// The mean rotation of the nodes about each axis through @p centre:
  /// sum of (X - c) x u over the sum of |X - c|^2 in the plane normal to
  /// the axis. Collective.
  dealii::Tensor<1, 3>
  mean_rotation(const Problem<3> &problem, const dealii::Point<3> &centre)
  {
    const auto          &dof_handler = problem.get_dof_handler();
    const auto          &u           = problem.solution();
    dealii::Tensor<1, 3> moment, inertia;
    testing::for_each_owned_vertex(
      dof_handler, [&](const auto &cell, const unsigned int v) {
        const dealii::Tensor<1, 3> x = cell->vertex(v) - centre;
        dealii::Tensor<1, 3>       d;
        for (unsigned int c = 0; c < 3; ++c)
          d[c] = u(cell->vertex_dof_index(v, c));
        const dealii::Tensor<1, 3> m = dealii::cross_product_3d(x, d);
        for (unsigned int k = 0; k < 3; ++k)
          {
            moment[k] += m[k];
            inertia[k] += x.norm_square() - x[k] * x[k];
          }
      });
    dealii::Tensor<1, 3> rotation;
    for (unsigned int k = 0; k < 3; ++k)
      rotation[k] = dealii::Utilities::MPI::sum(moment[k], MPI_COMM_WORLD) /
                    dealii::Utilities::MPI::sum(inertia[k], MPI_COMM_WORLD);
    return rotation;
  }

  void
  squeezed_ball(Checker &checker, const std::string &mesh)
  {
    const double      d_hat = 0.004;
    const std::string tag   = "frictionless squeezed ball: ";
    const std::string gap   = number(1. + 0.5 * d_hat);
    const std::string scene =
      subsection("Problem", entry("Dimension", "3")) +
      subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
      subsection("Material",
                 entry("Model", "neo-Hookean") + entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0.3")) +
      subsection("Loading", entry("Number of load steps", "4")) +
      subsection("Output",
                 entry("Write VTU", "false") + entry("Verbose", "false")) +
      subsection(
        "Contact",
        entry("Barrier distance", number(d_hat)) +
          subsection("Obstacle 1",
                     entry("Type", "plane") + entry("Point", "0, 0, -" + gap) +
                       entry("Normal", "0, 0, 1")) +
          subsection("Obstacle 2",
                     entry("Type", "plane") + entry("Point", "0, 0, " + gap) +
                       entry("Normal", "0, 0, -1") +
                       entry("Motion", "0; 0; -0.2*t")));
    const auto  problem = run_scene<3>(scene);
    const auto &last    = problem->summaries().back();
    checker.close(tag + "completed to t", last.load_factor, 1., 1., 1e-12);
    const double floor_force = column(last, "contact_force_1_z");
    const double plate_force = column(last, "contact_force_2_z");
    checker.above(tag + "plate force magnitude", std::abs(plate_force), 1e-3);
    checker.close(tag + "floor force = -plate force",
                  floor_force,
                  -plate_force,
                  std::abs(plate_force),
                  1e-8);
    const auto translation = rigid_part<3>(*problem);
    for (unsigned int d = 0; d < 2; ++d)
      checker.at_most(tag + "|mean displacement along " + axes[d] + "|",
                      std::abs(translation[d]),
                      1e-12);
    // Not yet at round-off: the ball rolls (its material turns about an
    // in-plane axis while its shape stays between the plates: not a rigid
    // motion of the current positions, which the plates resist; the coarse
    // polyhedron lowers its energy by turning onto a face). Reported only.
    const dealii::Tensor<1, 3> rotation =
      mean_rotation(*problem, dealii::Point<3>());
    checker.note(tag + "mean rotations about x, y, z (not asserted): " +
                 number(rotation[0]) + ", " + number(rotation[1]) + ", " +
                 number(rotation[2]));
    checker.above(tag + "smallest contact_min_distance",
                  smallest(problem->summaries(), "contact_min_distance"),
                  0.);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_case_for_dimension(
    argc,
    argv,
    "plates",
    [&](const std::string &which, Checker &checker) {
      if (which == "stacked")
        stacked<2>(checker, argc > 3 ? argv[3] : "block_on_block_2d.msh");
      else
        plates<2>(checker);
    },
    [&](const std::string &which, Checker &checker) {
      if (which == "stacked")
        stacked<3>(checker, argc > 3 ? argv[3] : "block_on_block_3d.msh");
      else if (which == "ball")
        squeezed_ball(checker, argc > 3 ? argv[3] : "ball_coarse_3d.msh");
      else
        plates<3>(checker);
    });
}
