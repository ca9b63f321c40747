// Scenes already in equilibrium (issue 56, item 1): a state at rest is
// accepted as converged, not taken for an indefinite tangent. Each case runs
// a scene whose steps start at an equilibrium and asserts that every step
// converged without a cut-back and, where nothing loads the body, that the
// displacement stays exactly zero.
//   clamped      a box clamped on one face, nothing else (2D: the box's
//                3D defaults left as they are, only Subdivisions set)
//   surface      a closed surface meshed on the fly, clamped on a cap
//   euler        a free body at rest in backward Euler dynamics
//   newmark      the same with Newmark
//   late_load    a displacement that starts only at t = 0.5: zero before,
//                the analytic stretch after
// Usage: mpirun -np N at_rest CASE DIM
#include <deal.II/base/mpi.h>

#include "support/dimension_main.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <string>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  std::string
  quiet_output()
  {
    return subsection("Output",
                      entry("Write VTU", "false") + entry("Verbose", "false"));
  }

  std::string
  neo_hookean()
  {
    return subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3"));
  }

  /// The box of Mesh/Source = box with its default corners; only the
  /// subdivisions are set (in 2D the defaults' first two values apply).
  std::string
  box(const int dim)
  {
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Subdivisions", dim == 2 ? "4, 2" : "4, 2, 2"));
  }

  /// Boundary 0 (x = 0) clamped with the Dirichlet defaults (all
  /// components held at zero: x, y in 2D).
  std::string
  clamp()
  {
    return subsection("Dirichlet 1", entry("Boundary id", "0"));
  }

  /// Every step converged without a cut-back, @p n_steps of them; the
  /// first @p n_at_rest of them (at an equilibrium from their start) in one
  /// Newton iteration each.
  template <int dim>
  void
  check_steps(Checker            &checker,
              const Problem<dim> &problem,
              const unsigned int  n_steps,
              const unsigned int  n_at_rest)
  {
    const auto &summaries = problem.summaries();
    checker.close("converged steps", summaries.size(), n_steps, 1., 1e-14);
    unsigned int cut_backs = 0, iterations = 0;
    for (unsigned int k = 0; k < summaries.size(); ++k)
      {
        cut_backs += summaries[k].cut_backs;
        if (k < n_at_rest)
          iterations = std::max(iterations, summaries[k].newton_iterations);
      }
    checker.close("cut-backs over all steps", cut_backs, 0., 1., 1e-14);
    checker.close("Newton iterations of a step at rest (largest)",
                  iterations,
                  1.,
                  1.,
                  1e-14);
  }

  template <int dim>
  void
  check_at_rest(Checker &checker, const std::string &scene, unsigned n_steps)
  {
    const auto problem = run_scene<dim>(scene);
    check_steps(checker, *problem, n_steps, n_steps);
    checker.close("largest |u| at the end",
                  problem->solution().linfty_norm(),
                  0.,
                  1.,
                  1e-300);
  }

  template <int dim>
  void
  run(const std::string &which, Checker &checker)
  {
    checker.section(which + ", " + std::to_string(dim) + "D");
    const std::string steps =
      subsection("Loading", entry("Number of load steps", "3"));
    if (which == "clamped")
      check_at_rest<dim>(checker,
                         box(dim) + neo_hookean() + steps + clamp() +
                           quiet_output(),
                         3);
    else if (which == "surface")
      check_at_rest<dim>(checker,
                         subsection("Problem", entry("Dimension", "3")) +
                           subsection("Mesh",
                                      entry("Source", "surface") +
                                        entry("File",
                                              std::string(SOURCE_DIR) +
                                                "/meshes/pebble_3d.obj")) +
                           neo_hookean() + steps +
                           subsection("Dirichlet 1",
                                      entry("Boundary region", "z < -0.4")) +
                           quiet_output(),
                         3);
    else if (which == "euler" || which == "newmark")
      check_at_rest<dim>(
        checker,
        box(dim) + neo_hookean() +
          subsection("Time integration",
                     entry("Scheme",
                           which == "euler" ? "backward Euler" : "Newmark") +
                       entry("Density", "1") + entry("Time step", "0.1") +
                       entry("End time", "0.3")) +
          quiet_output(),
        3);
    else if (which == "late_load")
      {
        // The far face x = 1 pulled by 0.1 (t - 0.5) from t = 0.5 on, the
        // near one held in x only, rollers below: a uniaxial stretch.
        const std::string scene =
          box(dim) + neo_hookean() +
          subsection("Loading", entry("Number of load steps", "4")) +
          subsection("Dirichlet 1",
                     entry("Boundary id", "0") + entry("Components", "x") +
                       entry("Displacement", "0")) +
          subsection("Dirichlet 2",
                     entry("Boundary id", "1") + entry("Components", "x") +
                       entry("Displacement", "0.1*max(t - 0.5, 0)")) +
          subsection("Dirichlet 3",
                     entry("Boundary id", "2") + entry("Components", "y") +
                       entry("Displacement", "0")) +
          (dim == 3
             ? subsection("Dirichlet 4",
                          entry("Boundary id", "4") + entry("Components", "z") +
                            entry("Displacement", "0"))
             : "") +
          quiet_output();
        const auto problem = run_scene<dim>(scene);
        check_steps(checker, *problem, 4, 2);
        const auto &s = problem->summaries();
        for (unsigned int k = 0; k < 2; ++k)
          checker.close("deformed length at t = " +
                          std::to_string(s[k].load_factor),
                        s[k].deformed_max[0] - s[k].deformed_min[0],
                        1.,
                        1.,
                        1e-14);
        checker.close("deformed length at t = 1",
                      s.back().deformed_max[0] - s.back().deformed_min[0],
                      1.05,
                      1.,
                      1e-10);
      }
    else
      throw InputError("unknown case '" + which + "'");
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_case_for_dimension(argc, argv, "clamped", run<2>, run<3>);
}
