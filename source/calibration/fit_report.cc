// The fit's summary and files (see the header).
#include <hyperelastic/calibration/fit_report.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hyperelastic
{
  namespace calibration
  {
    GoodnessOfFit
    goodness_of_fit(const std::vector<double> &measured,
                    const std::vector<double> &fitted)
    {
      GoodnessOfFit fit;
      double        mean = 0., residual = 0., total = 0.;
      for (const double y : measured)
        mean += y / measured.size();
      for (unsigned int i = 0; i < measured.size(); ++i)
        {
          residual += (fitted[i] - measured[i]) * (fitted[i] - measured[i]);
          total += (measured[i] - mean) * (measured[i] - mean);
        }
      fit.rms       = std::sqrt(residual / measured.size());
      fit.r_squared = total > 0. ? 1. - residual / total : 1.;
      return fit;
    }

    std::vector<std::string>
    FitReport::summary() const
    {
      std::vector<std::string> lines;
      std::ostringstream       line;
      const auto               flush = [&]() {
        lines.push_back(line.str());
        line.str("");
      };
      const bool scene = !data.empty() && data[0].type == TestType::scene;
      if (scene)
        line << "Fit of the " << model << " model through a scene, absolute "
             << "residuals of its CSV column";
      else
        line << "Fit of the " << model << " model to " << data.size()
             << " test(s), "
             << (incompressible ? "incompressible (the fit assumed J = 1)"
                                : "compressible (lateral stretches solved)")
             << ", absolute nominal-stress residuals";
      flush();
      for (const std::string &note : notes)
        {
          line << note;
          flush();
        }
      line << "Levenberg-Marquardt: " << result.starts_converged
           << " start(s) converged, " << result.iterations
           << " iterations in all, " << std::setprecision(3) << seconds << " s";
      flush();
      for (unsigned int k = 0; k < names.size(); ++k)
        {
          line << std::setprecision(10) << "  " << names[k] << " = "
               << result.values[k] << "  (standard error "
               << std::setprecision(3) << result.standard_errors[k] << ")";
          flush();
        }
      std::vector<double> all_measured, all_fitted;
      for (unsigned int t = 0; t < data.size(); ++t)
        {
          const GoodnessOfFit fit =
            goodness_of_fit(data[t].measured, fitted[t]);
          line << std::setprecision(4) << "  Data " << data[t].index << " ("
               << test_type_name(data[t].type) << ", "
               << data[t].measured.size() << " values): RMS " << fit.rms
               << ", R^2 " << std::setprecision(6) << fit.r_squared;
          flush();
          all_measured.insert(all_measured.end(),
                              data[t].measured.begin(),
                              data[t].measured.end());
          all_fitted.insert(all_fitted.end(),
                            fitted[t].begin(),
                            fitted[t].end());
        }
      const GoodnessOfFit overall = goodness_of_fit(all_measured, all_fitted);
      line << std::setprecision(4) << "  Overall: RMS " << overall.rms
           << ", R^2 " << std::setprecision(6) << overall.r_squared;
      flush();
      line << "Drucker stability ("
           << (incompressible ? "J = 1" : "compressible") << "):";
      flush();
      for (const StabilityVerdict &verdict : stability)
        {
          line << "  " << verdict.text();
          flush();
        }
      if (!stable())
        {
          line << "WARNING: the fitted constants are not Drucker stable over "
                  "the stability range: a scene reaching those stretches can "
                  "lose uniqueness; fit other data, fix or bound constants, "
                  "or choose another model.";
          flush();
        }
      return lines;
    }

    bool
    FitReport::stable() const
    {
      for (const StabilityVerdict &verdict : stability)
        if (!verdict.stable())
          return false;
      return true;
    }

    void
    write_fit_csv(std::ostream &out, const FitReport &report)
    {
      out << "data,test,stretch_1,stretch_2,measured,fitted,component,time\n"
          << std::setprecision(17);
      for (unsigned int t = 0; t < report.data.size(); ++t)
        {
          const TestData &test = report.data[t];
          for (unsigned int i = 0; i < test.states.size(); ++i)
            out << test.index << "," << test_type_name(test.type) << ","
                << test.states[i].stretch_1 << "," << report.stretch_2[t][i]
                << "," << test.measured[i] << "," << report.fitted[t][i] << ","
                << test.states[i].component + 1 << "," << test.states[i].time
                << "\n";
        }
    }

    void
    write_curve_csv(std::ostream                           &out,
                    const std::vector<TestData>            &curves,
                    const std::vector<std::vector<double>> &values)
    {
      out << "data,test,stretch_1,stretch_2,fitted,component,time\n"
          << std::setprecision(12);
      for (unsigned int t = 0; t < curves.size(); ++t)
        for (unsigned int i = 0; i < curves[t].states.size(); ++i)
          {
            const TestState &state = curves[t].states[i];
            out << curves[t].index << "," << test_type_name(curves[t].type)
                << "," << state.stretch_1 << "," << state.stretch_2 << ","
                << values[t][i] << "," << state.component + 1 << ","
                << state.time << "\n";
          }
    }

    void
    write_material_file(std::ostream         &out,
                        const FitReport      &report,
                        const ModelConstants &constants)
    {
      out << "# Written by hyperelastic --fit.\n";
      for (const std::string &line : report.summary())
        out << "# " << line << "\n";
      constants.write_material_block(out, report.result.values);
    }
  } // namespace calibration
} // namespace hyperelastic
