// The displacement formulation: (P_k)^dim Lagrange simplices, the
// displacement the only unknown, the material part from the P1 kernel or the
// generic FEValues loops. Stiffness warping derives from it (same element,
// its own material part).
#pragma once

#include <hyperelastic/formulation/formulation.h>
#include <hyperelastic/parameters.h>

namespace hyperelastic
{
  template <int dim>
  class DisplacementFormulation : public Formulation<dim>
  {
  public:
    explicit DisplacementFormulation(const Parameters &parameters);

    dealii::FESystem<dim>
    finite_element() const override;

    std::string
    element_description() const override;

    /// P1 with nu > 0.45 locks volumetrically.
    std::string
    warning(const Material<dim> &material) const override;

    /// The scene checks: an exactly incompressible material needs the
    /// pressure as an unknown.
    static void
    check(Parameters &parameters);

  protected:
    const unsigned int degree;
  };
} // namespace hyperelastic
