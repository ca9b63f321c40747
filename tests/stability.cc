// Stability cases of ../shared/reference/stress-tests.md (12 to 17): loads
// far too large for one Newton solve, which the line search and the load-step
// cut-back must handle, and loads past what a model can carry, which must end
// in a reported failure. Every accepted Newton iterate is inspected.
//
// Usage: mpirun -np N stability CASE
//   compress_nh      neo-Hookean block, bottom glued, top plate sliding, to
//                    30 % of its height in one load step
//   compress_snh     stable neo-Hookean block between frictionless plates to
//                    30 % in one step: also against the exact homogeneous state
//   twist_180        neo-Hookean bar twisted by 180 degrees in one load step
//   stvk_limit       St. Venant-Kirchhoff bar pushed by a dead traction past
//                    its compressive limit load
//   projected        the twist with the exact tangent and with the default
//                    fallback to the projected one (when projection helps)
//   locking          cantilever with nu = 0.3 ... 0.499, P1 and P2
//   collective       an error on one MPI rank only reaches every rank
//   crush            stress test 25, the cube clamped top and bottom and
//                    crushed to 10 % in one nominal step: corotational and
//                    stable neo-Hookean with the defaults (<= 20 Newton
//                    iterations per step, no increment below 1/16; the
//                    automatic tangent's predictor extended at zero
//                    Poisson's ratio); stable neo-Hookean with 50
//                    iterations likewise (exact Newton stops at the fold
//                    t = 0.977); both released to u = 0 (1e-10)
//   negative_curvature
//                    the crush with nu = 0.3 in one step of at most 50
//                    iterations: the automatic tangent ends at a saddle;
//                    with Newton/Follow negative curvature the trust
//                    region leaves it for a lower minimum
//   crush_snaps      the two crushes of benchmarks/stability's family that
//                    fold (8^3 boxes nu = 0.4, 6^3 nu = 0.45, to 10 %),
//                    defaults: snap sub-steps, every step <= 20 Newton
//                    iterations, arrive at t = 1, stable end state, no
//                    row of a pseudo time step
//   arch_plate MESH  the shallow arch MESH (meshes/arch_2d.msh) pressed by
//                    a rigid plate to half its height, negative curvature
//                    followed: snaps through, completes, stable states
//   arch_displacement MESH DIM
//                    the example scenes' shallow arch with its crown vertex
//                    pushed to the far side (displacement control): no
//                    cut-back, at most 20 iterations a step, the crown's
//                    reaction changes sign twice
//   shell_plate MESH a quarter hemispherical shell (meshes/hemisphere_
//                    shell_3d.msh) pressed by a rigid plate to half its
//                    height: buckles, the snap step passes the buckle, no
//                    increment below 1/16, stable states, the force falls
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/analytic_bar.h"
#include "support/checker.h"
#include "support/scene_text.h"
#include "support/summary_columns.h"

