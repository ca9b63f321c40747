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
//   arch SCENE  the example scene SCENE (parameters/snap_through_arch_*.prm:
//       a clamped shallow arch, point load P t at the crown) by arc length:
//       the path passes the limit point (t then falls below 0.6 of its
//       value there, 'stability' negative) and ends on t = 1 on the far
//       side. The same discrete problem under displacement control (the
//       crown vertex's u_y prescribed along the arc-length crown
//       displacements, 'Dirichlet/Vertex', no point load) gives at every
//       point the same support reaction (1e-6 of the largest) and crown
//       position, and the same limit load (the vertex of the parabola
//       through the three points around the first maximum, 1e-4); the
//       arc-length reactions balance P t (1e-8).
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/loads/boundary_conditions.h>

#include "support/analytic_bar.h"
#include "support/checker.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

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

  /// The text of the scene file @p path, its mesh path made absolute.
  std::string
  scene_file_text(const std::string &path)
  {
    std::ifstream in(path);
    AssertThrow(in, ExcMessage("cannot read " + path));
    std::stringstream text;
    text << in.rdbuf();
    std::string       scene    = text.str();
    const std::string relative = "../meshes/";
    const auto        at       = scene.find(relative);
    if (at != std::string::npos)
      scene.replace(at,
                    relative.size(),
                    path.substr(0, path.rfind('/') + 1) + relative);
    return scene;
  }

  /// An expression of t, linear between t = (k - 1)/n and k/n, that takes
  /// the value @p w[k - 1] at t = k/n and 0 at t = 0 (n = w.size()).
  std::string
  piecewise_linear(const std::vector<double> &w)
  {
    const std::size_t  n = w.size();
    std::ostringstream e;
    e << std::setprecision(17);
    for (std::size_t k = 1; k <= n; ++k)
      {
        const double before = k == 1 ? 0. : w[k - 2];
        e << (k == 1 ? "" : " + ") << "(t > " << double(k - 1) / n
          << ") * (t <= " << double(k) / n << ") * (" << before << " + (" << n
          << " * t - " << k - 1 << ") * (" << w[k - 1] - before << "))";
      }
    return e.str();
  }

  /// The index of the first local maximum of @p y (the limit point).
  std::size_t
  first_maximum(const std::vector<double> &y)
  {
    std::size_t i = 0;
    while (i + 1 < y.size() && y[i + 1] >= y[i])
      ++i;
    return i;
  }

  /// The vertex height of the parabola through the three points around
  /// the first local maximum of @p y (over @p x).
  double
  parabola_peak(const std::vector<double> &x, const std::vector<double> &y)
  {
    const std::size_t i = first_maximum(y);
    if (i == 0 || i + 1 >= y.size())
      return y[i];
    const double x0 = x[i - 1], x1 = x[i], x2 = x[i + 1];
    const double y0 = y[i - 1], y1 = y[i], y2 = y[i + 1];
    // Divided differences: y = y0 + d1 (x - x0) + d2 (x - x0)(x - x1).
    const double d1 = (y1 - y0) / (x1 - x0);
    const double d2 = ((y2 - y1) / (x2 - x1) - d1) / (x2 - x0);
    if (!(d2 < 0.))
      return y[i];
    const double xm = 0.5 * (x0 + x1) - 0.5 * d1 / d2;
    return y0 + d1 * (xm - x0) + d2 * (xm - x0) * (xm - x1);
  }

  /// The upward support reaction of the arch's clamped ends (ids 1, 2).
  template <int dim>
  double
  support_reaction(const StepSummary<dim> &s)
  {
    return column(s, "reaction_1_y") + column(s, "reaction_2_y");
  }

  template <int dim>
  void
  arch(Checker &checker, const std::string &path)
  {
    const std::string tag = std::to_string(dim) + "D arch: ";
    const std::string scene =
      scene_file_text(path) +
      subsection("Output",
                 entry("Write VTU", "false") +
                   entry("Base name", "arch_" + std::to_string(dim) + "d"));
    Parameters parameters;
    parameters.read_from_string(scene);
    AssertThrow(!parameters.loading.point_loads.empty() &&
                  !parameters.output.points.empty(),
                ExcMessage(path + " needs 'Point load 1' and Output/Points"));
    std::string crown;
    for (const double x : parameters.output.points[0])
      crown += (crown.empty() ? "" : ", ") + std::to_string(x);
    // The point load's magnitude P: minus its y force at t = 1.
    const auto force =
      parse_vector_function<dim>(parameters.loading.point_loads[0].expressions,
                                 parameters.loading.constants,
                                 "Point load 1/Force");
    force->set_time(1.);
    const double P = -force->value(Point<dim>(), 1);

    const auto          problem = run_scene<dim>(scene);
    std::vector<double> t, w, reaction;
    double              balance = 0., most_negative = 0.;
    for (const auto &s : problem->summaries())
      {
        t.push_back(s.load_factor);
        w.push_back(column(s, "point1_uy"));
        reaction.push_back(support_reaction(s));
        balance = std::max(balance, std::abs(reaction.back() - P * t.back()));
        most_negative = std::min(most_negative, column(s, "stability"));
      }
    checker.at_least(tag + "arc-length steps", t.size(), 10);
    if (t.size() < 10)
      return;
    const double scale =
      std::max(*std::max_element(reaction.begin(), reaction.end()),
               -*std::min_element(reaction.begin(), reaction.end()));
    checker.at_most(tag + "largest |support reaction - P t| / largest",
                    balance / scale,
                    1e-8);
    checker.is_true(tag + "ends on t = 1 ('Maximum load factor')",
                    t.back() == 1.);
    const std::size_t limit_point = first_maximum(t);
    checker.below(tag + "t at the first maximum (a limit point)",
                  t[limit_point],
                  1.);
    double fall = t[limit_point];
    for (std::size_t k = limit_point; k < t.size(); ++k)
      fall = std::min(fall, t[k]);
    checker.below(tag + "smallest t after the limit point / limit t",
                  fall / t[limit_point],
                  0.6);
    checker.below(tag + "smallest stability (negative past the limit)",
                  most_negative,
                  0.);

    // The same discrete problem under displacement control of the crown.
    const std::string controlled =
      scene + subsection("Load stepping", entry("Method", "load control")) +
      subsection("Loading",
                 entry("Number of load steps", std::to_string(t.size()))) +
      subsection("Point load 1", entry("Point", "")) +
      subsection("Dirichlet 3",
                 entry("Boundary id", "3") + entry("Components", "y") +
                   entry("Vertex", crown) +
                   entry("Displacement", piecewise_linear(w))) +
      subsection("Output",
                 entry("Base name",
                       "arch_controlled_" + std::to_string(dim) + "d"));
    const auto          controlled_problem = run_scene<dim>(controlled);
    double              reaction_error = 0., position_error = 0.;
    unsigned int        matched = 0;
    std::vector<double> w_controlled, reaction_controlled;
    for (const auto &s : controlled_problem->summaries())
      {
        const double      n = s.load_factor * t.size();
        const std::size_t k = std::lround(n);
        if (k == 0 || std::abs(n - k) > 1e-9)
          continue; // a cut-back's intermediate state
        ++matched;
        reaction_error =
          std::max(reaction_error,
                   std::abs(support_reaction(s) - reaction[k - 1]));
        position_error =
          std::max(position_error, std::abs(column(s, "point1_uy") - w[k - 1]));
        w_controlled.push_back(column(s, "point1_uy"));
        reaction_controlled.push_back(support_reaction(s));
      }
    checker.at_least(tag + "displacement-controlled points matched",
                     matched,
                     t.size());
    checker.at_most(tag + "largest |reaction (displacement control) - "
                          "reaction (arc length)| / largest",
                    reaction_error / scale,
                    1e-6);
    checker.at_most(tag + "largest crown position difference / largest",
                    position_error / -*std::min_element(w.begin(), w.end()),
                    1e-9);
    const double limit = parabola_peak(w, reaction);
    checker.close(tag + "limit load, displacement control vs arc length",
                  parabola_peak(w_controlled, reaction_controlled),
                  limit,
                  limit,
                  1e-4);
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
      else if (which == "arch")
        dim == 2 ? arch<2>(checker, argv[3]) : arch<3>(checker, argv[3]);
      else
        throw InputError(
          "usage: arc_length arc_length DIM [DEGREE [pressure]] | "
                  "displacement DIM | "
                  "mixed DIM | load_control DIM | arch DIM SCENE");
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
