// The scene: every parameter a .prm file can set, one struct per subsection.
// Each struct declares its entries (with pattern, default and documentation)
// and parses them, rejecting invalid values with a message naming the entry.
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <hyperelastic/materials/material.h>

#include <map>
#include <string>
#include <vector>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  struct ProblemParameters
  {
    unsigned int dimension = 3;
    unsigned int fe_degree = 1;
    /// Use the precomputed P1 kernel when the degree is 1 ("Assembly =
    /// automatic"); false: the generic FEValues loops for every degree.
    bool fast_p1_assembly = true;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  enum class MeshSource
  {
    box,
    file
  };

  struct MeshParameters
  {
    MeshSource                source = MeshSource::box;
    std::string               file; ///< resolved against the scene's folder
    std::vector<double>       lower_corner;
    std::vector<double>       upper_corner;
    std::vector<unsigned int> subdivisions;
    unsigned int              global_refinements = 0;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const std::string &scene_folder);
  };

  struct MaterialParameters
  {
    std::string    model;
    LameParameters lame;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /// A displacement prescribed on one boundary id for some components.
  struct DirichletCondition
  {
    dealii::types::boundary_id boundary_id = 0;
    std::vector<unsigned int>  components;  ///< 0 = x, 1 = y, 2 = z
    std::vector<std::string>   expressions; ///< one per entry of components
    std::string                subsection;  ///< for error messages
  };

  /// A traction (force per unit reference area) on one boundary id.
  struct TractionCondition
  {
    dealii::types::boundary_id boundary_id = 0;
    std::vector<std::string>   expressions; ///< one per space dimension
    std::string                subsection;
  };

  struct LoadingParameters
  {
    unsigned int                    n_load_steps = 10;
    std::vector<std::string>        body_force; ///< empty: no body force
    std::map<std::string, double>   constants;
    std::vector<DirichletCondition> dirichlet;
    std::vector<TractionCondition>  tractions;

    static constexpr unsigned int max_dirichlet = 8;
    static constexpr unsigned int max_tractions = 4;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /// Which tangent Newton uses.
  enum class NewtonTangent
  {
    exact,               ///< full Newton
    projected,           ///< dP/dF projected to semi-definite everywhere
    exact_then_projected ///< full Newton; projected where its step fails
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
    NewtonTangent tangent = NewtonTangent::exact_then_projected;
    /// Inexact Newton: Krylov tolerances from the Eisenstat-Walker forcing
    /// terms (choice 2), at most max_forcing.
    bool   inexact     = true;
    double max_forcing = 0.1;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  struct LoadSteppingParameters
  {
    bool         adaptive             = true;
    double       minimum_increment    = 1e-4;
    unsigned int easy_step_iterations = 6;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  enum class LinearSolverType
  {
    cg_amg,
    direct
  };

  struct LinearSolverParameters
  {
    LinearSolverType type                  = LinearSolverType::cg_amg;
    double           relative_tolerance    = 1e-8;
    unsigned int     max_iterations        = 1000;
    std::string      direct_solver         = "Amesos_Klu";
    double           aggregation_threshold = 1e-4;
    unsigned int     smoother_sweeps       = 2;
    /// The AMG hierarchy is rebuilt once CG needs more than this factor
    /// times the iterations (per decade of residual reduction) of the first
    /// solve with the current hierarchy; 0: rebuilt for every solve.
    double amg_rebuild_growth = 1.5;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  struct OutputParameters
  {
    std::string directory = "output";
    std::string base_name = "solution";
    bool        write_vtu = true;
    bool        verbose   = true;
    /// Reference points at which the displacement is reported every load
    /// step ("Points"): each 2 or 3 coordinates as written (the number is
    /// checked against the dimension at setup).
    std::vector<std::vector<double>> points;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /// All subsections of a scene.
  struct Parameters
  {
    ProblemParameters      problem;
    MeshParameters         mesh;
    MaterialParameters     material;
    LoadingParameters      loading;
    NewtonParameters       newton;
    LoadSteppingParameters load_stepping;
    LinearSolverParameters linear_solver;
    OutputParameters       output;

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
