// Reactions and their moments, deformed bounding box, point displacements and
// pressure range of a converged step.
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
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->at_boundary())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            for (unsigned int r = 0; r < reaction_ids.size(); ++r)
              if (cell->face(f)->boundary_id() == reaction_ids[r])
                {
                  // The face's dofs looked up among the cell's, whose
                  // numbering gives each its support point and its node's
                  // other components whatever the face's orientation.
                  cell->face(f)->get_dof_indices(face_dofs);
                  cell->get_dof_indices(cell_dofs);
                  for (unsigned int i = 0; i < cell_dofs.size(); ++i)
                    {
                      const auto [c, j] = fe.system_to_component_index(i);
                      if (c >= dim || !prescribed[r][c] ||
                          !owned.is_element(cell_dofs[i]) ||
                          std::find(face_dofs.begin(),
                                    face_dofs.end(),
                                    cell_dofs[i]) == face_dofs.end())
                        continue;
                      ReactionDof d{cell_dofs[i],
                                    c,
                                    mapping.transform_unit_to_real_cell(
                                      cell, fe.unit_support_point(i)),
                                    {}};
                      for (unsigned int e = 0; e < dim; ++e)
                        d.node[e] =
                          cell_dofs[fe.component_to_system_index(e, j)];
                      reaction_dofs[r].push_back(d);
                    }
                }
    for (auto &dofs : reaction_dofs)
      {
        const auto by_dof = [](const ReactionDof &a, const ReactionDof &b) {
          return a.dof < b.dof;
        };
        std::sort(dofs.begin(), dofs.end(), by_dof);
        dofs.erase(std::unique(dofs.begin(),
                               dofs.end(),
                               [](const ReactionDof &a, const ReactionDof &b) {
                                 return a.dof == b.dof;
                               }),
                   dofs.end());
      }
    for (unsigned int d = 0; d < dim; ++d)
      moment_point[d] = output.moment_point[d];
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
    // Their moments about the moment point p: each nodal force at its
    // node's deformed position, (X + u - p) x f (in 2D the z component).
    for (unsigned int r = 0; r < reaction_ids.size(); ++r)
      {
        Tensor<1, dim> force;
        Tensor<1, 3>   moment;
        for (const ReactionDof &d : reaction_dofs[r])
          {
            Tensor<1, dim> nodal_force, arm = d.X - moment_point;
            nodal_force[d.component] = residual(d.dof);
            for (unsigned int e = 0; e < dim; ++e)
              arm[e] += u(d.node[e]);
            force += nodal_force;
            moment += moment_of(arm, nodal_force);
          }
        s.reactions.emplace_back(reaction_ids[r],
                                 Utilities::MPI::sum(force, comm));
        s.reaction_moments.emplace_back(reaction_ids[r],
                                        Utilities::MPI::sum(moment, comm));
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
