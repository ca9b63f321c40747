// What a contact term measures at a converged state for the step's summary
// (the contact layer, contact/contact_layer.h, writes the columns).
#pragma once

#include <deal.II/base/mpi.h>

#include <hyperelastic/output/step_summary.h>

#include <limits>
#include <string>
#include <vector>

namespace hyperelastic
{
  struct ContactMeasures
  {
    /// The force each obstacle exerts on the body, as columns
    /// contact_force_<k>_<axis> (obstacles only).
    std::vector<SummaryColumn> forces;
    /// The moment each obstacle exerts on the body about the obstacle's
    /// point (Point moved by its Motion), the forces taken at the body's
    /// deformed nodes: sum of (x - c) x f, as columns
    /// contact_moment_<k>_<axis> (2D: z only). By action and reaction it
    /// is minus the moment the body exerts on the obstacle about c
    /// (friction's forces act at the body's nodes, within d_hat of the
    /// obstacle).
    std::vector<SummaryColumn> moments;
    /// The smallest distance of a vertex (pair) to what it may touch
    /// (self contact: capped at d_hat).
    double min_distance = std::numeric_limits<double>::infinity();
    /// The number of pairs closer than d_hat.
    double active_pairs = 0.;

    /// The pairs' measures over all ranks from this rank's smallest
    /// distance @p closest and its @p active pairs. Collective.
    void
    set_pairs(const double closest, const unsigned int active, MPI_Comm comm)
    {
      min_distance = dealii::Utilities::MPI::min(closest, comm);
      active_pairs = dealii::Utilities::MPI::sum(active, comm);
    }

    /// Appends the force and moment columns of the obstacles @p numbers
    /// from this rank's parts of their forces and moments. Collective.
    template <int dim>
    void
    add_obstacles(const std::vector<unsigned int>           &numbers,
                  const std::vector<dealii::Tensor<1, dim>> &force,
                  const std::vector<dealii::Tensor<1, 3>>   &moment,
                  MPI_Comm                                   comm)
    {
      for (unsigned int k = 0; k < numbers.size(); ++k)
        add_obstacle<dim>(numbers[k],
                          dealii::Utilities::MPI::sum(force[k], comm),
                          dealii::Utilities::MPI::sum(moment[k], comm));
    }

    /// Appends obstacle @p number's force and moment columns.
    template <int dim>
    void
    add_obstacle(const unsigned int            number,
                 const dealii::Tensor<1, dim> &force,
                 const dealii::Tensor<1, 3>   &moment)
    {
      const char        axes[3] = {'x', 'y', 'z'};
      const std::string k       = std::to_string(number);
      for (unsigned int d = 0; d < dim; ++d)
        forces.push_back({"contact_force_" + k + "_" + axes[d], force[d]});
      for (unsigned int d = (dim == 3 ? 0 : 2); d < 3; ++d)
        moments.push_back({"contact_moment_" + k + "_" + axes[d], moment[d]});
    }
  };
} // namespace hyperelastic
