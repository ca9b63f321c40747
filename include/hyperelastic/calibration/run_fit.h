// 'hyperelastic --fit FIT.prm': reads the fit's parameter file
// (calibration/fit_parameters.h) and its data, fits the model
// (calibration/material_fit.h), checks Drucker stability, prints the
// summary and writes <Base name>_material.prm and <Base name>_fit.csv
// (calibration/fit_report.h). Every rank computes the same fit (it is
// serial and deterministic); rank 0 prints and writes.
#pragma once

#include <mpi.h>

#include <string>

namespace hyperelastic
{
  namespace calibration
  {
    void
    run_fit(const std::string &fit_file, MPI_Comm comm);
  } // namespace calibration
} // namespace hyperelastic
