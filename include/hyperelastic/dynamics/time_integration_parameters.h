// The scene's Time integration subsection: quasi-static load stepping (the
// default) or implicit dynamics. Declared with pattern, default and
// documentation; parsed with the values checked (an invalid value is an
// InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  enum class TimeScheme
  {
    quasi_static,
    backward_euler,
    newmark, ///< average acceleration: beta = 1/4, gamma = 1/2
    midpoint ///< implicit midpoint rule
  };

  struct TimeIntegrationParameters
  {
    TimeScheme scheme = TimeScheme::quasi_static;
    double     density   = 1.;
    double     time_step = 0.1;
    double     end_time  = 1.;
    /// dim expressions of (x, y, z); empty: at rest.
    std::vector<std::string> initial_velocity;
    bool                     lumped_mass = false;
    double                   mass_damping      = 0.; ///< Rayleigh a: C = a M + b K0
    double                   stiffness_damping = 0.; ///< Rayleigh b
    unsigned int             output_every      = 1;
    /// One linearised solve per time step (the semi-implicit step of
    /// Muller et al. 2002) instead of Newton to convergence.
    bool linearize_once = false;

    bool
    dynamic() const
    {
      return scheme != TimeScheme::quasi_static;
    }

    /// The entry's name of the scheme, for the run header.
    std::string
    scheme_name() const;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
    /// 'Initial velocity' against Problem/Dimension @p dim (one expression
    /// per coordinate, if given).
    void
    check_dimension(unsigned int dim) const;
  };
} // namespace hyperelastic
