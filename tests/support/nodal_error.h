// The largest difference, over all degrees of freedom of a (P1 or P2)
// displacement field, between the computed value at the dof's support point
// and an exact displacement u(X); and over the pressure unknowns of a mixed
// discretisation (component dim), from an exact constant pressure
// (collective).
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/trilinos_vector.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hyperelastic::testing
{
  /// @p exact: Point<dim> -> Tensor<1, dim>. @p u with ghost entries.
  template <int dim, typename ExactDisplacement>
  double
  max_nodal_error(const dealii::DoFHandler<dim>               &dof_handler,
                  const dealii::TrilinosWrappers::MPI::Vector &u,
                  ExactDisplacement                          &&exact)
  {
    const dealii::MappingFE<dim> mapping(dealii::FE_SimplexP<dim>(1));
    const auto &fe      = dof_handler.get_fe();
    const auto &support = fe.get_unit_support_points();
    std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
    double                                       error = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              if (c >= dim) // the pressure of a mixed discretisation
                continue;
              const dealii::Point<dim> X =
                mapping.transform_unit_to_real_cell(cell, support[i]);
              error = std::max(error, std::abs(u(dofs[i]) - exact(X)[c]));
            }
        }
    return dealii::Utilities::MPI::max(error, dof_handler.get_communicator());
  }

  /// Largest |p - @p p_exact| over the pressure unknowns (component dim) of
  /// a mixed discretisation.
  template <int dim>
  double
  max_pressure_error(const dealii::DoFHandler<dim>               &dof_handler,
                     const dealii::TrilinosWrappers::MPI::Vector &solution,
                     const double                                 p_exact)
  {
    const auto &fe = dof_handler.get_fe();
    std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
    double                                       error = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (fe.system_to_component_index(i).first == dim)
              error = std::max(error, std::abs(solution(dofs[i]) - p_exact));
        }
    return dealii::Utilities::MPI::max(error, dof_handler.get_communicator());
  }
} // namespace hyperelastic::testing
