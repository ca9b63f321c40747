// The scene as a whole: every subsection declared and parsed, then the
// entries that depend on other subsections resolved and checked (each check
// lives with the entry it is about).
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/formulation/formulation_registry.h>
#include <hyperelastic/scene/parameter_checks.h>
#include <hyperelastic/scene/parameters.h>

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
    RegionParameters::declare(prm);
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
    mesh.parse(prm, scene_folder, problem.dimension);
    material.parse(prm);
    regions = RegionParameters::parse_all(prm);
    loading.parse(prm, problem.dimension);
    newton.parse(prm);
    load_stepping.parse(prm);
    linear_solver.parse(prm);
    output.parse(prm, problem.dimension);
    time_integration.parse(prm);
    contact.parse(prm, scene_folder);

    // The entries whose number of values follows Problem/Dimension.
    const unsigned int dim = problem.dimension;
    contact.check(dim);
    mesh.check_dimension(dim);
    time_integration.check_dimension(dim);
    loading.check_dimension(dim);
    // The formulation (an alias resolved, its degree set), and the other
    // entries checked against it and against each other.
    resolve_formulation(problem, material);
    formulation_kind(problem.formulation)
      .check({problem, material, linear_solver, time_integration});
    // Each region's material meets the same checks as the top-level one.
    for (const RegionParameters &region : regions)
      {
        // Stiffness warping is the formulation of the whole mesh: every
        // region's model is stiffness warping too (its own rest moduli).
        if (material.stiffness_warping && !region.material.stiffness_warping)
          rethrow_in_region(
            region,
            "scene entry 'Material/Model' = '" + region.material.model +
              "': with the top-level 'Material/Model = stiffness warping' "
              "every region's model is stiffness warping too (each with "
              "its own elastic constants)");
        check_in_region(region, [&](const MaterialParameters &m) {
          if (m.stiffness_warping && !material.stiffness_warping)
            reject("Material/Model",
                   m.model,
                   "stiffness warping is the formulation of the whole mesh: "
                   "it needs the top-level 'Material/Model = stiffness "
                   "warping' too");
          formulation_kind(problem.formulation)
            .check({problem, m, linear_solver, time_integration});
          check_viscoelasticity(m, load_stepping, time_integration);
          check_inverted_elements(newton, m);
        });
      }
    check_arc_length(load_stepping, time_integration, contact, problem);
    check_checkpoints(output, load_stepping, time_integration);
    check_loaded_reference(problem, mesh, contact, output);
    if (output.write_mesh)
      {
        if (mesh.source != MeshSource::surface)
          reject("Output/Write mesh",
                 "true",
                 "writes the mesh generated from a closed surface: it needs "
                 "'Mesh/Source = surface'");
        mesh.generated_mesh_file =
          output.directory + "/" + output.base_name + "_mesh.msh";
      }
    check_viscoelasticity(material, load_stepping, time_integration);
    check_inverted_elements(newton, material);
    loading.check_dirichlet_conflicts();
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
