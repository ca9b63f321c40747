// Implicit dynamics (issue 16), on the ranks of MPI_COMM_WORLD, for
// backward Euler, Newmark (average acceleration) and implicit midpoint,
// consistent and lumped mass:
//   free_fall   an unsupported neo-Hookean block under gravity from rest:
//               every node and the momentum follow the scheme's own
//               recurrence (backward Euler u_n = -g h^2 n (n + 1) / 2,
//               Newmark and midpoint the exact -g t^2 / 2; momentum -m g t)
//               to 1e-12;
//   momentum    a free block set spinning and deforming (no loads, no
//               supports): total linear momentum constant to 1e-12 of its
//               size, every registered model, scheme and mass (stiffness
//               warping does not conserve it: tests/stiffness_warping.cc);
//   energy      the same body, linear elastic: Newmark and midpoint keep the
//               total energy to 1e-10; backward Euler's never increases
//               (1e-12 slack) and does decrease;
//   angular     the spinning neo-Hookean body with implicit midpoint: angular
//               momentum constant to 1e-10 of its size; the drift of the
//               total energy (not conserved by midpoint in a nonlinear
//               problem) below 2e-3 (observed 5.7e-4 in 2D, 8.3e-4 in 3D);
//   damped      a neo-Hookean block glued to the floor under gravity, with
//               mass damping, and with stiffness damping, backward Euler to
//               t = 40: ends at the quasi-static equilibrium of the same
//               scene (1e-6);
//   rayleigh    the vibrating bar below with stiffness damping b = 2 zeta /
//               omega: logarithmic decrement of the tip peaks against
//               2 pi zeta / sqrt(1 - zeta^2) for zeta = 0.05 (1 %; observed
//               7e-4 in 2D, 1.5e-4 in 3D);
//   linearized  a cantilever swinging under gravity (neo-Hookean, Newmark)
//               with 'Linearize once per step': one Newton iteration in
//               every step (full Newton takes more), and the tip within 2 %
//               of the tip deflection of full Newton;
//   vibration   a nu = 0 bar clamped at x = 0, released in its first mode
//               (v_x = V sin(pi x / 2L)), linear elastic, Newmark with the
//               consistent mass: the period of the tip motion against
//               4 L sqrt(rho / E) within 1 %;
//   vibration_order  the period error of that bar converges at order 2 (at
//               least 1.8) in the time step and in the element size.
//   long_fall   issue 41: a 3 x 3 x 3 neo-Hookean cube (E = 1, gravity 1)
//               falls freely to t = 10 (500 steps of 0.02) with each scheme
//               (direct solver): no cut-back, momentum_z = -m g t at every
//               step to 1e-9, at most 2 Newton iterations per step; with
//               Newmark and CG + AMG too: the same, and the AMG hierarchy
//               built once for the whole fall;
//   long_spin   issue 41: a free body spinning about an off-centre axis for
//               50 turns with implicit midpoint: angular momentum constant
//               to 1e-9 of its size; the total energy error (midpoint does
//               not conserve energy in a nonlinear problem) below 2e-3 and
//               not growing from the first 25 turns to the last 25;
//   impact      issue 41: a 4 x 4 x 4 block (E = 1) dropped 0.2 onto a
//               frictionless plane under gravity 1 (dt = 0.02), Newmark and
//               implicit midpoint: it completes, contact_min_distance > 0
//               at every step, and the total energy (kinetic, elastic,
//               gravity, barrier) never exceeds its start by more than 1 %
//               of the kinetic energy at impact; backward Euler never gains
//               energy in a step and ends with less.
//
// Usage: mpirun -np N dynamics CASE DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/nodal_error.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  const std::vector<std::string> schemes = {"backward Euler",
                                            "Newmark",
                                            "implicit midpoint"};
  const std::vector<std::string> masses  = {"consistent", "lumped"};

  std::string
  time_section(const std::string &scheme,
               const std::string &mass,
               const double       density,
               const double       h,
               const double       end,
               const std::string &velocity          = "",
               const double       stiffness_damping = 0.)
  {
    return subsection("Time integration",
                      entry("Scheme", scheme) + entry("Mass", mass) +
                        entry("Density", number(density)) +
                        entry("Time step", number(h)) +
                        entry("End time", number(end)) +
                        entry("Initial velocity", velocity) +
                        entry("Stiffness damping", number(stiffness_damping)));
  }

  /// A unit block (square) of 2^dim boxes, no supports, no output files.
  template <int dim>
  std::string
  block(const std::string &model)
  {
    const bool three = dim == 3;
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "1, 1, 1" : "1, 1") +
                        entry("Subdivisions", three ? "2, 2, 2" : "2, 2")) +
           material_section(model,
                            entry("Young's modulus", "1") +
                              entry("Poisson's ratio", "0.3"),
                            LameParameters::from_young_poisson(1., 0.3)) +
           tight_solver("direct") +
           subsection("Output",
                      entry("Directory", "dynamics_output") +
                        entry("Write VTU", "false") +
                        entry("Verbose", "false"));
  }

  template <int dim>
  void
  free_fall(Checker &checker)
  {
    const double rho = 2., g = 0.5, h = 0.1;
    const int    n_steps = 10;
    const std::string gravity =
      dim == 3 ? "0; 0; " + number(-rho * g) : "0; " + number(-rho * g);
    for (const std::string &scheme : schemes)
      for (const std::string &mass : masses)
        {
          auto problem = run_scene<dim>(
            block<dim>("neo-Hookean") +
            subsection("Loading", entry("Body force", gravity)) +
            time_section(scheme, mass, rho, h, n_steps * h));
          const bool        euler = scheme == "backward Euler";
          // Newmark and midpoint integrate a constant force exactly.
          const double      n     = n_steps;
          const double      fall  = euler ? -g * h * h * n * (n + 1.) / 2. :
                                            -g * (n * h) * (n * h) / 2.;
          const std::string tag =
            std::to_string(dim) + "D " + scheme + ", " + mass + " mass: ";
          const double error = max_nodal_error(
            problem->get_dof_handler(),
            problem->solution(),
            [&](const Point<dim> &) {
              Tensor<1, dim> u;
              u[dim - 1] = fall;
              return u;
            });
          checker.at_most(tag + "max |u - u_exact| / |u_exact| after 10 steps",
                          error / std::abs(fall),
                          1e-12);
          const auto  &last = problem->summaries().back();
          const double mass_total = rho; // unit volume
          checker.close(tag + "momentum = -m g t",
                        last.linear_momentum[dim - 1],
                        -mass_total * g * n * h,
                        mass_total * g * n * h,
                        1e-12);
        }
  }

  /// A spin about the block's centre plus a shear: v = w x (X - c) + shear.
  template <int dim>
  std::string
  spinning_velocity()
  {
    return dim == 3 ?
             "0.1 - 0.3*(y - 0.5) + 0.1*(z - 0.5)*y; "
             "0.3*(x - 0.5) - 0.05; 0.02 - 0.1*(x - 0.5)*x" :
             "0.1 - 0.3*(y - 0.5) + 0.05*y*y; 0.3*(x - 0.5) - 0.05";
  }

  template <int dim>
  void
  momentum(Checker &checker)
  {
    for (const MaterialModel &model : material_models())
    for (const std::string &scheme : schemes)
      for (const std::string &mass : masses)
        {
          auto problem = run_scene<dim>(
            block<dim>(model.name) +
            time_section(scheme, mass, 1., 0.2, 2., spinning_velocity<dim>()));
          const auto &steps = problem->summaries();
          const auto  p0    = steps.front().linear_momentum;
          double      drift = 0.;
          for (const auto &s : steps)
            drift = std::max(drift, (s.linear_momentum - p0).norm());
          checker.at_most(std::to_string(dim) + "D " + model.name + ", " +
                            scheme + ", " + mass +
                            " mass: linear momentum drift / |p| over " +
                            std::to_string(steps.size()) + " steps",
                          drift / p0.norm(),
                          1e-12);
        }
  }

  template <int dim>
  void
  energy(Checker &checker)
  {
    for (const std::string &scheme : schemes)
      {
        auto problem = run_scene<dim>(
          block<dim>("linear elastic") +
          time_section(scheme, "consistent", 1., 0.2, 4., spinning_velocity<dim>()));
        const auto        &steps = problem->summaries();
        const std::string  tag   = std::to_string(dim) + "D " + scheme + ": ";
        const double       E0    = steps.front().kinetic_energy + steps.front().energy;
        double             worst_drift = 0., worst_rise = -1e300;
        for (std::size_t k = 0; k < steps.size(); ++k)
          {
            const double E = steps[k].kinetic_energy + steps[k].energy;
            worst_drift    = std::max(worst_drift, std::abs(E - E0) / E0);
            if (k > 0)
              worst_rise = std::max(worst_rise,
                                    (E - (steps[k - 1].kinetic_energy +
                                          steps[k - 1].energy)) /
                                      E0);
          }
        if (scheme != "backward Euler")
          checker.at_most(tag + "total energy drift (relative) over " +
                            std::to_string(steps.size()) + " steps",
                          worst_drift,
                          1e-10);
        else
          {
            checker.at_most(tag + "largest rise of the total energy in a step "
                                  "(relative)",
                            worst_rise,
                            1e-12);
            checker.above(tag + "energy lost over the run (relative)",
                          worst_drift,
                          1e-3);
          }
      }
  }

  template <int dim>
  void
  angular(Checker &checker)
  {
    auto problem = run_scene<dim>(
      block<dim>("neo-Hookean") +
      time_section("implicit midpoint", "consistent", 1., 0.2, 4.,
                   spinning_velocity<dim>()));
    const auto  &steps = problem->summaries();
    const auto   L0    = steps.front().angular_momentum;
    const double E0    = steps.front().kinetic_energy + steps.front().energy;
    double       drift = 0., energy_drift = 0.;
    for (const auto &s : steps)
      {
        drift = std::max(drift, (s.angular_momentum - L0).norm());
        energy_drift =
          std::max(energy_drift,
                   std::abs(s.kinetic_energy + s.energy - E0) / E0);
      }
    const std::string tag = std::to_string(dim) + "D implicit midpoint, " +
                            "neo-Hookean, " + std::to_string(steps.size()) +
                            " steps: ";
    checker.at_most(tag + "angular momentum drift / |L|", drift / L0.norm(), 1e-10);
    checker.at_most(tag + "total energy drift (relative)", energy_drift, 2e-3);
  }

  template <int dim>
  void
  damped(Checker &checker)
  {
    const bool        three = dim == 3;
    const std::string statics =
      block<dim>("neo-Hookean") +
      subsection("Loading",
                 entry("Number of load steps", "2") +
                   entry("Body force", three ? "0; 0; -0.1" : "0; -0.1")) +
      dirichlet(1, three ? 4 : 2, three ? "x, y, z" : "x, y",
                three ? "0; 0; 0" : "0; 0");
    auto equilibrium = run_scene<dim>(statics);
    for (const std::string damping : {"Mass damping", "Stiffness damping"})
      {
        const std::string value   = damping == "Mass damping" ? "2" : "1";
        auto              settled = run_scene<dim>(
          statics + subsection("Time integration",
                               entry("Scheme", "backward Euler") +
                                 entry("Time step", "0.5") +
                                 entry("End time", "40") +
                                 entry(damping, value)));
        const VectorType &a = settled->solution(),
                         &b = equilibrium->solution();
        double difference = 0., size = 0.;
        for (const auto i : a.locally_owned_elements())
          {
            difference = std::max(difference, std::abs(a(i) - b(i)));
            size       = std::max(size, std::abs(b(i)));
          }
        difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
        size       = Utilities::MPI::max(size, MPI_COMM_WORLD);
        checker.at_most(std::to_string(dim) + "D backward Euler, " + damping +
                          " " + value +
                          ", t = 40: |u - u_static|_max / |u_static|_max",
                        difference / size,
                        1e-6);
      }
  }

  template <int dim>
  void
  linearized(Checker &checker)
  {
    const bool        three = dim == 3;
    const std::string scene =
      subsection("Problem", entry("Dimension", std::to_string(dim))) +
      subsection("Mesh",
                 entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                   entry("Upper corner", three ? "4, 0.5, 0.5" : "4, 0.5") +
                   entry("Subdivisions", three ? "8, 1, 1" : "16, 2")) +
      subsection("Material",
                 entry("Model", "neo-Hookean") + entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0.3")) +
      subsection("Loading",
                 entry("Body force", three ? "0; 0; -0.002" : "0; -0.002")) +
      dirichlet(1, 0, three ? "x, y, z" : "x, y", three ? "0; 0; 0" : "0; 0") +
      tight_solver("direct") +
      subsection("Output",
                 entry("Directory", "dynamics_output") +
                   entry("Write VTU", "false") + entry("Verbose", "false") +
                   entry("Points", three ? "4, 0.25, 0.25" : "4, 0.25"));
    const std::string time =
      entry("Scheme", "Newmark") + entry("Time step", "1") +
      entry("End time", "24");
    auto full = run_scene<dim>(scene + subsection("Time integration", time));
    auto once = run_scene<dim>(
      scene + subsection("Time integration",
                         time + entry("Linearize once per step", "true")));
    unsigned int most = 0, least_full = 1000;
    for (const auto &s : once->summaries())
      most = std::max(most, s.newton_iterations);
    for (const auto &s : full->summaries())
      least_full = std::min(least_full, s.newton_iterations);
    const std::string tag = std::to_string(dim) + "D Newmark, neo-Hookean: ";
    checker.is_true(tag + "linearized: one Newton iteration per step (full "
                          "Newton: at least " +
                      std::to_string(least_full) + ")",
                    most == 1 && least_full > 1);
    const double tip_full = full->summaries().back().point_displacements[0][dim - 1];
    const double tip_once = once->summaries().back().point_displacements[0][dim - 1];
    checker.close(tag + "tip deflection at t = 24, linearized vs full Newton",
                  tip_once,
                  tip_full,
                  std::abs(tip_full),
                  2e-2);
  }

  /// The nu = 0 bar [0, 1] (E = rho = 1, clamped at x = 0, linear
  /// elastic) released in its first mode, v_x = V sin(pi x / 2), on @p n
  /// elements along it, with Newmark, the consistent mass and
  /// @p steps_per_period time steps per exact period 4, for @p periods
  /// periods, with @p stiffness_damping b.
  template <int dim>
  std::unique_ptr<Problem<dim>>
  vibrating_bar(const unsigned int n,
                const unsigned int steps_per_period,
                const double       periods,
                const double       stiffness_damping = 0.)
  {
    const double T = 4., V = 0.01, h = T / steps_per_period;
    const bool   three = dim == 3;
    const std::string text =
      subsection("Problem", entry("Dimension", std::to_string(dim))) +
      subsection("Mesh",
                 entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                   entry("Upper corner", three ? "1, 0.1, 0.1" : "1, 0.1") +
                   entry("Subdivisions",
                         std::to_string(n) + (three ? ", 1, 1" : ", 1"))) +
      subsection("Material",
                 entry("Model", "linear elastic") +
                   entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0")) +
      dirichlet(1, 0, three ? "x, y, z" : "x, y", three ? "0; 0; 0" : "0; 0") +
      tight_solver("direct") +
      time_section("Newmark",
                   "consistent",
                   1.,
                   h,
                   periods * T,
                   number(V) + "*sin(pi*x/2)" + (three ? "; 0; 0" : "; 0"),
                   stiffness_damping) +
      subsection("Output",
                 entry("Directory", "dynamics_output") +
                   entry("Write VTU", "false") + entry("Verbose", "false") +
                   entry("Points", three ? "1, 0.05, 0.05" : "1, 0.05"));
    return run_scene<dim>(text);
  }

  /// The first-mode period of the bar (see vibrating_bar) on @p n elements
  /// along it, with Newmark and @p steps_per_period time steps per exact
  /// period 4: twice the time between the first two zero crossings of the
  /// tip motion (linear interpolation between steps; at a crossing the
  /// motion has no curvature, so the interpolation error is third order).
  template <int dim>
  double
  vibration_period(const unsigned int n, const unsigned int steps_per_period)
  {
    const auto          problem = vibrating_bar<dim>(n, steps_per_period, 1.25);
    std::vector<double> crossings;
    double              t_prev = 0., u_prev = 0.;
    for (const auto &s : problem->summaries())
      {
        const double u = s.point_displacements[0][0];
        if (t_prev > 0. &&
            ((u_prev > 0. && u <= 0.) || (u_prev < 0. && u >= 0.)))
          crossings.push_back(t_prev + (s.load_factor - t_prev) * u_prev /
                                         (u_prev - u));
        t_prev = s.load_factor;
        u_prev = u;
      }
    AssertThrow(crossings.size() >= 2,
                ExcMessage("fewer than two zero crossings of the tip"));
    return 2. * (crossings[1] - crossings[0]);
  }

  /// Stiffness-proportional damping b K0: the bar of vibrating_bar damped
  /// at the ratio zeta = b omega / 2 = 0.05 in its first mode (omega =
  /// pi / 2): over three periods, the logarithmic decrement of successive
  /// positive tip peaks against 2 pi zeta / sqrt(1 - zeta^2) (Newmark, 128
  /// steps a period; the peaks sampled at the steps).
  template <int dim>
  void
  rayleigh(Checker &checker)
  {
    const double zeta = 0.05, omega = 0.5 * M_PI;
    const auto   problem = vibrating_bar<dim>(16, 128, 3.2, 2. * zeta / omega);
    std::vector<double> peaks;
    const auto         &steps = problem->summaries();
    for (unsigned int k = 1; k + 1 < steps.size(); ++k)
      {
        const double u = steps[k].point_displacements[0][0];
        if (u > 0. && u > steps[k - 1].point_displacements[0][0] &&
            u >= steps[k + 1].point_displacements[0][0])
          peaks.push_back(u);
      }
    AssertThrow(peaks.size() >= 3, ExcMessage("fewer than three tip peaks"));
    const double expected = 2. * M_PI * zeta / std::sqrt(1. - zeta * zeta);
    const std::string tag =
      std::to_string(dim) + "D Newmark, stiffness damping for zeta = 0.05: ";
    for (unsigned int k = 0; k + 1 < 3; ++k)
      checker.close(tag + "log decrement, periods " + std::to_string(k + 1) +
                      " -> " + std::to_string(k + 2),
                    std::log(peaks[k] / peaks[k + 1]),
                    expected,
                    expected,
                    1e-2);
  }

  template <int dim>
  void
  vibration(Checker &checker)
  {
    // 16 elements along the bar, 64 steps per period.
    checker.close(std::to_string(dim) + "D Newmark: period of the first mode "
                  "against 4 L sqrt(rho/E)",
                  vibration_period<dim>(16, 64),
                  4.,
                  4.,
                  1e-2);
  }

  /// Orders of the period error: in the time step (16 elements; 16, 32, 64
  /// steps per period against 512) and in the element size (8, 16, 32
  /// elements at 1024 steps per period, against the exact 4).
  template <int dim>
  void
  vibration_order(Checker &checker)
  {
    const std::string tag = std::to_string(dim) + "D Newmark: ";
    const double      fine = vibration_period<dim>(16, 512);
    std::vector<double> dt_errors;
    for (const unsigned int steps : {16u, 32u, 64u})
      dt_errors.push_back(std::abs(vibration_period<dim>(16, steps) - fine));
    for (unsigned int k = 0; k + 1 < dt_errors.size(); ++k)
      checker.at_least(tag + "order of the period error in the time step (" +
                         std::to_string(16 << k) + " -> " +
                         std::to_string(32 << k) + " steps per period)",
                       std::log2(dt_errors[k] / dt_errors[k + 1]),
                       1.8);
    std::vector<double> h_errors;
    for (const unsigned int n : {8u, 16u, 32u})
      h_errors.push_back(std::abs(vibration_period<dim>(n, 1024) - 4.));
    for (unsigned int k = 0; k + 1 < h_errors.size(); ++k)
      checker.at_least(tag + "order of the period error in the element size (" +
                         std::to_string(8 << k) + " -> " +
                         std::to_string(16 << k) + " elements)",
                       std::log2(h_errors[k] / h_errors[k + 1]),
                       1.8);
  }

  /// Problem, Mesh (a box from @p lower to @p upper, corners as the scene
  /// writes them, with @p divisions along each axis) and a neo-Hookean
  /// Material of Young's modulus @p E, nu = 0.3.
  template <int dim>
  std::string
  neo_hookean_box(const std::string &lower,
                  const std::string &upper,
                  const std::string &divisions,
                  const std::string &E)
  {
    std::string d = divisions;
    for (int k = 1; k < dim; ++k)
      d += ", " + divisions;
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Lower corner", lower) +
                        entry("Upper corner", upper) +
                        entry("Subdivisions", d)) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", E) +
                        entry("Poisson's ratio", "0.3"));
  }

  /// No files, no printing.
  std::string
  quiet_output()
  {
    return subsection("Output",
                      entry("Directory", "dynamics_output") +
                        entry("Write VTU", "false") + entry("Verbose", "false"));
  }

  /// The free cube of issue 41 (E = 1, 3 x 3 x 3, side 3, density 1)
  /// under gravity 1, falling for @p end with steps of 0.02.
  template <int dim>
  std::string
  falling_cube(const std::string &scheme,
               const std::string &solver,
               const double       end)
  {
    const bool three = dim == 3;
    return neo_hookean_box<dim>(three ? "0, 0, 0" : "0, 0",
                                three ? "3, 3, 3" : "3, 3",
                                "3",
                                "1") +
           subsection("Loading",
                      entry("Body force", three ? "0; 0; -1" : "0; -1")) +
           (solver == "direct" ? tight_solver("direct") : std::string()) +
           time_section(scheme, "consistent", 1., 0.02, end) + quiet_output();
  }

  template <int dim>
  void
  long_fall(Checker &checker)
  {
    const double mass = dim == 3 ? 27. : 9.; // density 1, gravity 1
    const auto   check = [&](const std::string &scheme,
                           const std::string &solver) {
      auto problem = run_scene<dim>(falling_cube<dim>(scheme, solver, 10.));
      const auto       &steps = problem->summaries();
      const std::string tag   = std::to_string(dim) + "D " + scheme + ", " +
                              solver + ": ";
      unsigned int cut_backs = 0, most_iterations = 0;
      double       momentum_error = 0.;
      for (const auto &s : steps)
        {
          cut_backs += s.cut_backs;
          if (s.step > 0)
            most_iterations = std::max(most_iterations, s.newton_iterations);
          const double expected = -mass * s.load_factor;
          momentum_error =
            std::max(momentum_error,
                     std::abs(s.linear_momentum[dim - 1] - expected) /
                       (mass * std::max(s.load_factor, 0.02)));
        }
      checker.close(tag + "time reached", steps.back().load_factor, 10., 10., 1e-12);
      checker.is_true(tag + "500 steps, no cut-back (" +
                        std::to_string(cut_backs) + " cut-backs, " +
                        std::to_string(steps.size()) + " rows)",
                      cut_backs == 0 && steps.size() >= 500);
      checker.at_most(tag + "max |momentum_z + m g t| / (m g t) over all steps",
                      momentum_error,
                      1e-9);
      checker.at_most(tag + "most Newton iterations in a step",
                      most_iterations,
                      2);
      return problem;
    };
    for (const std::string &scheme : schemes)
      check(scheme, "direct");
    // CG + AMG: the tangent of a rigid motion does not change, nor does the
    // hierarchy.
    const auto iterative = check("Newmark", "CG with AMG");
    checker.at_most(std::to_string(dim) +
                      "D Newmark, CG with AMG: AMG hierarchies built over "
                      "the fall",
                    iterative->n_preconditioner_setups(),
                    1);
  }

  template <int dim>
  void
  long_spin(Checker &checker)
  {
    // A stiff block (E = 100) spinning at omega = 1 about the axis through
    // (2, 0.5, 0.5) (the block is [0, 1]^dim: the axis is off the centre,
    // so the centre of mass circles it), 50 turns of 80 steps.
    const double      omega = 1., turns = 50., per_turn = 80.;
    const double      h     = 2. * M_PI / omega / per_turn;
    const bool        three = dim == 3;
    const std::string velocity =
      three ? "-(y - 0.5); x - 2; 0" : "-(y - 0.5); x - 2";
    auto problem = run_scene<dim>(
      neo_hookean_box<dim>(three ? "0, 0, 0" : "0, 0",
                           three ? "1, 1, 1" : "1, 1",
                           "2",
                           "100") +
      tight_solver("direct") +
      time_section("implicit midpoint", "consistent", 1., h, turns * per_turn * h,
                   velocity) +
      quiet_output());
    const auto  &steps = problem->summaries();
    const auto   L0    = steps.front().angular_momentum;
    const double E0    = steps.front().kinetic_energy + steps.front().energy;
    // Midpoint is symplectic, not energy-conserving, in a nonlinear problem:
    // its energy error oscillates with an amplitude of order h^3.6 here
    // (measured: 5.8e-3 at 40 steps a turn, 4.0e-5 at 160) and does not
    // grow. Held: the amplitude, and no growth from the first 25 turns to
    // the last 25.
    double drift = 0., first_half = 0., second_half = 0.;
    for (const auto &s : steps)
      {
        drift = std::max(drift, (s.angular_momentum - L0).norm());
        const double e = std::abs(s.kinetic_energy + s.energy - E0) / E0;
        (s.load_factor <= 0.5 * turns * per_turn * h ? first_half :
                                                       second_half) =
          std::max(s.load_factor <= 0.5 * turns * per_turn * h ? first_half :
                                                                 second_half,
                   e);
      }
    const std::string tag = std::to_string(dim) + "D implicit midpoint, 50 "
                            "turns of 80 steps about an off-centre axis: ";
    checker.close(tag + "time reached",
                  steps.back().load_factor,
                  turns * per_turn * h,
                  1.,
                  1e-9);
    checker.at_most(tag + "angular momentum drift / |L|", drift / L0.norm(), 1e-9);
    checker.at_most(tag + "total energy error (relative), 50 turns",
                    std::max(first_half, second_half),
                    2e-3);
    checker.at_most(tag + "energy error of turns 26-50 / that of turns 1-25 "
                          "(no drift)",
                    second_half / first_half,
                    1.5);
  }

  template <int dim>
  void
  impact(Checker &checker)
  {
    const bool        three = dim == 3;
    const std::string scene =
      neo_hookean_box<dim>(three ? "0, 0, 0.2" : "0, 0.2",
                           three ? "1, 1, 1.2" : "1, 1.2",
                           "4",
                           "1") +
      subsection("Loading",
                 entry("Body force", three ? "0; 0; -1" : "0; -1")) +
      subsection("Contact",
                 subsection("Obstacle 1",
                            entry("Type", "plane") +
                              entry("Point", three ? "0, 0, 0" : "0, 0") +
                              entry("Normal", three ? "0, 0, 1" : "0, 1"))) +
      quiet_output();
    for (const std::string &scheme : schemes)
      {
        auto problem = run_scene<dim>(
          scene + time_section(scheme, "consistent", 1., 0.02, 1.5));
        const auto &steps = problem->summaries();
        double      closest = 1e300, highest = -1e300, impact_energy = 0.;
        double      rise = -1e300;
        for (std::size_t k = 0; k < steps.size(); ++k)
          {
            const double total = column(steps[k], "total_energy");
            closest =
              std::min(closest, column(steps[k], "contact_min_distance"));
            highest       = std::max(highest, total);
            impact_energy = std::max(impact_energy, steps[k].kinetic_energy);
            if (k > 0)
              rise = std::max(rise,
                              total - column(steps[k - 1], "total_energy"));
          }
        const double      start = column(steps.front(), "total_energy");
        const std::string tag   = std::to_string(dim) + "D drop, " + scheme + ": ";
        checker.close(tag + "time reached", steps.back().load_factor, 1.5, 1.5, 1e-12);
        checker.above(tag + "smallest contact_min_distance over all steps",
                      closest,
                      0.);
        checker.at_most(tag + "(largest total energy - initial) / kinetic "
                              "energy at impact",
                        (highest - start) / impact_energy,
                        1e-2);
        if (scheme == "backward Euler")
          {
            checker.at_most(tag + "largest rise of the total energy in a "
                                  "step / kinetic energy at impact",
                            rise / impact_energy,
                            1e-12);
            checker.above(tag + "energy lost over the run / kinetic energy "
                                "at impact",
                          (start - column(steps.back(), "total_energy")) /
                            impact_energy,
                          1e-2);
          }
      }
  }

  template <int dim>
  void
  run_case(const std::string &which, Checker &checker)
  {
    if (which == "free_fall")
      free_fall<dim>(checker);
    else if (which == "momentum")
      momentum<dim>(checker);
    else if (which == "energy")
      energy<dim>(checker);
    else if (which == "angular")
      angular<dim>(checker);
    else if (which == "damped")
      damped<dim>(checker);
    else if (which == "linearized")
      linearized<dim>(checker);
    else if (which == "rayleigh")
      rayleigh<dim>(checker);
    else if (which == "vibration")
      vibration<dim>(checker);
    else if (which == "vibration_order")
      vibration_order<dim>(checker);
    else if (which == "long_fall")
      long_fall<dim>(checker);
    else if (which == "long_spin")
      long_spin<dim>(checker);
    else if (which == "impact")
      impact<dim>(checker);
    else
      throw std::runtime_error("unknown case " + which);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_case_for_dimension(argc,
                                argv,
                                "free_fall",
                                run_case<2>,
                                run_case<3>);
}
