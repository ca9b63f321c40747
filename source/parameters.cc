// Declaration, documentation and validation of every scene parameter.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/loads/load_terms.h>
#include <hyperelastic/materials/material_registry.h>
#include <hyperelastic/parameters.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

namespace hyperelastic
{
  using namespace entry_patterns;

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
    prm.declare_entry(
      "Formulation",
      "displacement",
      Selection("displacement|mixed"),
      "'displacement': the displacement is the only unknown (the default). "
      "'mixed': displacement and pressure p (the Cauchy mean stress) with "
      "the volumetric-isochoric split psi = psi_iso(F) + U(J), coupled through "
      "the Legendre transform of U (exact for any U, see "
      "doc/manual.md, 'Mixed formulation'): for nearly incompressible "
      "solids (nu > 0.45), where P1 locks and AMG stalls. Needs a model with "
      "a split (decoupled neo-Hookean, Mooney-Rivlin); the element is then "
      "'Mixed element', and 'Finite element degree' is ignored.");
    prm.declare_entry(
      "Mixed element",
      "P1-bubble/P1",
      Selection("P1-bubble/P1|P1/P1 stabilized|P2/P1"),
      "The displacement/pressure pair of 'Formulation = mixed': "
      "'P1-bubble/P1' (MINI: P1 plus a cell bubble, condensed on the cell, "
      "so the system holds P1 unknowns only), 'P1/P1 stabilized' (equal "
      "order with Dohrmann-Bochev pressure-projection stabilisation "
      "-1/mu int (p - Pi0 p)(q - Pi0 q)), 'P2/P1' (Taylor-Hood). All are "
      "inf-sup stable in 2D and 3D.");
    prm.leave_subsection();
  }

  void
  ProblemParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    dimension = prm.get_integer("Dimension");
    fe_degree = prm.get_integer("Finite element degree");
    fast_p1_assembly = prm.get("Assembly") == "automatic";
    mixed            = prm.get("Formulation") == "mixed";
    const std::string element = prm.get("Mixed element");
    mixed_element = element == "P2/P1"              ? MixedElement::taylor_hood
                    : element == "P1/P1 stabilized" ? MixedElement::stabilized
                                                    : MixedElement::mini;
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
    TimeIntegrationParameters::declare(prm);
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
    time_integration.parse(prm);

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
    if (time_integration.dynamic() && problem.mixed)
      reject("Time integration/Scheme",
             time_integration.scheme_name(),
             "implicit dynamics is not available with 'Problem/Formulation "
             "= mixed' yet");
    if (!time_integration.initial_velocity.empty() &&
        time_integration.initial_velocity.size() != dim)
      reject("Time integration/Initial velocity",
             size(time_integration.initial_velocity) + " expressions",
             "needs " + std::to_string(dim) + " expressions");
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
    for (const auto &c : loading.boundary_loads)
      {
        const bool vector_valued =
          boundary_load_kind(c.kind).vector_valued;
        if (vector_valued && c.expressions.size() != dim)
          reject(c.subsection + "/" + c.kind,
                 size(c.expressions) + " expressions",
                 "needs " + std::to_string(dim) +
                   " expressions separated by ';'");
        if (!vector_valued && c.expressions.size() != 1)
          reject(c.subsection + "/" + c.kind,
                 size(c.expressions) + " expressions",
                 "needs one expression");
      }
    // Stiffness warping rotates the rest stiffness per vertex: P1 nodes
    // only, no pressure unknown.
    if (material.stiffness_warping && problem.mixed)
      reject("Problem/Formulation",
             "mixed",
             "'Material/Model = stiffness warping' works with the "
             "displacement formulation only");
    if (material.stiffness_warping && problem.fe_degree != 1)
      reject("Problem/Finite element degree",
             std::to_string(problem.fe_degree),
             "'Material/Model = stiffness warping' needs P1 elements (one "
             "rotation per vertex)");
    // The mixed formulation needs the model's volumetric split.
    if (problem.mixed)
      {
        if (!material_model(material.registered_model()).has_volumetric_split)
          {
            std::string with_split;
            for (const MaterialModel &m : material_models())
              if (m.has_volumetric_split)
                with_split += (with_split.empty() ? "'" : ", '") + m.name + "'";
            reject("Problem/Formulation",
                   "mixed",
                   "the " + material.model +
                     " model has no volumetric-isochoric split psi = "
                     "psi_iso(F) + U(J); use a model with one (" +
                     with_split + ") or 'Formulation = displacement'");
          }
        problem.fe_degree = displacement_degree(problem.mixed_element);
      }
    // Exact incompressibility needs the pressure as an unknown.
    if (!problem.mixed && !material.incompressible_entry.empty())
      reject(material.incompressible_entry,
             material.incompressible_value,
             std::string(material.incompressible_entry ==
                             "Material/Poisson's ratio" ?
                           "must lie strictly between -1 and 0.5 with the "
                           "displacement formulation; " :
                           "is exactly incompressible; ") +
               "an exactly incompressible material (nu = 0.5, bulk modulus "
               "'inf') needs 'Problem/Formulation = mixed' (and a model with "
               "a volumetric split)");
    // Accepting inverted equilibria needs a model defined at J <= 0.
    if (newton.inverted_elements == InvertedElements::warn)
      {
        const bool defined =
          material_model(material.registered_model()).defined_for_inverted_elements;
        if (!defined)
          reject("Newton/Inverted elements at equilibrium",
                 "warn",
                 "the " + material.model +
                   " model is not defined for inverted elements (its energy "
                   "is infinite at J <= 0), so no state with them can be "
                   "accepted; use 'automatic' or 'reject', or a model "
                   "defined there (e.g. stable neo-Hookean or corotational)");
      }
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
