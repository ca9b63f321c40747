// The scene's Load stepping subsection: declaration, documentation and
// validation of its entries.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/solvers/load_stepping_parameters.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace entry_patterns;

  void
  LoadSteppingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Load stepping");
    prm.declare_entry(
      "Method",
      "load control",
      Selection("load control|arc length"),
      "'load control': t goes from 0 to 1 in the steps of 'Loading/Number of "
      "load steps' (cut back when Newton fails); a maximum of the load on "
      "the path stops it. 'arc length': t becomes an unknown and each step "
      "has a prescribed length in the free displacements (Crisfield's "
      "cylindrical constraint |Delta u| = ds), so the path passes limit "
      "points and t may decrease; two solves per iteration with the same "
      "tangent and preconditioner; ds starts at the length of the first "
      "load step's tangent predictor, adapts to the iteration count (towards "
      "'Easy step iterations') and is halved on failure. The run ends at "
      "'Maximum load factor' (landed on exactly) or after 'Maximum steps'; "
      "the CSV gains a column 'stability'. Quasi-static scenes without "
      "contact; with the mixed formulation ds measures the displacements "
      "only.");
    prm.declare_entry("Maximum load factor",
                      "1",
                      Double(),
                      "Arc length: the run ends when the path reaches this "
                      "load factor t.");
    prm.declare_entry("Maximum steps",
                      "200",
                      Integer(1),
                      "Arc length: the run ends after this many steps "
                      "(the path may never reach 'Maximum load factor').");
    prm.declare_entry("Adaptive",
                      "true",
                      Bool(),
                      "When Newton fails in a load step (iteration limit, "
                      "line-search failure, linear-solver failure, NaN, "
                      "inverted elements at convergence that 'Newton/Inverted "
                      "elements at equilibrium' rejects), return to the last "
                      "converged state and retry with half the load "
                      "increment; after two easy steps in a row double it "
                      "again, up to 1 / 'Loading/Number of load steps' "
                      "(never past it). A step is easy when it took no more "
                      "Newton iterations than the scene's own full-size "
                      "steps: the most that one of the last three steps at "
                      "the nominal increment took without a cut-back, and "
                      "at least 'Easy step iterations' (a sliding contact "
                      "whose every step takes 10 iterations grows back; a "
                      "fixed bound of 6 kept it at 1/16). The log's progress "
                      "line and the run's closing line give the Newton "
                      "iterations per nominal step (failed attempts "
                      "included). false: stop at the first failure.");
    prm.declare_entry("Minimum increment",
                      "1e-4",
                      Double(0, 1),
                      "Smallest load-factor increment; below it the run "
                      "stops with a convergence failure (exit status 3).");
    prm.declare_entry(
      "Snap iterations",
      "20",
      Integer(0),
      "Snaps under displacement control (load control of a scene whose "
      "load factor moves only prescribed displacements and obstacles: no "
      "traction, pressure, body force or point load, so that every load "
      "factor has an energy minimum). Where a cut-back would take the "
      "increment below 1/16 of the nominal one (the path folds or "
      "bifurcates within the step: a buckle, a snap-through), the step is "
      "tried once instead at the nominal increment with up to this many "
      "Newton iterations: the energy descent of Newton's line search (and "
      "the trust region of 'Newton/Follow negative curvature') leaves the "
      "ended branch for an equilibrium beyond the fold. If that fails, the "
      "snap goes on in sub-steps ('Snap sub-step iterations'); if those "
      "fail too, the cut-backs continue as before. The Newton table prints "
      "'snap step'. 0: no snap steps.");
    prm.declare_entry(
      "Snap sub-step iterations",
      "400",
      Integer(0),
      "A snap step whose first Newton solve ('Snap iterations') failed goes "
      "on from the last converged state in sub-steps: each a pseudo time "
      "step at the snap's load factor, the potential plus the damping "
      "c/2 |u - u_k|^2 (lumped mass of unit density, u_k the sub-step's "
      "start) solved by Newton (at most 'Newton/Max iterations', until the "
      "residual has fallen tenfold; negative curvature followed), and an "
      "accepted step of its own (a row of the CSV, 'snap sub-step' in the "
      "log; not an equilibrium, no checkpoint); c starts at 1/16 of the "
      "tangent's mean diagonal and falls after easy sub-steps and with the residual. "
      "From the sub-steps an undamped Newton solve (exact tangent, negative "
      "curvature followed) is tried each time their residual has fallen "
      "fourfold; the first one that converges ends the snap. This many "
      "Newton iterations at most in all the sub-steps and undamped solves "
      "together (failed ones counted whole). If the sub-steps fail before "
      "one is accepted, the cut-backs continue; after, the run stops. 0: no "
      "sub-steps.");
    prm.declare_entry("Easy step iterations",
                      "6",
                      Integer(1),
                      "A load step converged in at most this many Newton "
                      "iterations counts as easy, and so does one that took "
                      "no more than the scene's recent full-size steps "
                      "('Adaptive').");
    prm.declare_entry(
      "Predictor",
      "none",
      Selection("none|secant"),
      "How a load step after the first starts. 'secant': from the last "
      "converged state plus its last increment scaled to the new increment "
      "(u_n + (t - t_n)/(t_n - t_n-1) (u_n - u_n-1)), if no element of that "
      "state has J <= 0, else from u_n; Newton then starts closer to the "
      "answer. 'none': from the last converged state u_n, whose first Newton "
      "iteration (with the new loads and prescribed displacements) is the "
      "tangent predictor. Not used by a linear model. Measured (doc/"
      "performance.md): the secant start saves few Newton iterations over "
      "the tangent predictor on ramped loads, and can cost more under large "
      "prescribed rotations (a rotation extrapolated linearly stretches), "
      "hence 'none' by default.");
    prm.declare_entry(
      "Stop at load factors",
      "",
      List(Double()),
      "Load control: load factors (in dynamics: times) a step lands on "
      "exactly, as the last step lands on 1: the step that would pass one "
      "ends at it, before and after cut-backs. Strictly increasing and "
      "positive; those at or beyond the end are ignored, and one within a "
      "millionth of the nominal step of a step's start. For a CSV row at "
      "given load factors (a measured curve's, as 'hyperelastic --fit' "
      "with a scene uses). Empty: none.");
    prm.leave_subsection();
  }

  void
  LoadSteppingParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Load stepping");
    adaptive             = prm.get_bool("Adaptive");
    minimum_increment    = prm.get_double("Minimum increment");
    easy_step_iterations = prm.get_integer("Easy step iterations");
    snap_iterations      = prm.get_integer("Snap iterations");
    snap_sub_step_iterations = prm.get_integer("Snap sub-step iterations");
    secant_predictor     = prm.get("Predictor") == "secant";
    method = prm.get("Method") == "arc length" ? LoadControl::arc_length
                                               : LoadControl::load_control;
    maximum_load_factor = prm.get_double("Maximum load factor");
    stops.clear();
    for (const std::string &x :
         dealii::Utilities::split_string_list(prm.get("Stop at load factors")))
      {
        stops.push_back(dealii::Utilities::string_to_double(x));
        if (!std::isfinite(stops.back()) || !(stops.back() > 0.) ||
            (stops.size() > 1 && !(stops.back() > stops[stops.size() - 2])))
          reject("Load stepping/Stop at load factors",
                 prm.get("Stop at load factors"),
                 "must be positive, finite and strictly increasing");
      }
    maximum_steps       = prm.get_integer("Maximum steps");
    if (!std::isfinite(maximum_load_factor) || !(maximum_load_factor > 0.))
      reject("Load stepping/Maximum load factor",
             prm.get("Maximum load factor"),
             "must be positive and finite");
    if (!(minimum_increment > 0.))
      reject("Load stepping/Minimum increment",
             prm.get("Minimum increment"),
             "must be positive");
    prm.leave_subsection();
  }
} // namespace hyperelastic
