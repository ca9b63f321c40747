// The cell data of the mixed formulation's loops (MixedAssembler::CellData)
// and the loop over the owned cells with the bubble solved, shared by the
// assembler (mixed_assembler.cc) and its constant derivatives
// (mixed_constant_forces.cc). Private to source/assembly.
#pragma once

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/assembly/cell_loop.h>
#include <hyperelastic/assembly/mixed_assembler.h>

#include <limits>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  /// A cell's values, shape data and local system. Local unknowns: the
  /// element's dofs (0 .. n-1), then for MINI the dim bubble coefficients.
  template <int dim>
  struct MixedAssembler<dim>::CellData
  {
    CellData(const Mapping<dim>       &mapping,
             const FiniteElement<dim> &fe,
             const Quadrature<dim>    &quadrature,
             const unsigned int        n_bubble)
        : values(mapping,
                 fe,
                 quadrature,
                 update_values | update_gradients | update_JxW_values)
        , n(fe.dofs_per_cell)
        , n_bubble(n_bubble)
        , dofs(n)
        , x(n)
        , bubble(n_bubble)
        , component(n)
        , grad(quadrature.size(), std::vector<Tensor<1, dim>>(n + n_bubble))
        , psi(quadrature.size(), std::vector<double>(n, 0.))
        , residual(n + n_bubble)
        , matrix(n + n_bubble, n + n_bubble)
    {
      for (unsigned int i = 0; i < n; ++i)
        component[i] = fe.system_to_component_index(i).first;
      for (unsigned int b = 0; b < n_bubble; ++b)
        component.push_back(b);
    }

    /// Fills the shape gradients (u unknowns, bubble included) and the
    /// pressure shape values of the cell.
    void
    reinit(const typename DoFHandler<dim>::active_cell_iterator &cell)
    {
      values.reinit(cell);
      cell->get_dof_indices(dofs);
      diameter   = cell->diameter();
      cell_index = cell->active_cell_index();
      for (unsigned int q = 0; q < grad.size(); ++q)
        {
          for (unsigned int i = 0; i < n; ++i)
            if (component[i] < dim)
              grad[q][i] = values.shape_grad_component(i, q, component[i]);
            else
              psi[q][i] = values.shape_value_component(i, q, dim);
          if (n_bubble == 0)
            continue;
          // The pressure shape functions of P1 are the barycentric
          // coordinates l_k: b = c prod l_k, grad b = c sum_k grad l_k
          // prod_{m != k} l_m.
          const double   c = dim == 2 ? 27. : 256.;
          Tensor<1, dim> grad_b;
          for (unsigned int k = 0; k < n; ++k)
            if (component[k] == dim)
              {
                double product = c;
                for (unsigned int m = 0; m < n; ++m)
                  if (component[m] == dim && m != k)
                    product *= psi[q][m];
                grad_b += product * values.shape_grad_component(k, q, dim);
              }
          for (unsigned int b = 0; b < n_bubble; ++b)
            grad[q][n + b] = grad_b;
        }
    }

    /// F = I + grad u at point @p q from the cell's values and bubble.
    Tensor<2, dim>
    deformation_gradient(const unsigned int q) const
    {
      Tensor<2, dim> F = unit_symmetric_tensor<dim>();
      for (unsigned int i = 0; i < n; ++i)
        if (component[i] < dim)
          F[component[i]] += x[i] * grad[q][i];
      for (unsigned int b = 0; b < n_bubble; ++b)
        F[b] += bubble[b] * grad[q][n + b];
      return F;
    }

    FEValues<dim>                        values;
    const unsigned int                   n;
    const unsigned int                   n_bubble;
    std::vector<types::global_dof_index> dofs;
    Vector<double>                       x;
    Vector<double>                       bubble;
    std::vector<unsigned int>            component;
    /// [q][i]: gradient of the only nonzero component of u unknown i.
    std::vector<std::vector<Tensor<1, dim>>> grad;
    /// [q][i]: value of pressure shape function i (0 for u unknowns).
    std::vector<std::vector<double>> psi;
    double                           diameter   = 0.;
    unsigned int                     cell_index = 0;

    // Results of evaluate_cell().
    Vector<double>     residual;
    FullMatrix<double> matrix;
    double             energy    = 0.;
    double             min_J     = std::numeric_limits<double>::infinity();
    double             force_sum = 0.; ///< for the round-off estimate
  };

  template <int dim>
  template <typename Worker>
  void
  MixedAssembler<dim>::for_each_cell(const VectorType       &u,
                                     const bool              with_matrix,
                                     const TangentProjection project_tangent,
                                     Worker                &&worker) const
  {
    const unsigned int n_bubble = element == MixedElement::mini ? dim : 0;
    CellData data(mapping, dof_handler.get_fe(), quadrature, n_bubble);
    for_each_owned_cell(dof_handler, [&](const auto &cell) {
      data.reinit(cell);
      cell->get_dof_values(u, data.x);
      if (n_bubble > 0)
        solve_bubble(data, with_matrix, project_tangent);
      else
        evaluate_cell(data,
                      with_matrix ? CellOutput::residual_and_matrix
                                  : CellOutput::residual,
                      project_tangent);
      worker(data);
    });
  }

} // namespace hyperelastic
