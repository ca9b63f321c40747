// MixedAssembler::constant_forces(): the derivatives of the mixed residual
// [R_u; R_p] with respect to the model's constants at a state, for the
// adjoint of a fit through a scene (Problem::reaction_sensitivities).
//
// The isochoric model of the split is the model's own class with kappa = 0,
// so its ConstantDerivatives D_k(F) are dP_iso/dc_k plus what the bulk
// modulus contributes through the constant: dkappa/dc_k V(F), with
// V = (J^2 - 1)/2 F^-T the stress of U(J) = kappa/4 (J^2 - 1 - 2 ln J) per
// unit kappa (dkappa/dc_k = 1 for an entry 'Bulk modulus'; 2/3 and 1 for
// the Lame pair, kappa = lambda + 2 mu / 3). Then
//   dR_u/dc_k = int (D_k - dkappa/dc_k V) : grad du dV,
//   dR_p/dc_k = -int dJ*/dkappa dkappa/dc_k dp dV      (R_p: J - J*(p)),
//   P1/P1 stabilized: + dmu/dc_k / mu^2 int (p - pbar) dp dV,
// mu the small-strain shear modulus of the stabilisation, whose derivative
// is taken from D_k in a simple shear of +-1e-4 (central difference: the
// shear stress is odd in the shear, so the error is of order 1e-8 of it),
// after checking that the model's own shear stress gives mu there.
// MINI: the bubble b(u_r, c) solves R_b = 0 on its cell, so the condensed
// residual's derivative is dr_r/dc = dR_r/dc - K_rb K_bb^-1 dR_b/dc.
#include <deal.II/base/mpi.h>

#include <hyperelastic/assembly/mixed_assembler.h>
#include <hyperelastic/materials/constant_derivatives.h>
#include <hyperelastic/materials/material.h>

#include "mixed_cell.h"

#include <cmath>
#include <string>

namespace hyperelastic
{
  namespace
  {
    /// dkappa/dc_k in the order of @p names: the Lame pair (kappa = lambda
    /// + 2 mu / 3) or a constant named 'Bulk modulus'; empty otherwise.
    std::vector<double>
    bulk_modulus_derivatives(const std::vector<std::string> &names)
    {
      if (names == std::vector<std::string>{"mu", "lambda"})
        return {2. / 3., 1.};
      std::vector<double> d(names.size(), 0.);
      bool                found = false;
      for (unsigned int k = 0; k < names.size(); ++k)
        if (names[k] == "Bulk modulus")
          {
            d[k]  = 1.;
            found = true;
          }
      return found ? d : std::vector<double>{};
    }

    template <int dim>
    Tensor<2, dim>
    simple_shear(const double gamma)
    {
      Tensor<2, dim> F;
      for (unsigned int i = 0; i < dim; ++i)
        F[i][i] = 1.;
      F[0][1] = gamma;
      return F;
    }

    /// dmu/dc_k of the small-strain shear modulus from the derivatives in a
    /// small simple shear; empty if @p iso's own shear stress there does
    /// not give @p mu (an anisotropic model, fibres in the shear plane).
    template <int dim>
    std::vector<double>
    shear_modulus_derivatives(const Material<dim>            &iso,
                              const ConstantDerivatives<dim> &derivatives,
                              const double                    mu)
    {
      constexpr double gamma = 1e-4;
      const auto       plus  = simple_shear<dim>(gamma),
                 minus       = simple_shear<dim>(-gamma);
      const double measured  = (iso.first_piola_kirchhoff(plus)[0][1] -
                               iso.first_piola_kirchhoff(minus)[0][1]) /
                              (2. * gamma);
      if (!(std::abs(measured - mu) <= 1e-6 * std::abs(mu)))
        return {};
      const auto          D_plus  = derivatives.stress_derivatives(plus);
      const auto          D_minus = derivatives.stress_derivatives(minus);
      std::vector<double> d;
      for (unsigned int k = 0; k < D_plus.size(); ++k)
        d.push_back((D_plus[k][0][1] - D_minus[k][0][1]) / (2. * gamma));
      return d;
    }

    /// MINI: dr_r/dc = dR_r/dc - K_rb K_bb^-1 dR_b/dc in each of
    /// @p cell_force (rows: the cell's unknowns, then its bubble's), with
    /// K_rb and K_bb from the cell's matrix (@p data of the mixed loops).
    template <typename CellData>
    void
    condense_bubble(const CellData              &data,
                    std::vector<Vector<double>> &cell_force)
    {
      const unsigned int n = data.n, nb = data.n_bubble;
      FullMatrix<double> K_bb(nb, nb), K_bb_inverse(nb, nb);
      for (unsigned int a = 0; a < nb; ++a)
        for (unsigned int b = 0; b < nb; ++b)
          K_bb(a, b) = data.matrix(n + a, n + b);
      K_bb_inverse.invert(K_bb);
      for (auto &force : cell_force)
        for (unsigned int a = 0; a < nb; ++a)
          {
            double S = 0.;
            for (unsigned int b = 0; b < nb; ++b)
              S += K_bb_inverse(a, b) * force[n + b];
            for (unsigned int i = 0; i < n; ++i)
              force[i] -= data.matrix(i, n + a) * S;
          }
    }
  } // namespace

