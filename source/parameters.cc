// Declaration, documentation and validation of every scene parameter.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hyperelastic/error_handling.h>
#include <hyperelastic/parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

namespace hyperelastic
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;
  using dealii::Patterns::MultipleSelection;
  using dealii::Patterns::Selection;

  namespace
  {
    [[noreturn]] void
    reject(const std::string &entry,
           const std::string &value,
           const std::string &why)
    {
      throw InputError("scene entry '" + entry + "' = '" + value + "': " + why);
    }

    double
    get_finite(ParameterHandler  &prm,
               const std::string &section,
               const std::string &name)
    {
      const double v = prm.get_double(name);
      if (!std::isfinite(v))
        reject(section + "/" + name, prm.get(name), "must be a finite number");
      return v;
    }

    /// Split "a; b; c" into trimmed expressions; an all-blank string gives {}.
    std::vector<std::string>
    split_expressions(const std::string &text)
    {
      if (dealii::Utilities::trim(text).empty())
        return {};
      return dealii::Utilities::split_string_list(text, ';');
    }

    unsigned int
    component_index(const std::string &name)
    {
      return name == "x" ? 0 : (name == "y" ? 1 : 2);
    }
  } // namespace

  // ---------------------------------------------------------------- Problem
  void
  ProblemParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    prm.declare_entry("Dimension",
                      "3",
                      Integer(2, 3),
                      "Space dimension: 2 (plane strain, triangles) or 3 "
                      "(tetrahedra).");
    prm.declare_entry("Finite element degree",
                      "1",
                      Integer(1, 2),
                      "Polynomial degree of the simplex Lagrange element: 1 "
                      "(P1, linear) or 2 (P2, quadratic).");
    prm.declare_entry(
      "Assembly",
      "automatic",
      Selection("automatic|generic"),
      "'automatic': P1 forces, tangent and energy from the precomputed P1 "
      "kernel (hat-function gradients and volumes stored per cell, values "
      "written straight into the matrix rows), P2 from FEValues. 'generic': "
      "FEValues for every degree (several times slower for P1; the reference "
      "the kernel is tested against).");
    prm.leave_subsection();
  }

  void
  ProblemParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    dimension = prm.get_integer("Dimension");
    fe_degree = prm.get_integer("Finite element degree");
    fast_p1_assembly = prm.get("Assembly") == "automatic";
    prm.leave_subsection();
  }

  // ------------------------------------------------------------------- Mesh
  void
  MeshParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry(
      "Source",
      "box",
      Selection("box|file"),
      "'box': a generated box of simplices (rectangle in 2D) with boundary ids "
      "0/1 on the faces x = min/max, 2/3 on y = min/max, 4/5 on z = min/max. "
      "'file': a gmsh .msh file (format 2 or 4, ASCII) whose physical tags on "
      "boundary faces become boundary ids.");
    prm.declare_entry("File",
                      "",
                      Anything(),
                      "Mesh file for Source = file; a relative path is read "
                      "relative to the folder of the scene file.");
    prm.declare_entry("Lower corner",
                      "0, 0, 0",
                      List(Double(), 2, 3),
                      "Box: coordinates of the lower corner (dim values).");
    prm.declare_entry("Upper corner",
                      "1, 1, 1",
                      List(Double(), 2, 3),
                      "Box: coordinates of the upper corner (dim values).");
    prm.declare_entry("Subdivisions",
                      "1, 1, 1",
                      List(Integer(1), 2, 3),
                      "Box: number of cells per direction (dim values); each "
                      "square is split into 2 triangles, each cube into 5 "
                      "tetrahedra.");
    prm.declare_entry("Global refinements",
                      "0",
                      Integer(0, 10),
                      "Uniform refinements of the mesh before it is "
                      "partitioned (each one multiplies the cell count by "
                      "2^dim).");
    prm.leave_subsection();
  }

  void
  MeshParameters::parse(ParameterHandler &prm, const std::string &scene_folder)
  {
    prm.enter_subsection("Mesh");
    source = prm.get("Source") == "box" ? MeshSource::box : MeshSource::file;
    file   = dealii::Utilities::trim(prm.get("File"));
    if (source == MeshSource::file)
      {
        if (file.empty())
          reject("Mesh/File", file, "a mesh file is needed when Source = file");
        if (file[0] != '/')
          file = scene_folder + "/" + file;
      }
    for (const auto &v :
         dealii::Utilities::split_string_list(prm.get("Lower corner")))
      lower_corner.push_back(dealii::Utilities::string_to_double(v));
    for (const auto &v :
         dealii::Utilities::split_string_list(prm.get("Upper corner")))
      upper_corner.push_back(dealii::Utilities::string_to_double(v));
    for (const auto &v :
         dealii::Utilities::split_string_list(prm.get("Subdivisions")))
      subdivisions.push_back(dealii::Utilities::string_to_int(v));
    global_refinements = prm.get_integer("Global refinements");
    prm.leave_subsection();
  }

  // --------------------------------------------------------------- Material
  void
  MaterialParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Model",
                      "neo-Hookean",
                      Selection(material_model_names()),
                      "Constitutive model: 'linear elastic' (small strain), "
                      "'St. Venant-Kirchhoff', 'corotational' (ARAP when "
                      "lambda = 0), 'neo-Hookean' (log barrier: undefined "
                      "for inverted elements), 'stable neo-Hookean' (Smith, "
                      "de Goes, Kim 2018; finite for inverted elements; the "
                      "same small-strain E and nu) or 'decoupled neo-Hookean' "
                      "(psi = kappa/4 (J^2 - 1 - 2 ln J) + mu/2 (J^(-2/3) I1 "
                      "- 3), the model of the finite-strain literature, e.g. "
                      "Cook's membrane; bulk modulus kappa = lambda + 2 mu / "
                      "3; undefined for inverted elements). See README, "
                      "'Choosing a model'.");
    prm.declare_entry("Elastic constants",
                      "Young's modulus and Poisson's ratio",
                      Selection("Young's modulus and Poisson's ratio|Lame|"
                                "shear and bulk modulus"),
                      "Which pair of constants the scene gives: (E, nu), "
                      "the Lame constants (mu, lambda), or the shear and "
                      "bulk moduli (mu, kappa), converted to lambda = kappa "
                      "- 2 mu / 3.");
    prm.declare_entry(
      "Young's modulus",
      "1",
      Double(),
      "E > 0 (used with 'Young's modulus and Poisson's ratio').");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Double(),
                      "-1 < nu < 0.5 (used with 'Young's modulus and Poisson's "
                      "ratio').");
    prm.declare_entry("Shear modulus",
                      "1",
                      Double(),
                      "Lame mu > 0 (used with 'Lame' and 'shear and bulk "
                      "modulus').");
    prm.declare_entry("Lame lambda",
                      "1",
                      Double(),
                      "Lame lambda, with lambda + 2 mu / 3 > 0 (used with "
                      "'Lame').");
    prm.declare_entry("Bulk modulus",
                      "1",
                      Double(),
                      "kappa > 0 (used with 'shear and bulk modulus'; "
                      "lambda = kappa - 2 mu / 3).");
    prm.leave_subsection();
  }

  void
  MaterialParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    model                       = prm.get("Model");
    const std::string constants = prm.get("Elastic constants");
    if (constants == "shear and bulk modulus")
      {
        lame.mu            = get_finite(prm, "Material", "Shear modulus");
        const double kappa = get_finite(prm, "Material", "Bulk modulus");
        if (!(lame.mu > 0.))
          reject("Material/Shear modulus",
                 prm.get("Shear modulus"),
                 "must be positive");
        if (!(kappa > 0.))
          reject("Material/Bulk modulus",
                 prm.get("Bulk modulus"),
                 "must be positive");
        lame.lambda = kappa - 2. * lame.mu / 3.;
        // kappa far below mu can round lambda + 2 mu / 3 to 0.
        if (!(lame.lambda + 2. * lame.mu / 3. > 0.))
          reject("Material/Bulk modulus",
                 prm.get("Bulk modulus"),
                 "is too small against the shear modulus to be represented");
      }
    else if (constants == "Lame")
      {
        lame.mu     = get_finite(prm, "Material", "Shear modulus");
        lame.lambda = get_finite(prm, "Material", "Lame lambda");
        if (!(lame.mu > 0.))
          reject("Material/Shear modulus",
                 prm.get("Shear modulus"),
                 "must be positive");
        if (!(lame.lambda + 2. * lame.mu / 3. > 0.))
          reject("Material/Lame lambda",
                 prm.get("Lame lambda"),
                 "the bulk modulus lambda + 2 mu / 3 must be positive");
      }
    else
      {
        const double E  = get_finite(prm, "Material", "Young's modulus");
        const double nu = get_finite(prm, "Material", "Poisson's ratio");
        if (!(E > 0.))
          reject("Material/Young's modulus",
                 prm.get("Young's modulus"),
                 "must be positive");
        if (!(nu > -1. && nu < 0.5))
          reject("Material/Poisson's ratio",
                 prm.get("Poisson's ratio"),
                 "must lie strictly between -1 and 0.5");
        lame = LameParameters::from_young_poisson(E, nu);
      }
    prm.leave_subsection();
  }

  // ---------------------------------------------------------------- Loading
  void
  LoadingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    prm.declare_entry("Number of load steps",
                      "10",
                      Integer(1),
                      "The load factor t goes from 0 to 1 in this many equal "
                      "steps (smaller ones where Newton needs them: see "
                      "'Load stepping'); every expression below may use t.");
    prm.declare_entry("Body force",
                      "",
                      Anything(),
                      "Force per unit reference volume: dim expressions of "
                      "x, y, (z,) t separated by ';' (for example '0; 0; "
                      "-0.1*t'). Empty: no body force.");
    prm.declare_entry("Constants",
                      "",
                      Anything(),
                      "Named constants usable in every expression, as "
                      "'name = value' pairs separated by ',' (for example "
                      "'L = 10, angle = 1.5708'). pi is always defined.");
    prm.leave_subsection();

    for (unsigned int i = 1; i <= max_dirichlet; ++i)
      {
        prm.enter_subsection("Dirichlet " + std::to_string(i));
        prm.declare_entry("Boundary id",
                          "-1",
                          Integer(-1),
                          "Boundary id on which the displacement is "
                          "prescribed; -1 leaves this slot unused.");
        prm.declare_entry("Components",
                          "x, y, z",
                          MultipleSelection("x|y|z"),
                          "Displacement components that are prescribed; the "
                          "others stay free (so 'x' on a face x = const is a "
                          "symmetry roller).");
        prm.declare_entry("Displacement",
                          "0; 0; 0",
                          Anything(),
                          "One expression of x, y, (z,) t per listed "
                          "component, separated by ';': the displacement of "
                          "the reference point (x, y, z) at load factor t.");
        prm.leave_subsection();
      }
    for (unsigned int i = 1; i <= max_tractions; ++i)
      {
        prm.enter_subsection("Traction " + std::to_string(i));
        prm.declare_entry("Boundary id",
                          "-1",
                          Integer(-1),
                          "Boundary id loaded by this traction; -1 leaves this "
                          "slot unused.");
        prm.declare_entry("Traction",
                          "0; 0; 0",
                          Anything(),
                          "Force per unit reference area (a nominal, "
                          "dead-load traction): dim expressions of x, y, (z,) "
                          "t separated by ';'.");
        prm.leave_subsection();
      }
  }

  void
  LoadingParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    n_load_steps                     = prm.get_integer("Number of load steps");
    body_force                       = split_expressions(prm.get("Body force"));
    const std::string constants_text = prm.get("Constants");
    prm.leave_subsection();

    for (const auto &pair :
         dealii::Utilities::split_string_list(constants_text, ','))
      {
        const auto        eq = pair.find('=');
        const std::string name =
          eq == std::string::npos ? ""
                                  : dealii::Utilities::trim(pair.substr(0, eq));
        double             value = 0;
        std::istringstream value_stream(
          eq == std::string::npos ? "" : pair.substr(eq + 1));
        value_stream >> value;
        if (name.empty() || value_stream.fail() || !std::isfinite(value) ||
            !(value_stream >> std::ws).eof())
          reject("Loading/Constants",
                 constants_text,
                 "expected 'name = number' pairs separated by ',', got '" +
                   pair + "'");
        const bool identifier =
          (std::isalpha(static_cast<unsigned char>(name[0])) ||
           name[0] == '_') &&
          std::all_of(name.begin(), name.end(), [](const char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
          });
        if (!identifier || name == "x" || name == "y" || name == "z" ||
            name == "t" || name == "pi")
          reject("Loading/Constants",
                 constants_text,
                 "'" + name +
                   "' cannot be a constant's name: use letters, digits and "
                   "'_' (starting with a letter), other than x, y, z, t and "
                   "pi");
        constants[name] = value;
      }

    for (unsigned int i = 1; i <= max_dirichlet; ++i)
      {
        const std::string section = "Dirichlet " + std::to_string(i);
        prm.enter_subsection(section);
        const int id = prm.get_integer("Boundary id");
        if (id >= 0)
          {
            DirichletCondition c;
            c.boundary_id = id;
            c.subsection  = section;
            for (const auto &name :
                 dealii::Utilities::split_string_list(prm.get("Components")))
              {
                if (std::count(c.components.begin(),
                               c.components.end(),
                               component_index(name)) > 0)
                  reject(section + "/Components",
                         prm.get("Components"),
                         "component " + name + " is listed twice");
                c.components.push_back(component_index(name));
              }
            c.expressions = split_expressions(prm.get("Displacement"));
            if (c.components.empty())
              reject(section + "/Components",
                     prm.get("Components"),
                     "list at least one of x, y, z");
            if (c.expressions.size() != c.components.size())
              reject(section + "/Displacement",
                     prm.get("Displacement"),
                     "needs one expression per listed component (" +
                       std::to_string(c.components.size()) +
                       "), separated by ';'");
            dirichlet.push_back(c);
          }
        prm.leave_subsection();
      }
    for (unsigned int i = 1; i <= max_tractions; ++i)
      {
        const std::string section = "Traction " + std::to_string(i);
        prm.enter_subsection(section);
        const int id = prm.get_integer("Boundary id");
        if (id >= 0)
          {
            TractionCondition c;
            c.boundary_id = id;
            c.subsection  = section;
            c.expressions = split_expressions(prm.get("Traction"));
            tractions.push_back(c);
          }
        prm.leave_subsection();
      }
  }

  // ----------------------------------------------------------------- Newton
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
                      "run (all degrees of freedom, so reactions count), "
                      "and ...");
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
      "exact, projected on failure",
      Selection("exact|projected|exact, projected on failure"),
      "'exact': full Newton with the exact tangent. 'projected': projected "
      "Newton: the negative eigenvalues of dP/dF at every quadrature point "
      "are clamped to zero, so the tangent is positive semi-definite and "
      "every direction descends (robust under extreme compression, but only "
      "linearly convergent where the exact tangent is indefinite). 'exact, "
      "projected on failure': full Newton, and an iteration whose direction "
      "does not descend or whose line search fails is repeated with the "
      "projected tangent.");
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
    tangent = tangent_name == "exact" ? NewtonTangent::exact
              : tangent_name == "projected"
                ? NewtonTangent::projected
                : NewtonTangent::exact_then_projected;
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

  // ---------------------------------------------------------- Load stepping
  void
  LoadSteppingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Load stepping");
    prm.declare_entry("Adaptive",
                      "true",
                      Bool(),
                      "When Newton fails in a load step (iteration limit, "
                      "line-search failure, linear-solver failure, NaN, "
                      "inverted elements at convergence), return to the last "
                      "converged state and retry with half the load "
                      "increment; after two easy steps in a row double it "
                      "again, up to 1 / 'Loading/Number of load steps'. "
                      "false: stop at the first failure.");
    prm.declare_entry("Minimum increment",
                      "1e-4",
                      Double(0, 1),
                      "Smallest load-factor increment; below it the run "
                      "stops with a convergence failure (exit status 3).");
    prm.declare_entry("Easy step iterations",
                      "6",
                      Integer(1),
                      "A load step converged in at most this many Newton "
                      "iterations counts as easy.");
    prm.leave_subsection();
  }

  void
  LoadSteppingParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Load stepping");
    adaptive             = prm.get_bool("Adaptive");
    minimum_increment    = prm.get_double("Minimum increment");
    easy_step_iterations = prm.get_integer("Easy step iterations");
    if (!(minimum_increment > 0.))
      reject("Load stepping/Minimum increment",
             prm.get("Minimum increment"),
             "must be positive");
    prm.leave_subsection();
  }

  // ---------------------------------------------------------- Linear solver
  void
  LinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Type",
                      "CG with AMG",
                      Selection("CG with AMG|direct"),
                      "'CG with AMG': conjugate gradients preconditioned by "
                      "Trilinos ML algebraic multigrid with all rigid-body "
                      "modes (scales to large meshes). 'direct': sparse LU "
                      "(robust, for small problems).");
    prm.declare_entry("Relative tolerance",
                      "1e-8",
                      Double(0, 1),
                      "CG stops when the residual is reduced by this factor.");
    prm.declare_entry(
      "Max iterations",
      "1000",
      Integer(1),
      "CG iterations before a linear-solver failure is reported.");
    prm.declare_entry(
      "Direct solver",
      "Amesos_Klu",
      Selection("Amesos_Klu|Amesos_Umfpack|Amesos_Mumps|Amesos_Superludist"),
      "Amesos solver used by Type = direct. Not every Trilinos build has "
      "all of them (Debian 12's: Amesos_Klu and Amesos_Mumps); one that is "
      "missing is rejected at start, with the list of those available.");
    prm.declare_entry("AMG aggregation threshold",
                      "1e-4",
                      Double(0, 1),
                      "ML drops matrix entries below this (relative) when "
                      "forming aggregates.");
    prm.declare_entry("AMG smoother sweeps",
                      "2",
                      Integer(1, 10),
                      "Degree of the Chebyshev smoother on each level.");
    prm.declare_entry(
      "AMG rebuild growth",
      "1.5",
      Double(0),
      "The AMG hierarchy (the expensive part of a CG solve) is kept across "
      "Newton iterations and load steps, and rebuilt from the current "
      "tangent once CG needs more than this factor times the iterations per "
      "decade of residual reduction of the first solve with the hierarchy "
      "(and at least 5 more), or when CG fails with an old hierarchy. 0: "
      "rebuild for every solve.");
    prm.leave_subsection();
  }

  void
  LinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    type               = prm.get("Type") == "direct" ? LinearSolverType::direct
                                                     : LinearSolverType::cg_amg;
    relative_tolerance = prm.get_double("Relative tolerance");
    if (!(relative_tolerance > 0.))
      reject("Linear solver/Relative tolerance",
             prm.get("Relative tolerance"),
             "must be positive");
    max_iterations        = prm.get_integer("Max iterations");
    direct_solver         = prm.get("Direct solver");
    aggregation_threshold = prm.get_double("AMG aggregation threshold");
    smoother_sweeps       = prm.get_integer("AMG smoother sweeps");
    amg_rebuild_growth    = prm.get_double("AMG rebuild growth");
    prm.leave_subsection();
  }

  // ----------------------------------------------------------------- Output
  void
  OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "output",
                      Anything(),
                      "Folder for all output (created if missing; relative to "
                      "the working directory).");
    prm.declare_entry("Base name",
                      "solution",
                      Anything(),
                      "Prefix of the output files: <base>.pvd, "
                      "<base>_<step>.pvtu, <base>_<step>.<rank>.vtu and "
                      "<base>.csv.");
    prm.declare_entry("Write VTU",
                      "true",
                      Bool(),
                      "Write the ParaView files at every load step (the CSV "
                      "summary is always written).");
    prm.declare_entry("Verbose",
                      "true",
                      Bool(),
                      "Print the Newton table of every load step.");
    prm.declare_entry(
      "Points",
      "",
      Anything(),
      "Reference points at which the displacement is reported after every "
      "converged load step, as 'x, y; x, y' in 2D or 'x, y, z; x, y, z' in "
      "3D (for example '48, 60; 48, 52'). Each point adds the CSV columns "
      "point<k>_ux, point<k>_uy (, point<k>_uz), k = 1, 2, ... in the order "
      "given. A point on a vertex, edge or face shared by several cells gets "
      "their average. A point outside the mesh is an input error. Empty: no "
      "points.");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    directory = dealii::Utilities::trim(prm.get("Directory"));
    base_name = dealii::Utilities::trim(prm.get("Base name"));
    write_vtu = prm.get_bool("Write VTU");
    verbose   = prm.get_bool("Verbose");
    if (directory.empty())
      reject("Output/Directory", "", "must not be empty");
    if (base_name.empty() || base_name.find('/') != std::string::npos)
      reject("Output/Base name", base_name, "must be a non-empty file name");
    const std::string points_text = prm.get("Points");
    points.clear();
    for (const auto &point : split_expressions(points_text))
      {
        std::vector<double> coordinates;
        bool                ok = true;
        for (const auto &c : dealii::Utilities::split_string_list(point, ','))
          {
            std::istringstream in(c);
            double             x = 0.;
            in >> x;
            ok = ok && !in.fail() && std::isfinite(x) && (in >> std::ws).eof();
            coordinates.push_back(x);
          }
        if (!ok || coordinates.size() < 2 || coordinates.size() > 3)
          reject("Output/Points",
                 points_text,
                 "expected points 'x, y[, z]' separated by ';', got '" +
                   point + "'");
        points.push_back(coordinates);
      }
    prm.leave_subsection();
  }

  // ------------------------------------------------------------ Parameters
  void
  Parameters::declare(ParameterHandler &prm)
  {
    ProblemParameters::declare(prm);
    MeshParameters::declare(prm);
    MaterialParameters::declare(prm);
    LoadingParameters::declare(prm);
    NewtonParameters::declare(prm);
    LoadSteppingParameters::declare(prm);
    LinearSolverParameters::declare(prm);
    OutputParameters::declare(prm);
  }

  void
  Parameters::parse(ParameterHandler &prm, const std::string &scene_folder)
  {
    problem.parse(prm);
    mesh.parse(prm, scene_folder);
    material.parse(prm);
    loading.parse(prm);
    newton.parse(prm);
    load_stepping.parse(prm);
    linear_solver.parse(prm);
    output.parse(prm);

    // Checks that need the dimension.
    const unsigned int dim = problem.dimension;
    const auto size = [](const auto &v) { return std::to_string(v.size()); };
    if (mesh.source == MeshSource::box)
      {
        if (mesh.lower_corner.size() != dim)
          reject("Mesh/Lower corner",
                 size(mesh.lower_corner) + " values",
                 "needs " + std::to_string(dim) + " values for dimension " +
                   std::to_string(dim));
        if (mesh.upper_corner.size() != dim)
          reject("Mesh/Upper corner",
                 size(mesh.upper_corner) + " values",
                 "needs " + std::to_string(dim) + " values");
        if (mesh.subdivisions.size() != dim)
          reject("Mesh/Subdivisions",
                 size(mesh.subdivisions) + " values",
                 "needs " + std::to_string(dim) + " values");
        for (unsigned int d = 0; d < dim; ++d)
          if (!(mesh.upper_corner[d] > mesh.lower_corner[d]))
            reject("Mesh/Upper corner",
                   std::to_string(mesh.upper_corner[d]),
                   "every coordinate must exceed the lower corner's");
      }
    if (!loading.body_force.empty() && loading.body_force.size() != dim)
      reject("Loading/Body force",
             size(loading.body_force) + " expressions",
             "needs " + std::to_string(dim) + " expressions separated by ';'");
    for (const auto &c : loading.dirichlet)
      for (const unsigned int component : c.components)
        if (component >= dim)
          reject(c.subsection + "/Components",
                 "z",
                 "there is no z component in 2D");
    for (const auto &c : loading.tractions)
      if (c.expressions.size() != dim)
        reject(c.subsection + "/Traction",
               size(c.expressions) + " expressions",
               "needs " + std::to_string(dim) +
                 " expressions separated by ';'");
    // Two conditions on the same id and component contradict each other.
    for (unsigned int a = 0; a < loading.dirichlet.size(); ++a)
      for (unsigned int b = a + 1; b < loading.dirichlet.size(); ++b)
        if (loading.dirichlet[a].boundary_id ==
            loading.dirichlet[b].boundary_id)
          for (const unsigned int ca : loading.dirichlet[a].components)
            for (const unsigned int cb : loading.dirichlet[b].components)
              if (ca == cb)
                reject(loading.dirichlet[b].subsection + "/Boundary id",
                       std::to_string(loading.dirichlet[b].boundary_id),
                       "component " + std::string(1, "xyz"[ca]) +
                         " of this boundary id is already prescribed in " +
                         loading.dirichlet[a].subsection);
  }

  void
  Parameters::read(const std::string &scene_file)
  {
    std::ifstream in(scene_file);
    if (!in)
      throw InputError("cannot open scene file '" + scene_file + "'");
    std::stringstream text;
    text << in.rdbuf();
    const auto        slash = scene_file.rfind('/');
    const std::string folder =
      slash == std::string::npos ? "." : scene_file.substr(0, slash);
    try
      {
        read_from_string(text.str(), folder, scene_file);
      }
    catch (const InputError &e)
      {
        const std::string what = e.what();
        // Messages from the parser already name the file.
        throw InputError(what.find(scene_file) != std::string::npos
                           ? what
                           : "scene file '" + scene_file + "': " + what);
      }
  }

  void
  Parameters::read_from_string(const std::string &text,
                               const std::string &scene_folder,
                               const std::string &scene_name)
  {
    ParameterHandler prm;
    declare(prm);
    try
      {
        std::istringstream in(text);
        prm.parse_input(in, scene_name);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError(exception_message(e));
      }
    parse(prm, scene_folder);
  }
} // namespace hyperelastic
