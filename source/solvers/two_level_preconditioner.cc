// The two-level P2 -> P1 preconditioner: interpolation matrix, Galerkin
// coarse operator, Chebyshev smoother, V-cycle.
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hyperelastic/solvers/rigid_body_modes.h>
#include <hyperelastic/solvers/two_level_preconditioner.h>

#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <memory>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  TwoLevelPreconditioner<dim>::TwoLevelPreconditioner(
    const DoFHandler<dim> &fine,
    const unsigned int     smoother_degree)
      : coarse(fine.get_triangulation())
      , smoother_degree(smoother_degree)
  {
    const FiniteElement<dim> &fe_fine = fine.get_fe();
    AssertThrow(fe_fine.n_components() == dim && fe_fine.degree == 2,
                ExcMessage("the two-level preconditioner is for P2 "
                           "displacement fields"));
    coarse.distribute_dofs(FESystem<dim>(FE_SimplexP<dim>(1), dim));
    const FiniteElement<dim> &fe_coarse = coarse.get_fe();

    // Weights of the P1 shape functions at the P2 support points, per
    // component: 1 at a vertex, 1/2 at the midpoint of an edge, else 0.
    const auto &points = fe_fine.get_unit_support_points();
    FullMatrix<double> weights(fe_fine.n_dofs_per_cell(),
                               fe_coarse.n_dofs_per_cell());
    for (unsigned int i = 0; i < weights.m(); ++i)
      for (unsigned int j = 0; j < weights.n(); ++j)
        if (fe_fine.system_to_component_index(i).first ==
            fe_coarse.system_to_component_index(j).first)
          {
            const double w = fe_coarse.shape_value(j, points[i]);
            weights(i, j)  = std::abs(w) < 1e-12 ? 0. : w;
          }

    const IndexSet &rows    = fine.locally_owned_dofs();
    const IndexSet &columns = coarse.locally_owned_dofs();
    std::vector<types::global_dof_index> fine_dofs(weights.m()),
      coarse_dofs(weights.n());
    DynamicSparsityPattern pattern(fine.n_dofs(), coarse.n_dofs(), rows);
    // Each owned P2 unknown lies on a cell of its owner, so the owned cells
    // give every owned row.
    const auto for_each_entry = [&](const auto &visit) {
      for (const auto &cell : fine.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const typename DoFHandler<dim>::active_cell_iterator
              coarse_cell(&coarse.get_triangulation(),
                          cell->level(),
                          cell->index(),
                          &coarse);
            cell->get_dof_indices(fine_dofs);
            coarse_cell->get_dof_indices(coarse_dofs);
            for (unsigned int i = 0; i < weights.m(); ++i)
              if (rows.is_element(fine_dofs[i]))
                for (unsigned int j = 0; j < weights.n(); ++j)
                  if (weights(i, j) != 0.)
                    visit(fine_dofs[i], coarse_dofs[j], weights(i, j));
          }
    };
    for_each_entry([&](auto i, auto j, double) { pattern.add(i, j); });
    P.reinit(rows, columns, pattern, fine.get_communicator());
    for_each_entry([&](auto i, auto j, double w) { P.set(i, j, w); });
    P.compress(VectorOperation::insert);

    coarse_modes =
      rigid_body_modes(MappingFE<dim>(FE_SimplexP<dim>(1)), coarse);
  }

  template <int dim>
  void
  TwoLevelPreconditioner<dim>::initialize(const Matrix &matrix)
  {
    A = &matrix;
    Matrix AP;
    A->mmult(AP, P);
    P.Tmmult(coarse_matrix, AP);

    // ML on the P1 operator, configured like the one-level solver: smoothed
    // aggregation with the rigid-body near-null space.
    TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
    amg_data.elliptic       = true;
    amg_data.smoother_type  = "Chebyshev";
    amg_data.coarse_type    = "Amesos-KLU";
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> unused;
    amg_data.set_parameters(list, unused, coarse_matrix);
    list.set("PDE equations", dim);
    list.set("null space: type", "pre-computed");
    list.set("null space: dimension",
             static_cast<int>(n_rigid_body_modes<dim>));
    static double no_rows = 0.;
    list.set("null space: vectors",
             coarse_modes.empty() ? &no_rows : coarse_modes.data());
    amg.initialize(coarse_matrix, list);

    // Chebyshev on the smooth-out range [lambda_max / 15, lambda_max] of
    // D^-1 A (lambda_max estimated by a few CG steps).
    typename Smoother::AdditionalData data;
    data.degree              = smoother_degree;
    data.smoothing_range     = 15.;
    data.eig_cg_n_iterations = 12;
    data.preconditioner      = std::make_shared<InverseDiagonal>();
    Vector &inverse_diagonal = data.preconditioner->values;
    inverse_diagonal.reinit(A->locally_owned_range_indices(),
                            A->get_mpi_communicator());
    for (const auto i : A->locally_owned_range_indices())
      inverse_diagonal(i) = 1. / A->diag_element(i);
    inverse_diagonal.compress(VectorOperation::insert);
    smoother.initialize(*A, data);

    residual.reinit(inverse_diagonal);
    correction.reinit(inverse_diagonal);
    coarse_residual.reinit(coarse_matrix.locally_owned_range_indices(),
                           coarse_matrix.get_mpi_communicator());
    coarse_correction.reinit(coarse_residual);
  }

  template <int dim>
  void
  TwoLevelPreconditioner<dim>::vmult(Vector &x, const Vector &b) const
  {
    // Pre-smoothing from x = 0.
    smoother.vmult(x, b);
    // Coarse correction of the residual.
    A->vmult(residual, x);
    residual.sadd(-1., 1., b);
    P.Tvmult(coarse_residual, residual);
    amg.vmult(coarse_correction, coarse_residual);
    P.vmult(correction, coarse_correction);
    x += correction;
    // Post-smoothing (the same polynomial: the cycle is symmetric).
    A->vmult(residual, x);
    residual.sadd(-1., 1., b);
    smoother.vmult(correction, residual);
    x += correction;
  }

  template <int dim>
  std::string
  TwoLevelPreconditioner<dim>::description() const
  {
    return "a two-level preconditioner (Chebyshev degree " +
           std::to_string(smoother_degree) +
           " on P2, ML AMG with rigid-body modes on the P1 Galerkin "
           "operator)";
  }

  template class TwoLevelPreconditioner<2>;
  template class TwoLevelPreconditioner<3>;
} // namespace hyperelastic
