// The free constants of a fit as scene entries (see the header).
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/calibration/model_constants.h>
#include <hyperelastic/materials/constant_entries.h>
#include <hyperelastic/materials/material_parameters.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hyperelastic
{
  namespace calibration
  {
    namespace
    {
      bool
      contains(const std::vector<std::string> &names, const std::string &name)
      {
        return std::find(names.begin(), names.end(), name) != names.end();
      }

      /// The parsed material of the handler; InputError if it is invalid.
      MaterialParameters
      parsed(dealii::ParameterHandler &prm)
      {
        MaterialParameters material;
        material.parse(prm);
        return material;
      }
    } // namespace

    ModelConstants::ModelConstants(dealii::ParameterHandler       &prm,
                                   const std::vector<std::string> &free_names,
                                   const bool incompressible,
                                   const bool relaxation_data)
    {
      std::ostringstream text;
      prm.print_parameters(text, dealii::ParameterHandler::PRM);
      file_text                         = text.str();
      const MaterialParameters material = parsed(prm);
      model_name                        = material.model;
      if (material.stiffness_warping)
        reject("Material/Model",
               model_name,
               "is not a model of P(F): it "
               "cannot be fitted");
      file_viscoelasticity = material.viscoelasticity;
      file_prony.weights   = material.viscoelasticity.weights;
      file_prony.times   = material.viscoelasticity.relaxation_times;
      prm.enter_subsection("Material");
      prm.enter_subsection("Viscoelasticity");
      duration_text = prm.get("Quasi-static duration");
      prm.leave_subsection();
      prm.leave_subsection();
      if (material_model(model_name).uses_elastic_constants)
        {
          prm.enter_subsection("Material");
          pair = prm.get("Elastic constants");
          prm.leave_subsection();
        }
      const auto model = parsed(*handler({})).factory.create<3>();
      if (model->depends_on_position())
        reject("Material/Model",
               model_name,
               "has constants that vary with x, y, z here (fibre directions "
               "given as expressions of them): a fit of homogeneous tests "
               "needs them constant");
      const auto derivate =
        dynamic_cast<const ConstantDerivatives<3> *>(model.get());
      if (!derivate)
        reject("Material/Model",
               model_name,
               "does not give the derivatives "
               "of its stress with respect to its constants, so it cannot be "
               "fitted");
      if (!pair.empty())
        {
          all_entries =
            pair == "Lame"
              ? std::vector<std::string>{"Shear modulus", "Lame lambda"}
            : pair == "shear and bulk modulus"
              ? std::vector<std::string>{"Shear modulus", "Bulk modulus"}
              : std::vector<std::string>{"Young's modulus", "Poisson's ratio"};
          volumetric_entry = all_entries[1];
        }
      else
        {
          all_entries      = derivate->constant_names();
          volumetric_entry = "Bulk modulus";
        }
      select_free(free_names, incompressible, relaxation_data);
      // An exactly incompressible material ('inf', nu = 0.5): J = 1 leaves
      // its volumetric constant idle, but inf * 0 would be NaN, so a finite
      // stand-in is parsed instead (the written block keeps the file's text).
      volumetric_text = get(prm, volumetric_entry);
      if (std::isinf(model->small_strain_moduli().lambda))
        {
          if (!incompressible)
            reject("Material/" +
                     (pair.empty() ? model_name + "/" : std::string()) +
                     volumetric_entry,
                   volumetric_text,
                   "an incompressible material needs Fit/Incompressible = "
                   "true");
          volumetric_stand_in =
            volumetric_entry == "Poisson's ratio" ? "0.3" : "1";
        }
    }

    void
    ModelConstants::select_free(const std::vector<std::string> &free_names,
                                const bool                      incompressible,
                                const bool                      relaxation_data)
    {
      const bool        viscoelastic = !file_prony.weights.empty();
      bool              weights = false, times = false;
      const std::string entry = "Fit/Free constants";
      for (const std::string &name : free_names)
        {
          const bool prony = name == "Weights" || name == "Relaxation times";
          if (prony && !viscoelastic)
            reject(entry,
                   name,
                   "needs Material/Viscoelasticity with "
                   "starting Weights and Relaxation times");
          if (!prony && !contains(all_entries, name))
            reject(entry,
                   name,
                   "is not a constant of the " + model_name + " model" +
                     (pair.empty()
                        ? ""
                        : " with 'Elastic constants = " + pair + "'") +
                     "; its constants are " + listed(all_entries) +
                     (viscoelastic ? ", Weights, Relaxation times" : ""));
          if (incompressible && name == volumetric_entry)
            reject(entry,
                   name,
                   "is the volumetric constant, which cannot "
                   "be free with Fit/Incompressible = true");
          if (contains(free, name) || (name == "Weights" && weights) ||
              (name == "Relaxation times" && times))
            reject(entry, name, "is named twice");
          if (name == "Weights")
            weights = true;
          else if (name == "Relaxation times")
            times = true;
          else
            free.push_back(name);
        }
      if (free_names.empty())
        {
          for (const std::string &name : all_entries)
            if (name != volumetric_entry)
              free.push_back(name);
          weights = times = viscoelastic && relaxation_data;
        }
      value_names    = free;
      const auto add = [&](const bool         is_free,
                           const std::string &name,
                           std::vector<int>  &columns) {
        for (unsigned int j = 0; j < file_prony.weights.size(); ++j)
          {
            columns.push_back(is_free ? int(value_names.size()) : -1);
            if (is_free)
              value_names.push_back(name + " " + std::to_string(j + 1));
          }
      };
      add(weights, "Weights", weight_column);
      add(times, "Relaxation times", time_column);
    }

    const std::vector<std::string> &
    ModelConstants::names() const
    {
      return value_names;
    }

    const std::vector<int> &
    ModelConstants::weight_columns() const
    {
      return weight_column;
    }

    const std::vector<int> &
    ModelConstants::time_columns() const
    {
      return time_column;
    }

    PronySeries
    ModelConstants::prony(const std::vector<double> &values) const
    {
      PronySeries series = file_prony;
      for (unsigned int j = 0; j < series.weights.size(); ++j)
        {
          if (weight_column[j] >= 0 &&
              unsigned(weight_column[j]) < values.size())
            series.weights[j] = values[weight_column[j]];
          if (time_column[j] >= 0 && unsigned(time_column[j]) < values.size())
            series.times[j] = values[time_column[j]];
        }
      return series;
    }

    const std::string &
    ModelConstants::model() const
    {
      return model_name;
    }

    std::string
    ModelConstants::get(dealii::ParameterHandler &prm,
                        const std::string        &entry) const
    {
      return prm.get(pair.empty()
                       ? std::vector<std::string>{"Material", model_name}
                       : std::vector<std::string>{"Material"},
                     entry);
    }

    std::vector<double>
    ModelConstants::start() const
    {
      const auto          prm = handler({});
      std::vector<double> values;
      for (const std::string &name : free)
        values.push_back(std::stod(get(*prm, name)));
      for (unsigned int j = 0; j < file_prony.weights.size(); ++j)
        if (weight_column[j] >= 0)
          values.push_back(file_prony.weights[j]);
      for (unsigned int j = 0; j < file_prony.times.size(); ++j)
        if (time_column[j] >= 0)
          values.push_back(file_prony.times[j]);
      return values;
    }

    std::unique_ptr<dealii::ParameterHandler>
    ModelConstants::handler(const std::vector<double> &values) const
    {
      auto prm = std::make_unique<dealii::ParameterHandler>();
      MaterialParameters::declare(*prm);
      prm->parse_input_from_string(file_text, "", true);
      set_free(*prm, values);
      prm->enter_subsection("Material");
      prm->enter_subsection("Viscoelasticity");
      prm->set("Weights", "");
      prm->set("Relaxation times", "");
      prm->leave_subsection();
      prm->leave_subsection();
      return prm;
    }

    void
    ModelConstants::set_free(dealii::ParameterHandler  &prm,
                             const std::vector<double> &values) const
    {
      prm.enter_subsection("Material");
      if (pair.empty())
        prm.enter_subsection(model_name);
      for (unsigned int k = 0; k < values.size() && k < free.size(); ++k)
        prm.set(free[k], exact_entry_text(values[k]));
      if (!volumetric_stand_in.empty())
        prm.set(volumetric_entry, volumetric_stand_in);
      if (pair.empty())
        prm.leave_subsection();
      prm.leave_subsection();
    }

    std::unique_ptr<Material<3>>
    ModelConstants::material(const std::vector<double> &values) const
    {
      std::vector<std::vector<double>> d;
      return material_and_chain(values, d);
    }

    std::unique_ptr<Material<3>>
    ModelConstants::material_and_chain(
      const std::vector<double>        &values,
      std::vector<std::vector<double>> &d) const
    {
      const auto trial = parsed_trial(values, d);
      return trial ? trial->factory.create<3>() : nullptr;
    }

    std::optional<MaterialParameters>
    ModelConstants::parsed_trial(const std::vector<double>        &values,
                                 std::vector<std::vector<double>> &d) const
    {
      const PronySeries series = prony(values);
      for (unsigned int j = 0; j < series.weights.size(); ++j)
        if (!(series.weights[j] >= 0.) || !(series.times[j] > 0.) ||
            !std::isfinite(series.weights[j] + series.times[j]))
          return std::nullopt;
      if (!trial_handler)
        trial_handler = handler(values);
      else
        set_free(*trial_handler, values);
      try
        {
          ++n_trial_parses;
          MaterialParameters trial = parsed(*trial_handler);
          d                        = chain(*trial_handler);
          return trial;
        }
      catch (const InputError &)
        {
          trial_handler.reset();
          return std::nullopt;
        }
    }

    std::optional<MaterialParameters>
    ModelConstants::parameters(const std::vector<double>        &values,
                               std::vector<std::vector<double>> *d) const
    {
      std::vector<std::vector<double>> chain_here;
      auto trial = parsed_trial(values, d ? *d : chain_here);
      if (trial && !file_prony.weights.empty())
        {
          const PronySeries series               = prony(values);
          trial->viscoelasticity                  = file_viscoelasticity;
          trial->viscoelasticity.weights          = series.weights;
          trial->viscoelasticity.relaxation_times = series.times;
          trial->factory = MaterialFactory::of<Viscoelastic>(
            ViscoelasticConstants{trial->factory, trial->viscoelasticity});
        }
      return trial;
    }

    unsigned int
    ModelConstants::trial_parses() const
    {
      return n_trial_parses;
    }

    std::vector<std::vector<double>>
    ModelConstants::chain(dealii::ParameterHandler &prm) const
    {
      if (pair.empty())
        {
          std::vector<std::vector<double>> d(all_entries.size(),
                                             std::vector<double>(free.size()));
          for (unsigned int i = 0; i < all_entries.size(); ++i)
            for (unsigned int k = 0; k < free.size(); ++k)
              d[i][k] = all_entries[i] == free[k] ? 1. : 0.;
          return d;
        }
      // Rows mu, lambda.
      std::vector<std::vector<double>> d(2, std::vector<double>(free.size()));
      const bool   engineering = all_entries[0] == "Young's modulus";
      const double E  = engineering ? std::stod(get(prm, all_entries[0])) : 0.;
      const double nu = engineering ? std::stod(get(prm, all_entries[1])) : 0.;
      for (unsigned int k = 0; k < free.size(); ++k)
        {
          const std::string &name = free[k];
          if (name == "Young's modulus")
            {
              d[0][k] = 0.5 / (1. + nu);
              d[1][k] = nu / ((1. + nu) * (1. - 2. * nu));
            }
          else if (name == "Poisson's ratio")
            {
              const double q = (1. + nu) * (1. - 2. * nu);
              d[0][k]        = -0.5 * E / ((1. + nu) * (1. + nu));
              d[1][k]        = E * (1. + 2. * nu * nu) / (q * q);
            }
          else if (name == "Shear modulus")
            {
              d[0][k] = 1.;
              d[1][k] = pair == "Lame" ? 0. : -2. / 3.;
            }
          else // Lame lambda or Bulk modulus
            d[1][k] = 1.;
        }
      return d;
    }

    void
    ModelConstants::write_material_block(
      std::ostream              &out,
      const std::vector<double> &values) const
    {
      const auto prm   = handler(values);
      const auto value = [&](const std::string &entry) {
        return entry == volumetric_entry && !volumetric_stand_in.empty()
                 ? volumetric_text
                 : get(*prm, entry);
      };
      out << "subsection Material\n"
          << "  set Model = " << model_name << "\n";
      if (!pair.empty())
        {
          out << "  set Elastic constants = " << pair << "\n";
          for (const std::string &entry : all_entries)
            out << "  set " << entry << " = " << value(entry) << "\n";
        }
      else
        {
          // Every entry of the model's subsection (constants or not, such
          // as fibre directions), as the registry lists them.
          LameParameters unit;
          unit.mu = unit.lambda = 1.;
          out << "  subsection " << model_name << "\n";
          for (const auto &entry :
               material_model(model_name).entries_for_small_strain(unit))
            out << "    set " << entry.first << " = " << value(entry.first)
                << "\n";
          out << "  end\n";
        }
      if (!file_prony.weights.empty())
        {
          const PronySeries series = prony(values);
          const auto        list   = [](const std::vector<double> &x) {
            std::string text;
            for (const double v : x)
              text += (text.empty() ? "" : ", ") + exact_entry_text(v);
            return text;
          };
          out << "  subsection Viscoelasticity\n"
              << "    set Weights = " << list(series.weights) << "\n"
              << "    set Relaxation times = " << list(series.times) << "\n"
              << "    set Quasi-static duration = " << duration_text << "\n"
              << "  end\n";
        }
      out << "end\n";
    }
  } // namespace calibration
} // namespace hyperelastic