#include <cmath>
#include <iostream>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  bool print = false;

  struct Run
  {
    std::vector<StepSummary<3>> steps3;
    std::vector<StepSummary<2>> steps2;
    std::string                 failure; ///< empty if the run converged
  };

  template <int dim>
  std::vector<StepSummary<dim>>
  run_scene_text(const std::string &text, std::string &failure)
  {
    Parameters parameters;
    parameters.read_from_string(text);
    parameters.output.write_vtu = false;
    parameters.output.verbose   = false;
    parameters.output.directory = "output_stability";
    Problem<dim> problem(parameters, MPI_COMM_WORLD, print);
    try
      {
        problem.run();
      }
    catch (const ConvergenceFailure &e)
      {
        failure = e.what();
      }
    // Every case expects at least one converged step (checks read the last).
    if (problem.summaries().empty())
      throw ConvergenceFailure("no load step converged:\n" + failure);
    return problem.summaries();
  }

  /// The unit cube of 6 x 6 x 6 boxes, E = 1, in @p load_steps steps.
  std::string
  cube_scene(const std::string &model,
             const double       nu,
             const unsigned int load_steps = 1)
  {
    return subsection("Problem", entry("Dimension", "3")) +
           subsection("Mesh",
                      entry("Upper corner", "1, 1, 1") +
                        entry("Subdivisions", "6, 6, 6")) +
           subsection("Material",
                      entry("Model", model) + entry("Young's modulus", "1") +
                        entry("Poisson's ratio", std::to_string(nu))) +
           subsection("Loading",
                      entry("Number of load steps",
                            std::to_string(load_steps)));
  }

  std::string
  block_scene(const std::string &model,
              const double       nu,
              const bool         glued,
              const std::string &extra = "")
  {
    return cube_scene(model, nu) +
           (glued ? dirichlet(1, 4, "x, y, z", "0; 0; 0") :
                  // frictionless plates, and the planes x = 0, y = 0 fixed
                  // in their normal direction against rigid motions
              dirichlet(1, 4, "z", "0") + dirichlet(3, 0, "x", "0") +
                dirichlet(4, 2, "y", "0")) +
           dirichlet(2, 5, "z", "-0.7*t") + extra;
  }

  /// Checks of case 13 on every accepted iterate of every step.
  template <int dim>
  void
  check_iterates(Checker                             &checker,
                 const std::vector<StepSummary<dim>> &steps,
                 const std::string                   &name)
  {
    double       smallest_J = 1e300, worst_rise = -1e300;
    unsigned int energy_tested = 0, backtracks = 0, cut_backs = 0;
    for (const auto &s : steps)
      {
        cut_backs += s.cut_backs;
        for (const auto &row : s.newton_history)
          {
            // NaN (not computed) must not pass silently.
            smallest_J = std::isfinite(row.min_J)
                           ? std::min(smallest_J, row.min_J)
                           : -1e300;
            backtracks += row.backtracks;
            if (row.energy_tested)
              {
                ++energy_tested;
                // Rise of the energy along the accepted step, in units of
                // its round-off level.
                worst_rise = std::max(worst_rise,
                                      (row.energy - row.energy_before) /
                                        (row.energy_noise + 1e-300));
              }
          }
      }
    if (print)
      std::cout << "  " << name << ": " << steps.size() << " steps, "
                << cut_backs << " cut-backs, " << backtracks
                << " line-search backtracks, " << energy_tested
                << " energy-tested iterations" << std::endl;
    checker.at_least(name + ": min J over all accepted iterates",
                     smallest_J,
                     1e-12);
    checker.at_most(name + ": energy rise along a line search / noise",
                    worst_rise,
                    2.);
    checker.at_least(name + ": iterations with the energy tested",
                     energy_tested,
                     1);
  }

  unsigned int
  total_newton_iterations(const std::vector<StepSummary<3>> &steps)
  {
    unsigned int n = 0;
    for (const auto &s : steps)
      n += s.newton_iterations;
    return n;
  }

  unsigned int
  total_cut_backs(const std::vector<StepSummary<3>> &steps)
  {
    unsigned int n = 0;
    for (const auto &s : steps)
      n += s.cut_backs;
    return n;
  }

  void
  compress_nh(Checker &checker)
  {
    std::string failure;
    const auto  steps =
      run_scene_text<3>(block_scene("neo-Hookean", 0.3, true), failure);
    checker.is_true("glued neo-Hookean block reaches 30 % height",
                    failure.empty() && steps.back().load_factor == 1.);
    check_iterates(checker, steps, "neo-Hookean");
    checker.at_least("converged min J", steps.back().min_J, 1e-3);
  }

  void
  compress_snh(Checker &checker)
  {
    std::string failure;
    const auto  steps =
      run_scene_text<3>(block_scene("stable neo-Hookean", 0.3, false), failure);
    checker.is_true("stable neo-Hookean block reaches 30 % height",
                    failure.empty() && steps.back().load_factor == 1.);
    check_iterates(checker, steps, "stable neo-Hookean");
    // Homogeneous: compare the lateral stretch with the exact one.
    const double mu = 1. / 2.6, lambda = 0.3 / (1.3 * 0.4);
    const auto   exact = uniaxial("stable neo-Hookean", 3, 0.3, mu, lambda);
    const double l2    = steps.back().deformed_max[0];
    checker.at_most("lateral stretch against the exact one",
                    std::abs(l2 - exact.l2) / exact.l2,
                    1e-8);
  }

  /// Neo-Hookean bar 3 x 1 x 1 clamped at x = 0, its end x = 3 turned by
  /// 180 degrees about the axis (y, z) = (0.5, 0.5) in one load step.
  std::string
  twist_scene(const std::string &newton_entries = "")
  {
    return subsection("Problem", entry("Dimension", "3")) +
           subsection("Mesh",
                      entry("Upper corner", "3, 1, 1") +
                        entry("Subdivisions", "12, 4, 4")) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading", entry("Number of load steps", "1")) +
           dirichlet(1, 0, "x, y, z", "0; 0; 0") +
           dirichlet(2,
                     1,
                     "x, y, z",
                     "0; 0.5 + (y - 0.5)*cos(pi*t) - (z - 0.5)*sin(pi*t) - y; "
                     "0.5 + (y - 0.5)*sin(pi*t) + (z - 0.5)*cos(pi*t) - z") +
           (newton_entries.empty() ? std::string()
                                   : subsection("Newton", newton_entries));
  }

  void
  twist_180(Checker &checker)
  {
    std::string failure;
    const auto  steps = run_scene_text<3>(twist_scene(), failure);
    checker.is_true("bar twisted by 180 degrees in one step arrives",
                    failure.empty() && steps.back().load_factor == 1.);
    checker.at_least("cut-backs on the way", total_cut_backs(steps), 1);
    check_iterates(checker, steps, "twist");
  }

  void
  stvk_limit(Checker &checker)
  {
    // Homogeneous bar on rollers; P11 = E l (l^2 - 1) / 2 has its minimum
    // -E / (3 sqrt 3) at l = 1 / sqrt 3: a compressive dead load beyond it
    // has no solution with J > 0. Traction -0.25 E t: the limit is at
    // t* = 0.7698.
    const double      t_limit = 1. / (3. * std::sqrt(3.)) / 0.25;
    const std::string scene =
      subsection("Problem", entry("Dimension", "3")) +
      subsection("Mesh",
                 entry("Upper corner", "3, 1, 1") +
                   entry("Subdivisions", "3, 1, 1")) +
      subsection("Material",
                 entry("Model", "St. Venant-Kirchhoff") +
                   entry("Young's modulus", "1") +
                   entry("Poisson's ratio", "0.3")) +
      subsection("Loading", entry("Number of load steps", "10")) +
      subsection("Load stepping", entry("Minimum increment", "1e-3")) +
      dirichlet(1, 0, "x", "0") + dirichlet(2, 2, "y", "0") +
      dirichlet(3, 4, "z", "0") +
      subsection("Traction 1",
                 entry("Boundary id", "1") +
                   entry("Traction", "-0.25*t; 0; 0"));
    std::string failure;
    const auto  steps = run_scene_text<3>(scene, failure);
    if (print)
      std::cout << "  failure message: " << failure.substr(0, 300) << "..."
                << std::endl;
    checker.is_true("past the limit load the run fails",
                    failure.find("cannot be halved again") !=
                      std::string::npos);
    checker.at_most("last converged t", steps.back().load_factor, t_limit);
    checker.at_least("last converged t", steps.back().load_factor, 0.75);
    double smallest_J = 1e300;
    for (const auto &s : steps)
      smallest_J = std::min(smallest_J, s.min_J);
    checker.at_least("min J of every converged step", smallest_J, 1e-12);
  }

  void
  projected(Checker &checker)
  {
    // The 180-degree twist with the exact tangent only, and with the default
    // (exact, repeated with the projected tangent when the exact direction
    // does not descend or its line search fails). The exact tangent is
    // indefinite on the way; the projection turns a would-be cut-back into
    // a step.
    unsigned int iterations[2], cut_backs[2], projected_iterations[2];
    const char  *names[2] = {"exact", "exact, projected on failure"};
    for (unsigned int k = 0; k < 2; ++k)
      {
        std::string failure;
        const auto  steps =
          run_scene_text<3>(twist_scene(entry("Tangent", names[k])), failure);
        checker.is_true(std::string("tangent '") + names[k] + "' arrives",
                        failure.empty() && steps.back().load_factor == 1.);
        iterations[k]           = total_newton_iterations(steps);
        cut_backs[k]            = total_cut_backs(steps);
        projected_iterations[k] = 0;
        for (const auto &s : steps)
          for (const auto &row : s.newton_history)
            projected_iterations[k] += row.projected ? 1 : 0;
        if (print)
          std::cout << "  tangent '" << names[k] << "': " << steps.size()
                    << " load steps, " << cut_backs[k] << " cut-backs, "
                    << iterations[k] << " Newton iterations in converged "
                    << "steps, " << projected_iterations[k]
                    << " with the projected tangent" << std::endl;
      }
    checker.at_least("exact tangent: cut-backs", cut_backs[0], 1);
    checker.is_true("exact tangent: no projected iteration",
                    projected_iterations[0] == 0);
    checker.at_least("fallback: projected iterations",
                     projected_iterations[1],
                     1);
    checker.at_most("fallback: cut-backs (fewer than exact)",
                    cut_backs[1],
                    double(cut_backs[0]) - 1.);
    checker.at_most("fallback: Newton iterations (not more than exact)",
                    iterations[1],
                    iterations[0]);
  }

  void
  locking(Checker &checker)
  {
    // 2D cantilever 10 x 1 clamped at x = 0, a small shear traction at x = 10
    // (tip deflection about 2 % of the length: the locking, not the
    // nonlinearity, is measured). P1 locks as nu -> 0.5, P2 much less.
    double previous_ratio = 1.1, p2_first = 0., p2_last = 0.;
    for (const double nu : {0.3, 0.45, 0.49, 0.499})
      {
        double tip[2];
        for (const unsigned int degree : {1u, 2u})
          {
            const std::string scene =
              subsection("Problem",
                         entry("Dimension", "2") +
                           entry("Finite element degree",
                                 std::to_string(degree))) +
              subsection("Mesh",
                         entry("Lower corner", "0, 0") +
                           entry("Upper corner", "10, 1") +
                           entry("Subdivisions", "20, 2")) +
              subsection("Material",
                         entry("Model", "neo-Hookean") +
                           entry("Young's modulus", "1000") +
                           entry("Poisson's ratio", std::to_string(nu))) +
              subsection("Loading", entry("Number of load steps", "1")) +
              dirichlet(1, 0, "x, y", "0; 0") +
              subsection("Traction 1",
                         entry("Boundary id", "1") +
                           entry("Traction", "0; -0.005*t"));
            std::string failure;
            const auto  steps = run_scene_text<2>(scene, failure);
            checker.is_true("nu = " + std::to_string(nu) + ", P" +
                              std::to_string(degree) + " converges",
                            failure.empty() && steps.back().load_factor == 1.);
            tip[degree - 1] = -steps.back().deformed_min[1];
          }
        const double ratio = tip[0] / tip[1];
        p2_first           = p2_first == 0. ? tip[1] : p2_first;
        p2_last            = tip[1];
        if (print)
          std::cout << "  nu = " << nu << ": deflection P1 " << tip[0]
                    << ", P2 " << tip[1] << ", P1/P2 " << ratio << std::endl;
        checker.at_most("P1/P2 deflection ratio falls as nu grows",
                        ratio,
                        previous_ratio);
        previous_ratio = ratio;
      }
    checker.at_most("P1/P2 deflection at nu = 0.499", previous_ratio, 0.1);
    // Without locking, beam theory in plane strain scales the deflection by
    // (1 - nu^2): P2 follows it within 10 %.
    const double beam = (1. - 0.499 * 0.499) / (1. - 0.3 * 0.3);
    checker.at_least("P2 deflection 0.499 / 0.3 over beam theory's",
                     p2_last / p2_first / beam,
                     0.9);
    checker.at_most("P2 deflection 0.499 / 0.3 over beam theory's",
                    p2_last / p2_first / beam,
                    1.1);
  }

  void
  collective(Checker &checker)
  {
    // Case 17: an error raised on one rank only (here the last) reaches
    // every rank as the same ConvergenceFailure; no error, no exception.
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    std::string        message;
    try
      {
        throw_convergence_failure_if_any(rank == n_ranks - 1 ? "NaN in cell 7"
                                                             : "",
                                         comm);
      }
    catch (const ConvergenceFailure &e)
      {
        message = e.what();
      }
    const std::string expected =
      (n_ranks > 1 ? "on MPI rank " + std::to_string(n_ranks - 1) + ", "
                   : std::string()) +
      "NaN in cell 7";
    const unsigned int agree =
      dealii::Utilities::MPI::min(message == expected ? 1u : 0u, comm);
    checker.is_true("every rank gets the failing rank's message", agree == 1);
    bool thrown = false;
    try
      {
        throw_convergence_failure_if_any("", comm);
      }
    catch (const ConvergenceFailure &)
      {
        thrown = true;
      }
    checker.is_true("no error anywhere: no exception",
                    dealii::Utilities::MPI::max(thrown ? 1u : 0u, comm) == 0);
  }

  /// Stress test 25: the cube clamped top and bottom, crushed to 10 % of
  /// its height in one nominal step (released again with @p release: the
  /// top returns over a second step).
  std::string
  crush_scene(const std::string &model,
              const std::string &tangent,
              const unsigned int max_iterations,
              const bool         release)
  {
    return cube_scene(model, 0.4, release ? 2 : 1) +
           subsection("Newton",
                      entry("Tangent", tangent) +
                        entry("Max iterations",
                              std::to_string(max_iterations))) +
           subsection("Output",
                      entry("Points", "0.5, 0.5, 0.5; 0.25, 0.75, 0.5")) +
           dirichlet(1, 4, "x, y, z", "0; 0; 0") +
           dirichlet(2,
                     5,
                     "x, y, z",
                     release ? "0; 0; -0.9*(t <= 0.5 ? 2*t : 2 - 2*t)"
                             : "0; 0; -0.9*t");
  }

  /// What a crush run reached.
  struct CrushRun
  {
    bool         arrived        = false;
    double       last_t         = 0.;
    unsigned int most           = 0; ///< Newton iterations of the worst step
    unsigned int total          = 0;
    double       smallest_step  = 1.;
    double       largest_u_back = 0.; ///< |u| at the points at the end
  };

  CrushRun
  crush(const std::string &model,
        const std::string &tangent,
        const unsigned int max_iterations,
        const bool         release,
        const std::string &extra = "")
  {
    std::string failure;
    const auto  steps = run_scene_text<3>(
      crush_scene(model, tangent, max_iterations, release) + extra, failure);
    CrushRun run;
    run.last_t  = steps.back().load_factor;
    run.arrived = failure.empty() && run.last_t == 1.;
    for (const auto &s : steps)
      {
        run.most = std::max(run.most, s.newton_iterations);
        run.total += s.newton_iterations;
        run.smallest_step = std::min(run.smallest_step, s.load_increment);
      }
    for (const auto &u : steps.back().point_displacements)
      run.largest_u_back = std::max(run.largest_u_back, u.norm());
    if (print)
      std::cout << "  " << model << ", Tangent = " << tangent
                << ", Max iterations = " << max_iterations
                << (release ? ", crush and release" : "") << ": "
                << steps.size() << " steps to t = " << run.last_t << ", "
                << run.total << " Newton iterations, at most " << run.most
                << " per step, smallest increment " << run.smallest_step
                << std::endl;
    return run;
  }

  void
  crush_25(Checker &checker)
  {
    // Corotational: default settings.
    const CrushRun co = crush("corotational", "automatic", 20, false);
    checker.is_true("corotational, defaults: arrives at t = 1", co.arrived);
    checker.at_most("corotational, defaults: Newton iterations per step",
                    co.most,
                    20);
    checker.at_least("corotational, defaults: smallest increment",
                     co.smallest_step,
                     1. / 16.);
    // Stable neo-Hookean, default settings: the tangent's predictor would
    // invert cells; extended at zero Poisson's ratio, Newton converges in
    // one step (19 iterations on 1 rank).
    const CrushRun snh20 = crush("stable neo-Hookean", "automatic", 20, false);
    checker.is_true("stable neo-Hookean, defaults: arrives at t = 1",
                    snh20.arrived);
    checker.at_most("stable neo-Hookean, defaults: Newton iterations per step",
                    snh20.most,
                    20);
    checker.at_least("stable neo-Hookean, defaults: smallest increment",
                     snh20.smallest_step,
                     1. / 16.);
    // The exact path folds at t = 0.977 (benchmarks/stability); the
    // automatic tangent leaves it for states of lower energy with 50
    // iterations, where exact Newton stops.
    const CrushRun snh = crush("stable neo-Hookean", "automatic", 50, false);
    checker.is_true("stable neo-Hookean, automatic, 50 iterations: arrives",
                    snh.arrived);
    checker.at_least("stable neo-Hookean, automatic: smallest increment",
                     snh.smallest_step,
                     1. / 16.);
    checker.at_most("stable neo-Hookean, automatic: Newton iterations per "
                    "step",
                    snh.most,
                    50);
    // Exact Newton alone (no snap sub-steps) stops at the fold; with them
    // (the default) it passes it (9 steps, at most 11 iterations in one, on
    // 2 ranks).
    const CrushRun exact =
      crush("stable neo-Hookean",
            "exact",
            50,
            false,
            subsection("Load stepping",
                       entry("Snap sub-step iterations", "0")));
    checker.is_true("stable neo-Hookean, exact, 50 iterations: stops",
                    !exact.arrived);
    checker.below("stable neo-Hookean, exact: last t (the fold)",
                  exact.last_t,
                  0.98);
    const CrushRun exact_snaps =
      crush("stable neo-Hookean", "exact", 50, false);
    checker.is_true("stable neo-Hookean, exact, with snap sub-steps: arrives",
                    exact_snaps.arrived);
    checker.at_most("stable neo-Hookean, exact, with snap sub-steps: Newton "
                    "iterations per step",
                    exact_snaps.most,
                    20);
    // Released, both spring back to u = 0 with the defaults (the crushed
    // state of stable neo-Hookean is the one reached from the predictor
    // extended at zero Poisson's ratio, on 1 and 2 ranks alike).
    const CrushRun back = crush("corotational", "automatic", 20, true);
    checker.is_true("corotational, crushed and released: arrives",
                    back.arrived);
    checker.at_most("corotational, released: largest |u| at the points",
                    back.largest_u_back,
                    1e-10);
    const CrushRun snh_back =
      crush("stable neo-Hookean", "automatic", 20, true);
    checker.is_true("stable neo-Hookean, defaults, crushed and released: "
                    "arrives",
                    snh_back.arrived);
    checker.at_most("stable neo-Hookean, defaults, released: Newton "
                    "iterations per step",
                    snh_back.most,
                    20);
    checker.at_most("stable neo-Hookean, released: largest |u| at the points",
                    snh_back.largest_u_back,
                    1e-10);
  }

  /// The two crushes of the crush family (benchmarks/stability) whose path
  /// folds under displacement control: 8 x 8 x 8 boxes with nu = 0.4 and
  /// 6 x 6 x 6 with nu = 0.45, crushed to 10 % in one nominal step, stable
  /// neo-Hookean, default settings. Where the cut-backs would go below 1/16
  /// of the nominal increment, the snap sub-steps carry the step to its
  /// load factor: every step (sub-steps included) within 'Newton/Max
  /// iterations' = 20, some sub-steps at the snap's load factor, the run
  /// at t = 1, its last state an undamped equilibrium probed stable (1 rank,
  /// measured: 8 steps, at most 13 iterations, and 17 steps, at most 17).
  void
  crush_snaps(Checker &checker)
  {
    for (const auto &[boxes, nu] :
         {std::pair<unsigned int, double>{8, 0.4}, {6, 0.45}})
      {
        const std::string n = std::to_string(boxes);
        std::string       scene =
          cube_scene("stable neo-Hookean", nu) +
          dirichlet(1, 4, "x, y, z", "0; 0; 0") +
          dirichlet(2, 5, "x, y, z", "0; 0; -0.9*t");
        const std::string six = "Subdivisions = 6, 6, 6";
        scene.replace(scene.find(six), six.size(),
                      "Subdivisions = " + n + ", " + n + ", " + n);
        std::string failure;
        const auto  steps = run_scene_text<3>(scene, failure);
        const std::string name =
          n + "^3, nu = " + (nu == 0.4 ? "0.4" : "0.45") + ": ";
        unsigned int most = 0, not_increasing = 0, snapped = 0;
        double       previous_t = -1., previous_increment = 1.;
        for (const auto &s : steps)
          {
            most = std::max(most, s.newton_iterations);
            not_increasing += !(s.load_factor > previous_t);
            // A step reached by a snap (issue 57: the sub-steps are no rows
            // of their own): the snap step's and its failure's cut-backs,
            // and an increment beyond the doubling after easy steps (the
            // snap's nominal one), or the four halvings before them too.
            snapped += (s.cut_backs >= 2 &&
                        s.load_increment > 2. * previous_increment) ||
                       s.cut_backs >= 6;
            previous_t         = s.load_factor;
            previous_increment = s.load_increment;
          }
        if (print)
          std::cout << "  " << name << steps.size() << " steps, " << snapped
                    << " reached by snap sub-steps, at most " << most
                    << " Newton iterations in a step" << std::endl;
        checker.is_true(name + "arrives at t = 1",
                        failure.empty() && steps.back().load_factor == 1.);
        checker.at_most(name + "Newton iterations in a step", most, 20);
        checker.at_least(name + "steps reached by snap sub-steps", snapped, 1);
        checker.close(name + "rows whose load factor does not increase "
                             "(pseudo time steps)",
                      not_increasing,
                      0.,
                      1.,
                      1e-14);
        checker.is_true(name + "the last state probed stable",
                        steps.back().newton_history.back().probed_stable);
      }
  }

  /// Newton/Follow negative curvature on the crush of stress test 25 with
  /// nu = 0.3, in one step of at most 50 Newton iterations: the automatic
  /// tangent converges to a saddle (0.2496119; the exact tangent there has
  /// negative curvature); following that curvature in a trust region,
  /// Newton leaves it for a minimum of lower energy (0.2459701 on 1 rank
  /// in 28 iterations, 0.24526 on 2), every trust-region step lowering the
  /// energy, and ends with interior (Newton) steps.
  void
  negative_curvature(Checker &checker)
  {
    const auto scene = [](const std::string &follow) {
      return cube_scene("stable neo-Hookean", 0.3) +
             subsection("Newton",
                        entry("Max iterations", "50") +
                          entry("Follow negative curvature", follow)) +
             dirichlet(1, 4, "x, y, z", "0; 0; 0") +
             dirichlet(2, 5, "x, y, z", "0; 0; -0.9*t");
    };
    std::string failure;
    const auto  saddle = run_scene_text<3>(scene("false"), failure);
    checker.is_true("projected where J <= 0: converges in one step",
                    failure.empty() && saddle.size() == 1);
    checker.close("projected where J <= 0: energy (a saddle)",
                  saddle.back().energy,
                  0.2496119,
                  0.2496119,
                  1e-6);
    bool any_trust_region = false;
    for (const auto &row : saddle.back().newton_history)
      any_trust_region = any_trust_region || std::isfinite(row.trust_radius);
    checker.is_true("projected where J <= 0: no trust region",
                    !any_trust_region);

    const auto followed = run_scene_text<3>(scene("true"), failure);
    checker.is_true("negative curvature followed: converges in one step",
                    failure.empty() && followed.size() == 1);
    checker.below("negative curvature followed: energy below the saddle's",
                  followed.back().energy,
                  saddle.back().energy - 1e-3);
    unsigned int trust_rows = 0, curvature_rows = 0, untested = 0;
    double       worst_rise = -1e300;
    for (const auto &row : followed.back().newton_history)
      if (std::isfinite(row.trust_radius))
        {
          ++trust_rows;
          curvature_rows += row.negative_curvature;
          untested += !row.energy_tested;
          worst_rise = std::max(worst_rise,
                                (row.energy - row.energy_before) /
                                  (row.energy_noise + 1e-300));
        }
    if (print)
      std::cout << "  followed: " << followed.back().newton_iterations
                << " Newton iterations, " << trust_rows
                << " in the trust region, " << curvature_rows
                << " with negative curvature; energy " << followed.back().energy
                << std::endl;
    checker.at_least("trust-region rows", trust_rows, 3);
    checker.is_true("every trust-region row tested the energy", untested == 0);
    checker.at_least("rows that met negative curvature", curvature_rows, 1);
    checker.at_most("energy rise along a trust-region step (round-off units)",
                    worst_rise,
                    1.);
    checker.is_true("the last iteration is an interior Newton step",
                    !followed.back().newton_history.back().negative_curvature);
    checker.is_true("the converged state probed: no negative curvature",
                    followed.back().newton_history.back().probed_stable);
  }

  /// A structure of the mesh file @p mesh (neo-Hookean, E = 1000,
  /// nu = 0.3; 10 nominal load steps; negative curvature followed, for the
  /// probe of the accepted states) held by @p supports (Dirichlet
  /// sections) and pressed by a rigid frictionless plane through @p point
  /// with normal @p normal (into the body) moved by @p motion; the output
  /// point @p probe.
  std::string
  plate_scene(const int          dim,
              const std::string &mesh,
              const std::string &supports,
              const std::string &point,
              const std::string &normal,
              const std::string &motion,
              const std::string &probe)
  {
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1000") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading", entry("Number of load steps", "10")) +
           subsection("Newton", entry("Follow negative curvature", "true")) +
           supports +
           subsection("Contact",
                      subsection("Obstacle 1",
                                 entry("Type", "plane") +
                                   entry("Point", point) +
                                   entry("Normal", normal) +
                                   entry("Motion", motion))) +
           subsection("Output", entry("Points", probe));
  }

  /// A snap under displacement control: the clamped shallow arch of
  /// meshes/arch_2d.msh (span 2, rise 0.2, thickness 0.02, neo-Hookean
  /// E = 1000) pressed at its crown by a rigid plate moving down by half
  /// the arch's height (0.105) in 10 nominal steps, CG with AMG and
  /// Newton/Follow negative curvature. The arch buckles and snaps through
  /// ahead of the plate: the run completes, no increment falls below 1/16
  /// of the nominal one, every accepted state is probed stable (no
  /// negative curvature of the exact tangent), and the plate force drops
  /// after the buckle (1 rank: 0.0504 at t = 0.7, 0.0195 at t = 1; the
  /// crown moves 8 times as far as the plate in the step of the snap).
  void
  arch_plate(Checker &checker, const std::string &mesh)
  {
    const std::string scene =
      plate_scene(2,
                  mesh,
                  dirichlet(1, 1, "x, y", "0; 0") +
                    dirichlet(2, 2, "x, y", "0; 0"),
                  "0, 0.211",
                  "0, -1",
                  "0; -0.105*t",
                  "0, 0.21");
    std::string failure;
    const auto  steps = run_scene_text<2>(scene, failure);
    checker.is_true("arch under the plate: arrives at t = 1",
                    failure.empty() && steps.back().load_factor == 1.);
    double       smallest = 1., largest_force = 0., force_peak_t = 0.;
    double       largest_ratio = 0., previous_uy = 0., previous_t = 0.;
    unsigned int stable = 0;
    for (const auto &s : steps)
      {
        smallest = std::min(smallest, s.load_increment);
        stable += s.newton_history.back().probed_stable;
        const double force = -column(s, "contact_force_1_y");
        if (force > largest_force)
          {
            largest_force = force;
            force_peak_t  = s.load_factor;
          }
        // Crown travel over plate travel (0.105 per unit of t).
        const double uy = column(s, "point1_uy");
        largest_ratio =
          std::max(largest_ratio,
                   (previous_uy - uy) / (0.105 * (s.load_factor - previous_t)));
        previous_uy = uy;
        previous_t  = s.load_factor;
      }
    const double final_force = -column(steps.back(), "contact_force_1_y");
    if (print)
      std::cout << "  " << steps.size() << " steps, smallest increment "
                << smallest << ", largest plate force " << largest_force
                << " at t = " << force_peak_t << ", at the end " << final_force
                << std::endl;
    checker.at_least("smallest increment / nominal (0.1)",
                     smallest / 0.1,
                     1. / 16.);
    checker.is_true("every accepted state probed stable",
                    stable == steps.size());
    checker.below("t of the largest plate force (the buckle)",
                  force_peak_t,
                  1.);
    checker.below("plate force at the end / largest",
                  final_force / largest_force,
                  0.5);
    checker.at_least("largest crown travel / plate travel in a step (the "
                     "snap)",
                     largest_ratio,
                     4.);
  }

  /// A quarter of a thin hemispherical shell (MESH:
  /// meshes/hemisphere_shell_3d.msh, R = 1, t = 0.02, 3270 tetrahedra,
  /// symmetry planes on rollers, the rim clamped) pressed at its apex by a
  /// rigid frictionless plate to half its height (0.5) in 10 nominal steps,
  /// negative curvature followed (for the probe of the accepted states).
  /// The shell buckles near a plate travel of 0.2: the apex region inverts
  /// and leaves the plate. The snap step (Load stepping/Snap iterations;
  /// since issue 44's sub-steps: its one solve fails, and 7 snap sub-steps
  /// and an undamped solve follow on 1 rank) takes the run past it: it
  /// arrives at t = 1, no accepted increment below 1/16 of the nominal one,
  /// every accepted state probed stable, and from the equilibrium before
  /// the buckle to the one after it the plate force falls while the apex
  /// moves several times as far as the plate (with one solve: 0.211 to
  /// 0.170, 4.8). The snap sub-steps are no equilibria and have no rows
  /// (issue 57): the load factors increase strictly, and no row's plate
  /// force is a spike against its neighbours' (a sub-step's row was 88
  /// against 0.2 around it).
  void
  shell_plate(Checker &checker, const std::string &mesh)
  {
    const std::string scene =
      plate_scene(3,
                  mesh,
                  dirichlet(1, 1, "x, y, z", "0; 0; 0") +
                    dirichlet(2, 2, "x", "0") + dirichlet(3, 3, "y", "0"),
                  "0, 0, 1.0105",
                  "0, 0, -1",
                  "0; 0; -0.5*t",
                  "0, 0, 1.01");
    std::string failure;
    const auto  steps = run_scene_text<3>(scene, failure);
    checker.is_true("hemispherical shell under the plate: arrives at t = 1",
                    failure.empty() && steps.back().load_factor == 1.);
    double       smallest = 1., largest_drop = 1., drop_ratio = 0.;
    double       previous_force = 0., previous_uz = 0., previous_t = 0.;
    unsigned int stable = 0, not_increasing = 0;
    // The largest plate force of a row against the larger of its
    // neighbours' (a spike: a pseudo time step's row, issue 57).
    double spike = 0.;
    for (unsigned int k = 1; k + 1 < steps.size(); ++k)
      {
        const double f = -column(steps[k], "contact_force_1_z");
        const double around =
          std::max(std::abs(column(steps[k - 1], "contact_force_1_z")),
                   std::abs(column(steps[k + 1], "contact_force_1_z")));
        if (around > 0.)
          spike = std::max(spike, f / around);
      }
    for (unsigned int k = 0; k < steps.size(); ++k)
      {
        const auto &s = steps[k];
        smallest      = std::min(smallest, s.load_increment);
        stable += s.newton_history.back().probed_stable;
        if (print)
          std::cout << "  t " << s.load_factor << ": "
                    << s.newton_history.size() << " Newton iterations, "
                    << "plate force " << -column(s, "contact_force_1_z")
                    << ", apex u_z " << column(s, "point1_uz") << std::endl;
        not_increasing += k > 0 && !(s.load_factor > steps[k - 1].load_factor);
        const double force = -column(s, "contact_force_1_z");
        const double uz    = column(s, "point1_uz");
        if (previous_force > 0. && force / previous_force < largest_drop)
          {
            largest_drop = force / previous_force;
            // Apex travel over plate travel (0.5 per unit of t).
            drop_ratio = (previous_uz - uz) / (0.5 * (s.load_factor - previous_t));
          }
        previous_force = force;
        previous_uz    = uz;
        previous_t     = s.load_factor;
      }
    if (print)
      std::cout << "  " << steps.size() << " steps, smallest increment "
                << smallest << ", largest fall of the plate force in a step "
                << largest_drop << " (apex / plate travel " << drop_ratio
                << ")" << std::endl;
    checker.at_least("smallest increment / nominal (0.1)",
                     smallest / 0.1,
                     1. / 16.);
    checker.is_true("every accepted state probed stable",
                    stable == steps.size());
    checker.below("plate force after / before the step of the buckle",
                  largest_drop,
                  0.9);
    checker.at_least("apex travel / plate travel in that step (the snap)",
                     drop_ratio,
                     3.);
    checker.close("rows whose load factor does not increase (pseudo time "
                  "steps)",
                  not_increasing,
                  0.,
                  1.,
                  1e-14);
    checker.at_most("plate force of a row / its neighbours' (no spike)",
                    spike,
                    2.);
  }

  /// The shallow arch of the example scenes (MESH: meshes/arch_<dim>d.msh,
  /// clamped ends) under displacement control: the crown's top vertex
  /// pushed down by 0.42 (twice its height: to the mirror image of the
  /// arch) in 20 load steps, load control, direct solver. The path passes
  /// the limit point and the snap-through: the crown's vertical reaction
  /// resists, then holds the arch back (changes sign), then pushes it on
  /// beyond the inverted equilibrium (changes sign again). Measured: 5 to 7
  /// Newton iterations per step, no cut-back, in 2D and 3D.
  void
  arch_displacement(Checker &checker, const std::string &mesh, const int dim)
  {
    const bool        three = dim == 3;
    const std::string crown = three ? "0, 0.21, 0.05" : "0, 0.21";
    const std::string scene =
      subsection("Problem", entry("Dimension", std::to_string(dim))) +
      subsection("Mesh", entry("Source", "file") + entry("File", mesh)) +
      subsection("Material",
                 entry("Model", "neo-Hookean") +
                   entry("Young's modulus", "1000") +
                   entry("Poisson's ratio", "0.3")) +
      subsection("Loading", entry("Number of load steps", "20")) +
      subsection("Linear solver", entry("Type", "direct")) +
      dirichlet(1, 1, three ? "x, y, z" : "x, y", three ? "0; 0; 0" : "0; 0") +
      dirichlet(2, 2, three ? "x, y, z" : "x, y", three ? "0; 0; 0" : "0; 0") +
      subsection("Dirichlet 3",
                 entry("Boundary id", "3") + entry("Vertex", crown) +
                   entry("Components", "y") +
                   entry("Displacement", "-0.42*t"));
    std::string failure;
    const auto  check = [&](const auto &steps) {
      checker.is_true(std::to_string(dim) +
                        "D arch, crown pushed to the far side: arrives at "
                        "t = 1",
                      failure.empty() && steps.back().load_factor == 1.);
      unsigned int most = 0, sign_changes = 0, cut_backs = 0;
      double       previous = 0.;
      for (const auto &s : steps)
        {
          most = std::max(most, s.newton_iterations);
          cut_backs += s.cut_backs;
          const double reaction = column(s, "reaction_3_y");
          if (previous != 0. && reaction * previous < 0.)
            ++sign_changes;
          previous = reaction;
        }
      checker.at_most("largest Newton iterations in a step", most, 20);
      checker.at_most("cut-backs", cut_backs, 0);
      checker.at_least("sign changes of the crown's reaction (the limit "
                       "point and the snap-through passed)",
                       sign_changes,
                       2);
    };
    if (three)
      check(run_scene_text<3>(scene, failure));
    else
      check(run_scene_text<2>(scene, failure));
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  print = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  Checker           checker(print);
  const std::string which  = argc > 1 ? argv[1] : "";
  const int         status = run_and_report(
    [&]() {
      if (which == "compress_nh")
        compress_nh(checker);
      else if (which == "compress_snh")
        compress_snh(checker);
      else if (which == "twist_180")
        twist_180(checker);
      else if (which == "stvk_limit")
        stvk_limit(checker);
      else if (which == "projected")
        projected(checker);
      else if (which == "locking")
        locking(checker);
      else if (which == "collective")
        collective(checker);
      else if (which == "crush")
        crush_25(checker);
      else if (which == "negative_curvature")
        negative_curvature(checker);
      else if (which == "crush_snaps")
        crush_snaps(checker);
      else if (which == "arch_plate" && argc > 2)
        arch_plate(checker, argv[2]);
      else if (which == "shell_plate" && argc > 2)
        shell_plate(checker, argv[2]);
      else if (which == "arch_displacement" && argc > 3)
        arch_displacement(checker, argv[2], std::stoi(argv[3]));
      else
        throw InputError("unknown case '" + which + "'");
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
