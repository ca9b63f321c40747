// Declaration, documentation and validation of every scene parameter.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/formulation/formulation_registry.h>
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
    ContactParameters::declare(prm);
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
    contact.parse(prm, scene_folder);

    // Checks that need the dimension.
    const unsigned int dim = problem.dimension;
    contact.check(dim);
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
      {
        for (const unsigned int component : c.components)
          if (component >= dim)
            reject(c.subsection + "/Components",
                   "z",
                   "there is no z component in 2D");
        if (!c.vertex.empty() && c.vertex.size() != dim)
          reject(c.subsection + "/Vertex",
                 size(c.vertex) + " coordinates",
                 "needs " + std::to_string(dim));
      }
    for (const auto &p : loading.point_loads)
      {
        if (p.point.size() != dim)
          reject(p.subsection + "/Point",
                 size(p.point) + " coordinates",
                 "needs " + std::to_string(dim));
        if (p.expressions.size() != dim)
          reject(p.subsection + "/Force",
                 size(p.expressions) + " expressions",
                 "needs " + std::to_string(dim) +
                   " expressions separated by ';'");
      }
    for (const auto &c : loading.boundary_loads)
      {
        const bool vector_valued = boundary_load_kind(c.kind).vector_valued;
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
    // 'Material/Model = stiffness warping' is an alias of the stiffness
    // warping formulation with the corotational model.
    if (material.stiffness_warping)
      {
        if (problem.formulation == "mixed")
          reject("Problem/Formulation",
                 "mixed",
                 "'Material/Model = stiffness warping' works with the "
                 "displacement formulation only");
        problem.formulation = "stiffness warping";
      }
    formulation_kind(problem.formulation).check(*this);
    // Arc length continues a quasi-static path of the displacement
    // formulation (the constraint measures displacements; contact and
    // inertia have states of their own along t).
    if (load_stepping.method == LoadControl::arc_length)
      {
        const auto arc = [&](const std::string &entry,
                             const std::string &value,
                             const std::string &why) {
          reject(entry, value, "'Load stepping/Method = arc length' " + why);
        };
        if (time_integration.dynamic())
          arc("Time integration/Scheme",
              time_integration.scheme_name(),
              "continues quasi-static scenes only");
        if (contact.active())
          arc(contact.self_contact ? "Contact/Self contact"
                                   : "Contact/Obstacle 1/Type",
              contact.self_contact ? "true" : "(an obstacle)",
              "does not work with contact yet");
        if (problem.formulation == "stiffness warping")
          arc("Problem/Formulation",
              problem.formulation,
              "does not work with stiffness warping (a linearization per "
              "step, not a path)");
      }
    if (output.checkpoint_every > 0 &&
        load_stepping.method == LoadControl::arc_length &&
        !time_integration.dynamic())
      reject("Output/Checkpoint every",
             std::to_string(output.checkpoint_every),
             "checkpoints continue load control or time stepping; 'Load "
             "stepping/Method = arc length' is not supported");
    // Viscoelasticity: the history is written at the solved state of a
    // step of known length.
    if (material.viscoelasticity.active())
      {
        const auto viscous = [&](const std::string &entry,
                                 const std::string &value,
                                 const std::string &why) {
          reject(entry,
                 value,
                 "'Material/Viscoelasticity' (Weights = '" +
                   material.viscoelasticity.weights_text + "') " + why);
        };
        if (load_stepping.method == LoadControl::arc_length)
          viscous("Load stepping/Method",
                  "arc length",
                  "needs steps of known length (load control)");
        if (time_integration.scheme_name() == "implicit midpoint")
          viscous("Time integration/Scheme",
                  "implicit midpoint",
                  "needs a scheme that solves at the end of the step "
                  "(backward Euler or Newmark)");
      }
    // Accepting inverted equilibria needs a model defined at J <= 0.
    if (newton.inverted_elements == InvertedElements::warn)
      {
        const bool defined = material_model(material.registered_model())
                               .defined_for_inverted_elements;
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
              if (ca == cb &&
                  (loading.dirichlet[a].vertex.empty() ||
                   loading.dirichlet[b].vertex.empty() ||
                   loading.dirichlet[a].vertex == loading.dirichlet[b].vertex))
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
