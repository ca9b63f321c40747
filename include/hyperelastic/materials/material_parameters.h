// The scene's Material subsection: the model, the shared elastic constants of
// the Lame-based models, and the subsections Material/<model> of the models
// with constants of their own (all from the registry, material_registry.h).
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/materials/growth.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/material_registry.h>
#include <hyperelastic/materials/viscoelasticity.h>

#include <memory>
#include <string>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  struct MaterialParameters
  {
    /// Material/Model: a registered model name, or stiffness warping.
    std::string model;
    /// 'Material/Model = stiffness warping' (assembly/warped_assembler.h):
    /// not a function of F, so not in the registry; the Material object is
    /// then the corotational model with the same constants (rest moduli,
    /// reported energy and cell stresses).
    bool                         stiffness_warping      = false;
    static constexpr const char *stiffness_warping_name = "stiffness warping";

    /// The registered model behind the scene's (the model itself, or
    /// corotational for stiffness warping).
    std::string
    registered_model() const
    {
      return stiffness_warping ? "corotational" : model;
    }
    /// The shared elastic constants (E and nu, Lame, or shear and bulk
    /// modulus) as (mu, lambda). Read and checked only when the model takes
    /// them (MaterialModel::uses_elastic_constants); otherwise zero.
    LameParameters elastic_constants;
    /// The model with the scene's constants, for either dimension.
    MaterialFactory factory;
    /// Material/Viscoelasticity (the factory then makes the viscoelastic
    /// model around the registered one).
    ViscoelasticParameters viscoelasticity;
    /// Material/Growth and its entries (the factory then makes the grown
    /// model around the registered one, materials/grown.h).
    GrowthParameters growth;
    /// The subsection's path in messages that arise while the scene runs
    /// (a growth tensor that inverts): 'Material', or 'Region k/Material'
    /// (set before parse()).
    std::string section = "Material";
    /// The entry (and its value) that makes the material exactly
    /// incompressible (a bulk modulus 'inf', Poisson's ratio 0.5); empty if
    /// none. Only the mixed formulation accepts it.
    std::string incompressible_entry, incompressible_value;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);

  private:
    /// The shared entries as (mu, lambda), checked; the handler is inside
    /// the subsection Material.
    static void
    parse_elastic_constants(ParameterHandler &prm, LameParameters &lame);
  };

  /// The scene's model in @p dim dimensions (2D scenes also need the 3D twin
  /// for the out-of-plane stress).
  template <int dim>
  std::unique_ptr<Material<dim>>
  create_material(const MaterialParameters &parameters)
  {
    return parameters.factory.template create<dim>();
  }
} // namespace hyperelastic
