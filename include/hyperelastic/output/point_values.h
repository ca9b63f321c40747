// The displacement at fixed reference points ('Output/Points'), for the CSV
// summary: each point is located in the locally owned cells of every rank,
// and the values found are averaged over all cells (of all ranks) that hold
// the point, so the answer does not depend on the partition.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hyperelastic/output/output_parameters.h>

#include <mpi.h>
#include <vector>

namespace hyperelastic
{
  /// The points of 'Output/Points' as Point<dim>. Throws InputError (on
  /// every rank alike) if a point does not have dim coordinates.
  template <int dim>
  std::vector<dealii::Point<dim>>
  output_points(const OutputParameters &parameters);

  template <int dim>
  class PointValues
  {
  public:
    /// Locates every point in the locally owned cells (a point on a vertex,
    /// edge or face is found in all cells that share it). Collective over
    /// @p comm. Throws InputError naming 'Output/Points' and the point on
    /// every rank if a point lies in no cell of the mesh.
    PointValues(const std::vector<dealii::Point<dim>> &points,
                const dealii::DoFHandler<dim>         &dof_handler,
                const dealii::Mapping<dim>            &mapping,
                MPI_Comm                               comm);

    /// The FE field @p u (dim components, with ghost entries) at each point:
    /// the mean over all cells that hold the point. Collective.
    std::vector<dealii::Tensor<1, dim>>
    evaluate(const dealii::TrilinosWrappers::MPI::Vector &u) const;

    unsigned int
    n_points() const
    {
      return n_cells_per_point.size();
    }

  private:
    /// A locally owned cell that holds point @p point, and the FE shape
    /// values there.
    struct Location
    {
      unsigned int                                           point;
      typename dealii::DoFHandler<dim>::active_cell_iterator cell;
      std::vector<double>                                    shape_values;
    };

    const dealii::DoFHandler<dim> &dof_handler;
    const MPI_Comm                 comm;
    std::vector<Location>          locations;
    /// Over all ranks.
    std::vector<unsigned int> n_cells_per_point;
  };
} // namespace hyperelastic
