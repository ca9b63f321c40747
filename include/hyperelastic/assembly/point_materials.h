// The model at every quadrature point, for the models whose constants vary
// with the reference position (Material::depends_on_position():
// Holzapfel-Gasser-Ogden with fibre directions given as expressions of x, y,
// z). Built once, at the assembler's set-up, with the assembler's own
// quadrature, so that assembly evaluates a pure function of F at each point
// and never an expression. For every other model nothing is stored and the
// scene's model is handed out: a scene pays only for the feature it uses.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/material.h>

#include <memory>
#include <string>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class PointMaterials
  {
  public:
    /// At the points of @p quadrature mapped by @p mapping, on every cell
    /// this rank sees (locally owned and ghost).
    PointMaterials(const Material<dim>           &model,
                   const dealii::DoFHandler<dim> &dof_handler,
                   const dealii::Mapping<dim>    &mapping,
                   const dealii::Quadrature<dim> &quadrature)
        : model(model)
        , n_points(quadrature.size())
    {
      if (!model.depends_on_position())
        return;
      dealii::FEValues<dim> values(mapping,
                                   dof_handler.get_fe(),
                                   quadrature,
                                   dealii::update_quadrature_points);
      points.resize(dof_handler.get_triangulation().n_active_cells() *
                    n_points);
      collectively(dof_handler, [&](const auto &cell) {
        values.reinit(cell);
        for (unsigned int q = 0; q < n_points; ++q)
          points[cell->active_cell_index() * n_points + q] =
            model.at_position(values.quadrature_point(q));
      });
    }

    /// At the centre of every cell this rank sees: the one point of the
    /// P1 rule (the vertex average of a straight simplex).
    PointMaterials(const Material<dim>           &model,
                   const dealii::DoFHandler<dim> &dof_handler)
        : model(model)
        , n_points(1)
    {
      if (!model.depends_on_position())
        return;
      points.resize(dof_handler.get_triangulation().n_active_cells());
      collectively(dof_handler, [&](const auto &cell) {
        points[cell->active_cell_index()] = model.at_position(cell->center());
      });
    }

    /// The model at quadrature point @p q of the cell with active index
    /// @p cell.
    const Material<dim> &
    operator()(const unsigned int cell, const unsigned int q) const
    {
      return points.empty() ? model : *points[cell * n_points + q];
    }

  private:
    /// Calls @p build(cell) on every cell this rank sees; an input error
    /// (a fibre direction that vanishes at a point) on any rank is thrown
    /// on every rank with the message of the lowest such rank, so no rank
    /// waits in a later collective call.
    template <typename Build>
    static void
    collectively(const dealii::DoFHandler<dim> &dof_handler, Build &&build)
    {
      std::string error;
      try
        {
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (!cell->is_artificial())
              build(cell);
        }
      catch (const InputError &e)
        {
          error = e.what();
        }
      const MPI_Comm     comm = dof_handler.get_communicator();
      const unsigned int n_ranks =
        dealii::Utilities::MPI::n_mpi_processes(comm);
      const unsigned int first = dealii::Utilities::MPI::min(
        error.empty() ? n_ranks
                      : dealii::Utilities::MPI::this_mpi_process(comm),
        comm);
      if (first < n_ranks)
        throw InputError(dealii::Utilities::MPI::broadcast(comm, error, first));
    }

    const Material<dim> &model;
    const unsigned int   n_points;
    /// Empty unless model.depends_on_position().
    std::vector<std::unique_ptr<Material<dim>>> points;
  };
} // namespace hyperelastic
