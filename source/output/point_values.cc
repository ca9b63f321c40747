// Point values of the displacement ('Output/Points'): location of reference
// points in the owned cells, evaluation, and the average over ranks.
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/output/point_values.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    std::string
    point_text(const std::vector<double> &coordinates)
    {
      std::ostringstream text;
      text << std::setprecision(12) << '(';
      for (unsigned int d = 0; d < coordinates.size(); ++d)
        text << (d > 0 ? ", " : "") << coordinates[d];
      text << ')';
      return text.str();
    }

    template <int dim>
    std::string
    point_text(const Point<dim> &p)
    {
      std::vector<double> coordinates(dim);
      for (unsigned int d = 0; d < dim; ++d)
        coordinates[d] = p[d];
      return point_text(coordinates);
    }
  } // namespace

  template <int dim>
  std::vector<Point<dim>>
  output_points(const OutputParameters &parameters)
  {
    std::vector<Point<dim>> points;
    for (const auto &coordinates : parameters.points)
      {
        if (coordinates.size() != dim)
          throw InputError("scene entry 'Output/Points': the point " +
                           point_text(coordinates) + " has " +
                           std::to_string(coordinates.size()) +
                           " coordinates; a " + std::to_string(dim) +
                           "D scene needs " + std::to_string(dim));
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = coordinates[d];
        points.push_back(p);
      }
    return points;
  }

  template <int dim>
  PointValues<dim>::PointValues(const std::vector<Point<dim>> &points,
                                const DoFHandler<dim>         &dof_handler,
                                const Mapping<dim>            &mapping,
                                const MPI_Comm                 comm)
      : dof_handler(dof_handler)
      , comm(comm)
  {
    const FiniteElement<dim> &fe = dof_handler.get_fe();
    // In unit coordinates: admits points on a face up to round-off in the
    // inverse mapping, and nothing that is visibly outside.
    const double tolerance = 1e-10;

    std::vector<unsigned int> local_count(points.size(), 0);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Cheap rejection by the cell's bounding box (with a margin
          // relative to its size) before the inverse mapping.
          Point<dim> lower = cell->vertex(0), upper = cell->vertex(0);
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] = std::min(lower[d], cell->vertex(v)[d]);
                upper[d] = std::max(upper[d], cell->vertex(v)[d]);
              }
          const double margin = 1e-8 * lower.distance(upper);

          for (unsigned int k = 0; k < points.size(); ++k)
            {
              bool in_box = true;
              for (unsigned int d = 0; d < dim; ++d)
                in_box = in_box && points[k][d] >= lower[d] - margin &&
                         points[k][d] <= upper[d] + margin;
              if (!in_box)
                continue;

              Point<dim> unit;
              try
                {
                  unit = mapping.transform_real_to_unit_cell(cell, points[k]);
                }
              catch (const typename Mapping<dim>::ExcTransformationFailed &)
                {
                  continue;
                }
              if (!cell->reference_cell().contains_point(unit, tolerance))
                continue;

              Location location{k,
                                cell,
                                std::vector<double>(fe.n_dofs_per_cell())};
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                location.shape_values[i] = fe.shape_value(i, unit);
              locations.push_back(std::move(location));
              ++local_count[k];
            }
        }

    n_cells_per_point.resize(points.size());
    Utilities::MPI::sum(local_count, comm, n_cells_per_point);
    // Every rank has the same counts: it throws the same error, or none.
    for (unsigned int k = 0; k < points.size(); ++k)
      if (n_cells_per_point[k] == 0)
        throw InputError(
          "scene entry 'Output/Points': the point " + point_text(points[k]) +
          " (point " + std::to_string(k + 1) + ") lies in no cell of the mesh");
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  PointValues<dim>::evaluate(const TrilinosWrappers::MPI::Vector &u) const
  {
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    std::vector<double>                  sums(n_points() * dim, 0.);
    for (const Location &location : locations)
      {
        location.cell->get_dof_indices(dof_indices);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            if (c < dim) // not a mixed pressure
              sums[location.point * dim + c] +=
                u(dof_indices[i]) * location.shape_values[i];
          }
      }
    Utilities::MPI::sum(sums, comm, sums);

    std::vector<Tensor<1, dim>> values(n_points());
    for (unsigned int k = 0; k < n_points(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        values[k][d] = sums[k * dim + d] / n_cells_per_point[k];
    return values;
  }

  template std::vector<Point<2>>
  output_points<2>(const OutputParameters &);
  template std::vector<Point<3>>
  output_points<3>(const OutputParameters &);
  template class PointValues<2>;
  template class PointValues<3>;
} // namespace hyperelastic
