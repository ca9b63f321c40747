// Body force and dead tractions integrated with FEValues on the reference
// configuration.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/loads/dead_loads.h>
#include <hyperelastic/loads/load_terms.h>

#include <cmath>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Adds int f N_i over the quadrature points of @p values (a cell's or
    /// a face's) to @p cell_forces; false if f was not finite somewhere.
    template <int dim, typename FEValuesType>
    bool
    add_dead_load(const FEValuesType       &values,
                  const Function<dim>      &f,
                  const FiniteElement<dim> &fe,
                  Vector<double>           &cell_forces)
    {
      Vector<double> value(dim);
      bool           finite = true;
      for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
        {
          f.vector_value(values.quadrature_point(q), value);
          for (const double v : value)
            finite = finite && std::isfinite(v);
          const double JxW = values.JxW(q);
          for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
            {
              // Displacement components only (not a mixed pressure).
              const unsigned int c = fe.system_to_component_index(i).first;
              if (c < dim)
                cell_forces[i] += value[c] * values.shape_value(i, q) * JxW;
            }
        }
      return finite;
    }
  } // namespace

  template <int dim>
  BodyForce<dim>::BodyForce(Function<dim>         &force,
                            const DoFHandler<dim> &dof_handler,
                            const Mapping<dim>    &mapping)
      : force(force)
      , dof_handler(dof_handler)
      , mapping(mapping)
      , quadrature(QGaussSimplex<dim>(dof_handler.get_fe().degree + 1))
  {
  }

  template <int dim>
  ForceSize
  BodyForce<dim>::add_forces(const VectorType &,
                             const double t,
                             VectorType  &forces) const
  {
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    FEValues<dim>                        values(mapping,
                         fe,
                         quadrature,
                         update_values | update_quadrature_points |
                           update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.dofs_per_cell);
    Vector<double>                       cell_forces(fe.dofs_per_cell);
    force.set_time(t);
    bool finite = true;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          cell_forces = 0.;
          finite      = add_dead_load(values, force, fe, cell_forces) && finite;
          cell->get_dof_indices(dofs);
          forces.add(dofs, cell_forces);
        }
    throw_if_load_not_finite(!finite, name(), dof_handler.get_communicator());
    return {};
  }

  template <int dim>
  DeadTraction<dim>::DeadTraction(Function<dim>           &traction,
                                  const types::boundary_id boundary_id,
                                  const std::string       &subsection,
                                  const DoFHandler<dim>   &dof_handler,
                                  const Mapping<dim>      &mapping)
      : traction(traction)
      , boundary_id(boundary_id)
      , subsection(subsection)
      , dof_handler(dof_handler)
      , mapping(mapping)
      , quadrature(QGaussSimplex<dim - 1>(dof_handler.get_fe().degree + 1))
  {
  }

  template <int dim>
  ForceSize
  DeadTraction<dim>::add_forces(const VectorType &,
                                const double t,
                                VectorType  &forces) const
  {
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    FEFaceValues<dim>                    values(mapping,
                             fe,
                             quadrature,
                             update_values | update_quadrature_points |
                               update_JxW_values);
    std::vector<types::global_dof_index> dofs(fe.dofs_per_cell);
    Vector<double>                       cell_forces(fe.dofs_per_cell);
    traction.set_time(t);
    bool finite = true;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == boundary_id)
            {
              values.reinit(cell, f);
              cell_forces = 0.;
              finite =
                add_dead_load(values, traction, fe, cell_forces) && finite;
              cell->get_dof_indices(dofs);
              forces.add(dofs, cell_forces);
            }
    throw_if_load_not_finite(!finite, name(), dof_handler.get_communicator());
    return {};
  }

  template class BodyForce<2>;
  template class BodyForce<3>;
  template class DeadTraction<2>;
  template class DeadTraction<3>;
} // namespace hyperelastic
