// Helpers that write scene (.prm) text for the tests.
#pragma once

#include <hyperelastic/materials/material_registry.h>

#include <iomanip>
#include <sstream>
#include <string>

namespace hyperelastic::testing
{
  inline std::string
  subsection(const std::string &name, const std::string &body)
  {
    return "subsection " + name + "\n" + body + "end\n";
  }

  inline std::string
  entry(const std::string &name, const std::string &value)
  {
    return "  set " + name + " = " + value + "\n";
  }

  /// @p x with all 17 significant digits (std::to_string keeps 6
  /// decimals), for entries that must be exact.
  inline std::string
  number(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(17) << x;
    return s.str();
  }

  /// The Material section for any registered @p model: the shared
  /// elastic-constant entries @p elastic_entries (read by the Lame-based
  /// models) and, for a model with constants of its own, its subsection
  /// Material/<model> holding the constants the registry derives from
  /// @p small_strain (which should be the moduli @p elastic_entries give).
  /// For a Lame-based model the section is just Model and @p elastic_entries.
  inline std::string
  material_section(const std::string    &model,
                   const std::string    &elastic_entries,
                   const LameParameters &small_strain)
  {
    std::string own;
    for (const auto &[name, value] :
         material_model(model).entries_for_small_strain(small_strain))
      own += entry(name, value);
    return subsection("Material",
                      entry("Model", model) + elastic_entries +
                        (own.empty() ? "" : subsection(model, own)));
  }

  /// (mu, lambda) as a LameParameters.
  inline LameParameters
  lame_parameters(const double mu, const double lambda)
  {
    LameParameters p;
    p.mu     = mu;
    p.lambda = lambda;
    return p;
  }

