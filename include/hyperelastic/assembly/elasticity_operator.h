// The discrete hyperelastic problem: for a displacement field u it computes the
// total potential energy, the internal and external nodal forces and the
// tangent stiffness. The internal force of node a is the integral of
// P(F) grad N_a over the reference cell (for P1: |T| P Dm^-T, the negative of
// the nodal force acting on the node); the tangent is its exact derivative
// through dP/dF. All loads are dead loads referred to the reference
// configuration.
#pragma once

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/assembly/p1_assembler.h>

#include <limits>
#include <memory>

namespace hyperelastic
{
  using VectorType = dealii::TrilinosWrappers::MPI::Vector;
  using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

  /// Cell-wise derived quantities of a displacement field, for output. For
  /// P1 they are exact; for higher degrees they are cell averages.
  struct CellFields
  {
    dealii::Vector<double> J;
    dealii::Vector<double> energy_density;
    dealii::Vector<double> von_mises;
    /// Cauchy stress components xx, yy, zz, xy, xz, yz (zz from plane strain
    /// in 2D; xz and yz are zero there).
    std::array<dealii::Vector<double>, 6> cauchy;
  };

  /// The total potential energy of a state and its smallest J.
  struct EnergyEvaluation
  {
    double energy = 0.;
    /// Round-off level of the energy (from the sizes of the summed terms):
    /// energy differences below it are not meaningful.
    double noise = 0.;
    double min_J = 0.;
  };

  template <int dim>
  class ElasticityOperator
  {
  public:
    /// With @p fast_p1 (and a P1 element) forces, tangent and energy come
    /// from the P1Assembler kernel; otherwise, and for P2, from the generic
    /// FEValues loops (the reference the kernel is tested against).
    ElasticityOperator(const dealii::DoFHandler<dim> &dof_handler,
                       const dealii::Mapping<dim>    &mapping,
                       const Material<dim>           &material,
                       const BoundaryConditions<dim> &boundary_conditions,
                       bool                           fast_p1 = true);

    /// Whether the P1 kernel is in use.
    bool
    uses_p1_kernel() const
    {
      return p1 != nullptr;
    }

    /// Internal forces f_int(u) and external forces f_ext(t), unconstrained
    /// (both compressed, owned entries only). u must have ghost entries.
    /// Returns an estimate of the round-off level of the l2 norm of f_int:
    /// residuals below it cannot be resolved.
    double
    assemble_forces(const VectorType &u,
                    const double      t,
                    VectorType       &internal,
                    VectorType       &external) const;

    /// Tangent K = d f_int / du and right-hand side -(f_int - f_ext),
    /// condensed with @p constraints (whose inhomogeneities are imposed).
    /// With @p project_tangent, dP/dF at every quadrature point is projected
    /// to positive semi-definite first (projected Newton), so K is too.
    void
    assemble_system(const VectorType                        &u,
                    const double                             t,
                    const dealii::AffineConstraints<double> &constraints,
                    MatrixType                              &matrix,
                    VectorType                              &rhs,
                    bool project_tangent = false) const;

    /// Total potential energy (stored energy minus the work of the loads)
    /// if @p with_energy, and the smallest J at the quadrature points
    /// (collective). +infinity where the model is undefined.
    EnergyEvaluation
    evaluate(const VectorType &u, const double t, bool with_energy) const;

    /// Total potential energy alone (collective).
    double
    total_energy(const VectorType &u, const double t) const
    {
      return evaluate(u, t, true).energy;
    }

    /// J, energy density and Cauchy stress per locally owned cell; also the
    /// smallest J over the whole mesh (collective).
    CellFields
    cell_fields(const VectorType &u, double &min_J) const;

  private:
    /// The external (dead-load) forces at load factor t, owned entries;
    /// computed once per load factor (collective).
    const VectorType &
    external_forces(double t) const;

    /// Throws InputError on every rank if a load was not finite on any
    /// (@p bad: 0 none, 1 the body force, 2 + k traction k).
    void
    throw_if_non_finite_load(int bad) const;

    template <typename CellWorker>
    void
    for_each_cell(const VectorType &u, CellWorker &&worker) const;

    const dealii::DoFHandler<dim> &dof_handler;
    const dealii::Mapping<dim>    &mapping;
    const Material<dim>           &material;
    const BoundaryConditions<dim> &boundary_conditions;
    /// Quadrature for the stress terms: exact for P1 (one point) and for the
    /// linear-elastic stiffness of P2.
    const dealii::Quadrature<dim> stress_quadrature;
    /// Quadrature for body forces and tractions (one degree higher).
    const dealii::Quadrature<dim>     load_quadrature;
    const dealii::Quadrature<dim - 1> face_quadrature;

    std::unique_ptr<P1Assembler<dim>> p1;
    mutable VectorType                external_cache;
    mutable double external_cache_time = std::numeric_limits<double>::quiet_NaN();
  };
} // namespace hyperelastic
