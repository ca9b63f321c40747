// The scene's Material subsection: declaration, documentation and validation of
// its entries.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/material_parameters.h>
#include <hyperelastic/materials/grown.h>
#include <hyperelastic/materials/viscoelasticity.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace entry_patterns;

  namespace
  {
    /// Material/Model's documentation: one paragraph per registered model.
    std::string
    model_documentation()
    {
      std::string text =
        "Constitutive model, one of the registered models below. The "
        "Lame-based ones take the shared elastic constants of this "
        "subsection ('Elastic constants' and the moduli it selects); a model "
        "with constants of its own reads them from the subsection "
        "Material/<model name> and ignores the shared ones. See "
        "doc/manual.md, 'Choosing a model'.";
      for (const MaterialModel &m : material_models())
        text += "\n'" + m.name + "': " + m.documentation;
      text += "\n'" + std::string(MaterialParameters::stiffness_warping_name) +
              "': Mueller et al. 2002: the linear elastic stiffness K "
              "(shared elastic constants) warped by one rotation per vertex, "
              "R_i from the polar decomposition of sum over edges (x_j - "
              "x_i)(X_j - X_i)^T; forces f_i = R_i sum_j K_ij (R_i^T x_j - "
              "X_j), tangent R_i K_ij R_i^T (not symmetric: GMRES). Not "
              "derived from an energy: Newton's line search uses the residual "
              "norm, and the energy and cell stresses reported are the "
              "corotational model's. P1 displacement only; made for "
              "animation with 'Time integration/Linearize once per step'. "
              "Not a registered model: the per-model tests do not apply.";
      return text;
    }
  } // namespace

  void
  MaterialParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Model",
                      "neo-Hookean",
                      Selection(material_model_names() + "|" +
                                stiffness_warping_name),
                      model_documentation());
    prm.declare_entry("Elastic constants",
                      "Young's modulus and Poisson's ratio",
                      Selection("Young's modulus and Poisson's ratio|Lame|"
                                "shear and bulk modulus"),
                      "Which pair of constants the scene gives: (E, nu), "
                      "the Lame constants (mu, lambda), or the shear and "
                      "bulk moduli (mu, kappa), converted to lambda = kappa "
                      "- 2 mu / 3. Used by the Lame-based models only.");
    prm.declare_entry(
      "Young's modulus",
      "1",
      Double(),
      "E > 0 (used with 'Young's modulus and Poisson's ratio').");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      Double(),
                      "-1 < nu < 0.5 (used with 'Young's modulus and Poisson's "
                      "ratio'); nu = 0.5 is exactly incompressible (lambda = "
                      "infinity), accepted with 'Problem/Formulation = mixed' "
                      "only.");
    prm.declare_entry("Shear modulus",
                      "1",
                      Double(),
                      "Lame mu > 0 (used with 'Lame' and 'shear and bulk "
                      "modulus').");
    prm.declare_entry("Lame lambda",
                      "1",
                      Double(),
                      "Lame lambda, with lambda + 2 mu / 3 > 0 (used with "
                      "'Lame').");
    prm.declare_entry("Bulk modulus",
                      "1",
                      Anything(),
                      "kappa > 0 (used with 'shear and bulk modulus'; "
                      "lambda = kappa - 2 mu / 3), or 'inf': exactly "
                      "incompressible, with 'Problem/Formulation = mixed' "
                      "only.");
    // The models with constants of their own: one subsection each.
    for (const MaterialModel &m : material_models())
      if (m.declare_entries)
        {
          prm.enter_subsection(m.name);
          m.declare_entries(prm);
          prm.leave_subsection();
        }
    prm.enter_subsection("Viscoelasticity");
    ViscoelasticParameters::declare(prm);
    prm.leave_subsection();
    GrowthParameters::declare(prm);
    prm.leave_subsection();
  }

  void
  MaterialParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    model                           = prm.get("Model");
    stiffness_warping               = model == stiffness_warping_name;
    const MaterialModel &registered = material_model(registered_model());
    elastic_constants               = LameParameters();
    if (registered.uses_elastic_constants)
      parse_elastic_constants(prm, elastic_constants);
    factory = registered.parse(prm, elastic_constants);
    prm.enter_subsection("Viscoelasticity");
    viscoelasticity.parse(prm);
    prm.leave_subsection();
    if (viscoelasticity.active())
      {
        if (!registered.has_volumetric_split || stiffness_warping)
          reject("Material/Viscoelasticity/Weights",
                 viscoelasticity.weights_text,
                 "viscoelasticity acts on the isochoric stress of a model "
                 "with a volumetric-isochoric split (decoupled neo-Hookean, "
                 "Mooney-Rivlin, Yeoh, Gent, Arruda-Boyce, Ogden, "
                 "Holzapfel-Gasser-Ogden); the " +
                   model + " model has none");
        factory = MaterialFactory::of<Viscoelastic>(
          ViscoelasticConstants{factory, viscoelasticity});
      }
    growth.parse(prm);
    if (growth.kind != GrowthParameters::Kind::none)
      {
        if (stiffness_warping || viscoelasticity.active())
          reject("Material/Growth",
                 prm.get("Growth"),
                 stiffness_warping ?
                   "stiffness warping is not a function of F and cannot "
                   "grow" :
                   "growth of a viscoelastic model is not available");
        // The expressions parsed now: an error names its entry.
        GrowthLaw(growth, "Material");
        factory = MaterialFactory::of<Grown>(
          GrowthConstants{factory, growth, section});
      }
    // Which entry, if any, makes the material exactly incompressible.
    incompressible_entry.clear();
    if (std::isinf(factory.create<3>()->small_strain_moduli().lambda))
      {
        if (!registered.uses_elastic_constants)
          {
            incompressible_entry =
              "Material/" + registered.name + "/Bulk modulus";
            prm.enter_subsection(registered.name);
            incompressible_value = prm.get("Bulk modulus");
            prm.leave_subsection();
          }
        else if (prm.get("Elastic constants") == "shear and bulk modulus")
          {
            incompressible_entry = "Material/Bulk modulus";
            incompressible_value = prm.get("Bulk modulus");
          }
        else
          {
            incompressible_entry = "Material/Poisson's ratio";
            incompressible_value = prm.get("Poisson's ratio");
          }
      }
    prm.leave_subsection();
  }

  void
  MaterialParameters::parse_elastic_constants(ParameterHandler &prm,
                                              LameParameters   &lame)
  {
    const std::string constants = prm.get("Elastic constants");
    if (constants == "shear and bulk modulus")
      {
        lame.mu            = get_finite(prm, "Material", "Shear modulus");
        const double kappa = get_bulk_modulus(prm, "Material", "Bulk modulus");
        if (!(lame.mu > 0.))
          reject("Material/Shear modulus",
                 prm.get("Shear modulus"),
                 "must be positive");
        if (!(kappa > 0.))
          reject("Material/Bulk modulus",
                 prm.get("Bulk modulus"),
                 "must be positive");
        lame.lambda = kappa - 2. * lame.mu / 3.;
        // kappa far below mu can round lambda + 2 mu / 3 to 0.
        if (!(lame.lambda + 2. * lame.mu / 3. > 0.))
          reject("Material/Bulk modulus",
                 prm.get("Bulk modulus"),
                 "is too small against the shear modulus to be represented");
      }
    else if (constants == "Lame")
      {
        lame.mu     = get_finite(prm, "Material", "Shear modulus");
        lame.lambda = get_finite(prm, "Material", "Lame lambda");
        if (!(lame.mu > 0.))
          reject("Material/Shear modulus",
                 prm.get("Shear modulus"),
                 "must be positive");
        if (!(lame.lambda + 2. * lame.mu / 3. > 0.))
          reject("Material/Lame lambda",
                 prm.get("Lame lambda"),
                 "the bulk modulus lambda + 2 mu / 3 must be positive");
      }
    else
      {
        const double E  = get_finite(prm, "Material", "Young's modulus");
        const double nu = get_finite(prm, "Material", "Poisson's ratio");
        if (!(E > 0.))
          reject("Material/Young's modulus",
                 prm.get("Young's modulus"),
                 "must be positive");
        // nu = 0.5 (lambda = infinity) only with the mixed formulation:
        // the displacement formulation rejects it (its scene check).
        if (!(nu > -1. && nu <= 0.5))
          reject("Material/Poisson's ratio",
                 prm.get("Poisson's ratio"),
                 "must lie strictly between -1 and 0.5");
        lame = LameParameters::from_young_poisson(E, nu);
      }
  }
} // namespace hyperelastic