  /// Problem, Mesh and Material sections of the unit block [0, 1]^dim of
  /// neo-Hookean (E = 1, nu = 0.3) in 4 x 4 (2D) or 2 x 2 x 2 (3D) boxes.
  inline std::string
  unit_block(const int dim)
  {
    const bool three = dim == 3;
    return subsection("Problem", entry("Dimension", std::to_string(dim))) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "1, 1, 1" : "1, 1") +
                        entry("Subdivisions", three ? "2, 2, 2" : "4, 4")) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3"));
  }

  inline std::string
  dirichlet(const int          slot,
            const int          id,
            const std::string &components,
            const std::string &value)
  {
    return subsection("Dirichlet " + std::to_string(slot),
                      entry("Boundary id", std::to_string(id)) +
                        entry("Components", components) +
                        entry("Displacement", value));
  }

  /// Problem and Mesh sections of the bar [0,3] x [0,1] (x [0,1]) of
  /// 12 x 4 (2D) or 6 x 2 x 2 (3D) boxes, with elements of @p degree.
  inline std::string
  small_bar(const int dim, const unsigned int degree)
  {
    const bool three = dim == 3;
    return subsection("Problem",
                      entry("Dimension", std::to_string(dim)) +
                        entry("Finite element degree",
                              std::to_string(degree))) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "3, 1, 1" : "3, 1") +
                        entry("Subdivisions", three ? "6, 2, 2" : "12, 4"));
  }

  /// Tight solver settings so that results are limited by round-off.
  inline std::string
  tight_solver(const std::string &linear_solver)
  {
    return subsection("Newton",
                      entry("Max iterations", "25") +
                        entry("Absolute residual tolerance", "1e-14") +
                        entry("Relative residual tolerance", "1e-12") +
                        entry("Update tolerance", "1e-10")) +
           subsection("Linear solver",
                      entry("Type",
                            linear_solver == "direct" ? "direct"
                                                      : "CG with AMG") +
                        entry("Relative tolerance", "1e-10"));
  }

  /// A 4 x 1 x 1 bar of 4n x n x n boxes (6 tetrahedra each), neo-Hookean
  /// (E = 1, nu = 0.3), no output files.
  inline std::string
  bar_3d(const unsigned int n)
  {
    return subsection("Problem", entry("Dimension", "3")) +
           subsection("Mesh",
                      entry("Upper corner", "4, 1, 1") +
                        entry("Subdivisions",
                              std::to_string(4 * n) + ", " + std::to_string(n) +
                                ", " + std::to_string(n))) +
           subsection("Material",
                      entry("Model", "neo-Hookean") +
                        entry("Young's modulus", "1") +
                        entry("Poisson's ratio", "0.3")) +
           subsection("Output", entry("Write VTU", "false"));
  }

  /// 'Dirichlet 2' on boundary id 1 (the end x = const of a bar whose axis
  /// is y = z = 0.5): the end pulled by @p pull along x and turned by
  /// @p angle (radians) about the axis, both expressions of t.
  inline std::string
  twisted_end(const std::string &pull, const std::string &angle)
  {
    const std::string c = "cos(" + angle + ")", s = "sin(" + angle + ")";
    return dirichlet(2,
                     1,
                     "x, y, z",
                     pull + "; 0.5 + (y - 0.5)*" + c + " - (z - 0.5)*" + s +
                       " - y; 0.5 + (y - 0.5)*" + s + " + (z - 0.5)*" + c +
                       " - z");
  }

  /// The bar clamped at x = 0, its end at x = 4 turned by 90 degrees about
  /// its axis, under gravity, in 4 load steps (append to bar_3d()).
  inline std::string
  twist_loading()
  {
    return subsection("Loading",
                      entry("Number of load steps", "4") +
                        entry("Body force", "0; 0; -0.05")) +
           dirichlet(1, 0, "x, y, z", "0; 0; 0") + twisted_end("0", "pi/2*t");
  }
  /// The thick cylinder of tests/inflation.cc and tests/unloaded_shape.cc
  /// in 2 load steps: its outer circle (id 2, radius 2) moved radially by
  /// 0.2 t, the follower pressure @p p t on its inner one (id 1).
  inline std::string
  cylinder_inflation_loading(const double p)
  {
    return subsection("Loading", entry("Number of load steps", "2")) +
           dirichlet(1,
                     2,
                     "x, y",
                     "0.2*t*x/sqrt(x^2 + y^2); 0.2*t*y/sqrt(x^2 + y^2)") +
           subsection("Pressure 1",
                      entry("Boundary id", "1") +
                        entry("Pressure", number(p) + "*t"));
  }
  /// Homogeneous uniaxial stretch: the bar [0,3] x [0,1] (x [0,1]) of the
  /// model @p model (its own subsection's @p model_entries) on symmetry
  /// rollers (x = 0, y = 0, z = 0), its end x = 3 moved to the stretch
  /// @p l1 in 4 load steps, lateral faces free; direct solver, tight
  /// tolerances. @p mixed: the mixed formulation.
  inline std::string
  rollered_bar_stretch(const int          dim,
                       const std::string &model,
                       const std::string &model_entries,
                       const double       l1,
                       const bool         mixed)
  {
    const bool three = dim == 3;
    return subsection("Problem",
                      entry("Dimension", std::to_string(dim)) +
                        entry("Formulation",
                              mixed ? "mixed" : "displacement")) +
           subsection("Mesh",
                      entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                        entry("Upper corner", three ? "3, 1, 1" : "3, 1") +
                        entry("Subdivisions", three ? "3, 1, 1" : "6, 2")) +
           subsection("Material",
                      entry("Model", model) +
                        subsection(model, model_entries)) +
           subsection("Loading", entry("Number of load steps", "4")) +
           tight_solver("direct") + dirichlet(1, 0, "x", "0") +
           dirichlet(2, 2, "y", "0") +
           (three ? dirichlet(3, 4, "z", "0") : "") +
           dirichlet(4, 1, "x", std::to_string(3. * (l1 - 1.)) + "*t") +
           subsection("Output", entry("Write VTU", "false"));
  }
} // namespace hyperelastic::testing
