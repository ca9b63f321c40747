// The fit's parameter file (see the header).
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/calibration/fit_parameters.h>
#include <hyperelastic/materials/material_parameters.h>

namespace hyperelastic
{
  namespace calibration
  {
    using namespace entry_patterns;

    std::optional<ReactionColumn>
    reaction_column(const std::string &column)
    {
      const std::string prefix = "reaction_";
      const auto        last   = column.rfind('_');
      if (column.rfind(prefix, 0) != 0 || last == std::string::npos ||
          last + 2 != column.size() || last <= prefix.size())
        return std::nullopt;
      const std::string id = column.substr(prefix.size(), last - prefix.size());
      const auto        axis = std::string("xyz").find(column.back());
      if (id.find_first_not_of("0123456789") != std::string::npos ||
          id.size() > 9 || axis == std::string::npos)
        return std::nullopt;
      ReactionColumn reaction;
      reaction.boundary_id = std::stoi(id);
      reaction.component   = axis;
      return reaction;
    }

    void
    FitParameters::declare(dealii::ParameterHandler &prm)
    {
      MaterialParameters::declare(prm);
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "output",
                        Anything(),
                        "Folder of <Base name>_material.prm and "
                        "<Base name>_fit.csv (created if missing).");
      prm.declare_entry("Base name",
                        "fit",
                        Anything(),
                        "Prefix of the files the fit writes.");
      prm.leave_subsection();
      prm.enter_subsection("Fit");
      prm.declare_entry(
        "Free constants",
        "",
        List(Anything()),
        "The entries the fit varies, by their scene names: those of the "
        "model's own subsection (Ogden: mu1, alpha1, ...), or for the "
        "Lame-based models the pair 'Elastic constants' selects (Young's "
        "modulus, Poisson's ratio | Shear modulus, Lame lambda | Shear "
        "modulus, Bulk modulus). Empty: all of the model's constants but the "
        "volumetric one (Bulk modulus, Lame lambda or Poisson's ratio). The "
        "others keep the values of the Material subsection.");
      prm.declare_entry("Incompressible",
                        "true",
                        Bool(),
                        "true: the tests are fitted with J = 1 (a pressure "
                        "frees the lateral faces); the volumetric constant "
                        "cannot be free. false: the lateral stretches are "
                        "solved so that the free faces carry no stress, and "
                        "the bulk modulus takes part.");
      prm.declare_entry("Starts",
                        "8",
                        Integer(1, 1000),
                        "Levenberg-Marquardt runs: from the Material "
                        "subsection's values and from Starts - 1 points "
                        "around them (each free value times a factor in "
                        "[1/3, 3]); the best is kept.");
      prm.declare_entry("Stability range",
                        "0.1, 10",
                        Anything(),
                        "Lowest and highest stretch (lowest < 1 < highest) "
                        "over which Drucker stability is checked along the "
                        "uniaxial, equibiaxial and planar paths.");
      prm.declare_entry("Scene",
                        "",
                        Anything(),
                        "A scene file (relative to this file) to fit through: "
                        "its own Material subsection gives the model and the "
                        "starting constants, and it is run with trial "
                        "constants on the same mesh, its load steps landing "
                        "on the data's load factors. Then 'Scene data' is "
                        "the data and the Data k subsections must be empty. "
                        "Quasi-static scenes.");
      prm.declare_entry("Scene data",
                        "",
                        Anything(),
                        "With 'Scene': a CSV with the columns load_factor and "
                        "one column of the scene's CSV summary (for example "
                        "reaction_2_z), the measured values at those load "
                        "factors.");
      for (unsigned int k = 1; k <= max_data_sets; ++k)
        {
          prm.enter_subsection("Data " + std::to_string(k));
          prm.declare_entry("Test",
                            "uniaxial",
                            Selection(test_type_names()),
                            "The test of this file: uniaxial, equibiaxial "
                            "and planar: columns stretch, nominal_stress; "
                            "biaxial: stretch_1, stretch_2, "
                            "nominal_stress_1, nominal_stress_2; simple "
                            "shear: shear, nominal_shear_stress; "
                            "volumetric: J, pressure (minus the mean Cauchy "
                            "stress; Incompressible = false only); "
                            "relaxation: time, nominal_stress of a uniaxial "
                            "stretch held from time 0 (Incompressible = true "
                            "only; fits the Prony series of "
                            "Material/Viscoelasticity). The other tests are "
                            "taken as the long-term (relaxed) response.");
          prm.declare_entry("File",
                            "",
                            Anything(),
                            "CSV file with a header row naming the columns; "
                            "lines starting with # are comments. Empty: no "
                            "such data set.");
          prm.declare_entry("Weight",
                            "1",
                            Double(0.),
                            "Factor of this test's squared residuals.");
          prm.declare_entry("Stretch",
                            "1",
                            Double(),
                            "A relaxation test's held uniaxial stretch "
                            "(positive, not 1).");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }

