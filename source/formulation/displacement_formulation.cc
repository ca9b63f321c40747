// The displacement formulation: the element, the locking warning, the check
// that an exactly incompressible material is not asked of it.
#include <deal.II/fe/fe_simplex_p.h>

#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/formulation/displacement_formulation.h>
#include <hyperelastic/formulation/formulation_parameters.h>
#include <hyperelastic/materials/material_parameters.h>
#include <hyperelastic/solvers/linear_solver.h>
#include <hyperelastic/solvers/linear_solver_parameters.h>
#include <hyperelastic/solvers/two_level_preconditioner.h>

#include <sstream>

namespace hyperelastic
{
  template <int dim>
  DisplacementFormulation<dim>::DisplacementFormulation(
    const FormulationInputs &inputs)
      : degree(inputs.problem.fe_degree)
      , two_level(inputs.problem.fe_degree == 2 &&
                  inputs.linear_solver.type == LinearSolverType::cg_amg &&
                  inputs.linear_solver.p2_two_level)
  {
  }

  template <int dim>
  void
  DisplacementFormulation<dim>::configure_linear_solver(
    LinearSolver                  &solver,
    const dealii::DoFHandler<dim> &dof_handler,
    const dealii::Mapping<dim> &,
    const MaterialRegions<dim> &,
    const dealii::IndexSet &) const
  {
    if (two_level)
      solver.set_preconditioner(
        std::make_unique<TwoLevelPreconditioner<dim>>(dof_handler, 2));
  }

  template <int dim>
  dealii::FESystem<dim>
  DisplacementFormulation<dim>::finite_element() const
  {
    return dealii::FESystem<dim>(dealii::FE_SimplexP<dim>(degree), dim);
  }

  template <int dim>
  std::string
  DisplacementFormulation<dim>::element_description() const
  {
    return "P" + std::to_string(degree) + " simplices";
  }

  template <int dim>
  std::string
  DisplacementFormulation<dim>::warning(const Material<dim> &material) const
  {
    // Linear simplices have too few displacement modes to deform at nearly
    // constant volume: when lambda >> mu they lock (far too stiff in
    // bending and shear). Warn; it is not an error.
    const double nu = material.small_strain_moduli().poisson_ratio();
    if (degree != 1 || !(nu > 0.45))
      return {};
    std::ostringstream text;
    text << "warning: Poisson's ratio " << nu
         << " > 0.45 with P1 elements: expect volumetric locking (too "
            "stiff in bending and shear). Use 'Problem/Formulation = "
            "mixed' (with decoupled neo-Hookean or Mooney-Rivlin), "
            "'Problem/Finite element degree = 2' or a finer mesh, and "
            "check the answer does not change.";
    return text.str();
  }

  template <int dim>
  void
  DisplacementFormulation<dim>::check(const FormulationInputs &inputs)
  {
    // Exact incompressibility needs the pressure as an unknown.
    const MaterialParameters &material = inputs.material;
    if (!material.incompressible_entry.empty())
      reject(material.incompressible_entry,
             material.incompressible_value,
             std::string(material.incompressible_entry ==
                             "Material/Poisson's ratio"
                           ? "must lie strictly between -1 and 0.5 with the "
                             "displacement formulation; "
                           : "is exactly incompressible; ") +
               "an exactly incompressible material (nu = 0.5, bulk modulus "
               "'inf') needs 'Problem/Formulation = mixed' (and a model with "
               "a volumetric split)");
  }

  FormulationKind
  displacement_formulation_kind()
  {
    return FormulationKind::of<DisplacementFormulation>(
      "displacement",
      "the displacement is the only unknown (the default); P1 or P2 after "
      "'Finite element degree'.",
      &DisplacementFormulation<3>::check);
  }

  template class DisplacementFormulation<2>;
  template class DisplacementFormulation<3>;
} // namespace hyperelastic
