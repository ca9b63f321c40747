// Point loads: a nodal force on one mesh vertex each ('Point load 1', ...),
// the load at the crown of an arch or the tip of a beam. Dead loads: the
// forces do not depend on u, so their potential is minus their work.
#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/assembly/energy_term.h>

#include <vector>

namespace hyperelastic
{
  template <int dim>
  class PointLoads : public DeadTerm<dim>
  {
  public:
    /// Finds each load's vertex among the locally owned dofs. Throws
    /// InputError on every rank, naming the section, if a point is no
    /// vertex of the mesh. Collective.
    PointLoads(const std::vector<PointLoad<dim>> &loads,
               const dealii::DoFHandler<dim>     &dof_handler);

    std::string
    name() const override
    {
      return "Point load";
    }


    ForceSize
    add_forces(const VectorType &u,
               double            t,
               VectorType       &forces) const override;

  private:
    const std::vector<PointLoad<dim>> &loads;
    /// Per load, the owned dofs of its vertex, component by component
    /// (empty on the ranks that do not own it).
    std::vector<std::vector<dealii::types::global_dof_index>> dofs;
    MPI_Comm                                                  comm;
  };
} // namespace hyperelastic
