// Inverted cells of a displacement field, counted over all ranks.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <hyperelastic/assembly/material_point.h>
#include <hyperelastic/output/inverted_cells.h>

#include <limits>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  InvertedCells<dim>
  find_inverted_cells(const Mapping<dim>                  &mapping,
                      const DoFHandler<dim>               &dof_handler,
                      const TrilinosWrappers::MPI::Vector &u)
  {
    const MPI_Comm comm = dof_handler.get_communicator();
    // The points the stress terms are integrated at.
    const QGaussSimplex<dim>         quadrature(dof_handler.get_fe().degree);
    FEValues<dim>                    fe_values(mapping,
                            dof_handler.get_fe(),
                            quadrature,
                            update_gradients);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      grad_u(quadrature.size());

    types::global_cell_index n_local = 0;
    double                   min_J   = std::numeric_limits<double>::max();
    Point<dim>               worst;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(u, grad_u);
          double cell_min_J = std::numeric_limits<double>::max();
          for (const Tensor<2, dim> &grad : grad_u)
            cell_min_J =
              std::min(cell_min_J, determinant(deformation_gradient_of(grad)));
          if (!(cell_min_J > 0.))
            ++n_local;
          if (cell_min_J < min_J)
            {
              min_J = cell_min_J;
              worst = cell->center();
            }
        }

    InvertedCells<dim> result;
    result.n_cells = Utilities::MPI::sum(n_local, comm);
    // The rank with the smallest J says where it is.
    const auto extremes = Utilities::MPI::min_max_avg(min_J, comm);
    result.min_J        = extremes.min;
    result.worst_cell_center =
      Utilities::MPI::broadcast(comm, worst, extremes.min_index);
    return result;
  }

  template InvertedCells<2>
  find_inverted_cells(const Mapping<2> &,
                      const DoFHandler<2> &,
                      const TrilinosWrappers::MPI::Vector &);
  template InvertedCells<3>
  find_inverted_cells(const Mapping<3> &,
                      const DoFHandler<3> &,
                      const TrilinosWrappers::MPI::Vector &);
} // namespace hyperelastic
