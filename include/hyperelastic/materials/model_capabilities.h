// What only some models have, as opt-in interfaces a model implements besides
// Material (like ConstantDerivatives, constant_derivatives.h):
// - FibreFamilies: reference fibre directions (Holzapfel-Gasser-Ogden), which
//   fibre growth follows;
// - GrowingMaterial: a growth tensor Fg(X, t) (materials/grown.h), which
//   follows the load factor; the assemblers set it (PointMaterials) and the
//   output writes det Fg.
#pragma once

#include <deal.II/base/tensor.h>

#include <vector>

namespace hyperelastic
{
  class FibreFamilies
  {
  public:
    virtual ~FibreFamilies() = default;

    /// The unit reference directions of the fibre families (3D vectors,
    /// a_z = 0 in 2D); empty where they are not evaluated yet (directions
    /// that vary with position, before Material::at_position()).
    virtual std::vector<dealii::Tensor<1, 3>>
    fibre_directions() const = 0;
  };

  class GrowingMaterial
  {
  public:
    virtual ~GrowingMaterial() = default;

    /// The load factor at which this model, its point copies
    /// (Material::at_position()) and its 3D twin evaluate Fg from now on
    /// (they share it).
    virtual void
    set_load_factor(double t) const = 0;

    /// Fg at this point copy's reference position and the load factor set
    /// (the 3D tensor also in 2D). InputError if det Fg <= 0 there.
    virtual dealii::Tensor<2, 3>
    growth_tensor() const = 0;
  };
} // namespace hyperelastic
