// What a fit reports: the constants with their standard errors, RMS and R^2
// per test and overall, the Drucker verdict per mode; the files
// <Base name>_material.prm (a Material block ready to include in a scene,
// with this summary as its header) and <Base name>_fit.csv (one row per
// measured value: data, test, stretch_1, stretch_2, measured, fitted,
// component, time), and <Base name>_curve.csv (the fitted model along
// each test's range, for drawing). stretch_1 is the data's first column
// (stretch, shear, J; a relaxation test's held stretch), stretch_2 the second
// stretch (biaxial) or the fitted state's y stretch, component 1 or 2 the
// stress of a biaxial point, time a relaxation test's. scripts/plot_fit.py
// draws the CSV.
#pragma once

#include <hyperelastic/calibration/drucker_stability.h>
#include <hyperelastic/calibration/material_fit.h>
#include <hyperelastic/calibration/model_constants.h>
#include <hyperelastic/calibration/test_data.h>

#include <ostream>
#include <string>
#include <vector>

namespace hyperelastic
{
  namespace calibration
  {
    /// RMS of the (unweighted) residuals and R^2 = 1 - SS_res / SS_tot.
    struct GoodnessOfFit
    {
      double rms       = 0.;
      double r_squared = 0.;
    };

    GoodnessOfFit
    goodness_of_fit(const std::vector<double> &measured,
                    const std::vector<double> &fitted);

    struct FitReport
    {
      std::string                      model;
      std::vector<std::string>         names;
      FitResult                        result;
      std::vector<TestData>            data;
      std::vector<std::vector<double>> fitted;    ///< per test, per value
      std::vector<std::vector<double>> stretch_2; ///< per test, per value
      std::vector<StabilityVerdict>    stability;
      bool                             incompressible = true;
      double                           seconds        = 0.;
      /// Lines after the first of the summary (a scene fit's method).
      std::vector<std::string> notes;

      /// The summary, one line each (no trailing newline).
      std::vector<std::string>
      summary() const;

      /// True if every mode is Drucker stable over the range.
      bool
      stable() const;
    };

    /// <Base name>_fit.csv.
    void
    write_fit_csv(std::ostream &out, const FitReport &report);

    /// <Base name>_curve.csv: the fitted model along @p curves (states
    /// of curve_states()) with its @p values: data, test, stretch_1,
    /// stretch_2, fitted, component, time.
    void
    write_curve_csv(std::ostream                           &out,
                    const std::vector<TestData>            &curves,
                    const std::vector<std::vector<double>> &values);

    /// <Base name>_material.prm: the summary as '#' comments, then the
    /// Material block.
    void
    write_material_file(std::ostream         &out,
                        const FitReport      &report,
                        const ModelConstants &constants);
  } // namespace calibration
} // namespace hyperelastic
