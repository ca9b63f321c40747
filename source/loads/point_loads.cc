// Point loads: each vertex found once, its force added by the rank that owns
// the vertex's dofs.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/loads/point_loads.h>

#include <cmath>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  PointLoads<dim>::PointLoads(const std::vector<PointLoad<dim>> &loads,
                              const DoFHandler<dim>             &dof_handler)
      : loads(loads)
      , dofs(loads.size())
      , comm(dof_handler.get_communicator())
  {
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    for (unsigned int k = 0; k < loads.size(); ++k)
      {
        int found = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              if (is_vertex_at(cell->vertex(v),
                               loads[k].point,
                               cell->diameter()))
                {
                  found = 1;
                  if (dofs[k].empty() &&
                      owned.is_element(cell->vertex_dof_index(v, 0)))
                    for (unsigned int c = 0; c < dim; ++c)
                      dofs[k].push_back(cell->vertex_dof_index(v, c));
                }
        if (Utilities::MPI::max(found, comm) == 0)
          {
            std::ostringstream point;
            point << loads[k].point;
            throw InputError("scene entry '" + loads[k].subsection +
                             "/Point' = '" + point.str() +
                             "': no mesh vertex lies at this point");
          }
      }
  }

  template <int dim>
  ForceSize
  PointLoads<dim>::add_forces(const VectorType & /*u*/,
                              const double t,
                              VectorType  &forces) const
  {
    int non_finite = -1;
    for (unsigned int k = 0; k < loads.size(); ++k)
      if (!dofs[k].empty())
        {
          loads[k].force->set_time(t);
          for (unsigned int c = 0; c < dim; ++c)
            {
              const double f = loads[k].force->value(loads[k].point, c);
              if (!std::isfinite(f))
                non_finite = k;
              forces(dofs[k][c]) += f;
            }
        }
    non_finite = Utilities::MPI::max(non_finite, comm);
    if (non_finite >= 0)
      throw InputError("scene entry '" + loads[non_finite].subsection +
                       "/Force' is not a finite number at load factor t = " +
                       std::to_string(t));
    return {};
  }

  template class PointLoads<2>;
  template class PointLoads<3>;
} // namespace hyperelastic
