// A capability of a material part (an Assembler), opt-in like the terms'
// capabilities: the derivatives of its internal forces with respect to the
// model's constants at a state, d f_int / dc_k, in the order of the model's
// ConstantDerivatives (materials/constant_derivatives.h). The adjoint of a
// fit through a scene (Problem::reaction_sensitivities) uses them. The
// generic displacement assembler (P1, P2) and the mixed one (MINI with its
// bubble condensed, P1/P1 stabilized, Taylor-Hood) implement it.
#pragma once

#include <deal.II/base/mpi.h>

#include <hyperelastic/base/linear_algebra.h>

#include <vector>

namespace hyperelastic
{
  template <int dim>
  class ConstantForces
  {
  public:
    virtual ~ConstantForces() = default;

    /// d f_int / dc_k at @p u (ghosted) for each constant k, on the owned
    /// rows, each vector laid out like @p like; empty if a point's model
    /// does not give its derivatives (the same answer on every rank).
    /// Collective.
    virtual std::vector<VectorType>
    constant_forces(const VectorType &u, const VectorType &like) const = 0;
  };

  /// The collective end of a constant_forces(): @p forces as this rank
  /// added them (empty if it had no cells), compressed; every rank agrees
  /// on their count and returns none if a rank's model lacked them
  /// (@p available false). Collective.
  inline std::vector<VectorType>
  gathered_constant_forces(std::vector<VectorType> forces,
                           const bool              available,
                           const VectorType       &like,
                           const MPI_Comm          comm)
  {
    using dealii::Utilities::MPI::max;
    using dealii::Utilities::MPI::min;
    const unsigned int count =
      max(available ? static_cast<unsigned int>(forces.size()) : 0u, comm);
    if (min(available ? 1u : 0u, comm) == 0 || count == 0)
      return {};
    if (forces.empty())
      {
        forces.assign(count, like);
        for (VectorType &force : forces)
          force = 0.;
      }
    for (VectorType &force : forces)
      force.compress(dealii::VectorOperation::add);
    return forces;
  }
} // namespace hyperelastic
