// The scene: every parameter a .prm file can set. Each subsection's struct
// lives next to the code that uses it; this header only aggregates them.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/contact/contact_parameters.h>
#include <hyperelastic/dynamics/time_integration_parameters.h>
#include <hyperelastic/formulation/formulation_parameters.h>
#include <hyperelastic/loads/loading_parameters.h>
#include <hyperelastic/materials/material_parameters.h>
#include <hyperelastic/materials/region_parameters.h>
#include <hyperelastic/mesh/mesh_parameters.h>
#include <hyperelastic/output/output_parameters.h>
#include <hyperelastic/solvers/linear_solver_parameters.h>
#include <hyperelastic/solvers/load_stepping_parameters.h>
#include <hyperelastic/solvers/newton_parameters.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  /// All subsections of a scene.
  struct Parameters
  {
    ProblemParameters         problem;
    MeshParameters            mesh;
    MaterialParameters        material;
    LoadingParameters         loading;
    NewtonParameters          newton;
    LoadSteppingParameters    load_stepping;
    TimeIntegrationParameters time_integration;
    ContactParameters         contact;
    LinearSolverParameters    linear_solver;
    OutputParameters          output;
    /// Region 1 ... Region 8: the regions the scene uses, in order.
    std::vector<RegionParameters> regions;
    /// `hyperelastic --restart CHECKPOINT scene.prm`: the checkpoint the
    /// run continues from (not a scene entry; empty: from the start).
    std::string restart_checkpoint;

    static void
    declare(ParameterHandler &prm);

    /// Read a scene file. Throws InputError naming the file and entry.
    void
    read(const std::string &scene_file);

    /// Parse a scene given as text (for tests); relative paths are resolved
    /// against @p scene_folder.
    void
    read_from_string(const std::string &text,
                     const std::string &scene_folder = ".",
                     const std::string &scene_name   = "scene");

  private:
    void
    parse(ParameterHandler &prm, const std::string &scene_folder);
  };
} // namespace hyperelastic
