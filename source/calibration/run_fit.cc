// 'hyperelastic --fit' (see the header).
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/calibration/fit_parameters.h>
#include <hyperelastic/calibration/fit_report.h>
#include <hyperelastic/calibration/run_fit.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace hyperelastic
{
  namespace calibration
  {
    namespace
    {
      /// The file parsed into @p prm; InputErrors name the file.
      void
      read_parameter_file(const std::string        &file,
                          dealii::ParameterHandler &prm)
      {
        std::ifstream in(file);
        if (!in)
          throw InputError("cannot open fit file '" + file + "'");
        try
          {
            prm.parse_input(in, file);
          }
        catch (const dealii::ExceptionBase &e)
          {
            throw InputError(exception_message(e));
          }
      }

      void
      check_enough_data(const std::vector<TestData> &data,
                        const ModelConstants        &constants)
      {
        std::size_t values = 0;
        for (const TestData &test : data)
          values += test.measured.size();
        if (values < constants.names().size())
          {
            std::string names;
            for (const std::string &name : constants.names())
              names += (names.empty() ? "" : ", ") + name;
            reject("Fit/Free constants",
                   names,
                   std::to_string(constants.names().size()) +
                     " free constants need at least as many measured values; "
                     "the data files have " + std::to_string(values));
          }
      }

      /// The second stretch of every value (calibration/fit_report.h).
      std::vector<std::vector<double>>
      second_stretches(const Material<3>           &material,
                       const std::vector<TestData> &data,
                       const bool                   incompressible)
      {
        std::vector<std::vector<double>> stretches;
        for (const TestData &test : data)
          {
            stretches.emplace_back();
            for (const TestState &state : test.states)
              stretches.back().push_back(
                principal_stretches(material, state, incompressible)[1]);
          }
        return stretches;
      }

      void
      write_files(const FitParameters  &parameters,
                  const FitReport      &report,
                  const ModelConstants &constants,
                  const Material<3>    &material)
      {
        std::filesystem::create_directories(parameters.directory);
        const std::string base =
          parameters.directory + "/" + parameters.base_name;
        std::ofstream prm_file(base + "_material.prm");
        write_material_file(prm_file, report, constants);
        std::ofstream csv(base + "_fit.csv");
        write_fit_csv(csv, report);
        const std::vector<TestData> curves = curve_states(parameters.data);
        std::ofstream               curve(base + "_curve.csv");
        write_curve_csv(curve,
                        curves,
                        model_values(material,
                                     constants.prony(report.result.values),
                                     curves,
                                     parameters.incompressible));
        if (!prm_file || !csv || !curve)
          throw InputError("cannot write the fit's files in '" +
                           parameters.directory + "'");
        std::cout << "Wrote " << base << "_material.prm, " << base
                  << "_fit.csv and " << base
                  << "_curve.csv (picture: python3 scripts/plot_fit.py " << base
                  << "_fit.csv)" << std::endl;
      }
    } // namespace

    void
    run_fit(const std::string &fit_file, const MPI_Comm comm)
    {
      const auto               begin = std::chrono::steady_clock::now();
      dealii::ParameterHandler prm;
      FitParameters::declare(prm);
      read_parameter_file(fit_file, prm);
      const auto                      slash = fit_file.rfind('/');
      FitParameters                   parameters;
      std::unique_ptr<ModelConstants> fitted;
      try
        {
          parameters.parse(prm,
                           slash == std::string::npos ?
                             "." :
                             fit_file.substr(0, slash));
          bool relaxation = false;
          for (const TestData &test : parameters.data)
            relaxation = relaxation || test.type == TestType::relaxation;
          fitted = std::make_unique<ModelConstants>(prm,
                                                    parameters.free_constants,
                                                    parameters.incompressible,
                                                    relaxation);
          if (relaxation &&
              fitted->prony(fitted->start()).weights.empty())
            reject("Material/Viscoelasticity/Weights",
                   "",
                   "a relaxation test fits the Prony series: give starting "
                   "Weights and Relaxation times");
          check_enough_data(parameters.data, *fitted);
        }
      catch (const InputError &e)
        {
          const std::string what = e.what();
          throw InputError(what.find("test data file") == 0 ?
                             what :
                             "fit file '" + fit_file + "': " + what);
        }
      const ModelConstants &constants = *fitted;
      if (!constants.material(constants.start()))
        throw InputError("fit file '" + fit_file +
                         "': the Material subsection's constants are not "
                         "admissible");

      FitReport report;
      report.model          = constants.model();
      report.names          = constants.names();
      report.data           = parameters.data;
      report.incompressible = parameters.incompressible;
      report.result         = fit_material(constants,
                                   parameters.data,
                                   parameters.incompressible,
                                   parameters.starts);
      if (!std::isfinite(report.result.cost))
        throw InputError("fit file '" + fit_file + "': the " +
                         constants.model() +
                         " model is undefined at some data point for every "
                         "start (check the data's stretches and the "
                         "starting constants)");
      const auto material = constants.material(report.result.values);
      report.fitted = model_values(*material,
                                   constants.prony(report.result.values),
                                   parameters.data,
                                   parameters.incompressible);
      report.stretch_2 =
        second_stretches(*material, parameters.data, parameters.incompressible);
      report.stability = drucker_stability(*material,
                                           parameters.incompressible,
                                           parameters.stability_lowest,
                                           parameters.stability_highest);
      report.seconds = std::chrono::duration<double>(
                         std::chrono::steady_clock::now() - begin)
                         .count();
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      for (const std::string &line : report.summary())
        std::cout << line << "\n";
      write_files(parameters, report, constants, *material);
    }
  } // namespace calibration
} // namespace hyperelastic
