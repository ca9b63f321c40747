// The list of registered models (one line each) and the look-ups built on it.
//
// One explicit list rather than self-registering static objects: the library
// is a static archive, from which the linker drops object files nothing
// refers to (a model's registration object among them), and the order of
// static initialisation across files is unspecified, while the order here
// fixes the order of the names in the documentation and in error messages.
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/arruda_boyce.h>
#include <hyperelastic/materials/corotational.h>
#include <hyperelastic/materials/decoupled_neo_hookean.h>
#include <hyperelastic/materials/gent.h>
#include <hyperelastic/materials/holzapfel_gasser_ogden.h>
#include <hyperelastic/materials/linear_elastic.h>
#include <hyperelastic/materials/material_registry.h>
#include <hyperelastic/materials/mooney_rivlin.h>
#include <hyperelastic/materials/neo_hookean.h>
#include <hyperelastic/materials/ogden.h>
#include <hyperelastic/materials/st_venant_kirchhoff.h>
#include <hyperelastic/materials/stable_neo_hookean.h>
#include <hyperelastic/materials/yeoh.h>

namespace hyperelastic
{
  const std::vector<MaterialModel> &
  material_models()
  {
    // Built on first use (thread-safe, after every other static object).
    static const std::vector<MaterialModel> models = {
      make_material_model<LinearElastic>(),
      make_material_model<StVenantKirchhoff>(),
      make_material_model<Corotational>(),
      make_material_model<NeoHookean>(),
      make_material_model<StableNeoHookean>(),
      make_material_model<DecoupledNeoHookean>(),
      make_material_model<MooneyRivlin>(),
      make_material_model<Yeoh>(),
      make_material_model<Gent>(),
      make_material_model<ArrudaBoyce>(),
      make_material_model<Ogden>(),
      make_material_model<HolzapfelGasserOgden>(),
    };
    return models;
  }

  std::string
  material_model_names()
  {
    std::string names;
    for (const MaterialModel &model : material_models())
      names += (names.empty() ? "" : "|") + model.name;
    return names;
  }

  const MaterialModel &
  material_model(const std::string &name)
  {
    for (const MaterialModel &model : material_models())
      if (model.name == name)
        return model;
    throw InputError("unknown material model '" + name +
                     "'; the registered models are " + material_model_names());
  }

  template <int dim>
  std::unique_ptr<Material<dim>>
  MaterialFactory::create() const
  {
    if constexpr (dim == 2)
      {
        if (create_2d)
          return create_2d();
      }
    else
      {
        if (create_3d)
          return create_3d();
      }
    throw std::logic_error("MaterialFactory: no model was parsed or given");
  }

  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const std::string &name, const LameParameters &small_strain)
  {
    return material_model(name)
      .from_small_strain(small_strain)
      .template create<dim>();
  }

  template std::unique_ptr<Material<2>>
  MaterialFactory::create<2>() const;
  template std::unique_ptr<Material<3>>
  MaterialFactory::create<3>() const;
  template std::unique_ptr<Material<2>>
  create_material<2>(const std::string &, const LameParameters &);
  template std::unique_ptr<Material<3>>
  create_material<3>(const std::string &, const LameParameters &);
} // namespace hyperelastic