    void
    FitParameters::parse(dealii::ParameterHandler &prm,
                         const std::string        &folder)
    {
      prm.enter_subsection("Output");
      directory = dealii::Utilities::trim(prm.get("Directory"));
      base_name = dealii::Utilities::trim(prm.get("Base name"));
      prm.leave_subsection();
      if (directory.empty())
        reject("Output/Directory", "", "must not be empty");
      if (base_name.empty() || base_name.find('/') != std::string::npos)
        reject("Output/Base name", base_name, "must be a non-empty file name");

      prm.enter_subsection("Fit");
      free_constants.clear();
      for (const std::string &name :
           dealii::Utilities::split_string_list(prm.get("Free constants")))
        if (!dealii::Utilities::trim(name).empty())
          free_constants.push_back(dealii::Utilities::trim(name));
      incompressible = prm.get_bool("Incompressible");
      starts         = prm.get_integer("Starts");
      const std::vector<double> range =
        parse_coordinates(prm.get("Stability range"));
      if (range.size() != 2 || !(range[0] > 0.) || !(range[0] < 1.) ||
          !(range[1] > 1.))
        reject("Fit/Stability range",
               prm.get("Stability range"),
               "must be two stretches 'lowest, highest' with 0 < lowest < 1 "
               "< highest");
      stability_lowest  = range[0];
      stability_highest = range[1];
      data.clear();
      for (unsigned int k = 1; k <= max_data_sets; ++k)
        {
          prm.enter_subsection("Data " + std::to_string(k));
          const std::string file = dealii::Utilities::trim(prm.get("File"));
          if (!file.empty())
            {
              const TestType    type    = test_type(prm.get("Test"));
              const std::string section = "Fit/Data " + std::to_string(k);
              if (type == TestType::volumetric && incompressible)
                reject(section + "/Test",
                       prm.get("Test"),
                       "a volumetric test needs Fit/Incompressible = false");
              if (type == TestType::relaxation && !incompressible)
                reject(section + "/Test",
                       prm.get("Test"),
                       "a relaxation test is fitted with J = 1: it needs "
                       "Fit/Incompressible = true");
              const double stretch = prm.get_double("Stretch");
              if (type == TestType::relaxation &&
                  (!(stretch > 0.) || stretch == 1.))
                reject(section + "/Stretch",
                       prm.get("Stretch"),
                       "a relaxation test needs the held stretch (positive, "
                       "not 1)");
              TestData test =
                read_test_data(file[0] == '/' ? file : folder + "/" + file,
                               type,
                               stretch);
              test.index  = k;
              test.weight = prm.get_double("Weight");
              data.push_back(test);
            }
          prm.leave_subsection();
        }
      scene = dealii::Utilities::trim(prm.get("Scene"));
      const std::string scene_data =
        dealii::Utilities::trim(prm.get("Scene data"));
      const auto path = [&](const std::string &file) {
        return file[0] == '/' ? file : folder + "/" + file;
      };
      if (!scene.empty())
        {
          if (!data.empty())
            reject("Fit/Data " + std::to_string(data[0].index) + "/File",
                   data[0].file,
                   "a fit through a scene takes its data from 'Fit/Scene "
                   "data' only");
          if (scene_data.empty())
            reject("Fit/Scene data",
                   "",
                   "a fit through a scene needs its data");
          scene = path(scene);
          data.push_back(read_scene_data(path(scene_data), scene_column));
          scene_reaction = reaction_column(scene_column);
          data.back().index = 1;
        }
      else if (!scene_data.empty())
        reject("Fit/Scene data", scene_data, "needs 'Fit/Scene'");
      prm.leave_subsection();
      if (data.empty())
        reject("Fit/Data 1/File", "", "a fit needs at least one data file");
    }
  } // namespace calibration
} // namespace hyperelastic
