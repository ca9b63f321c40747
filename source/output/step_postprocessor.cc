// Reactions, deformed bounding box, point displacements and pressure range of
// a converged step.
#include <deal.II/base/mpi.h>

#include <hyperelastic/output/step_postprocessor.h>

#include <algorithm>
#include <limits>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  StepPostprocessor<dim>::StepPostprocessor(
    const DoFHandler<dim>         &dof_handler,
    const Mapping<dim>            &mapping,
    const BoundaryConditions<dim> &boundary_conditions,
    const OutputParameters        &output,
    const IndexSet                &pressure_dofs)
      : dof_handler(dof_handler)
      , pressure_dofs(pressure_dofs)
      , has_pressure(Utilities::MPI::max(pressure_dofs.n_elements() > 0 ? 1 : 0,
                                         dof_handler.get_communicator()) == 1)
  {
    if (!output.points.empty())
      point_values =
        std::make_unique<PointValues<dim>>(output_points<dim>(output),
                                           dof_handler,
                                           mapping,
                                           dof_handler.get_communicator());

    // Dofs on each Dirichlet boundary id with the components prescribed there
    // (by one or several sections). Ghost cells are visited too: a dof owned
    // here may lie only on a neighbour's boundary face.
    std::vector<std::vector<bool>> prescribed;
    for (const auto &d : boundary_conditions.dirichlet)
      {
        const auto it =
          std::find(reaction_ids.begin(), reaction_ids.end(), d.id);
        const unsigned int r = it - reaction_ids.begin();
        if (it == reaction_ids.end())
          {
            reaction_ids.push_back(d.id);
            prescribed.emplace_back(dim, false);
          }
        for (unsigned int c = 0; c < dim; ++c)
          prescribed[r][c] = prescribed[r][c] || d.mask[c];
      }
    reaction_dofs.assign(reaction_ids.size(), {});
    const FiniteElement<dim> &fe    = dof_handler.get_fe();
    const IndexSet           &owned = dof_handler.locally_owned_dofs();
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            for (unsigned int r = 0; r < reaction_ids.size(); ++r)
              if (cell->face(f)->boundary_id() == reaction_ids[r])
                {
                  cell->face(f)->get_dof_indices(face_dofs);
                  for (unsigned int i = 0; i < face_dofs.size(); ++i)
                    {
                      const unsigned int c =
                        fe.face_system_to_component_index(i, f).first;
                      if (c < dim && owned.is_element(face_dofs[i]) &&
                          prescribed[r][c])
                        reaction_dofs[r].emplace_back(face_dofs[i], c);
                    }
                }
    for (auto &dofs : reaction_dofs)
      {
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
      }
  }

  template <int dim>
  StepPostprocessor<dim>::~StepPostprocessor() = default;

  template <int dim>
  void
  StepPostprocessor<dim>::measure(const VectorType &u,
                                  const VectorType &residual,
                                  StepSummary<dim> &s) const
  {
    const MPI_Comm comm = dof_handler.get_communicator();
    // residual = f_int - f_ext at the converged state: on supported dofs it
    // is the force the support exerts on the body.
    for (unsigned int r = 0; r < reaction_ids.size(); ++r)
      {
        Tensor<1, dim> force;
        for (const auto &[dof, component] : reaction_dofs[r])
          force[component] += residual(dof);
        s.reactions.emplace_back(reaction_ids[r],
                                 Utilities::MPI::sum(force, comm));
      }

    // Bounding box of the deformed vertices.
    for (unsigned int d = 0; d < dim; ++d)
      {
        s.deformed_min[d] = std::numeric_limits<double>::max();
        s.deformed_max[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double x =
                cell->vertex(v)[d] + u(cell->vertex_dof_index(v, d));
              s.deformed_min[d] = std::min(s.deformed_min[d], x);
              s.deformed_max[d] = std::max(s.deformed_max[d], x);
            }
    for (unsigned int d = 0; d < dim; ++d)
      {
        s.deformed_min[d] = Utilities::MPI::min(s.deformed_min[d], comm);
        s.deformed_max[d] = Utilities::MPI::max(s.deformed_max[d], comm);
      }

    if (point_values)
      s.point_displacements = point_values->evaluate(u);

    if (has_pressure)
      {
        double low = std::numeric_limits<double>::max(), high = -low;
        for (const auto i : dof_handler.locally_owned_dofs())
          if (pressure_dofs.is_element(i))
            {
              low  = std::min(low, u(i));
              high = std::max(high, u(i));
            }
        s.has_pressure = true;
        s.pressure_min = Utilities::MPI::min(low, comm);
        s.pressure_max = Utilities::MPI::max(high, comm);
      }
  }

  template class StepPostprocessor<2>;
  template class StepPostprocessor<3>;
} // namespace hyperelastic
