// Rigid-body modes evaluated at the support points of the owned dofs.
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <hyperelastic/solvers/rigid_body_modes.h>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  std::vector<double>
  rigid_body_modes(const Mapping<dim>    &mapping,
                   const DoFHandler<dim> &dof_handler)
  {
    const FiniteElement<dim> &fe      = dof_handler.get_fe();
    const IndexSet           &owned   = dof_handler.locally_owned_dofs();
    const std::size_t         n_owned = owned.n_elements();
    const unsigned int        n_modes = n_rigid_body_modes<dim>;
    std::vector<double>       modes(n_modes * n_owned, 0.);

    // Centre of the whole body: average of the local bounding boxes' extremes.
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], cell->vertex(v)[d]);
              upper[d] = std::max(upper[d], cell->vertex(v)[d]);
            }
    Point<dim>     centre;
    const MPI_Comm comm = dof_handler.get_communicator();
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5 * (Utilities::MPI::min(lower[d], comm) +
                         Utilities::MPI::max(upper[d], comm));

    FEValues<dim>                        fe_values(mapping,
                            fe,
                            Quadrature<dim>(fe.get_unit_support_points()),
                            update_quadrature_points);
    std::vector<types::global_dof_index> dofs(fe.dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
            {
              if (!owned.is_element(dofs[i]))
                continue;
              const std::size_t  k = owned.index_within_set(dofs[i]);
              const unsigned int c = fe.system_to_component_index(i).first;
              if (c >= dim)
                continue; // a mixed pressure: zero in every mode
              const Tensor<1, dim> x = fe_values.quadrature_point(i) - centre;
              modes[c * n_owned + k] = 1.; // translation along c
              if (dim == 2)
                // rotation about z: (-y, x)
                modes[2 * n_owned + k] = (c == 0 ? -x[1] : x[0]);
              else
                {
                  // rotations about x: (0, -z, y), y: (z, 0, -x), z: (-y, x, 0)
                  const double rx[3]     = {0., -x[dim - 1], x[1]};
                  const double ry[3]     = {x[dim - 1], 0., -x[0]};
                  const double rz[3]     = {-x[1], x[0], 0.};
                  modes[3 * n_owned + k] = rx[c];
                  modes[4 * n_owned + k] = ry[c];
                  modes[5 * n_owned + k] = rz[c];
                }
            }
        }
    return modes;
  }

  template std::vector<double>
  rigid_body_modes(const Mapping<2> &, const DoFHandler<2> &);
  template std::vector<double>
  rigid_body_modes(const Mapping<3> &, const DoFHandler<3> &);
} // namespace hyperelastic
