// The scene's Time integration subsection: declaration, documentation and
// validation of its entries.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/dynamics/time_integration_parameters.h>

namespace hyperelastic
{
  using namespace entry_patterns;

  std::string
  TimeIntegrationParameters::scheme_name() const
  {
    switch (scheme)
      {
        case TimeScheme::backward_euler:
          return "backward Euler";
        case TimeScheme::newmark:
          return "Newmark";
        case TimeScheme::midpoint:
          return "implicit midpoint";
        default:
          return "quasi-static";
      }
  }

  void
  TimeIntegrationParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    prm.declare_entry(
      "Scheme",
      "quasi-static",
      Selection("quasi-static|backward Euler|Newmark|implicit midpoint"),
      "'quasi-static': equilibrium states for the load factor t from 0 to 1 "
      "(Loading/Number of load steps; no mass, velocity or acceleration is "
      "allocated). 'backward Euler': implicit, first order, dissipative (the "
      "total energy never increases). 'Newmark': average acceleration (beta "
      "= 1/4, gamma = 1/2), second order, conserves the energy of a linear "
      "problem. 'implicit midpoint': second order, conserves linear and "
      "angular momentum (the equations are solved at t_n + h/2, where the "
      "loads and prescribed displacements are evaluated). In dynamics t in every expression is the physical time, each "
      "time step minimises an incremental potential (inertia + strain energy "
      "- work of the loads), so the line search, the J > 0 filter and the "
      "cut-back (halving the time step, restored after easy steps) carry "
      "over, and a scene needs no Dirichlet condition.");
    prm.declare_entry("Density",
                      "1",
                      Double(0),
                      "Mass per unit reference volume (dynamics only); the "
                      "Loading/Body force is a force per unit volume, so "
                      "gravity g is 'Body force = 0; 0; -rho*g'.");
    prm.declare_entry("Time step", "0.1", Double(0), "Nominal time step h.");
    prm.declare_entry("End time", "1", Double(0), "Simulated time.");
    prm.declare_entry("Initial velocity",
                      "",
                      Anything(),
                      "dim expressions of (x, y, z) separated by ';' (the "
                      "velocity at t = 0 at the reference position); empty: "
                      "at rest. The initial displacement is zero.");
    prm.declare_entry("Mass",
                      "consistent",
                      Selection("consistent|lumped"),
                      "'consistent': the mass matrix int rho N_a N_b; "
                      "'lumped': its diagonal scaled to the element's mass "
                      "(row sums for P1, HRZ for P2).");
    prm.declare_entry("Mass damping",
                      "0",
                      Double(0),
                      "Rayleigh damping C = a M + b K0: the coefficient a "
                      "(1/time).");
    prm.declare_entry("Stiffness damping",
                      "0",
                      Double(0),
                      "Rayleigh damping C = a M + b K0: the coefficient b "
                      "(time), with K0 the linear elastic stiffness at rest "
                      "(the model's small-strain moduli). At small amplitude "
                      "a mode of angular frequency omega is damped at the "
                      "ratio b omega / 2 (higher modes more). K0 belongs to "
                      "the rest configuration: it also resists the velocity "
                      "of a large rigid rotation, so use mass damping for "
                      "spinning bodies.");
    prm.declare_entry("Output every",
                      "1",
                      Integer(1),
                      "Write the VTU files every this many time steps (and "
                      "the last one); the CSV has every step.");
    prm.declare_entry(
      "Linearize once per step",
      "false",
      Bool(),
      "true: each time step is one linear solve with the tangent at the "
      "step's start (the semi-implicit step of Muller et al. 2002, cheap "
      "for animation), accepted without a convergence test unless the line "
      "search shortens it (then Newton continues until a full step is "
      "taken). false: Newton to the Newton subsection's tolerances.");
    prm.leave_subsection();
  }

  void
  TimeIntegrationParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    const std::string s = prm.get("Scheme");
    scheme = s == "backward Euler" ? TimeScheme::backward_euler :
             s == "Newmark"        ? TimeScheme::newmark :
             s == "implicit midpoint" ? TimeScheme::midpoint :
                                        TimeScheme::quasi_static;
    density   = get_finite(prm, "Time integration", "Density");
    time_step = get_finite(prm, "Time integration", "Time step");
    end_time  = get_finite(prm, "Time integration", "End time");
    initial_velocity  = split_expressions(prm.get("Initial velocity"));
    lumped_mass       = prm.get("Mass") == "lumped";
    mass_damping      = get_finite(prm, "Time integration", "Mass damping");
    stiffness_damping = get_finite(prm, "Time integration", "Stiffness damping");
    output_every      = prm.get_integer("Output every");
    linearize_once    = prm.get_bool("Linearize once per step");
    prm.leave_subsection();
    if (!dynamic())
      return;
    if (!(density > 0.))
      reject("Time integration/Density",
             std::to_string(density),
             "must be positive in dynamics");
    if (!(time_step > 0.))
      reject("Time integration/Time step",
             std::to_string(time_step),
             "must be positive");
    if (!(end_time >= time_step))
      reject("Time integration/End time",
             std::to_string(end_time),
             "must be at least one time step (" + std::to_string(time_step) +
               ")");
  }

  void
  TimeIntegrationParameters::check_dimension(const unsigned int dim) const
  {
    if (!initial_velocity.empty() && initial_velocity.size() != dim)
      reject("Time integration/Initial velocity",
             std::to_string(initial_velocity.size()) + " expressions",
             "needs " + std::to_string(dim) + " expressions");
  }
} // namespace hyperelastic
