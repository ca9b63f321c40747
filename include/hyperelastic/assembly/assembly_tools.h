// Pieces every assembly loop shares: the round-off estimates of forces and
// energies (and the body's size they scale with), the collective totals of
// an energy pass, the finiteness check of a stress and tangent, and the
// text of a failure on one cell. The vector
// and matrix types are in base/linear_algebra.h.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>

#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/materials/material.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// The total potential energy of a state and its smallest J.
  struct EnergyEvaluation
  {
    double energy = 0.;
    /// Round-off level of the energy (from the sizes of the summed terms):
    /// energy differences below it are not meaningful.
    double noise = 0.;
    double min_J = 0.;
  };

  /// The diagonal of the bounding box of the reference mesh (its locally
  /// owned cells' vertices, over all ranks). Collective.
  template <int dim>
  double
  reference_diameter(const dealii::DoFHandler<dim> &dof_handler)
  {
    dealii::Point<dim> low, high;
    for (unsigned int d = 0; d < dim; ++d)
      {
        low[d]  = std::numeric_limits<double>::max();
        high[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              low[d]  = std::min(low[d], cell->vertex(v)[d]);
              high[d] = std::max(high[d], cell->vertex(v)[d]);
            }
    const MPI_Comm comm     = dof_handler.get_communicator();
    double         squared = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double side = dealii::Utilities::MPI::max(high[d], comm) -
                            dealii::Utilities::MPI::min(low[d], comm);
        squared += side * side;
      }
    return std::sqrt(squared);
  }

  /// @p values summed entry by entry over the ranks of @p comm
  /// (collective).
  inline std::vector<double>
  summed_over_ranks(std::vector<double> values, const MPI_Comm comm)
  {
    MPI_Allreduce(MPI_IN_PLACE,
                  values.data(),
                  static_cast<int>(values.size()),
                  MPI_DOUBLE,
                  MPI_SUM,
                  comm);
    return values;
  }

  /// Round-off bookkeeping of one assembly pass. Stress entries are computed
  /// from terms of the size of the moduli (lambda ln J cancels mu F at small
  /// strain), so each carries an error of about eps (|mu| + |lambda|)
  /// (1 + |F|^2) whatever its value; cell contributions add up randomly for
  /// forces (squares summed) and in magnitude for energies.
  class RoundOff
  {
  public:
    template <int dim>
    explicit RoundOff(const Material<dim> &material)
        : RoundOff(material.small_strain_moduli())
    {
    }

    /// With regions: the moduli of the stiffest (the largest noise).
    template <int dim>
    explicit RoundOff(const MaterialRegions<dim> &materials)
        : RoundOff(materials.stiffest_moduli())
    {
    }

    explicit RoundOff(const LameParameters &moduli)
        : modulus_scale(std::abs(moduli.mu) + std::abs(moduli.lambda))
    {
    }

    /// A cell's force contribution at one quadrature point: F there, the
    /// sum of the norms of the shape gradients, the weight JxW.
    template <int dim>
    void
    add_force(const dealii::Tensor<2, dim> &F,
              const double                  gradient_sum,
              const double                  JxW)
    {
      cell_force += modulus_scale * (1. + F.norm_square()) * gradient_sum * JxW;
    }

    /// Closes the force contributions of one cell.
    void
    end_cell()
    {
      force_squared += cell_force * cell_force;
      cell_force = 0.;
    }

    /// An energy density psi at F with weight JxW.
    template <int dim>
    void
    add_energy(const double                  psi,
               const dealii::Tensor<2, dim> &F,
               const double                  JxW)
    {
      energy_magnitude +=
        (std::abs(psi) + modulus_scale * (1. + F.norm_square())) * JxW;
    }

    /// A term added to the energy as it is (the work of a load).
    void
    add_energy_term(const double value)
    {
      energy_magnitude += std::abs(value);
    }

    /// Round-off of the l2 norm of the assembled forces (collective).
    double
    force_noise(const MPI_Comm comm) const
    {
      return std::numeric_limits<double>::epsilon() *
             std::sqrt(dealii::Utilities::MPI::sum(force_squared, comm));
    }

    /// This rank's sum of the magnitudes behind the energy (summed over
    /// the ranks by reduce_energy_evaluation).
    double
    local_energy_magnitude() const
    {
      return energy_magnitude;
    }

  private:
    double modulus_scale;
    double cell_force       = 0.;
    double force_squared    = 0.;
    double energy_magnitude = 0.;
  };

  /// The totals of a rank's energy pass over all ranks (collective): the
  /// smallest J and, if @p with_energy, the energy with its round-off level
  /// 1e-13 times the summed magnitudes of its terms (@p magnitude: this
  /// rank's sum).
  inline EnergyEvaluation
  reduce_energy_evaluation(const double   min_J,
                           const bool     with_energy,
                           const double   energy,
                           const double   magnitude,
                           const MPI_Comm comm)
  {
    constexpr double round_off = 1e-13;
    EnergyEvaluation result;
    result.min_J = dealii::Utilities::MPI::min(min_J, comm);
    if (with_energy)
      {
        result.energy = dealii::Utilities::MPI::sum(energy, comm);
        result.noise = round_off * dealii::Utilities::MPI::sum(magnitude, comm);
      }
    return result;
  }

  /// False if any entry of @p P or @p A is not finite (checked before
  /// anything is written: Trilinos would carry NaN into the solver).
  template <int dim>
  bool
  stress_and_tangent_finite(const dealii::Tensor<2, dim> &P,
                            const StressTangent<dim>     &A)
  {
    // A sum is non-finite if any term is.
    double sum = 0.;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int J = 0; J < dim; ++J)
        {
          sum += P[i][J];
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              sum += A[i][J][k][L];
        }
    return std::isfinite(sum);
  }

  /// The message for a non-finite stress or tangent.
  inline const char *
  non_finite_stress_message()
  {
    return "non-finite stress or tangent (the model may be undefined for "
           "this element's deformation, e.g. J <= 0)";
  }

  /// "cell N at (x y z): what", the text of a failure on one cell.
  template <int dim>
  std::string
  cell_failure_text(const unsigned int        active_cell_index,
                    const dealii::Point<dim> &center,
                    const std::string        &what)
  {
    std::ostringstream s;
    s << "cell " << active_cell_index << " at (" << center << "): " << what;
    return s.str();
  }

} // namespace hyperelastic
