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
            reject("Fit/Free constants",
                   listed(constants.names()),
                   std::to_string(constants.names().size()) +
                     " free constants need at least as many measured values; "
                     "the data files have " +
                     std::to_string(values));
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
                  const Material<3>    &material,
                  const bool            curves)
      {
        std::filesystem::create_directories(parameters.directory);
        const std::string base =
          parameters.directory + "/" + parameters.base_name;
        std::ofstream prm_file(base + "_material.prm");
        write_material_file(prm_file, report, constants);
        std::ofstream csv(base + "_fit.csv");
        write_fit_csv(csv, report);
        if (curves)
          {
            const std::vector<TestData> states = curve_states(parameters.data);
            std::ofstream               curve(base + "_curve.csv");
            write_curve_csv(curve,
                            states,
                            model_values(material,
                                         constants.prony(report.result.values),
                                         states,
                                         parameters.incompressible));
            if (!curve)
              throw InputError("cannot write the fit's files in '" +
                               parameters.directory + "'");
          }
        if (!prm_file || !csv)
          throw InputError("cannot write the fit's files in '" +
                           parameters.directory + "'");
        std::cout << "Wrote " << base << "_material.prm, " << base << "_fit.csv"
                  << (curves ? ", " + base + "_curve.csv" : "")
                  << " (picture: python3 scripts/plot_fit.py " << base
                  << "_fit.csv)" << std::endl;
      }
    } // namespace

    void
    read_fit_file(const std::string        &fit_file,
                  dealii::ParameterHandler &prm,
                  FitParameters            &parameters)
    {
      FitParameters::declare(prm);
      read_parameter_file(fit_file, prm);
      const auto slash = fit_file.rfind('/');
      try
        {
          parameters.parse(
            prm, slash == std::string::npos ? "." : fit_file.substr(0, slash));
        }
      catch (const InputError &e)
        {
          // A data file's errors name that file and line already.
          const std::string what            = e.what();
          bool              names_data_file = false;
          for (const char *start : {"test data file",
                                    "scene data file",
                                    "cannot open test data file",
                                    "cannot open scene data file"})
            names_data_file = names_data_file || what.rfind(start, 0) == 0;
          throw InputError(
            names_data_file ? what : "fit file '" + fit_file + "': " + what);
        }
    }

    std::unique_ptr<ModelConstants>
    fit_constants(dealii::ParameterHandler    &prm,
                  const FitParameters         &parameters,
                  const std::vector<TestData> &data,
                  const bool                   incompressible,
                  const std::string           &file)
    {
      std::unique_ptr<ModelConstants> constants;
      try
        {
          bool relaxation = false;
          for (const TestData &test : data)
            relaxation = relaxation || test.type == TestType::relaxation;
          constants = std::make_unique<ModelConstants>(
            prm, parameters.free_constants, incompressible, relaxation);
          if (relaxation &&
              constants->prony(constants->start()).weights.empty())
            reject("Material/Viscoelasticity/Weights",
                   "",
                   "a relaxation test fits the Prony series: give starting "
                   "Weights and Relaxation times");
          check_enough_data(data, *constants);
          // (The constructor parsed the starting constants: admissible.)
          const bool isotropic =
            isotropic_about_x(*constants->material(constants->start()));
          for (const TestData &test : data)
            if ((test.type == TestType::uniaxial ||
                 test.type == TestType::relaxation) &&
                !isotropic)
              reject("Fit/Data " + std::to_string(test.index) + "/Test",
                     test_type_name(test.type),
                     "the " + constants->model() +
                       " model here is not isotropic about the test's axis "
                       "(fibres off it), so a uniaxial test's lateral "
                       "stretches differ, which the tests do not model: fit "
                       "biaxial, equibiaxial, planar or simple shear data");
        }
      catch (const InputError &e)
        {
          throw InputError(file + ": " + e.what());
        }
      return constants;
    }

    void
    report_fit(const FitParameters  &parameters,
               const FitReport      &report,
               const ModelConstants &constants,
               const Material<3>    &material,
               const bool            curves,
               const MPI_Comm        comm)
    {
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      for (const std::string &line : report.summary())
        std::cout << line << "\n";
      write_files(parameters, report, constants, material, curves);
    }

    void
    fit_tests(dealii::ParameterHandler &prm,
              const FitParameters      &parameters,
              const std::string        &fit_file,
              const MPI_Comm            comm)
    {
      const auto            begin     = std::chrono::steady_clock::now();
      const auto            fitted    = fit_constants(prm,
                                        parameters,
                                        parameters.data,
                                        parameters.incompressible,
                                        "fit file '" + fit_file + "'");
      const ModelConstants &constants = *fitted;

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
      report.fitted       = model_values(*material,
                                   constants.prony(report.result.values),
                                   parameters.data,
                                   parameters.incompressible);
      report.stretch_2 =
        second_stretches(*material, parameters.data, parameters.incompressible);
      report.stability = drucker_stability(*material,
                                           parameters.incompressible,
                                           parameters.stability_lowest,
                                           parameters.stability_highest);
      report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin)
          .count();
      report_fit(parameters, report, constants, *material, true, comm);
    }
  } // namespace calibration
} // namespace hyperelastic
