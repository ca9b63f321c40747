// Problem::reaction_sensitivities(): the adjoint of a converged equilibrium.
//
// A reaction R = e_R . r(u, c), r = f_int - f_ext on every row and e_R the
// indicator of the supported dofs' component, at an equilibrium whose free
// rows vanish, r_f(u, c) = 0, with the supported dofs' values independent of
// the constants c. Then du_f/dc = -K_ff^-1 dr_f/dc (K = dr/du), and
//   dR/dc = e_R . dr/dc + (K^T e_R)_f . du_f/dc = (e_R - a) . dr/dc,
//   K_ff^T a = (K^T e_R)_f,
// one solve for every constant at once (a is zero on the constrained
// dofs). K^T e_R takes the supported rows of the tangent assembled without
// constraints; K_ff is the system's tangent at the converged state. A
// conservative operator has a symmetric tangent and the adjoint solve uses
// K_ff itself; otherwise (follower loads) it solves with K_ff^T
// (EquilibriumSystem::solve_transposed_tangent). dr/dc comes from the
// material part (ConstantForces): dP/dc of the model (ConstantDerivatives)
// assembled like the internal forces, and in the mixed formulation also the
// pressure rows and the condensed bubble.
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/equilibrium_system/equilibrium_system.h>
#include <hyperelastic/problem/problem.h>

namespace hyperelastic
{
  namespace
  {
    /// 1 on the owned dofs of component @p axis on the faces of boundary
    /// @p id, 0 elsewhere, laid out like @p like.
    template <int dim>
    VectorType
    reaction_indicator(const dealii::DoFHandler<dim>   &dof_handler,
                       const dealii::types::boundary_id id,
                       const unsigned int               axis,
                       const VectorType                &like)
    {
      VectorType              e(like);
      const dealii::IndexSet &owned = dof_handler.locally_owned_dofs();
      const dealii::FiniteElement<dim>            &fe = dof_handler.get_fe();
      std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_face());
      e = 0.;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == id)
              {
                cell->face(f)->get_dof_indices(dofs);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  if (fe.face_system_to_component_index(i).first == axis &&
                      owned.is_element(dofs[i]))
                    e[dofs[i]] = 1.;
              }
      e.compress(dealii::VectorOperation::insert);
      return e;
    }
  } // namespace

  template <int dim>
  std::vector<double>
  Problem<dim>::reaction_sensitivities(const dealii::types::boundary_id id,
                                       const unsigned int               axis)
  {
    const ElasticityOperator<dim> &op = *model.elasticity;
    const VectorType              &u  = system->solution();
    const bool symmetric = op.is_conservative();
    if (!symmetric && system->has_system_constraints())
      return {};
    const std::vector<VectorType> dr =
      op.constant_forces(u, system->residual_forces());
    if (dr.empty())
      return {};
    const VectorType e_R = reaction_indicator(model.dof_handler,
                                              id,
                                              axis,
                                              system->residual_forces());
    // K^T e_R from the tangent without constraints (the supported rows).
    MatrixType full;
    full.reinit(system->tangent_matrix());
    full = 0.;
    VectorType scratch(e_R), b(e_R), a(e_R);
    op.assemble_system(u,
                       system->load_factor(),
                       dealii::AffineConstraints<double>(),
                       full,
                       scratch,
                       TangentProjection::none);
    full.Tvmult(b, e_R);
    // K_ff^T a = b_f at the converged state.
    system->assemble_tangent();
    if (symmetric)
      system->solve_tangent(b, a);
    else
      system->solve_transposed_tangent(b, a);
    std::vector<double> derivatives;
    for (const VectorType &dr_dc : dr)
      derivatives.push_back(e_R * dr_dc - a * dr_dc);
    return derivatives;
  }

  template std::vector<double>
  Problem<2>::reaction_sensitivities(dealii::types::boundary_id, unsigned int);
  template std::vector<double>
  Problem<3>::reaction_sensitivities(dealii::types::boundary_id, unsigned int);
} // namespace hyperelastic
