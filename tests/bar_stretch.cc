// Analytic bar-stretch test: a bar with symmetry rollers on x = 0, y = 0
// (and z = 0) is stretched to 1.5 and compressed to 0.7 by an imposed end
// displacement, and pulled by a dead-load traction P11 chosen for stretch 1.3.
// The exact solution is homogeneous, so simplex elements reproduce it to
// round-off: stretches and reaction forces must match to 1e-8 relative.
//
// Usage: bar_stretch DIM MODEL SOLVER DEGREE [MESH_FILE | --soft | --fine]
//   MODEL: a material name; SOLVER: cg | direct; DEGREE: 1 | 2;
//   --soft instead of MESH_FILE: mu = lambda = 1e-12 on the generated box;
//   --fine: a box with more than 2000 unknowns, so that ML builds a real
//   multigrid hierarchy (below that it solves directly on its coarse level),
//   and CG iterations per Newton iteration must stay at or below 25;
//   MESH_FILE: a gmsh mesh of the box [0,3]x[0,1](x[0,1]) whose boundary
//   ids are the generated box's plus one (gmsh has no physical tag 0);
//   without it a generated box is used.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/analytic_bar.h"
#include "support/checker.h"
#include "support/scene_text.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace hyperelastic;
using namespace dealii;
using namespace hyperelastic::testing;

namespace
{
  constexpr double length = 3., tolerance = 1e-8;
  // Lame constants; '--soft' scales them by 1e-12 (forces become tiny, and a
  // residual test alone would stop Newton early).
  double mu = 1., lambda = 1.;
  bool   fine = false;

  /// Boundary id of the box face k (0: x = 0, 1: x = L, 2: y = 0, ...) is
  /// k + id_offset.
  int
  id_offset(const std::string &mesh_file)
  {
    return mesh_file.empty() ? 0 : 1;
  }

  std::string
  scene(const int          dim,
        const std::string &model,
        const std::string &solver,
        const int          degree,
        const std::string &mesh_file,
        const std::string &load,
        const std::string &name)
  {
    std::string text =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Finite element degree", std::to_string(degree)));
    if (mesh_file.empty())
      text +=
        subsection("Mesh",
                   entry("Source", "box") +
                     entry("Lower corner", dim == 3 ? "0, 0, 0" : "0, 0") +
                     entry("Upper corner", dim == 3 ? "3, 1, 1" : "3, 1") +
                     entry("Subdivisions",
                           fine ? (dim == 3 ? "30, 10, 10" : "60, 20")
                                : (dim == 3 ? "3, 2, 2" : "3, 2")));
    else
      text +=
        subsection("Mesh", entry("Source", "file") + entry("File", mesh_file));
    text += material_section(model,
                             entry("Elastic constants", "Lame") +
                               entry("Shear modulus", number(mu)) +
                               entry("Lame lambda", number(lambda)),
                             lame_parameters(mu, lambda));
    text += subsection("Loading", entry("Number of load steps", "5"));
    // Symmetry rollers on the faces x = 0 (id 0), y = 0 (id 2), z = 0 (id 4).
    const int off = id_offset(mesh_file);
    text += dirichlet(1, 0 + off, "x", "0") + dirichlet(2, 2 + off, "y", "0");
    if (dim == 3)
      text += dirichlet(3, 4 + off, "z", "0");
    text += load;
    text += tight_solver(solver);
    text +=
      subsection("Output",
                 entry("Directory", "bar_stretch_output") +
                   entry("Base name", name) + entry("Write VTU", "false") +
                   entry("Verbose", "false"));
    return text;
  }

