// The displacement formulation: (P_k)^dim Lagrange simplices, the
// displacement the only unknown, the material part from the P1 kernel or the
// generic FEValues loops. Stiffness warping derives from it (same element,
// its own material part).
#pragma once

#include <hyperelastic/formulation/formulation.h>
#include <hyperelastic/formulation/formulation_registry.h>

namespace hyperelastic
{
  /// The displacement formulation (Problem/Formulation = displacement).
  template <int dim>
  class DisplacementFormulation : public Formulation<dim>
  {
  public:
    /// Reads the degree and the linear solver's preconditioner choice.
    explicit DisplacementFormulation(const FormulationInputs &inputs);

    dealii::FESystem<dim>
    finite_element() const override;

    std::string
    element_description() const override;

    /// P1 with nu > 0.45 locks volumetrically.
    std::string
    warning(const Material<dim> &material) const override;

    /// P2 with CG + AMG: the two-level P2 -> P1 preconditioner, unless
    /// 'Linear solver/P2 preconditioner = AMG'.
    void
    configure_linear_solver(
      LinearSolver                  &solver,
      const dealii::DoFHandler<dim> &dof_handler,
      const dealii::Mapping<dim>    &mapping,
      const MaterialRegions<dim>    &material,
      const dealii::IndexSet        &pressure_dofs) const override;

    /// The scene checks: an exactly incompressible material needs the
    /// pressure as an unknown.
    static void
    check(const FormulationInputs &inputs);

  protected:
    const unsigned int degree;
    /// Whether P2 solves use the two-level preconditioner.
    const bool two_level;
  };
} // namespace hyperelastic
