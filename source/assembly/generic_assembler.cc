// The FEValues loops of the material part (any degree).
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/assembly/cell_loop.h>
#include <hyperelastic/assembly/generic_assembler.h>
#include <hyperelastic/assembly/material_point.h>
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/constant_derivatives.h>

#include <cmath>
#include <limits>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  struct GenericAssembler<dim>::CellData
  {
    CellData(const Mapping<dim>       &mapping,
             const FiniteElement<dim> &fe,
             const Quadrature<dim>    &quadrature)
        : values(mapping, fe, quadrature, update_gradients | update_JxW_values)
        , dofs(fe.dofs_per_cell)
        , u(fe.dofs_per_cell)
        , F(quadrature.size())
        , component(fe.dofs_per_cell)
    {
      for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
        component[i] = fe.system_to_component_index(i).first;
    }

    /// The gradient of shape function i's only nonzero component at q.
    Tensor<1, dim>
    gradient(const unsigned int i, const unsigned int q) const
    {
      return values.shape_grad_component(i, q, component[i]);
    }

    FEValues<dim>                        values;
    std::vector<types::global_dof_index> dofs;
    Vector<double>                       u;
    /// F = I + grad u at the quadrature points.
    std::vector<Tensor<2, dim>> F;
    std::vector<unsigned int>   component;
    /// The cell's active index.
    unsigned int cell = 0;
  };

  template <int dim>
  GenericAssembler<dim>::GenericAssembler(const DoFHandler<dim> &dof_handler,
                                          const Mapping<dim>    &mapping,
                                          const MaterialRegions<dim> &material)
      : dof_handler(dof_handler)
      , mapping(mapping)
      , material(material)
      , quadrature(QGaussSimplex<dim>(dof_handler.get_fe().degree))
      , materials(material, dof_handler, mapping, quadrature)
  {
  }

  template <int dim>
  template <typename CellWorker>
  void
  GenericAssembler<dim>::for_each_cell(const VectorType &u,
                                       CellWorker      &&worker) const
  {
    CellData data(mapping, dof_handler.get_fe(), quadrature);
    for_each_owned_cell(dof_handler, [&](const auto &cell) {
      cell->get_dof_indices(data.dofs);
      cell->get_dof_values(u, data.u);
      data.values.reinit(cell);
      data.cell = cell->active_cell_index();
      for (unsigned int q = 0; q < data.F.size(); ++q)
        {
          Tensor<2, dim> F = unit_symmetric_tensor<dim>();
          for (unsigned int i = 0; i < data.u.size(); ++i)
            F[data.component[i]] += data.u[i] * data.gradient(i, q);
          data.F[q] = F;
        }
      worker(data);
    });
  }

  template <int dim>
  double
  GenericAssembler<dim>::internal_forces(const VectorType &u,
                                         VectorType       &internal) const
  {
    internal = 0.;
    Vector<double> cell_internal(dof_handler.get_fe().dofs_per_cell);
    RoundOff       round_off(material);
    for_each_cell(u, [&](CellData &data) {
      cell_internal = 0.;
      for (unsigned int q = 0; q < data.F.size(); ++q)
        {
          const Tensor<2, dim> P =
            materials(data.cell, q).first_piola_kirchhoff(data.F[q]);
          const double JxW          = data.values.JxW(q);
          double       gradient_sum = 0.;
          for (unsigned int i = 0; i < cell_internal.size(); ++i)
            {
              const Tensor<1, dim> grad = data.gradient(i, q);
              cell_internal[i] += (P[data.component[i]] * grad) * JxW;
              gradient_sum += grad.norm();
            }
          round_off.add_force(data.F[q], gradient_sum, JxW);
        }
      round_off.end_cell();
      internal.add(data.dofs, cell_internal);
    });
    internal.compress(VectorOperation::add);
    return round_off.force_noise(dof_handler.get_communicator());
  }

  template <int dim>
  std::vector<VectorType>
  GenericAssembler<dim>::constant_forces(const VectorType &u,
                                         const VectorType &like) const
  {
    std::vector<VectorType> forces;
    bool                    available = true;
    Vector<double>          cell_force(dof_handler.get_fe().dofs_per_cell);
    for_each_cell(u, [&](CellData &data) {
      for (unsigned int q = 0; q < data.F.size() && available; ++q)
        {
          const auto *derivatives =
            dynamic_cast<const ConstantDerivatives<dim> *>(
              &materials(data.cell, q));
          if (!derivatives)
            {
              available = false;
              break;
            }
          const std::vector<Tensor<2, dim>> dP =
            derivatives->stress_derivatives(data.F[q]);
          if (forces.empty())
            {
              forces.assign(dP.size(), like);
              for (VectorType &force : forces)
                force = 0.;
            }
          const double JxW = data.values.JxW(q);
          for (unsigned int k = 0; k < dP.size(); ++k)
            {
              for (unsigned int i = 0; i < cell_force.size(); ++i)
                cell_force[i] =
                  (dP[k][data.component[i]] * data.gradient(i, q)) * JxW;
              forces[k].add(data.dofs, cell_force);
            }
        }
    });
    return gathered_constant_forces(
      std::move(forces), available, like, dof_handler.get_communicator());
  }

  template <int dim>
  bool
  GenericAssembler<dim>::system(const VectorType                &u,
                                const AffineConstraints<double> &constraints,
                                const TangentProjection project_tangent,
                                MatrixType             &matrix,
                                VectorType             &rhs) const
  {
    matrix                        = 0.;
    rhs                           = 0.;
    const unsigned int          n = dof_handler.get_fe().dofs_per_cell;
    FullMatrix<double>          cell_matrix(n, n);
    Vector<double>              cell_rhs(n);
    std::vector<Tensor<1, dim>> grad(n);
    Tensor<2, dim>              P;
    StressTangent<dim>          A;

    for_each_cell(u, [&](CellData &data) {
      cell_matrix = 0.;
      cell_rhs    = 0.;
      for (unsigned int q = 0; q < data.F.size(); ++q)
        {
          if (!stress_and_tangent_at(
                materials(data.cell, q), data.F[q], project_tangent, P, A))
            throw std::domain_error(non_finite_stress_message());
          const double JxW = data.values.JxW(q);
          for (unsigned int i = 0; i < n; ++i)
            grad[i] = data.gradient(i, q);
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int ci = data.component[i];
              cell_rhs[i] -= (P[ci] * grad[i]) * JxW;
              // A[ci][J][cj][L] grad_i[J] grad_j[L]
              const Tensor<3, dim> &A_i = A[ci];
              for (unsigned int j = 0; j < n; ++j)
                {
                  double k = 0.;
                  for (unsigned int J = 0; J < dim; ++J)
                    k += grad[i][J] * (A_i[J][data.component[j]] * grad[j]);
                  cell_matrix(i, j) += k * JxW;
                }
            }
        }
      constraints.distribute_local_to_global(
        cell_matrix, cell_rhs, data.dofs, matrix, rhs, true);
    });
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    return true;
  }

  template <int dim>
  EnergyEvaluation
  GenericAssembler<dim>::stored_energy(const VectorType &u,
                                       const bool        with_energy) const
  {
    double   energy = 0.;
    double   min_J  = std::numeric_limits<double>::infinity();
    RoundOff round_off(material);
    for_each_cell(u, [&](CellData &data) {
      for (unsigned int q = 0; q < data.F.size(); ++q)
        {
          min_J = std::min(min_J, static_cast<double>(determinant(data.F[q])));
          if (!with_energy)
            continue;
          const double JxW = data.values.JxW(q);
          const double psi = materials(data.cell, q).energy_density(data.F[q]);
          energy += psi * JxW;
          round_off.add_energy(psi, data.F[q], JxW);
        }
    });
    return reduce_energy_evaluation(min_J,
                                    with_energy,
                                    energy,
                                    round_off.local_energy_magnitude(),
                                    dof_handler.get_communicator());
  }

  template <int dim>
  std::vector<double>
  GenericAssembler<dim>::region_energies(const VectorType &u) const
  {
    std::vector<double> energy(material.n_regions(), 0.);
    for_each_cell(u, [&](CellData &data) {
      for (unsigned int q = 0; q < data.F.size(); ++q)
        energy[material.region(data.cell)] +=
          materials(data.cell, q).energy_density(data.F[q]) *
          data.values.JxW(q);
    });
    return summed_over_ranks(energy, dof_handler.get_communicator());
  }

  template <int dim>
  void
  GenericAssembler<dim>::accept_step(const VectorType &u)
  {
    if (materials.has_history())
      for_each_cell(u, [&](CellData &data) {
        for (unsigned int q = 0; q < data.F.size(); ++q)
          materials.accept_step(data.cell, q, data.F[q]);
      });
  }

  template class GenericAssembler<2>;
  template class GenericAssembler<3>;
} // namespace hyperelastic
