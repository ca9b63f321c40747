// Arc-length continuation and the limit-point diagnosis (issue 28) on the
// exact check of the reference: St. Venant-Kirchhoff with lambda = 0 (E = 1,
// nu = 0, mu = 1/2), a bar [0, 2] x [0, 1] (x [0, 1]) with u_x = 0 at x = 0
// and u_y = 0 at y = 0 (and u_z = 0 at z = 0), compressed by the dead
// traction -0.25 t on its end x = 2. The state is homogeneous: stretch l
// along x, lateral stretches 1, and P11 = mu l (l^2 - 1) = -0.25 t gives
//   t = 2 l (1 - l^2),
// whose maximum 4 / (3 sqrt 3) = 0.7698 lies at l = 1 / sqrt 3.
//   arc_length DIM [DEGREE [pressure]]  'Load stepping/Method = arc length'
//       for 30 steps, P1 (default) or P2 elements, the end load dead or
//       ('pressure') a follower pressure 0.25 t (the same load here: the end
//       face keeps its area and normal): every
//       converged (l, t) lies on the curve (1e-8 of the peak load), the path
//       passes the maximum (its largest t within 1e-3 of it) and follows the
//       softening branch down to l < 0.45 with t decreasing there; the CSV's
//       'stability', the stiffness along the path over the unloaded one,
//       is the homogeneous bar's dP11/dl / mu = (3 l^2 - 1) / 2 (1e-6):
//       positive before the maximum, negative after it.
//   displacement DIM  arc length with a prescribed end displacement instead
//       (u_x = -0.8 t at x = 2: l = 1 - 0.4 t) to 'Maximum load factor' 1:
//       every step on l = 1 - 0.4 t (1e-10), the end's reaction equal to
//       |P11| = mu l |l^2 - 1| times its area (1e-8 of the largest), and
//       the run lands on t = 1 exactly.
//   mixed DIM  arc length with the mixed formulation (default element):
//       a decoupled neo-Hookean bar (mu = 1, Lame lambda = 4) pulled by the
//       dead traction 0.5 t to 'Maximum load factor' 1: every step's P11 =
//       0.5 t equals the analytic uniaxial stress at its stretch
//       (support/analytic_bar.h; 1e-8), the pressures left out of the arc
//       length, and the run lands on t = 1.
//   load_control DIM  the same scene under load control to t = 1: the run
//       stops with "the load passed a maximum at t = T; use Load stepping/
//       Method = arc length", T within [0.74, 0.7698].
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>

#include "support/analytic_bar.h"
#include "support/checker.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <cmath>
#include <cstdlib>
#include <string>

namespace
{
  using namespace dealii;
  using namespace hyperelastic;
  using namespace hyperelastic::testing;

  const double peak_load    = 4. / (3. * std::sqrt(3.));
  const double peak_stretch = 1. / std::sqrt(3.);

