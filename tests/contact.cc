// Contact with rigid obstacles (Contact I): the barrier term against finite
// differences, and a block resting on a plane.
//   fd DIM      the barrier's forces against central differences of its
//               potential, for a plane and a sphere (relative 1e-6), and its
//               load stiffness against central differences of the forces
//               for the plane (1e-6); the sphere's projected stiffness is
//               positive semi-definite; the feasible step keeps every
//               distance positive and cuts a step that would cross.
//   resting DIM a block under gravity on a plane, rollers on its symmetry
//               planes: the plane's total force equals the weight (1e-8),
//               every distance lies in (0, d_hat), the run is the same on
//               any number of ranks (the CSV columns are printed).
//   drop DIM    a block dropped on a plane with backward Euler: every
//               step's contact_min_distance > 0, the total energy never
//               grows (the scheme dissipates), the block hits the floor and
//               bounces (upward momentum after the impact).
// Usage: mpirun -np N contact CASE DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/contact/obstacle_contact.h>

#include "support/box_discretisation.h"
#include "support/dimension_main.h"
#include "support/random_vector.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <cmath>
#include <string>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using dealii::Utilities::MPI::sum;

namespace
{
  /// The unit box's bottom face (y = 0 in 2D, z = 0 in 3D) is 'down'.
  template <int dim>
  ObstacleParameters
  obstacle(const ObstacleType type, const unsigned int number)
  {
    ObstacleParameters o;
    o.number     = number;
    o.subsection = "Contact/Obstacle " + std::to_string(number);
    o.type       = type;
    o.point      = std::vector<double>(dim, 0.5);
    o.normal     = std::vector<double>(dim, 0.);
    o.motion     = std::vector<std::string>(dim, "0");
    if (type == ObstacleType::plane)
      {
        // A tilted plane below the bottom: 0.00995 from its x = 0 edge,
        // 0.109 from its x = 1 edge.
        o.point[dim - 1]  = -0.06;
        o.normal[0]       = 0.1;
        o.normal[dim - 1] = 1.;
        const double norm = std::sqrt(1.01);
        for (double &n : o.normal)
          n /= norm;
      }
    else
      {
        o.radius         = 0.5;
        o.point[dim - 1] = -0.503;
      }
    return o;
  }

  double
  dot(const VectorType &a, const VectorType &b)
  {
    return a * b;
  }