  template <int dim>
  void
  run_case(Checker           &checker,
           const std::string &model,
           const std::string &solver,
           const int          degree,
           const std::string &mesh_file,
           const bool         traction,
           const double       l1_target,
           const std::string &name)
  {
    const UniaxialState exact = uniaxial(model, dim, l1_target, mu, lambda);
    const double        area  = 1.; // 1 x 1 in 3D, 1 x (unit thickness) in 2D
    std::string         load;
    Parameters          parameters;
    // std::to_string keeps 6 digits: give P11 and the displacement exactly.
    std::ostringstream value;
    value << std::setprecision(17)
          << (traction ? exact.P11 : (l1_target - 1.) * length);
    const std::string exact_text = value.str();
    const int         off        = id_offset(mesh_file);
    if (traction)
      load =
        subsection("Traction 1",
                   entry("Boundary id", std::to_string(1 + off)) +
                     entry("Traction",
                           exact_text + "*t; 0" + (dim == 3 ? "; 0" : "")));
    else
      load = dirichlet(4, 1 + off, "x", exact_text + "*t");
    parameters.read_from_string(
      scene(dim, model, solver, degree, mesh_file, load, name), ".", name);

    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.run();
    const StepSummary<dim> &s = problem.summaries().back();

    checker.section(name + " (" + std::to_string(s.newton_iterations) +
                    " Newton iterations in the last step)");
    if (fine)
      {
        unsigned int newton = 0, krylov = 0;
        for (const auto &step : problem.summaries())
          {
            newton += step.newton_iterations;
            krylov += step.linear_iterations;
          }
        checker.at_most("CG iterations per Newton iteration (" +
                          std::to_string(problem.get_dof_handler().n_dofs()) +
                          " unknowns)",
                        double(krylov) / newton,
                        25.);
      }
    const double l1 = (s.deformed_max[0] - s.deformed_min[0]) / length;
    checker.close("axial stretch l1", l1, l1_target, l1_target,
                    tolerance);
    for (unsigned int d = 1; d < dim; ++d)
      checker.close("lateral stretch l2 (" + std::string(1, "xyz"[d]) + ")",
                    s.deformed_max[d] - s.deformed_min[d],
                    exact.l2,
                    exact.l2,
                    tolerance);
    const double force_scale = std::abs(exact.P11) * area;
    for (const auto &[id, force] : s.reactions)
      {
        // Roller on x = 0 carries -P11 A; the end face (if supported) +P11 A;
        // the lateral rollers carry nothing.
        double expected = 0.;
        if (id == types::boundary_id(0 + off))
          expected = -exact.P11 * area;
        if (id == types::boundary_id(1 + off))
          expected = exact.P11 * area;
        checker.close("reaction x on boundary " + std::to_string(id),
                      force[0],
                      expected,
                      force_scale,
                    tolerance);
        for (unsigned int d = 1; d < dim; ++d)
          checker.close("reaction " + std::string(1, "xyz"[d]) +
                          " on boundary " + std::to_string(id),
                        force[d],
                        0.,
                        force_scale,
                    tolerance);
      }
  }

  template <int dim>
  void
  run_all(Checker           &checker,
          const std::string &model,
          const std::string &solver,
          const int          degree,
          const std::string &mesh_file,
          const std::string &tag)
  {
    run_case<dim>(
      checker, model, solver, degree, mesh_file, false, 1.5, tag + "_stretch");
    run_case<dim>(
      checker, model, solver, degree, mesh_file, false, 0.7, tag + "_compress");
    run_case<dim>(
      checker, model, solver, degree, mesh_file, true, 1.3, tag + "_traction");
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 5)
    {
      std::cerr << "usage: bar_stretch DIM MODEL SOLVER DEGREE [MESH_FILE]\n";
      return 2;
    }
  const int         dim       = std::stoi(argv[1]);
  const std::string model     = argv[2];
  const std::string solver    = argv[3];
  const int         degree    = std::stoi(argv[4]);
  const bool        soft      = argc > 5 && std::string(argv[5]) == "--soft";
  fine                        = argc > 5 && std::string(argv[5]) == "--fine";
  const std::string mesh_file = argc > 5 && !soft && !fine ? argv[5] : "";
  if (soft)
    mu = lambda = 1e-12;
  const unsigned int n_ranks =
    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);

  std::string tag = std::to_string(dim) + "d_";
  for (const char c : model)
    tag += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  tag += "_" + solver + "_p" + std::to_string(degree) +
         (mesh_file.empty() ? "" : "_gmsh") + (soft ? "_soft" : "") +
         (fine ? "_fine" : "") + "_np" + std::to_string(n_ranks);

  Checker checker(dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) ==
                  0);
  const int status = run_and_report(
    [&]() {
      if (dim == 2)
        run_all<2>(checker, model, solver, degree, mesh_file, tag);
      else
        run_all<3>(checker, model, solver, degree, mesh_file, tag);
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
