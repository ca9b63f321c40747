// Stiffness warping (Problem/Formulation = stiffness warping, or its alias
// Material/Model = stiffness warping): the displacement formulation's P1
// element with the warped rest stiffness as the material part
// (assembly/warped_assembler.h). Its forces have no potential.
#include <hyperelastic/assembly/warped_assembler.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/formulation/displacement_formulation.h>
#include <hyperelastic/formulation/formulation_parameters.h>
#include <hyperelastic/formulation/formulation_registry.h>
#include <hyperelastic/materials/material_parameters.h>

namespace hyperelastic
{
  namespace
  {
    template <int dim>
    class StiffnessWarpingFormulation : public DisplacementFormulation<dim>
    {
    public:
      explicit StiffnessWarpingFormulation(const FormulationInputs &inputs)
          : DisplacementFormulation<dim>(inputs)
          , note(std::string(inputs.material.stiffness_warping
                               ? ""
                               : ", stiffness warping") +
                 " of the linear elastic stiffness (no potential; energy "
                 "and cell stresses: " +
                 inputs.material.registered_model() + ")")
      {
      }

      std::unique_ptr<Assembler<dim>>
      material_part(const dealii::DoFHandler<dim> &dof_handler,
                    const dealii::Mapping<dim>    &mapping,
                    const MaterialRegions<dim>    &material) const override
      {
        return std::make_unique<WarpedAssembler<dim>>(dof_handler,
                                                      mapping,
                                                      material);
      }

      bool
      has_potential() const override
      {
        return false;
      }

      std::string
      why_no_potential() const override
      {
        return "stiffness warping's forces are not the gradient of an energy";
      }

      std::string
      material_note() const override
      {
        return note;
      }

    private:
      const std::string note;
    };

    void
    check_stiffness_warping(const FormulationInputs &inputs)
    {
      DisplacementFormulation<3>::check(inputs);
      // One rotation per vertex: P1 nodes only.
      if (inputs.problem.fe_degree != 1)
        reject("Problem/Finite element degree",
               std::to_string(inputs.problem.fe_degree),
               "'Material/Model = stiffness warping' needs P1 elements (one "
               "rotation per vertex)");
    }
  } // namespace

  FormulationKind
  stiffness_warping_formulation_kind()
  {
    return FormulationKind::of<StiffnessWarpingFormulation>(
      "stiffness warping",
      "Mueller et al. 2002: the linear elastic stiffness K at rest (from the "
      "model's small-strain moduli) warped by one rotation per vertex; P1 "
      "only, no potential (residual line search, GMRES); the energy and cell "
      "stresses reported are the model's. 'Material/Model = stiffness "
      "warping' is the same with the corotational model. See doc/manual.md, "
      "'Stiffness warping'.",
      &check_stiffness_warping);
  }
} // namespace hyperelastic