  template <int dim>
  void
  fd(Checker &checker)
  {
    const MPI_Comm         comm = MPI_COMM_WORLD;
    BoxDiscretisation<dim> box(1., 4, 4, 1, comm);
    LameParameters         moduli = lame_parameters(1., 1.);
    for (const ObstacleType type : {ObstacleType::plane, ObstacleType::sphere})
      {
        const std::string name =
          std::to_string(dim) + "D " +
          (type == ObstacleType::plane ? "plane" : "sphere") + ": ";
        ContactParameters parameters;
        parameters.barrier_distance = 0.1;
        parameters.obstacles.push_back(obstacle<dim>(type, 1));
        const ObstacleContact<dim> contact(
          parameters, {}, box.dof_handler, box.mapping, moduli);

        VectorType u(box.owned, comm), u_ghosted(box.owned, box.relevant, comm);
        VectorType v(box.owned, comm), w(box.owned, comm);
        fill_random(u, 1e-4, 1);
        fill_random(v, 1., 2);
        const double h  = 1e-7;
        const auto   at = [&](const double s) {
          w = u;
          w.add(s, v);
          u_ghosted = w;
          return u_ghosted;
        };
        // Forces g = -dV/du.
        VectorType g(box.owned, comm);
        u_ghosted = u;
        contact.add_forces(u_ghosted, 0., g);
        g.compress(dealii::VectorOperation::add);
        const double slope = -dot(g, v);
        const double fd_slope =
          (contact.potential(at(h), 0.) - contact.potential(at(-h), 0.)) /
          (2. * h);
        checker.close(name +
                        "forces . v against (V(u + h v) - V(u - h v)) / 2h",
                      slope,
                      fd_slope,
                      std::abs(fd_slope),
                      1e-6);
        checker.above(name + "barrier active (|g . v| > 0)",
                      std::abs(slope),
                      0.);

        // Load stiffness K = d2V/du2.
        MatrixType K;
        box.reinit_matrix(K);
        VectorType                        rhs(box.owned, comm);
        dealii::AffineConstraints<double> none;
        none.close();
        u_ghosted = u;
        contact.add_load_stiffness(u_ghosted, 0., none, K, rhs);
        K.compress(dealii::VectorOperation::add);
        VectorType Kv(box.owned, comm), g_plus(box.owned, comm),
          g_minus(box.owned, comm);
        K.vmult(Kv, v);
        contact.add_forces(at(h), 0., g_plus);
        contact.add_forces(at(-h), 0., g_minus);
        g_plus.compress(dealii::VectorOperation::add);
        g_minus.compress(dealii::VectorOperation::add);
        // -dg/du v.
        VectorType difference = g_minus;
        difference -= g_plus;
        difference /= 2. * h;
        if (type == ObstacleType::plane)
          {
            VectorType error = Kv;
            error -= difference;
            checker.at_most(name + "|K v - FD of the forces| / |K v|",
                            error.l2_norm() / Kv.l2_norm(),
                            1e-6);
          }
        else
          {
            // Projected: v.K v >= 0 for every v, and along v the projected
            // curvature is at least the exact one (the dropped tangential
            // part is negative).
            double smallest = 1e300;
            for (unsigned int seed = 3; seed < 13; ++seed)
              {
                fill_random(w, 1., seed);
                K.vmult(Kv, w);
                smallest = std::min(smallest, dot(w, Kv) / dot(w, w));
              }
            checker.at_least(name + "projected stiffness: min over 10 random "
                                    "v of v.K v / v.v",
                             smallest,
                             0.);
            K.vmult(Kv, v);
            checker.at_least(name + "v.K v - v.(FD of -dg/du) v >= 0",
                             dot(v, Kv) - dot(v, difference) +
                               1e-6 * std::abs(dot(v, Kv)),
                             0.);
          }

        // The feasible step: along a direction that pushes everything down
        // by 1 the step is cut so that no distance becomes negative.
        VectorType down(box.owned, comm);
        for (const auto i : box.owned)
          if (i % dim == dim - 1)
            down(i) = -1.;
        down.compress(dealii::VectorOperation::insert);
        const double alpha = contact.largest_feasible_step(u, down, 0.);
        checker.is_true(name + "feasible step along -e_vertical in (0, 1): " +
                          std::to_string(alpha),
                        alpha > 0. && alpha < 1.);
        w = u;
        w.add(alpha, down);
        u_ghosted = w;
        checker.is_true(name + "potential finite at the feasible step",
                        std::isfinite(contact.potential(u_ghosted, 0.)));
        w = u;
        w.add(alpha / 0.9 * 1.001, down);
        u_ghosted = w;
        checker.is_true(name + "past the crossing the potential is infinite",
                        !std::isfinite(contact.potential(u_ghosted, 0.)));
      }
  }

