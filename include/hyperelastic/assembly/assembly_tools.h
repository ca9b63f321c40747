// Pieces every assembly loop shares: the vector and matrix types, the
// round-off estimates of forces and energies, the finiteness check of a
// stress and tangent, and the collective report of a failure on one cell.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hyperelastic/materials/material.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace hyperelastic
{
  using VectorType = dealii::TrilinosWrappers::MPI::Vector;
  using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

  /// The total potential energy of a state and its smallest J.
  struct EnergyEvaluation
  {
    double energy = 0.;
    /// Round-off level of the energy (from the sizes of the summed terms):
    /// energy differences below it are not meaningful.
    double noise = 0.;
    double min_J = 0.;
  };

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
        : modulus_scale(std::abs(material.small_strain_moduli().mu) +
                        std::abs(material.small_strain_moduli().lambda))
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

    /// Round-off of the assembled energy (collective).
    double
    energy_noise(const MPI_Comm comm) const
    {
      constexpr double round_off = 1e-13;
      return round_off * dealii::Utilities::MPI::sum(energy_magnitude, comm);
    }

  private:
    double modulus_scale;
    double cell_force       = 0.;
    double force_squared    = 0.;
    double energy_magnitude = 0.;
  };

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

  /// Condenses one matrix row with Dirichlet @p constraints: removes from
  /// @p columns and @p values the constrained columns and returns the sum of
  /// their values times the prescribed values (what moves to the right-hand
  /// side, with a minus sign). Throws for constraints with entries.
  inline double
  condense_row(const dealii::AffineConstraints<double>      &constraints,
               std::vector<dealii::types::global_dof_index> &columns,
               std::vector<double>                          &values)
  {
    double       moved = 0.;
    unsigned int kept  = 0;
    for (unsigned int j = 0; j < columns.size(); ++j)
      {
        if (!constraints.is_constrained(columns[j]))
          {
            columns[kept]  = columns[j];
            values[kept++] = values[j];
            continue;
          }
        const auto *entries = constraints.get_constraint_entries(columns[j]);
        if (entries != nullptr && !entries->empty())
          throw std::logic_error(
            "condense_row: only Dirichlet constraints are supported");
        moved += values[j] * constraints.get_inhomogeneity(columns[j]);
      }
    columns.resize(kept);
    values.resize(kept);
    return moved;
  }

  /// Adds @p cell_matrix (rows and columns @p dofs) to the rows of @p matrix
  /// whose dofs are not constrained, moving the columns of Dirichlet-
  /// constrained dofs to @p rhs with their prescribed values, as
  /// AffineConstraints::distribute_local_to_global would, except that
  /// constrained rows are left alone (they already read d du_r = d g_r).
  /// The caller compresses both.
  inline void
  add_condensed(const dealii::FullMatrix<double>                   &cell_matrix,
                const std::vector<dealii::types::global_dof_index> &dofs,
                const dealii::AffineConstraints<double>            &constraints,
                MatrixType                                         &matrix,
                VectorType                                         &rhs)
  {
    std::vector<dealii::types::global_dof_index> columns;
    std::vector<double>                          values;
    for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        if (constraints.is_constrained(dofs[i]))
          continue;
        columns = dofs;
        values.assign(&cell_matrix(i, 0), &cell_matrix(i, 0) + dofs.size());
        const double moved = condense_row(constraints, columns, values);
        matrix.add(dofs[i], columns.size(), columns.data(), values.data());
        if (moved != 0.)
          rhs.add(std::vector<dealii::types::global_dof_index>{dofs[i]},
                  std::vector<double>{-moved});
      }
  }

  /// u . v over the owned entries (u with ghost entries, v without; not
  /// summed over ranks).
  inline double
  local_owned_dot(const VectorType &u_ghosted, const VectorType &v)
  {
    double sum = 0.;
    for (const auto i : v.locally_owned_elements())
      sum += u_ghosted(i) * v(i);
    return sum;
  }
} // namespace hyperelastic
