// A fit through a whole scene (issue 58, item 5): the constants of the
// scene's own Material subsection that make one column of its CSV summary
// (a reaction force, a point displacement) match measured values at given
// load factors. The scene is built once and run with each trial set of
// constants on the same mesh (Problem::rebuild_materials); its load steps
// land exactly on the data's load factors ('Load stepping/Stop at load
// factors'), cut-backs or not, and each data point is read from the step
// that carries its stop's index (StepSummary::stop). A trial's constants go
// to the built scene as numbers (ModelConstants::parameters(): one parse a
// trial, no text written and read back), and a reaction column is read by
// its boundary id and component (FitParameters::scene_reaction).
// Levenberg-Marquardt as for homogeneous tests (calibration/material_fit.h),
// with the Jacobian from the adjoint of the converged equilibria, or from
// central differences where the adjoint does not apply (2 runs per free
// constant and iteration); the summary says which. The adjoint (Problem::
// reaction_sensitivities()) takes one solve per data point with the
// converged tangent (its transpose where follower loads make it
// non-symmetric), for a reaction column of a scene without contact, in the
// displacement or the mixed formulation. A step that fails rejects the
// trial constants.
// Quasi-static scenes with one material (no regions).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/calibration/fit_parameters.h>
#include <hyperelastic/calibration/material_fit.h>

#include <array>
#include <mpi.h>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// The fit of a read fit file with Fit/Scene on the ranks of @p comm;
  /// rank 0 prints the summary and writes the files (those of a fit, and
  /// <Base name>_scene.csv: the scene's summary with the fitted constants).
  /// For tests: the Jacobian of the data's residuals with respect to the
  /// free constants at the scene's starting constants, by the adjoint
  /// (first; empty where it does not apply) and by central differences of
  /// runs (second).
  std::array<std::vector<std::vector<double>>, 2>
  scene_jacobians(const calibration::FitParameters &parameters, MPI_Comm comm);

  calibration::FitResult
  fit_through_scene(const calibration::FitParameters &parameters,
                    const std::string                &fit_file,
                    MPI_Comm                          comm);
} // namespace hyperelastic
