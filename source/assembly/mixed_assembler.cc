// The FEValues loops of the displacement-pressure formulation, with the MINI
// bubble solved and condensed per cell.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/assembly/cell_loop.h>
#include <hyperelastic/assembly/material_point.h>
#include <hyperelastic/assembly/mixed_assembler.h>
#include <hyperelastic/base/error_handling.h>

#include "mixed_cell.h"

#include <cmath>
#include <limits>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Quadrature exact for the products the element integrates at F = I
    /// (MINI: bubble gradients squared).
    unsigned int
    quadrature_points_1d(const MixedElement element)
    {
      return element == MixedElement::stabilized ? 2 : 3;
    }

    /// The volumetric-isochoric split of each region's model (null where a
    /// model has none).
    template <int dim>
    std::vector<std::unique_ptr<VolumetricSplit<dim>>>
    region_splits(const MaterialRegions<dim> &material)
    {
      std::vector<std::unique_ptr<VolumetricSplit<dim>>> splits;
      for (unsigned int r = 0; r < material.n_regions(); ++r)
        splits.push_back(material.model(r).volumetric_split());
      return splits;
    }

    /// The regions with their models' isochoric parts.
    template <int dim>
    MaterialRegions<dim>
    isochoric_parts(
      const MaterialRegions<dim>                               &material,
      const std::vector<std::unique_ptr<VolumetricSplit<dim>>> &splits)
    {
      std::vector<const Material<dim> *> parts;
      for (unsigned int r = 0; r < splits.size(); ++r)
        {
          AssertThrow(splits[r] != nullptr,
                      ExcMessage("the mixed formulation needs a model with a "
                                 "volumetric-isochoric split"));
          parts.push_back(splits[r]->isochoric.get());
        }
      return material.with_models(parts);
    }
  } // namespace

  template <int dim>
  MixedAssembler<dim>::MixedAssembler(const DoFHandler<dim>      &dof_handler,
                                      const Mapping<dim>         &mapping,
                                      const MaterialRegions<dim> &material,
                                      const MixedElement          element)
      : dof_handler(dof_handler)
      , mapping(mapping)
      , material(material)
      , split(region_splits(material))
      , element(element)
      , quadrature(QGaussSimplex<dim>(quadrature_points_1d(element)))
      , isochoric(isochoric_parts(material, split),
                  dof_handler,
                  mapping,
                  quadrature)
  {
    for (unsigned int r = 0; r < material.n_regions(); ++r)
      inverse_shear_modulus.push_back(
        1. / material.model(r).small_strain_moduli().mu);
    AssertThrow(dof_handler.get_fe().n_components() == dim + 1,
                ExcMessage("the mixed formulation needs dim + 1 components"));
  }

  template <int dim>
  MixedAssembler<dim>::~MixedAssembler() = default;

  template <int dim>
  void
  MixedAssembler<dim>::evaluate_cell(
    CellData               &data,
    const CellOutput        output,
    const TangentProjection project_tangent) const
  {
    const bool with_matrix = output != CellOutput::residual;
    // The bubble's block: its rows and columns only, no energy.
    const bool         bubble_only = output == CellOutput::bubble_block;
    const unsigned int first       = bubble_only ? data.n : 0;
    const unsigned int n_total     = data.n + data.n_bubble;
    const auto &vol = split[material.region(data.cell_index)]->volumetric;
    data.residual   = 0.;
    if (with_matrix)
      data.matrix = 0.;
    data.energy    = 0.;
    data.min_J     = std::numeric_limits<double>::infinity();
    data.force_sum = 0.;

    Tensor<2, dim>      P;
    StressTangent<dim>  A;
    double              volume = 0., p_mean = 0.;
    std::vector<double> p_q(quadrature.size());
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const auto          &grad = data.grad[q];
        const auto          &psi  = data.psi[q];
        const Tensor<2, dim> F    = data.deformation_gradient(q);
        double               p    = 0.;
        for (unsigned int i = 0; i < data.n; ++i)
          if (data.component[i] == dim)
            p += data.x[i] * psi[i];
        p_q[q]           = p;
        const double JxW = data.values.JxW(q);
        volume += JxW;
        p_mean += p * JxW;

        const Material<dim> &iso = isochoric(data.cell_index, q);
        const double         J   = determinant(F);
        data.min_J               = std::min(data.min_J, J);
        if (!(J > 0.))
          {
            // Outside the model's domain: no finite residual.
            for (auto &r : data.residual)
              r = std::numeric_limits<double>::quiet_NaN();
            data.energy = std::numeric_limits<double>::infinity();
            return;
          }
        const Tensor<2, dim> JG = J * transpose(invert(F));
        if (with_matrix)
          {
            if (!stress_and_tangent_at(iso, F, project_tangent, P, A))
              throw std::domain_error(non_finite_stress_message());
            // p d(J G)/dF = p/J (JG (x) JG - JG [x] JG).
            const double pJ = p / J;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int I = 0; I < dim; ++I)
                for (unsigned int k = 0; k < dim; ++k)
                  for (unsigned int L = 0; L < dim; ++L)
                    A[i][I][k][L] +=
                      pJ * (JG[i][I] * JG[k][L] - JG[i][L] * JG[k][I]);
          }
        else
          P = iso.first_piola_kirchhoff(F);
        if (!bubble_only)
          data.energy +=
            (iso.energy_density(F) + p * (J - 1.) - vol.conjugate(p)) * JxW;
        P += p * JG;

        const double volumetric_residual = J - vol.conjugate_J(p);
        const double pressure_stiffness  = -vol.conjugate_second_derivative(p);
        for (unsigned int i = first; i < n_total; ++i)
          {
            const unsigned int ci = data.component[i];
            if (i < data.n && ci == dim)
              {
                data.residual[i] += volumetric_residual * psi[i] * JxW;
                if (with_matrix)
                  for (unsigned int j = 0; j < data.n; ++j)
                    if (data.component[j] == dim)
                      data.matrix(i, j) +=
                        pressure_stiffness * psi[i] * psi[j] * JxW;
                continue;
              }
            data.residual[i] += (P[ci] * grad[i]) * JxW;
            data.force_sum += grad[i].norm() * JxW;
            if (!with_matrix)
              continue;
            const double coupling = (JG[ci] * grad[i]) * JxW;
            for (unsigned int j = first; j < n_total; ++j)
              {
                const unsigned int cj = data.component[j];
                if (j < data.n && cj == dim)
                  {
                    data.matrix(i, j) += coupling * psi[j];
                    data.matrix(j, i) += coupling * psi[j];
                    continue;
                  }
                double k = 0.;
                for (unsigned int I = 0; I < dim; ++I)
                  k += grad[i][I] * (A[ci][I][cj] * grad[j]);
                data.matrix(i, j) += k * JxW;
              }
          }
      }

    if (element == MixedElement::stabilized)
      add_stabilization(data, p_q, p_mean / volume, volume, with_matrix);
  }

  template <int dim>
  void
  MixedAssembler<dim>::add_stabilization(CellData                  &data,
                                         const std::vector<double> &p_q,
                                         const double               p_mean,
                                         const double               volume,
                                         const bool with_matrix) const
  {
    // -1/(2 mu) int (p - pbar)^2: residual -1/mu int (p - pbar) q, matrix
    // -1/mu (int psi_i psi_j - |T| psibar_i psibar_j).
    const double inverse_shear_modulus =
      this->inverse_shear_modulus[material.region(data.cell_index)];
    std::vector<double> psi_mean(data.n, 0.);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const double JxW = data.values.JxW(q);
        const double d   = p_q[q] - p_mean;
        data.energy -= 0.5 * inverse_shear_modulus * d * d * JxW;
        for (unsigned int i = 0; i < data.n; ++i)
          if (data.component[i] == dim)
            {
              data.residual[i] -=
                inverse_shear_modulus * d * data.psi[q][i] * JxW;
              psi_mean[i] += data.psi[q][i] * JxW / volume;
              if (with_matrix)
                for (unsigned int j = 0; j < data.n; ++j)
                  if (data.component[j] == dim)
                    data.matrix(i, j) -= inverse_shear_modulus *
                                         data.psi[q][i] * data.psi[q][j] * JxW;
            }
      }
    if (with_matrix)
      for (unsigned int i = 0; i < data.n; ++i)
        for (unsigned int j = 0; j < data.n; ++j)
          if (data.component[i] == dim && data.component[j] == dim)
            data.matrix(i, j) +=
              inverse_shear_modulus * volume * psi_mean[i] * psi_mean[j];
  }

  template <int dim>
  typename MixedAssembler<dim>::BubbleOutcome
  MixedAssembler<dim>::iterate_bubble(
    CellData               &data,
    const TangentProjection project_tangent) const
  {
    const unsigned int n = data.n, nb = data.n_bubble;
    FullMatrix<double> K_bb(nb, nb), K_bb_inverse(nb, nb);
    // Newton on R_b(bubble) = 0 with the cell's other unknowns fixed; the
    // bubble's equations are those of a stiff small-strain problem, so a
    // few iterations reach round-off.
    constexpr unsigned int max_iterations = 30;
    double                 step           = 0.;
    for (unsigned int it = 0; it < max_iterations; ++it)
      {
        evaluate_cell(data, CellOutput::bubble_block, project_tangent);
        if (!(data.min_J > 0.))
          return BubbleOutcome::inadmissible;
        for (unsigned int a = 0; a < nb; ++a)
          for (unsigned int b = 0; b < nb; ++b)
            K_bb(a, b) = data.matrix(n + a, n + b);
        K_bb_inverse.invert(K_bb);
        step = 0.;
        for (unsigned int a = 0; a < nb; ++a)
          {
            double d = 0.;
            for (unsigned int b = 0; b < nb; ++b)
              d -= K_bb_inverse(a, b) * data.residual[n + b];
            data.bubble[a] += d;
            step = std::max(step, std::abs(d));
          }
        if (step <= 1e-14 * data.diameter)
          return BubbleOutcome::converged;
      }
    return step <= 1e-10 * data.diameter ? BubbleOutcome::converged
                                         : BubbleOutcome::not_converged;
  }

  template <int dim>
  void
  MixedAssembler<dim>::solve_bubble(
    CellData               &data,
    const bool              with_matrix,
    const TangentProjection project_tangent) const
  {
    const unsigned int n = data.n, nb = data.n_bubble;
    const std::size_t  n_cached =
      std::size_t(dof_handler.get_triangulation().n_active_cells()) * nb;
    if (bubble_cache.size() != n_cached)
      bubble_cache.assign(n_cached, 0.);
    double *cached = bubble_cache.data() + std::size_t(data.cell_index) * nb;

    bool warm = false;
    for (unsigned int a = 0; a < nb; ++a)
      {
        data.bubble[a] = cached[a];
        warm           = warm || cached[a] != 0.;
      }
    BubbleOutcome outcome = iterate_bubble(data, project_tangent);
    if (outcome != BubbleOutcome::converged && warm)
      {
        // The last bubble was too far from this state: from zero.
        data.bubble = 0.;
        outcome     = iterate_bubble(data, project_tangent);
      }
    if (outcome == BubbleOutcome::inadmissible)
      return; // data holds the NaN residual and min_J <= 0
    if (outcome == BubbleOutcome::not_converged)
      throw std::domain_error("the cell's bubble equations did not converge");
    for (unsigned int a = 0; a < nb; ++a)
      cached[a] = data.bubble[a];

    if (!with_matrix)
      {
        // R_b is zero to round-off: the condensed residual R_r - K_rb
        // K_bb^-1 R_b is R_r.
        evaluate_cell(data, CellOutput::residual, project_tangent);
        return;
      }
    FullMatrix<double> K_bb(nb, nb), K_bb_inverse(nb, nb);
    evaluate_cell(data, CellOutput::residual_and_matrix, project_tangent);
    if (!(data.min_J > 0.))
      return;
    for (unsigned int a = 0; a < nb; ++a)
      for (unsigned int b = 0; b < nb; ++b)
        K_bb(a, b) = data.matrix(n + a, n + b);
    K_bb_inverse.invert(K_bb);
    // Condense: R* = R_r - K_rb K_bb^-1 R_b, K* = K_rr - K_rb K_bb^-1 K_br.
    std::vector<double> S_R(nb, 0.);
    for (unsigned int a = 0; a < nb; ++a)
      for (unsigned int b = 0; b < nb; ++b)
        S_R[a] += K_bb_inverse(a, b) * data.residual[n + b];
    FullMatrix<double> S_K(nb, n);
    for (unsigned int a = 0; a < nb; ++a)
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int b = 0; b < nb; ++b)
          S_K(a, j) += K_bb_inverse(a, b) * data.matrix(n + b, j);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int a = 0; a < nb; ++a)
        {
          const double K_ia = data.matrix(i, n + a);
          data.residual[i] -= K_ia * S_R[a];
          for (unsigned int j = 0; j < n; ++j)
            data.matrix(i, j) -= K_ia * S_K(a, j);
        }
  }

  template <int dim>
  double
  MixedAssembler<dim>::internal_forces(const VectorType &u,
                                       VectorType       &internal) const
  {
    internal               = 0.;
    const double   modulus = material.largest_shear_modulus();
    double         squared = 0.;
    Vector<double> cell_residual(dof_handler.get_fe().dofs_per_cell);
    for_each_cell(u, false, TangentProjection::none, [&](CellData &data) {
      for (unsigned int i = 0; i < data.n; ++i)
        cell_residual[i] = data.residual[i];
      internal.add(data.dofs, cell_residual);
      // Round-off: stress entries carry about eps (mu + |p|) each.
      double p_max = 0.;
      for (unsigned int i = 0; i < data.n; ++i)
        if (data.component[i] == dim)
          p_max = std::max(p_max, std::abs(data.x[i]));
      const double cell = (modulus + p_max) * data.force_sum;
      squared += cell * cell;
    });
    internal.compress(VectorOperation::add);
    return std::numeric_limits<double>::epsilon() *
           std::sqrt(
             Utilities::MPI::sum(squared, dof_handler.get_communicator()));
  }

  template <int dim>
  bool
  MixedAssembler<dim>::system(const VectorType                &u,
                              const AffineConstraints<double> &constraints,
                              const TangentProjection          project_tangent,
                              MatrixType                      &matrix,
                              VectorType                      &rhs) const
  {
    matrix               = 0.;
    rhs                  = 0.;
    const unsigned int n = dof_handler.get_fe().dofs_per_cell;
    FullMatrix<double> cell_matrix(n, n);
    Vector<double>     cell_rhs(n);
    for_each_cell(u, true, project_tangent, [&](CellData &data) {
      if (!(data.min_J > 0.))
        throw std::domain_error(non_finite_stress_message());
      for (unsigned int i = 0; i < n; ++i)
        {
          cell_rhs[i] = -data.residual[i];
          for (unsigned int j = 0; j < n; ++j)
            cell_matrix(i, j) = data.matrix(i, j);
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
  MixedAssembler<dim>::stored_energy(const VectorType &u,
                                     const bool        with_energy) const
  {
    double energy = 0., magnitude = 0.;
    double min_J = std::numeric_limits<double>::infinity();
    for_each_cell(u, false, TangentProjection::none, [&](CellData &data) {
      min_J = std::min(min_J, data.min_J);
      energy += data.energy;
      magnitude += std::abs(data.energy);
    });
    return reduce_energy_evaluation(
      min_J, with_energy, energy, magnitude, dof_handler.get_communicator());
  }

  template <int dim>
  std::vector<double>
  MixedAssembler<dim>::region_energies(const VectorType &u) const
  {
    std::vector<double> energy(material.n_regions(), 0.);
    for_each_cell(u, false, TangentProjection::none, [&](CellData &data) {
      energy[material.region(data.cell_index)] += data.energy;
    });
    return summed_over_ranks(energy, dof_handler.get_communicator());
  }

  template <int dim>
  void
  MixedAssembler<dim>::accept_step(const VectorType &u)
  {
    if (!isochoric.has_history())
      return;
    for_each_cell(u, false, TangentProjection::none, [&](CellData &data) {
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        isochoric.accept_step(data.cell_index, q, data.deformation_gradient(q));
    });
  }

  template class MixedAssembler<2>;
  template class MixedAssembler<3>;
} // namespace hyperelastic
