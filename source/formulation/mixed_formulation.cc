// The mixed displacement-pressure formulation (Problem/Formulation = mixed):
// (P_k)^dim x P1 after 'Problem/Mixed element', the material part from the
// mixed assembler, the pressure unknowns, and the block preconditioner with
// the lumped pressure mass. A saddle point: no potential to minimise.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>

#include <hyperelastic/assembly/mixed_assembler.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/dynamics/time_integration_parameters.h>
#include <hyperelastic/formulation/formulation_parameters.h>
#include <hyperelastic/formulation/formulation_registry.h>
#include <hyperelastic/materials/material_parameters.h>
#include <hyperelastic/solvers/linear_solver_parameters.h>

#include <array>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    class MixedFormulation : public Formulation<dim>
    {
    public:
      explicit MixedFormulation(const FormulationInputs &inputs)
          : element(inputs.problem.mixed_element)
          , block_preconditioner(inputs.linear_solver.type ==
                                 LinearSolverType::cg_amg)
      {
      }

      FESystem<dim>
      finite_element() const override
      {
        return FESystem<dim>(FE_SimplexP<dim>(displacement_degree(element)),
                             dim,
                             FE_SimplexP<dim>(1),
                             1);
      }

      std::string
      element_description() const override
      {
        switch (element)
          {
          case MixedElement::mini:
            return "mixed u-p P1-bubble/P1 (MINI, bubble condensed) "
                   "simplices";
          case MixedElement::stabilized:
            return "mixed u-p P1/P1 stabilized simplices";
          default:
            return "mixed u-p P2/P1 (Taylor-Hood) simplices";
          }
      }

      std::unique_ptr<Assembler<dim>>
      material_part(const DoFHandler<dim>      &dof_handler,
                    const Mapping<dim>         &mapping,
                    const MaterialRegions<dim> &material) const override
      {
        return std::make_unique<MixedAssembler<dim>>(dof_handler,
                                                     mapping,
                                                     material,
                                                     element);
      }

      bool
      has_potential() const override
      {
        return false;
      }

      std::string
      why_no_potential() const override
      {
        return "the mixed functional is a saddle point in the pressure";
      }

      IndexSet
      pressure_dofs(const DoFHandler<dim> &dof_handler) const override
      {
        // The dofs are not renumbered by component (each rank's owned dofs
        // then stay one range; deal.II 9.4's DataOut hung on two ranks with
        // the split ranges): the blocks are index sets instead.
        const FiniteElement<dim>            &fe = dof_handler.get_fe();
        IndexSet                             dofs(dof_handler.n_dofs());
        std::vector<types::global_dof_index> cell_dofs(fe.dofs_per_cell);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            {
              cell->get_dof_indices(cell_dofs);
              for (unsigned int i = 0; i < cell_dofs.size(); ++i)
                if (fe.system_to_component_index(i).first == dim)
                  dofs.add_index(cell_dofs[i]);
            }
        dofs.compress();
        return dofs;
      }

      void
      configure_linear_solver(LinearSolver               &solver,
                              const DoFHandler<dim>      &dof_handler,
                              const Mapping<dim>         &mapping,
                              const MaterialRegions<dim> &material,
                              const IndexSet &pressure) const override
      {
        if (!block_preconditioner)
          return;
        // The lumped pressure mass int psi_i dV on the owned pressure
        // unknowns, scaled by 1/mu: the Schur complement's diagonal. With
        // regions each cell's mass is scaled by its own 1/mu.
        const bool                regions = !material.cell_regions().empty();
        const FiniteElement<dim> &fe      = dof_handler.get_fe();
        const IndexSet           &owned   = dof_handler.locally_owned_dofs();
        const MPI_Comm            comm    = dof_handler.get_communicator();
        VectorType                mass(owned, comm);
        const QGaussSimplex<dim>  quadrature(2);
        FEValues<dim>             values(mapping,
                             fe,
                             quadrature,
                             update_values | update_JxW_values);
        std::vector<types::global_dof_index> dofs(fe.dofs_per_cell);
        Vector<double>                       cell_mass(fe.dofs_per_cell);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              values.reinit(cell);
              cell_mass = 0.;
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  if (fe.system_to_component_index(i).first == dim)
                    cell_mass[i] += values.shape_value(i, q) * values.JxW(q);
              if (regions)
                cell_mass /=
                  material(cell->active_cell_index()).small_strain_moduli().mu;
              mass.add(dofs, cell_mass);
            }
        mass.compress(VectorOperation::add);
        const double mu =
          regions ? 1. : material.top().small_strain_moduli().mu;
        std::vector<double> shear_schur;
        for (const auto i : owned)
          if (pressure.is_element(i))
            shear_schur.push_back(mass(i) / mu);
        solver.set_saddle_point(std::make_unique<SaddlePointPreconditioner>(
          owned, pressure, std::move(shear_schur), comm));
      }

    private:
      const MixedElement element;
      const bool         block_preconditioner;
    };

    void
    check_mixed(const FormulationInputs &inputs)
    {
      if (inputs.time_integration.dynamic())
        reject("Time integration/Scheme",
               inputs.time_integration.scheme_name(),
               "implicit dynamics is not available with 'Problem/Formulation "
               "= mixed' yet");
      // The mixed formulation needs the model's volumetric split.
      const MaterialParameters &material = inputs.material;
      if (material.growth.kind != GrowthParameters::Kind::none)
        reject("Material/Growth",
               std::array<const char *, 4>{
                 "none",
                 "isotropic",
                 "fibre",
                 "tensor"}[static_cast<int>(material.growth.kind)],
               "growth is not available with 'Problem/Formulation = "
               "mixed' (the grown model has no volumetric-isochoric split)");
      if (!material_model(material.registered_model()).has_volumetric_split)
        {
          std::string with_split;
          for (const MaterialModel &m : material_models())
            if (m.has_volumetric_split)
              with_split += (with_split.empty() ? "'" : ", '") + m.name + "'";
          reject("Problem/Formulation",
                 "mixed",
                 "the " + material.model +
                   " model has no volumetric-isochoric split psi = "
                   "psi_iso(F) + U(J); use a model with one (" +
                   with_split + ") or 'Formulation = displacement'");
        }
    }
  } // namespace

  FormulationKind
  mixed_formulation_kind()
  {
    return FormulationKind::of<MixedFormulation>(
      "mixed",
      "displacement and pressure p (the Cauchy mean stress) with the "
      "volumetric-isochoric split psi = psi_iso(F) + U(J), coupled through "
      "the Legendre transform of U (exact for any U, see doc/manual.md, "
      "'Mixed formulation'): for nearly incompressible solids (nu > 0.45), "
      "where P1 locks and AMG stalls. Needs a model with a split (decoupled "
      "neo-Hookean, Mooney-Rivlin); the element is then 'Mixed element', and "
      "'Finite element degree' is ignored.",
      &check_mixed,
      [](const ProblemParameters &problem) {
        return displacement_degree(problem.mixed_element);
      });
  }
} // namespace hyperelastic
