// The model at every quadrature point, for the models whose constants vary
// with the reference position (Material::depends_on_position():
// Holzapfel-Gasser-Ogden with fibre directions given as expressions of x, y,
// z) and for those with history (Material::has_history(): viscoelasticity,
// whose state each point holds). Built once, at the assembler's set-up, with
// the assembler's own quadrature, so that assembly evaluates a pure function
// of F at each point and never an expression. For every other model nothing
// is stored and the cell's model (its region's, assembly/material_regions.h)
// is handed out: a scene pays only for the feature it uses. Grown models
// (materials/grown.h) are per point too; set_load_factor() moves their growth
// tensors along the load path.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/model_capabilities.h>

#include <limits>
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
    PointMaterials(const MaterialRegions<dim>    &regions,
                   const dealii::DoFHandler<dim> &dof_handler,
                   const dealii::Mapping<dim>    &mapping,
                   const dealii::Quadrature<dim> &quadrature)
        : regions(regions)
        , n_points(quadrature.size())
        , communicator(dof_handler.get_communicator())
    {
      if (!regions.any_per_point())
        return;
      dealii::FEValues<dim> values(mapping,
                                   dof_handler.get_fe(),
                                   quadrature,
                                   dealii::update_quadrature_points);
      points.resize(dof_handler.get_triangulation().n_active_cells() *
                    n_points);
      collectively(dof_handler, [&](const auto &cell) {
        const Material<dim> &model = regions(cell->active_cell_index());
        if (!per_point(model))
          return;
        values.reinit(cell);
        for (unsigned int q = 0; q < n_points; ++q)
          points[cell->active_cell_index() * n_points + q] =
            model.at_position(values.quadrature_point(q));
      });
    }

    /// At the centre of every cell this rank sees: the one point of the
    /// P1 rule (the vertex average of a straight simplex).
    PointMaterials(const MaterialRegions<dim>    &regions,
                   const dealii::DoFHandler<dim> &dof_handler)
        : regions(regions)
        , n_points(1)
        , communicator(dof_handler.get_communicator())
    {
      if (!regions.any_per_point())
        return;
      points.resize(dof_handler.get_triangulation().n_active_cells());
      collectively(dof_handler, [&](const auto &cell) {
        const Material<dim> &model = regions(cell->active_cell_index());
        if (per_point(model))
          points[cell->active_cell_index()] = model.at_position(cell->center());
      });
    }

    /// The model at quadrature point @p q of the cell with active index
    /// @p cell.
    const Material<dim> &
    operator()(const unsigned int cell, const unsigned int q) const
    {
      if (points.empty())
        return regions(cell);
      const Material<dim> *point = points[cell * n_points + q].get();
      return point ? *point : regions(cell);
    }

    /// The regions' models and the region of each cell.
    const MaterialRegions<dim> &
    cell_materials() const
    {
      return regions;
    }

    /// Whether the points hold history (Material::has_history()).
    bool
    has_history() const
    {
      return !points.empty() && regions.any_history();
    }

    /// The growing models (GrowingMaterial) evaluate their growth tensors at
    /// the load factor @p t from now on; an inadmissible one at some point
    /// (det Fg <= 0) is an InputError on every rank. Nothing if no region
    /// grows or @p t is the last load factor set. Collective.
    void
    set_load_factor(const double t) const
    {
      if (t == load_factor || points.empty())
        return;
      bool any = false;
      for (unsigned int r = 0; r < regions.n_regions(); ++r)
        if (const auto *growing =
              dynamic_cast<const GrowingMaterial *>(&regions.model(r)))
          {
            growing->set_load_factor(t);
            any = true;
          }
      if (!any)
        return;
      load_factor = t;
      std::string problem;
      try
        {
          for (const auto &point : points)
            if (const auto *growing =
                  dynamic_cast<const GrowingMaterial *>(point.get()))
              growing->growth_tensor();
        }
      catch (const InputError &e)
        {
          problem = e.what();
        }
      throw_input_error_of_first_rank(problem, communicator);
    }

    /// Every point's next step lasts @p dt (Material::begin_step()).
    void
    begin_step(const double dt) const
    {
      for (const auto &point : points)
        if (point)
          point->begin_step(dt);
    }

    /// The step ended with @p F at point @p q of cell @p cell.
    void
    accept_step(const unsigned int    cell,
                const unsigned int    q,
                const Tensor<2, dim> &F) const
    {
      if (const auto &point = points[cell * n_points + q])
        point->accept_step(F);
    }

    /// Appends every point's history to @p state (points in their order:
    /// the same on a restart with the same mesh and ranks).
    void
    save_history(std::vector<double> &state) const
    {
      if (has_history())
        for (const auto &point : points)
          if (point && point->has_history())
            point->save_history(state);
    }

    /// Every point's history from @p state at @p position.
    void
    load_history(const std::vector<double> &state, std::size_t &position) const
    {
      if (has_history())
        for (const auto &point : points)
          if (point && point->has_history())
            point->load_history(state, position);
    }

  private:
    static bool
    per_point(const Material<dim> &model)
    {
      return model.depends_on_position() || model.has_history();
    }

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

    const MaterialRegions<dim> regions;
    const unsigned int         n_points;
    const MPI_Comm             communicator;
    /// The last load factor set (set_load_factor()).
    mutable double load_factor = std::numeric_limits<double>::quiet_NaN();
    /// Empty unless some region's model is per point; then null at the
    /// points of the other regions' cells.
    std::vector<std::unique_ptr<Material<dim>>> points;
  };
} // namespace hyperelastic