namespace hyperelastic
{
  void
  ViscoelasticParameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry(
      "Weights",
      "",
      List(Double(0), 0, 3),
      "beta_j >= 0 of up to three relaxation processes (a Prony series, "
      "Simo 1987): the instantaneous isochoric stiffness is (1 + sum beta_j) "
      "times the long-term one of the model. Empty (the default): elastic.");
    prm.declare_entry("Relaxation times",
                      "",
                      List(Double(0), 0, 3),
                      "tau_j > 0, one per weight, in the scene's time unit.");
    prm.declare_entry(
      "Quasi-static duration",
      "1",
      Double(0),
      "The physical time a quasi-static scene takes for the load factor to "
      "go from 0 to 1: a load step of increment dt lasts this times dt "
      "(implicit dynamics uses its own time step).");
  }

  void
  ViscoelasticParameters::parse(ParameterHandler &prm)
  {
    const auto numbers = [&](const std::string &name) {
      std::vector<double> values;
      for (const std::string &x :
           dealii::Utilities::split_string_list(prm.get(name)))
        values.push_back(dealii::Utilities::string_to_double(x));
      return values;
    };
    weights                   = numbers("Weights");
    weights_text              = prm.get("Weights");
    relaxation_times          = numbers("Relaxation times");
    quasi_static_duration     = prm.get_double("Quasi-static duration");
    const std::string section = "Material/Viscoelasticity/";
    if (relaxation_times.size() != weights.size())
      reject(section + "Relaxation times",
             prm.get("Relaxation times"),
             "needs one time per weight ('Weights' = '" + prm.get("Weights") +
               "')");
    for (const double tau : relaxation_times)
      if (!(tau > 0.) || !std::isfinite(tau))
        reject(section + "Relaxation times",
               prm.get("Relaxation times"),
               "every time must be positive and finite");
    for (const double beta : weights)
      if (!std::isfinite(beta))
        reject(section + "Weights", prm.get("Weights"), "must be finite");
    if (!(quasi_static_duration > 0.) || !std::isfinite(quasi_static_duration))
      reject(section + "Quasi-static duration",
             prm.get("Quasi-static duration"),
             "must be positive and finite");
  }
} // namespace hyperelastic
