// Stiffness-proportional damping: K0 assembled once, applied as a matrix.
#include <hyperelastic/assembly/rest_stiffness.h>
#include <hyperelastic/dynamics/stiffness_damping.h>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  StiffnessDampingTerm<dim>::StiffnessDampingTerm(
    const DoFHandler<dim>      &dof_handler,
    const Mapping<dim>         &mapping,
    const MaterialRegions<dim> &materials)
  {
    assemble_rest_stiffness(dof_handler, mapping, materials, stiffness);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    for (VectorType *v : {&zero, &difference, &product})
      v->reinit(owned, dof_handler.get_communicator());
  }

  template <int dim>
  void
  StiffnessDampingTerm<dim>::set_step(const double s, const VectorType &d)
  {
    scale = s;
    zero  = d;
  }

  template <int dim>
  void
  StiffnessDampingTerm<dim>::apply(const VectorType &u,
                                   VectorType       &diff,
                                   VectorType       &Kd) const
  {
    for (const auto i : diff.locally_owned_elements())
      diff(i) = u(i) - zero(i);
    diff.compress(VectorOperation::insert);
    stiffness.vmult(Kd, diff);
  }

  template <int dim>
  ForceSize
  StiffnessDampingTerm<dim>::add_forces(const VectorType &u,
                                        const double,
                                        VectorType &forces) const
  {
    apply(u, difference, product);
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    for (const auto i : product.locally_owned_elements())
      {
        indices.push_back(i);
        values.push_back(-scale * product(i));
      }
    forces.add(indices, values);
    return {};
  }

  template <int dim>
  void
  StiffnessDampingTerm<dim>::add_stiffness(
    const VectorType &,
    const double,
    TangentProjection,
    const AffineConstraints<double> &constraints,
    MatrixType                      &matrix,
    VectorType                      &rhs) const
  {
    // Row by row: free rows get s K0 on their free columns; the prescribed
    // values of constrained columns move to the right-hand side.
    std::vector<types::global_dof_index> columns;
    std::vector<double>                  values;
    for (const auto row : product.locally_owned_elements())
      {
        if (constraints.is_constrained(row))
          continue;
        columns.clear();
        values.clear();
        for (auto entry = stiffness.begin(row); entry != stiffness.end(row);
             ++entry)
          {
            columns.push_back(entry->column());
            values.push_back(scale * entry->value());
          }
        const double moved = condense_row(constraints, columns, values);
        matrix.add(row, columns.size(), columns.data(), values.data());
        if (moved != 0.)
          rhs.add(std::vector<types::global_dof_index>{row},
                  std::vector<double>{-moved});
      }
  }

  template <int dim>
  double
  StiffnessDampingTerm<dim>::energy(const VectorType &u, const double) const
  {
    apply(u, difference, product);
    return 0.5 * scale * (difference * product);
  }

  template class StiffnessDampingTerm<2>;
  template class StiffnessDampingTerm<3>;
} // namespace hyperelastic
