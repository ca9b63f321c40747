// 'hyperelastic --fit FIT.prm' for homogeneous tests: reads the fit's
// parameter file (calibration/fit_parameters.h) and its data, fits the
// model (calibration/material_fit.h), checks Drucker stability, prints the
// summary and writes <Base name>_material.prm, _fit.csv and _curve.csv
// (calibration/fit_report.h). Every rank computes the same fit (it is
// serial and deterministic); rank 0 prints and writes. A fit through a
// scene (Fit/Scene) is scene_fit.h's, above the concerns; it shares the
// reading and the report.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/calibration/fit_parameters.h>
#include <hyperelastic/calibration/fit_report.h>

#include <mpi.h>
#include <string>

namespace hyperelastic
{
  namespace calibration
  {
    /// The fit file parsed into @p prm (declared by FitParameters) and
    /// @p parameters; InputErrors name the fit file (or the data file and
    /// line).
    void
    read_fit_file(const std::string        &fit_file,
                  dealii::ParameterHandler &prm,
                  FitParameters            &parameters);

    /// The free constants of the Material subsection in @p prm for
    /// @p data; InputErrors name @p file for what the constants or the data
    /// do not allow (a free constant the model lacks, fewer values than
    /// constants, a relaxation test without a Prony series).
    std::unique_ptr<ModelConstants>
    fit_constants(dealii::ParameterHandler    &prm,
                  const FitParameters         &parameters,
                  const std::vector<TestData> &data,
                  bool                         incompressible,
                  const std::string           &file);

    /// Rank 0: the summary on the terminal, the Material block, the
    /// fit's CSV and (@p curves, for homogeneous tests) the model's
    /// curves.
    void
    report_fit(const FitParameters  &parameters,
               const FitReport      &report,
               const ModelConstants &constants,
               const Material<3>    &material,
               bool                  curves,
               MPI_Comm              comm);

    /// The fit to homogeneous tests of a read fit file.
    void
    fit_tests(dealii::ParameterHandler &prm,
              const FitParameters      &parameters,
              const std::string        &fit_file,
              MPI_Comm                  comm);
  } // namespace calibration
} // namespace hyperelastic