  std::string
  compressed_bar(const int          dim,
                 const std::string &stepping,
                 const unsigned int degree   = 1,
                 const bool         pressure = false)
  {
    const bool three = dim == 3;
    return subsection("Problem",
                      entry("Dimension", std::to_string(dim)) +
                        entry("Finite element degree",
                              std::to_string(degree))) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "2, 1, 1" : "2, 1") +
                        entry("Subdivisions", three ? "4, 2, 2" : "8, 4")) +
           subsection("Material",
                      entry("Model", "St. Venant-Kirchhoff") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0")) +
           subsection("Loading", entry("Number of load steps", "10")) +
           dirichlet(1, 0, "x", "0") + dirichlet(2, 2, "y", "0") +
           (three ? dirichlet(3, 4, "z", "0") : "") +
           (pressure
              ? subsection("Pressure 1",
                           entry("Boundary id", "1") +
                             entry("Pressure", "0.25*t"))
              : subsection("Traction 1",
                           entry("Boundary id", "1") +
                             entry("Traction",
                                   three ? "-0.25*t; 0; 0" : "-0.25*t; 0"))) +
           subsection("Newton",
                      entry("Absolute residual tolerance", "1e-13") +
                        entry("Relative residual tolerance", "1e-12")) +
           subsection("Linear solver", entry("Relative tolerance", "1e-12")) +
           subsection("Load stepping", stepping) +
           subsection("Output", entry("Write VTU", "false"));
  }

  template <int dim>
  void
  arc_length(Checker &checker, const unsigned int degree, const bool pressure)
  {
    const std::string tag =
      std::to_string(dim) + "D StVK bar, P" + std::to_string(degree) +
      (pressure ? ", follower pressure" : "") + ", arc length: ";
    const auto problem =
      run_scene<dim>(compressed_bar(dim,
                                    entry("Method", "arc length") +
                                      entry("Maximum steps", "30"),
                                    degree,
                                    pressure));
    const auto &steps = problem->summaries();
    double      worst = 0., largest_t = 0., smallest_l = 1.;
    bool        decreasing      = true;
    double      stability_error = 0., most_negative = 0.;
    double      last_t = 0.;
    for (const auto &s : steps)
      {
        const double l = column(s, "deformed_max_x") / 2.;
        const double t = s.load_factor;
        worst          = std::max(worst, std::abs(t - 2. * l * (1. - l * l)));
        largest_t      = std::max(largest_t, t);
        smallest_l     = std::min(smallest_l, l);
        if (l < peak_stretch - 0.02)
          decreasing = decreasing && t < last_t;
        const double stability = column(s, "stability");
        stability_error =
          std::max(stability_error,
                   std::abs(stability - 0.5 * (3. * l * l - 1.)));
        if (std::isnan(stability))
          stability_error = stability;
        most_negative = std::min(most_negative, stability);
        last_t        = t;
      }
    checker.at_least(tag + "converged steps", steps.size(), 30);
    checker.at_most(tag + "largest |t - 2 l (1 - l^2)| / peak load",
                    worst / peak_load,
                    1e-8);
    checker.close(tag + "largest t on the path vs the peak 4 / (3 sqrt 3)",
                  largest_t,
                  peak_load,
                  peak_load,
                  1e-3);
    checker.below(tag + "smallest stretch reached (softening branch)",
                  smallest_l,
                  0.45);
    checker.is_true(tag + "t decreases along the softening branch", decreasing);
    checker.at_most(tag + "largest |stability - (3 l^2 - 1) / 2|",
                    stability_error,
                    1e-6);
    checker.below(tag + "smallest stability (negative past the maximum)",
                  most_negative,
                  -0.1);
  }

  template <int dim>
  void
  displacement(Checker &checker)
  {
    const std::string tag =
      std::to_string(dim) + "D StVK bar, arc length, end displaced: ";
    std::string scene = compressed_bar(dim, entry("Method", "arc length"));
    // The traction becomes a prescribed end displacement.
    const std::string traction = dim == 2 ? "-0.25*t; 0" : "-0.25*t; 0; 0";
    scene.replace(scene.find(traction),
                  traction.size(),
                  dim == 2 ? "0; 0" : "0; 0; 0");
    scene += dirichlet(4, 1, "x", "-0.8*t");
    const auto  problem       = run_scene<dim>(scene);
    const auto &steps         = problem->summaries();
    double      stretch_error = 0., reaction_error = 0., largest = 0.;
    for (const auto &s : steps)
      {
        const double l = column(s, "deformed_max_x") / 2.;
        stretch_error =
          std::max(stretch_error, std::abs(l - (1. - 0.4 * s.load_factor)));
        const double exact = 0.5 * l * std::abs(l * l - 1.);
        reaction_error =
          std::max(reaction_error,
                   std::abs(std::abs(column(s, "reaction_1_x")) - exact));
        largest = std::max(largest, exact);
      }
    checker.at_least(tag + "converged steps", steps.size(), 3);
    checker.at_most(tag + "largest |l - (1 - 0.4 t)|", stretch_error, 1e-10);
    checker.at_most(tag + "largest ||reaction_1_x| - mu l |l^2 - 1|| / "
                          "largest",
                    reaction_error / largest,
                    1e-8);
    checker.is_true(tag + "ends on t = 1 exactly ('Maximum load factor')",
                    !steps.empty() && steps.back().load_factor == 1.);
  }

  template <int dim>
  void
  mixed(Checker &checker)
  {
    const std::string tag   = std::to_string(dim) + "D mixed bar, arc length: ";
    const bool        three = dim == 3;
    const double      mu = 1., lambda = 4., kappa = lambda + 2. / 3. * mu;
    const std::string scene =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Formulation", "mixed")) +
      subsection("Mesh",
                 entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                   entry("Upper corner", three ? "2, 1, 1" : "2, 1") +
                   entry("Subdivisions", three ? "3, 2, 2" : "4, 2")) +
      material_section("decoupled neo-Hookean",
                       entry("Elastic constants", "Lame") +
                         entry("Shear modulus", number(mu)) +
                         entry("Lame lambda", number(lambda)),
                       lame_parameters(mu, lambda)) +
      subsection("Loading", entry("Number of load steps", "4")) +
      dirichlet(1, 0, "x", "0") + dirichlet(2, 2, "y", "0") +
      (three ? dirichlet(3, 4, "z", "0") : "") +
      subsection("Traction 1",
                 entry("Boundary id", "1") +
                   entry("Traction", three ? "0.5*t; 0; 0" : "0.5*t; 0")) +
      subsection("Newton",
                 entry("Relative residual tolerance", "1e-13") +
                   entry("Update tolerance", "1e-12")) +
      subsection("Linear solver", entry("Type", "direct")) +
      subsection("Load stepping", entry("Method", "arc length")) +
      subsection("Output", entry("Write VTU", "false"));
    const auto  problem = run_scene<dim>(scene);
    const auto &steps   = problem->summaries();
    double      worst   = 0.;
    for (const auto &s : steps)
      {
        const double l = column(s, "deformed_max_x") / 2.;
        worst =
          std::max(worst,
                   std::abs(
                     uniaxial_mooney_rivlin(dim, l, 0.5 * mu, 0., kappa).P11 -
                     0.5 * s.load_factor));
      }
    checker.at_least(tag + "converged steps", steps.size(), 3);
    checker.at_most(tag + "largest |P11(l) - 0.5 t| / 0.5", worst / 0.5, 1e-8);
    checker.is_true(tag + "ends on t = 1 exactly ('Maximum load factor')",
                    !steps.empty() && steps.back().load_factor == 1.);
  }

  template <int dim>
  void
  load_control(Checker &checker)
  {
    const std::string tag = std::to_string(dim) + "D StVK bar, load control: ";
    std::string       message;
    try
      {
        run_scene<dim>(compressed_bar(dim, entry("Method", "load control")));
      }
    catch (const ConvergenceFailure &e)
      {
        message = e.what();
      }
    const std::string said = "the load passed a maximum at t = ";
    const auto        at   = message.find(said);
    checker.is_true(tag + "stops with \"" + said + "...\"",
                    at != std::string::npos);
    checker.is_true(tag + "names the remedy",
                    message.find("use Load stepping/Method = arc length") !=
                      std::string::npos);
    if (at == std::string::npos)
      return;
    const double t = std::atof(message.c_str() + at + said.size());
    checker.at_least(tag + "the maximum's t", t, 0.74);
    checker.at_most(tag + "the maximum's t", t, peak_load);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker checker(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const std::string which  = argc > 1 ? argv[1] : "";
  const int         dim    = argc > 2 ? std::atoi(argv[2]) : 2;
  const int         status = run_and_report(
    [&]() {
      const unsigned int degree = argc > 3 ? std::atoi(argv[3]) : 1;
      const bool pressure = argc > 4 && std::string(argv[4]) == "pressure";
      if (which == "arc_length")
        dim == 2 ? arc_length<2>(checker, degree, pressure)
                         : arc_length<3>(checker, degree, pressure);
      else if (which == "mixed")
        dim == 2 ? mixed<2>(checker) : mixed<3>(checker);
      else if (which == "displacement")
        dim == 2 ? displacement<2>(checker) : displacement<3>(checker);
      else if (which == "load_control")
        dim == 2 ? load_control<2>(checker) : load_control<3>(checker);
      else
        throw InputError(
          "usage: arc_length arc_length DIM [DEGREE [pressure]] | "
                  "displacement DIM | "
                  "mixed DIM | load_control DIM");
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
