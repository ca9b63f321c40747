// Kinetic energy and momenta of the discrete motion.
#include <deal.II/fe/fe.h>

#include <hyperelastic/dynamics/motion.h>

#include <set>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  Motion<dim>::Motion(const DoFHandler<dim> &dof_handler,
                      const Mapping<dim>    &mapping,
                      const InertiaTerm<dim> &inertia)
      : dof_handler(dof_handler)
      , inertia(inertia)
  {
    const FiniteElement<dim> &fe    = dof_handler.get_fe();
    const auto               &unit  = fe.base_element(0).get_unit_support_points();
    const IndexSet           &owned = dof_handler.locally_owned_dofs();
    std::vector<types::global_dof_index> dofs(fe.dofs_per_cell);
    std::set<types::global_dof_index>    seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int k = 0; k < unit.size(); ++k)
            {
              Node node;
              for (unsigned int d = 0; d < dim; ++d)
                node.dofs[d] = dofs[fe.component_to_system_index(d, k)];
              if (!owned.is_element(node.dofs[0]) ||
                  !seen.insert(node.dofs[0]).second)
                continue;
              node.X = mapping.transform_unit_to_real_cell(cell, unit[k]);
              nodes.push_back(node);
            }
        }
    momentum.reinit(owned, dof_handler.get_communicator());
  }

  template <int dim>
  MotionMeasures
  Motion<dim>::measure(const VectorType &u, const VectorType &v) const
  {
    inertia.mass_product(v, momentum);
    MotionMeasures m;
    m.kinetic_energy = 0.5 * local_owned_dot(v, momentum);
    for (const Node &node : nodes)
      {
        Tensor<1, 3> x, p;
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d] = node.X[d] + u(node.dofs[d]);
            p[d] = momentum(node.dofs[d]);
          }
        m.linear_momentum += p;
        m.angular_momentum += cross_product_3d(x, p);
      }
    const MPI_Comm comm = dof_handler.get_communicator();
    m.kinetic_energy    = Utilities::MPI::sum(m.kinetic_energy, comm);
    m.linear_momentum   = Utilities::MPI::sum(m.linear_momentum, comm);
    m.angular_momentum  = Utilities::MPI::sum(m.angular_momentum, comm);
    return m;
  }

  template class Motion<2>;
  template class Motion<3>;
} // namespace hyperelastic
