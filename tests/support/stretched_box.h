// The unit box [0,1]^dim on symmetry rollers (x = 0, y = 0, z = 0), its face
// x = 1 pulled to the stretch 1.3 in two load steps (neo-Hookean, E = 1,
// nu = 0.3, direct solver): a homogeneous deformation x = diag(l) X, exact
// for every element. The output tests compare what they read back with it.
#pragma once

#include <hyperelastic/output/step_summary.h>

#include "scene_text.h"
#include "summary_columns.h"

#include <array>
#include <string>

namespace hyperelastic::testing
{
  /// The scene of n^dim boxes (@p subdivisions, e.g. "3, 3, 3"), with
  /// @p problem_entries added to its Problem section and @p output_entries
  /// as its Output section.
  inline std::string
  stretched_unit_box(const int          dim,
                     const std::string &subdivisions,
                     const std::string &output_entries,
                     const std::string &problem_entries = "")
  {
    const bool three = dim == 3;
    return subsection("Problem",
                      entry("Dimension", std::to_string(dim)) +
                        problem_entries) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "1, 1, 1" : "1, 1") +
                        entry("Subdivisions", subdivisions)) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Loading", entry("Number of load steps", "2")) +
           tight_solver("direct") + dirichlet(1, 0, "x", "0") +
           dirichlet(2, 2, "y", "0") +
           (three ? dirichlet(3, 4, "z", "0") : "") +
           dirichlet(4, 1, "x", "0.3*t") + subsection("Output", output_entries);
  }

  /// The stretches l of the step summarised by @p last: its deformed
  /// extents (1 beyond dim).
  template <int dim>
  std::array<double, 3>
  box_stretches(const StepSummary<dim> &last)
  {
    const char            axes[3] = {'x', 'y', 'z'};
    std::array<double, 3> l       = {{1., 1., 1.}};
    for (unsigned int d = 0; d < dim; ++d)
      l[d] = column(last, std::string("deformed_max_") + axes[d]) -
             column(last, std::string("deformed_min_") + axes[d]);
    return l;
  }
} // namespace hyperelastic::testing
