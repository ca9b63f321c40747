// The scene's Newton subsection: tolerances, line search, tangent, inexact
// Newton. Declared with pattern, default and documentation; parsed with the
// values checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  /// Which tangent Newton uses.
  enum class NewtonTangent
  {
    exact,                ///< full Newton
    projected,            ///< dP/dF projected to semi-definite everywhere
    exact_then_projected, ///< full Newton; projected where its step fails
    /// projected where J <= 0 until the residual has fallen by
    /// automatic_switch_ratio, exact after; projected on failure
    automatic
  };

  /// What happens to a converged state with inverted elements (J <= 0 at a
  /// quadrature point).
  enum class InvertedElements
  {
    automatic, ///< warn for models defined at J <= 0, reject otherwise
    reject,    ///< the attempt fails (and the load step is cut back)
    warn       ///< the state is accepted, with a warning
  };

  struct NewtonParameters
  {
    unsigned int  max_iterations              = 20;
    double        absolute_residual_tolerance = 0.;
    double        relative_residual_tolerance = 1e-10;
    double        update_tolerance            = 1e-8;
    bool          line_search                 = true;
    double        armijo_constant             = 1e-4;
    double        minimum_step_length         = 1e-4;
    NewtonTangent tangent                     = NewtonTangent::automatic;
    /// The automatic tangent is exact once the residual is below this
    /// times the first residual of the solve.
    static constexpr double automatic_switch_ratio = 1e-3;
    /// Where CG on the exact tangent meets negative curvature, the load
    /// step goes on in a trust region (Steihaug-Toint truncated CG).
    bool follow_negative_curvature = false;
    /// Inexact Newton: Krylov tolerances from the Eisenstat-Walker forcing
    /// terms (choice 2), at most max_forcing.
    bool   inexact     = true;
    double max_forcing = 0.1;
    /// "Inverted elements at equilibrium".
    InvertedElements inverted_elements = InvertedElements::automatic;

    /// Whether a converged state with inverted elements is accepted, for a
    /// model that is (@p model_defined_there) or is not defined at J <= 0.
    /// A model undefined there never accepts one.
    bool
    accepts_inverted_elements(const bool model_defined_there) const
    {
      return model_defined_there &&
             inverted_elements != InvertedElements::reject;
    }

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };
} // namespace hyperelastic
