// Inverted cells of a displacement field, counted over all ranks.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <hyperelastic/assembly/material_point.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/output/inverted_cells.h>

#include <limits>
#include <sstream>
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

  template <int dim>
  void
  judge_inverted_cells(const InvertedCells<dim> &inverted,
                       const NewtonParameters   &newton,
                       const std::string        &model,
                       const bool                defined,
                       const ConditionalOStream &pcout)
  {
    if (inverted.n_cells == 0)
      return;
    std::ostringstream where;
    where << inverted.n_cells << " inverted cell"
          << (inverted.n_cells == 1 ? "" : "s")
          << " (J <= 0; smallest J = " << inverted.min_J
          << " in the cell centred at (" << inverted.worst_cell_center << "))";
    if (newton.accepts_inverted_elements(defined))
      {
        pcout << "   warning: equilibrium with " << where.str()
              << ", accepted: the " << model
              << " model is defined there ('Newton/Inverted elements at "
                 "equilibrium = warn')"
              << std::endl;
        return;
      }
    std::ostringstream message;
    message << "Newton converged to an equilibrium with " << where.str();
    if (defined)
      message << ", rejected by 'Newton/Inverted elements at equilibrium = "
                 "reject'; the "
              << model
              << " model is defined for J <= 0 and this can be its correct "
                 "discrete answer: set that entry to 'warn' to accept it";
    else
      message << ", where the " << model
              << " model is not defined (infinite energy): not a solution; "
                 "keep 'Newton/Line search = true' (its J > 0 filter keeps "
                 "this model's iterates admissible) or use a model defined "
                 "for J <= 0 (stable neo-Hookean, corotational)";
    throw ConvergenceFailure(message.str());
  }

  template void
  judge_inverted_cells(const InvertedCells<2> &,
                       const NewtonParameters &,
                       const std::string &,
                       bool,
                       const ConditionalOStream &);
  template void
  judge_inverted_cells(const InvertedCells<3> &,
                       const NewtonParameters &,
                       const std::string &,
                       bool,
                       const ConditionalOStream &);

  template InvertedCells<2>
  find_inverted_cells(const Mapping<2> &,
                      const DoFHandler<2> &,
                      const TrilinosWrappers::MPI::Vector &);
  template InvertedCells<3>
  find_inverted_cells(const Mapping<3> &,
                      const DoFHandler<3> &,
                      const TrilinosWrappers::MPI::Vector &);
} // namespace hyperelastic
