// A formulation says what the unknowns of a scene are and who computes the
// material part of its equations: the finite element, the Assembler (null:
// the displacement assemblers, the P1 kernel or the generic loops), extra
// unknowns (a pressure) and what the linear solver needs for them, whether
// the discrete problem has a potential Newton can search along, and the lines
// of the run header. Problem asks these questions and never branches on the
// formulation itself.
//
// A new formulation is one file in source/formulation/ (the class and its
// FormulationKind: name, documentation, checks of the scene) plus one line in
// formulation_registry.cc (and the file in CMakeLists.txt's source list).
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/assembly/assembler.h>
#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/solvers/linear_solver.h>

#include <memory>
#include <string>

namespace hyperelastic
{
  template <int dim>
  class Formulation
  {
  public:
    virtual ~Formulation() = default;

    /// The element of the unknowns: (P_k)^dim, then any extra unknowns.
    virtual dealii::FESystem<dim>
    finite_element() const = 0;

    /// The element as the run header names it ("P1 simplices").
    virtual std::string
    element_description() const = 0;

    /// The material part; null: the displacement assemblers (the P1 kernel
    /// where it applies, the generic FEValues loops otherwise), which
    /// ElasticityOperator chooses.
    virtual std::unique_ptr<Assembler<dim>>
    material_part(const dealii::DoFHandler<dim> &dof_handler,
                  const dealii::Mapping<dim>    &mapping,
                  const MaterialRegions<dim>    &material) const
    {
      (void)dof_handler, (void)mapping, (void)material;
      return nullptr;
    }

    /// Whether the equations are the gradient of a potential that Newton's
    /// line search may minimise (the loads must have one too).
    virtual bool
    has_potential() const
    {
      return true;
    }

    /// Why not, when has_potential() is false.
    virtual std::string
    why_no_potential() const
    {
      return {};
    }

    /// The unknowns other than the displacement among the locally relevant
    /// ones (the pressure of the mixed formulation); empty by default.
    virtual dealii::IndexSet
    pressure_dofs(const dealii::DoFHandler<dim> &dof_handler) const
    {
      return dealii::IndexSet(dof_handler.n_dofs());
    }

    /// Hands the linear solver what this formulation's tangent needs beyond
    /// AMG with rigid-body modes (the mixed formulation's block
    /// preconditioner). @p pressure_dofs: as pressure_dofs() returned.
    virtual void
    configure_linear_solver(LinearSolver                  &solver,
                            const dealii::DoFHandler<dim> &dof_handler,
                            const dealii::Mapping<dim>    &mapping,
                            const MaterialRegions<dim>    &material,
                            const dealii::IndexSet        &pressure_dofs) const
    {
      (void)solver, (void)dof_handler, (void)mapping, (void)material,
        (void)pressure_dofs;
    }

    /// What the run header adds after the model's name (empty by default).
    virtual std::string
    material_note() const
    {
      return {};
    }

    /// A warning about the scene for this formulation and @p material
    /// (volumetric locking), printed after the run header; empty if none.
    virtual std::string
    warning(const Material<dim> &material) const
    {
      (void)material;
      return {};
    }
  };
} // namespace hyperelastic