  template <int dim>
  std::vector<VectorType>
  MixedAssembler<dim>::constant_forces(const VectorType &u,
                                       const VectorType &like) const
  {
    const bool              mini       = element == MixedElement::mini;
    const bool              stabilized = element == MixedElement::stabilized;
    std::vector<VectorType> forces;
    std::vector<Vector<double>> cell_force;
    Vector<double>              rows(dof_handler.get_fe().dofs_per_cell);
    bool                        available = true;
    for_each_cell(u, mini, TangentProjection::none, [&](CellData &data) {
      if (!available || !(data.min_J > 0.))
        {
          available = false;
          return;
        }
      const unsigned int  r       = material.region(data.cell_index);
      const auto         &vol     = split[r]->volumetric;
      const unsigned int  n       = data.n;
      const unsigned int  n_total = n + data.n_bubble;
      double              volume = 0., p_mean = 0.;
      std::vector<double> p_q(quadrature.size(), 0.);
      std::vector<double> dkappa, dmu;
      for (unsigned int q = 0; q < quadrature.size() && available; ++q)
        {
          const Material<dim> &iso = isochoric(data.cell_index, q);
          const auto          *derivatives =
            dynamic_cast<const ConstantDerivatives<dim> *>(&iso);
          if (derivatives && q == 0)
            {
              dkappa = bulk_modulus_derivatives(derivatives->constant_names());
              if (stabilized && !dkappa.empty())
                dmu = shear_modulus_derivatives(iso,
                                                *derivatives,
                                                1. / inverse_shear_modulus[r]);
            }
          if (!derivatives || dkappa.empty() || (stabilized && dmu.empty()))
            {
              available = false;
              break;
            }
          if (cell_force.size() != dkappa.size())
            cell_force.assign(dkappa.size(), Vector<double>(n_total));
          if (q == 0)
            for (auto &force : cell_force)
              force = 0.;
          const auto          &grad = data.grad[q];
          const auto          &psi  = data.psi[q];
          const Tensor<2, dim> F    = data.deformation_gradient(q);
          const double         J    = determinant(F);
          const Tensor<2, dim> V    = 0.5 * (J * J - 1.) * transpose(invert(F));
          for (unsigned int i = 0; i < n; ++i)
            if (data.component[i] == dim)
              p_q[q] += data.x[i] * psi[i];
          const double JxW = data.values.JxW(q);
          volume += JxW;
          p_mean += p_q[q] * JxW;
          const double dJ_dkappa = vol.conjugate_J_bulk_derivative(p_q[q]);
          const std::vector<Tensor<2, dim>> D =
            derivatives->stress_derivatives(F);
          for (unsigned int k = 0; k < D.size(); ++k)
            {
              const Tensor<2, dim> dP = D[k] - dkappa[k] * V;
              for (unsigned int i = 0; i < n_total; ++i)
                {
                  const unsigned int ci = data.component[i];
                  cell_force[k][i] +=
                    (i < n && ci == dim ? -dJ_dkappa * dkappa[k] * psi[i]
                                        : dP[ci] * grad[i]) *
                    JxW;
                }
            }
        }
      if (!available)
        return;
      if (stabilized)
        {
          // -1/mu int (p - pbar) q: d/dc_k = dmu/dc_k / mu^2 int ...
          const double inverse = inverse_shear_modulus[r];
          p_mean /= volume;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            for (unsigned int i = 0; i < n; ++i)
              if (data.component[i] == dim)
                for (unsigned int k = 0; k < cell_force.size(); ++k)
                  cell_force[k][i] += dmu[k] * inverse * inverse *
                                      (p_q[q] - p_mean) * data.psi[q][i] *
                                      data.values.JxW(q);
        }
      if (mini)
        condense_bubble(data, cell_force);
      if (forces.empty())
        {
          forces.assign(cell_force.size(), like);
          for (VectorType &force : forces)
            force = 0.;
        }
      for (unsigned int k = 0; k < cell_force.size(); ++k)
        {
          for (unsigned int i = 0; i < n; ++i)
            rows[i] = cell_force[k][i];
          forces[k].add(data.dofs, rows);
        }
    });
    return gathered_constant_forces(std::move(forces),
                                    available,
                                    like,
                                    dof_handler.get_communicator());
  }

  template std::vector<VectorType>
  MixedAssembler<2>::constant_forces(const VectorType &,
                                     const VectorType &) const;
  template std::vector<VectorType>
  MixedAssembler<3>::constant_forces(const VectorType &,
                                     const VectorType &) const;
} // namespace hyperelastic
