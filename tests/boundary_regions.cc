// Boundary faces selected by position ('Boundary region'): a scene whose
// Dirichlet and traction sections select their faces by conditions on the
// face centre gives the same run, bit for bit, as the scene that names the
// faces' gmsh physical tags.
//
// Cook's membrane (meshes/cook_<dim>d_4.msh, P1, neo-Hookean, 2 load steps):
// the edge (2D) or face (3D) x = 0 is clamped (tag 1) and x = 48 carries a
// shear traction (tag 2). The second run selects them by 'x < 1e-6' and
// 'x > 48 - 1e-6' (with a Loading constant), clamping x and y in two
// Dirichlet sections that share one condition. Every summary column and the
// displacement of the tip must be equal (0 difference); only the names of
// the reaction columns differ (they carry the boundary id).
//
// Usage: boundary_regions DIM
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_run.h"
#include "support/scene_text.h"

#include <algorithm>
#include <cmath>

using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  /// Cook's membrane with the faces named by @p clamp (twice: x and y, z)
  /// and @p loaded: 'Boundary id' or 'Boundary region' entries.
  std::string
  cook_scene(const int          dim,
             const std::string &clamp,
             const std::string &loaded)
  {
    const bool three = dim == 3;
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Source", "file") +
                        entry("File",
                              std::string(SOURCE_DIR) + "/meshes/cook_" +
                                std::to_string(dim) + "d_4.msh")) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "240") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading",
                      entry("Number of load steps", "2") +
                        entry("Constants", "L = 48, q = 2")) +
           subsection("Dirichlet 1",
                      clamp + entry("Components", "x") +
                        entry("Displacement", "0")) +
           subsection("Dirichlet 2",
                      clamp + entry("Components", three ? "y, z" : "y") +
                        entry("Displacement", three ? "0; 0" : "0")) +
           subsection("Traction 1",
                      loaded + entry("Traction",
                                     three ? "0; q*t; 0" : "0; q*t")) +
           tight_solver("direct") +
           subsection("Output",
                      entry("Write VTU", "false") +
                        entry("Verbose", "false") +
                        entry("Points", three ? "48, 60, 0.5" : "48, 60"));
  }

  template <int dim>
  void
  check(Checker &checker)
  {
    checker.section(
      "Cook's membrane " + std::to_string(dim) +
      "D: tagged faces against 'Boundary region', " +
      std::to_string(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)) +
      " rank(s)");
    const auto tagged = run_scene<dim>(
      cook_scene(dim, entry("Boundary id", "1"), entry("Boundary id", "2")));
    const auto by_position =
      run_scene<dim>(cook_scene(dim,
                                entry("Boundary region", "x < 1e-6"),
                                entry("Boundary region", "x > L - 1e-6")));
    const auto &sa = tagged->summaries();
    const auto &sb = by_position->summaries();
    checker.is_true("the same number of load steps", sa.size() == sb.size());
    for (unsigned int k = 0; k < std::min(sa.size(), sb.size()); ++k)
      {
        const auto ca = sa[k].columns();
        const auto cb = sb[k].columns();
        // The reaction columns carry the boundary id in their names: the
        // region's id (printed in the run header) instead of the tag.
        checker.is_true("as many columns in step " + std::to_string(k + 1),
                        ca.size() == cb.size());
        double      difference = 0.;
        std::string worst;
        for (unsigned int c = 0; c < std::min(ca.size(), cb.size()); ++c)
          if (ca[c].name != "wall_time" &&
              std::abs(ca[c].value - cb[c].value) >= difference)
            {
              difference = std::abs(ca[c].value - cb[c].value);
              worst      = ca[c].name;
            }
        if (!checker.at_most("largest column difference, step " +
                               std::to_string(k + 1),
                             difference,
                             0.))
          checker.note("in column " + worst);
      }
    const double tip = sb.back().point_displacements[0][1];
    checker.at_most("difference of the tip's vertical displacement",
                    std::abs(tip - sa.back().point_displacements[0][1]),
                    0.);
    // The run moves: the loaded tip rises.
    checker.above("tip's vertical displacement", tip, 0.1);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_checks_for_dimension(
    argc,
    argv,
    [](Checker &checker, bool) { check<2>(checker); },
    [](Checker &checker, bool) { check<3>(checker); });
}
