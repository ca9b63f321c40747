// Dead loads, fixed in the reference configuration: a body force per unit
// reference volume and tractions per unit reference area. Their forces do
// not depend on u, so they have no load stiffness and their potential is
// minus their work.
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/assembly/energy_term.h>
#include <hyperelastic/loads/loading_parameters.h>

namespace hyperelastic
{
  /// int b(X, t) N_a dV over the reference body.
  template <int dim>
  class BodyForce : public DeadTerm<dim>
  {
  public:
    BodyForce(dealii::Function<dim>         &force,
              const dealii::DoFHandler<dim> &dof_handler,
              const dealii::Mapping<dim>    &mapping);

    std::string
    name() const override
    {
      return "Loading/Body force";
    }


    ForceSize
    add_forces(const VectorType &u,
               double            t,
               VectorType       &forces) const override;

  private:
    dealii::Function<dim>         &force;
    const dealii::DoFHandler<dim> &dof_handler;
    const dealii::Mapping<dim>    &mapping;
    /// One degree above the element's.
    const dealii::Quadrature<dim> quadrature;
  };

  /// int t0(X, t) N_a dA over the reference faces with one boundary id.
  template <int dim>
  class DeadTraction : public DeadTerm<dim>
  {
  public:
    /// @p subsection: the scene section, for messages ("Traction 1").
    DeadTraction(dealii::Function<dim>         &traction,
                 dealii::types::boundary_id     boundary_id,
                 const std::string             &subsection,
                 const dealii::DoFHandler<dim> &dof_handler,
                 const dealii::Mapping<dim>    &mapping);

    /// The scene sections "Traction 1" ... "Traction 4".
    static BoundaryLoadKind
    scene_kind()
    {
      BoundaryLoadKind kind;
      kind.name          = "Traction";
      kind.max_sections  = 4;
      kind.vector_valued = true;
      kind.default_value = "0; 0; 0";
      kind.id_documentation =
        "Boundary id loaded by this traction; -1 leaves this slot unused.";
      kind.value_documentation =
        "Force per unit reference area (a nominal, dead-load traction): dim "
        "expressions of x, y, (z,) t separated by ';'.";
      return kind;
    }

    std::string
    name() const override
    {
      return subsection + "/Traction";
    }


    ForceSize
    add_forces(const VectorType &u,
               double            t,
               VectorType       &forces) const override;

  private:
    dealii::Function<dim>            &traction;
    const dealii::types::boundary_id  boundary_id;
    const std::string                 subsection;
    const dealii::DoFHandler<dim>    &dof_handler;
    const dealii::Mapping<dim>       &mapping;
    const dealii::Quadrature<dim - 1> quadrature;
  };
} // namespace hyperelastic