  /// A unit block of neo-Hookean material (Young's modulus @p young,
  /// Poisson's ratio 0.3) with its bottom at height @p bottom, in boxes of
  /// @p n per side (2D; n / 2 in 3D), under the gravity @p g per unit
  /// volume, above a floor plane at height @p floor (Contact/Obstacle 1,
  /// barrier distance @p d_hat), without VTU output or Newton table.
  template <int dim>
  std::string
  block_above_floor(const double       bottom,
                    const unsigned int n,
                    const std::string &young,
                    const std::string &g,
                    const std::string &floor,
                    const std::string &d_hat)
  {
    const bool        three = dim == 3;
    const std::string low = number(bottom), high = number(bottom + 1.);
    const std::string m = std::to_string(three ? n / 2 : n);
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection(
             "Mesh",
             entry("Lower corner", three ? "0, 0, " + low : "0, " + low) +
               entry("Upper corner", three ? "1, 1, " + high : "1, " + high) +
               entry("Subdivisions",
                     three ? m + ", " + m + ", " + m : m + ", " + m)) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", young) +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading",
                      entry("Body force", three ? "0; 0; -" + g : "0; -" + g)) +
           subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false")) +
           subsection(
             "Contact",
             entry("Barrier distance", d_hat) +
               subsection("Obstacle 1",
                          entry("Type", "plane") +
                            entry("Point",
                                  three ? "0, 0, " + floor : "0, " + floor) +
                            entry("Normal", three ? "0, 0, 1" : "0, 1")));
  }

  /// The value of CSV column @p name in @p summary (NaN if absent).
  template <int dim>
  double
  column(const StepSummary<dim> &summary, const std::string &name)
  {
    for (const auto &c : summary.columns())
      if (c.name == name)
        return c.value;
    return std::nan("");
  }

  template <int dim>
  void
  resting(Checker &checker)
  {
    const bool        three = dim == 3;
    const std::string scene =
      block_above_floor<dim>(0., 6, "1", "0.1", "-0.005", "0.01") +
      subsection("Loading", entry("Number of load steps", "2")) +
      dirichlet(1, 0, "x", "0") + (three ? dirichlet(2, 2, "y", "0") : "") +
      tight_solver("direct");
    const auto        problem = run_scene<dim>(scene);
    const auto       &last    = problem->summaries().back();
    const std::string tag     = std::to_string(dim) + "D resting block: ";
    const std::string up      = three ? "z" : "y";
    // Weight: 0.1 per unit volume of the unit block.
    checker.close(tag + "contact_force_1_" + up + " = weight 0.1",
                  column(last, "contact_force_1_" + up),
                  0.1,
                  0.1,
                  1e-8);
    checker.at_most(tag + "|contact_force_1_x| / weight",
                    std::abs(column(last, "contact_force_1_x")) / 0.1,
                    1e-8);
    const double d = column(last, "contact_min_distance");
    checker.is_true(tag + "0 < contact_min_distance = " + std::to_string(d) +
                      " < d_hat",
                    d > 0. && d < 0.01);
    checker.above(tag + "contact_active_pairs",
                  column(last, "contact_active_pairs"),
                  0.);
  }

  template <int dim>
  void
  drop(Checker &checker)
  {
    const std::string scene =
      block_above_floor<dim>(0.1, 4, "20", "1", "0", "0.005") +
      subsection("Time integration",
                 entry("Scheme", "backward Euler") +
                   entry("Time step", "0.05") + entry("End time", "1.5"));
    const auto        problem  = run_scene<dim>(scene);
    const std::string up       = dim == 3 ? "z" : "y";
    double            smallest = 1e300, growth = -1e300, most_force = 0.;
    double            previous = 0., upward = 0.;
    bool              hit = false;
    for (const auto &s : problem->summaries())
      {
        const double total = column(s, "total_energy");
        const double force = column(s, "contact_force_1_" + up);
        smallest = std::min(smallest, column(s, "contact_min_distance"));
        if (s.step > 1)
          growth = std::max(growth, total - previous);
        previous   = total;
        most_force = std::max(most_force, force);
        hit        = hit || force > 0.;
        if (hit)
          upward = std::max(upward, column(s, "momentum_" + up));
      }
    const std::string tag = std::to_string(dim) + "D drop: ";
    checker.above(tag + "smallest contact_min_distance over all steps",
                  smallest,
                  0.);
    checker.at_most(tag + "largest growth of the total energy per step",
                    growth,
                    1e-12);
    checker.above(tag + "largest contact force (the block hit the floor)",
                  most_force,
                  0.);
    checker.above(tag + "largest upward momentum after the impact (bounce)",
                  upward,
                  0.);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_case_for_dimension(
    argc,
    argv,
    "fd",
    [](const std::string &which, Checker &checker) {
      if (which == "fd")
        fd<2>(checker);
      else if (which == "drop")
        drop<2>(checker);
      else
        resting<2>(checker);
    },
    [](const std::string &which, Checker &checker) {
      if (which == "fd")
        fd<3>(checker);
      else if (which == "drop")
        drop<3>(checker);
      else
        resting<3>(checker);
    });
}
