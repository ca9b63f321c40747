// The registry of constitutive models: every model a scene can name, with its
// documentation, its own scene entries and how to build it in 2D and 3D.
// Material/Model's pattern and documentation, material_model_names(), the
// error for an unknown name, the tests' model loops and the per-model ctests
// (tests/list_models) all come from here, so that a new model is one header
// (the model and its constants) plus one line in
// source/materials/material_registry.cc, plus its tests.
//
// What a model class template Model<dim> provides to be registered:
//   Model<dim>(const Model<dim>::Constants &)   construction from its
//                                              constants;
//   static const char *documentation()        one paragraph for the scene
//                                              documentation;
//   name(), is_linear(), defined_for_inverted_elements() (the Material
//   interface; asked once at registration).
// Constants is LameParameters for the models derived from LameBasedMaterial,
// which take the shared elastic-constant entries of the Material subsection.
// Any other Constants type has entries of its own in the subsection
// Material/<name> and provides
//   static void declare(ParameterHandler &)         every entry with pattern,
//                                                   default, documentation;
//   static Constants parse(ParameterHandler &, const std::string &section)
//                                                   read and validated (an
//                                                   InputError naming
//                                                   section/entry);
//   static Constants from_small_strain(const LameParameters &)
//                                                   constants whose rest
//                                                   tangent is the (mu,
//                                                   lambda) tensor;
//   std::vector<std::pair<std::string, std::string>> entries() const
//                                                   the scene entries that
//                                                   parse back to them.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/materials/material.h>

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  /// A model with its constants fixed: creates it for either dimension
  /// (plane-strain post-processing needs the 3D twin of a 2D model, and a
  /// scene is parsed before the dimension's Problem exists).
  class MaterialFactory
  {
  public:
    MaterialFactory() = default;

    /// Creates Model<dim>(constants) for dim = 2 and 3.
    template <template <int> class Model, typename Constants>
    static MaterialFactory
    of(const Constants &constants)
    {
      MaterialFactory factory;
      factory.create_2d = [constants]() {
        return std::unique_ptr<Material<2>>(
          std::make_unique<Model<2>>(constants));
      };
      factory.create_3d = [constants]() {
        return std::unique_ptr<Material<3>>(
          std::make_unique<Model<3>>(constants));
      };
      return factory;
    }

    /// The model in @p dim dimensions; throws if nothing was parsed.
    template <int dim>
    std::unique_ptr<Material<dim>>
    create() const;

  private:
    std::function<std::unique_ptr<Material<2>>()> create_2d;
    std::function<std::unique_ptr<Material<3>>()> create_3d;
  };

  /// One registered model.
  struct MaterialModel
  {
    /// The value of Material/Model.
    std::string name;
    /// One paragraph: the energy, its constants and what it is good for.
    std::string documentation;
    /// dP/dF is constant: one linear solve is the whole answer.
    bool is_linear = false;
    /// psi, P and dP/dF are finite for J <= 0.
    bool defined_for_inverted_elements = false;
    /// Takes the shared elastic-constant entries of the Material subsection
    /// (E and nu, Lame, or shear and bulk modulus); otherwise the model has
    /// entries of its own in the subsection Material/<name>.
    bool uses_elastic_constants = true;
    /// Whether the model splits into psi_iso(F) + U(J) (needed by the
    /// mixed displacement-pressure formulation).
    bool has_volumetric_split = false;

    /// Declares the model's own entries; the handler is inside the
    /// subsection Material/<name>. Empty for Lame-based models.
    std::function<void(ParameterHandler &)> declare_entries;

    /// The model with the constants of the scene: the handler is inside the
    /// subsection Material; @p elastic_constants are the parsed shared
    /// entries (valid only if uses_elastic_constants).
    std::function<MaterialFactory(ParameterHandler &,
                                  const LameParameters &elastic_constants)>
      parse;

    /// The model with these small-strain moduli (see create_material()).
    std::function<MaterialFactory(const LameParameters &small_strain)>
      from_small_strain;

    /// The model's own entries (name, value) that parse to the same
    /// constants as from_small_strain(@p small_strain); empty for the
    /// Lame-based models. Lets tests write a scene for any registered model.
    std::function<std::vector<std::pair<std::string, std::string>>(
      const LameParameters &small_strain)>
      entries_for_small_strain;
  };

  /// Every registered model, in registration order (the order of
  /// material_model_names() and of the documentation).
  const std::vector<MaterialModel> &
  material_models();

  /// The registered model called @p name; an unknown name throws an
  /// InputError listing the registered ones.
  const MaterialModel &
  material_model(const std::string &name);

  /// The registry entry of the model class template @p Model (see the top
  /// of this file for what it must provide).
  template <template <int> class Model>
  MaterialModel
  make_material_model()
  {
    using Constants = typename Model<3>::Constants;
    MaterialModel model;
    model.documentation = Model<3>::documentation();
    // Flags from an instance, so that the registry cannot contradict the
    // class: any valid constants will do.
    {
      LameParameters unit;
      unit.mu     = 1.;
      unit.lambda = 1.;
      Constants constants;
      if constexpr (std::is_same_v<Constants, LameParameters>)
        constants = unit;
      else
        constants = Constants::from_small_strain(unit);
      const Model<3> instance(constants);
      model.name      = instance.name();
      model.is_linear = instance.is_linear();
      model.defined_for_inverted_elements =
        instance.defined_for_inverted_elements();
      model.has_volumetric_split = instance.volumetric_split() != nullptr;
    }
    if constexpr (std::is_same_v<Constants, LameParameters>)
      {
        model.uses_elastic_constants = true;
        model.parse = [](ParameterHandler &, const LameParameters &elastic) {
          return MaterialFactory::of<Model>(elastic);
        };
        model.from_small_strain = [](const LameParameters &small_strain) {
          return MaterialFactory::of<Model>(small_strain);
        };
        model.entries_for_small_strain = [](const LameParameters &) {
          return std::vector<std::pair<std::string, std::string>>();
        };
      }
    else
      {
        model.uses_elastic_constants = false;
        model.declare_entries        = [](ParameterHandler &prm) {
          Constants::declare(prm);
        };
        const std::string name = model.name;
        model.parse = [name](ParameterHandler &prm, const LameParameters &) {
          prm.enter_subsection(name);
          const Constants constants = Constants::parse(prm, "Material/" + name);
          prm.leave_subsection();
          return MaterialFactory::of<Model>(constants);
        };
        model.from_small_strain = [](const LameParameters &small_strain) {
          return MaterialFactory::of<Model>(
            Constants::from_small_strain(small_strain));
        };
        model.entries_for_small_strain =
          [](const LameParameters &small_strain) {
            return Constants::from_small_strain(small_strain).entries();
          };
      }
    return model;
  }
} // namespace hyperelastic
