// The scene's Newton subsection: declaration, documentation and validation of
// its entries.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/solvers/newton_parameters.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace entry_patterns;

  void
  NewtonParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    prm.declare_entry("Max iterations",
                      "20",
                      Integer(1),
                      "Newton iterations allowed per load step before the run "
                      "stops with a convergence failure.");
    prm.declare_entry("Absolute residual tolerance",
                      "0",
                      Double(0),
                      "Converged when the l2 norm of the residual on the free "
                      "degrees of freedom is below this (force units; 0: no "
                      "absolute floor) ...");
    prm.declare_entry("Relative residual tolerance",
                      "1e-10",
                      Double(0),
                      "... or below this times the largest l2 norm of the "
                      "internal or external force vector seen so far in the "
                      "run (all degrees of freedom, so reactions count; in "
                      "dynamics also of the inertial forces, which cancel "
                      "gravity in a free fall), or below the round-off "
                      "level of the residual's evaluation, and ...");
    prm.declare_entry("Update tolerance",
                      "1e-8",
                      Double(0),
                      "... the last Newton update is below this times the "
                      "largest l2 norm of the displacement vector reached so "
                      "far in the run.");
    prm.declare_entry("Line search",
                      "true",
                      Bool(),
                      "Backtrack along each Newton direction (halving the "
                      "step) until the total potential energy decreases "
                      "enough (Armijo) and no element leaves the model's "
                      "domain (J <= 0 for neo-Hookean). While prescribed "
                      "displacements are still being imposed only the "
                      "second test applies. false: plain Newton.");
    prm.declare_entry("Armijo constant",
                      "1e-4",
                      Double(0, 0.5),
                      "Sufficient decrease: a step of length a is accepted "
                      "if the energy drops by at least this times a times "
                      "the directional derivative.");
    prm.declare_entry("Minimum step length",
                      "1e-4",
                      Double(0, 1),
                      "The line search fails (and the load step is cut "
                      "back) when the step length would fall below this.");
    prm.declare_entry(
      "Tangent",
      "automatic",
      Selection("automatic|exact|projected|exact, projected on failure"),
      "'exact': full Newton with the exact tangent. 'projected': projected "
      "Newton: the negative eigenvalues of dP/dF at every quadrature point "
      "are clamped to zero, so the tangent is positive semi-definite and "
      "every direction descends (robust under extreme compression, but only "
      "linearly convergent where the exact tangent is indefinite). 'exact, "
      "projected on failure': full Newton, and an iteration whose direction "
      "does not descend or whose line search fails is repeated with the "
      "projected tangent. 'automatic': dP/dF is projected at the quadrature "
      "points where J <= 0 (only the models defined there reach them: "
      "stable neo-Hookean, corotational, St. Venant-Kirchhoff) until the "
      "residual has fallen by 1e-3 from the solve's first iteration, and is "
      "exact everywhere after that, so Newton ends quadratically; an "
      "iteration that fails is repeated with the tangent projected where "
      "J <= 0, then everywhere. Without inverted points it is 'exact, "
      "projected on failure'. Also 'automatic' only: when a load step's "
      "predictor (the first iteration, which imposes the increment of the "
      "prescribed displacements through the tangent) would invert cells of "
      "a state that has none, the increment is extended into the body with "
      "linear elasticity at zero Poisson's ratio instead (displacement "
      "formulation, models defined at J <= 0; marked in the Newton "
      "table): the crush of stress test 25 then converges in one step "
      "instead of stalling at the fold of its path.");
    prm.declare_entry(
      "Follow negative curvature",
      "false",
      Bool(),
      "true: where CG on the exact tangent meets a direction of negative "
      "curvature (p^T K p <= 0: the tangent is indefinite, at a snap, a "
      "fold or a buckle), that iteration and the rest of the load step "
      "are solved in a trust region instead (Steihaug-Toint truncated CG "
      "on the exact tangent, preconditioned by AMG on the tangent projected "
      "to positive semi-definite): the step follows the negative curvature "
      "to the trust region's boundary, the energy decides whether it is "
      "taken (at least 'Armijo constant' times the decrease the quadratic "
      "model predicts; shortened by halving from the feasible step of "
      "contact), and the radius, kept through the load step, follows how "
      "well the model predicted. Converged states are then minima the "
      "exact tangent cannot see past, not saddles. Marked 'trust region' "
      "in the Newton table. With Tangent = automatic, exact or exact, "
      "projected on failure; needs the iterative linear solver, a "
      "symmetric tangent and a potential (otherwise without effect).");
    prm.declare_entry(
      "Inexact Newton",
      "true",
      Bool(),
      "Solve each linearization only as accurately as the nonlinear "
      "residual needs (Eisenstat-Walker forcing terms, choice 2: gamma = "
      "0.9, exponent 2, safeguarded): early iterations are cheap, and the "
      "convergence tests, hence the final accuracy, are unchanged. Krylov "
      "tolerances stay between 'Linear solver/Relative tolerance' and "
      "'Maximum forcing term'. false: every solve to the linear solver's "
      "tolerance. Ignored for the linear elastic model (one solve) and the "
      "direct solver.");
    prm.declare_entry("Maximum forcing term",
                      "0.1",
                      Double(0, 1),
                      "Loosest relative Krylov tolerance of inexact Newton "
                      "(used in the first two iterations of a load step).");
    prm.declare_entry(
      "Inverted elements at equilibrium",
      "automatic",
      Selection("automatic|reject|warn"),
      "What happens when Newton converges to a state in which some cell has "
      "J <= 0 at a quadrature point. 'warn': the state is accepted; one line "
      "gives the number of inverted cells, the smallest J and where it is, "
      "and the CSV column inverted_cells counts them. For the models defined "
      "at J <= 0 (stable neo-Hookean, corotational, St. Venant-Kirchhoff, "
      "linear elastic) such an equilibrium can be the correct discrete "
      "answer, for example near a clamped edge of a crushed body. 'reject': "
      "the attempt fails like a Newton failure (the load step is cut back, "
      "see 'Load stepping/Adaptive'). 'automatic': 'warn' for the models "
      "defined at J <= 0, 'reject' for those whose energy is infinite there "
      "(neo-Hookean, decoupled neo-Hookean: with the line search on, their "
      "iterates never reach J <= 0). 'warn' with such a model is an input "
      "error.");
    prm.leave_subsection();
  }

  void
  NewtonParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Newton");
    max_iterations              = prm.get_integer("Max iterations");
    absolute_residual_tolerance = prm.get_double("Absolute residual tolerance");
    relative_residual_tolerance = prm.get_double("Relative residual tolerance");
    update_tolerance            = prm.get_double("Update tolerance");
    line_search                 = prm.get_bool("Line search");
    armijo_constant             = prm.get_double("Armijo constant");
    minimum_step_length         = prm.get_double("Minimum step length");
    inexact                     = prm.get_bool("Inexact Newton");
    max_forcing                 = prm.get_double("Maximum forcing term");
    if (!(max_forcing > 0.))
      reject("Newton/Maximum forcing term",
             prm.get("Maximum forcing term"),
             "must be positive");
    const std::string tangent_name = prm.get("Tangent");
    tangent                    = tangent_name == "exact" ? NewtonTangent::exact
                                 : tangent_name == "projected" ? NewtonTangent::projected
                                 : tangent_name == "automatic"
                                   ? NewtonTangent::automatic
                                   : NewtonTangent::exact_then_projected;
    follow_negative_curvature      = prm.get_bool("Follow negative curvature");
    if (follow_negative_curvature && tangent == NewtonTangent::projected)
      reject("Newton/Follow negative curvature",
             "true",
             "the projected tangent (Tangent = projected) has no negative "
             "curvature to follow; use Tangent = automatic or exact");
    const std::string inverted = prm.get("Inverted elements at equilibrium");
    inverted_elements          = inverted == "reject" ? InvertedElements::reject
                                 : inverted == "warn" ? InvertedElements::warn
                                                      : InvertedElements::automatic;
    if (!(minimum_step_length > 0.))
      reject("Newton/Minimum step length",
             prm.get("Minimum step length"),
             "must be positive");
    if (absolute_residual_tolerance == 0. && relative_residual_tolerance == 0.)
      reject("Newton/Relative residual tolerance",
             "0",
             "absolute and relative residual tolerance cannot both be zero");
    prm.leave_subsection();
  }
} // namespace hyperelastic
