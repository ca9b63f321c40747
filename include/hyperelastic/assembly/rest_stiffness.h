// The linear elastic stiffness K0 at rest of a displacement field, with
// every coupling of the dofs (as Problem's tangent) and no constraints: the
// matrix stiffness warping rotates and stiffness-proportional damping uses;
// and K0 condensed with constraints (the automatic tangent's softened
// predictor).
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <hyperelastic/assembly/assembly_tools.h>
#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/materials/material.h>

namespace hyperelastic
{
  /// K0 of linear elasticity with the small-strain moduli @p moduli into
  /// @p stiffness (reinitialised on the owned rows; collective).
  template <int dim>
  void
  assemble_rest_stiffness(const dealii::DoFHandler<dim> &dof_handler,
                          const dealii::Mapping<dim>    &mapping,
                          const LameParameters          &moduli,
                          MatrixType                    &stiffness);

  /// K0 of linear elasticity with each cell's small-strain moduli (its
  /// region's model's, @p materials) into @p stiffness (reinitialised on
  /// the owned rows; collective). One region: the same matrix as with its
  /// moduli above.
  template <int dim>
  void
  assemble_rest_stiffness(const dealii::DoFHandler<dim> &dof_handler,
                          const dealii::Mapping<dim>    &mapping,
                          const MaterialRegions<dim>    &materials,
                          MatrixType                    &stiffness);

  /// K0 condensed with @p constraints into @p matrix (whose sparsity is
  /// set) and the right-hand side @p rhs of their inhomogeneities: the
  /// solution, distributed, meets the constraints and is K0-harmonic on
  /// the free dofs. Collective.
  template <int dim>
  void
  assemble_rest_system(const dealii::DoFHandler<dim>           &dof_handler,
                       const dealii::Mapping<dim>              &mapping,
                       const LameParameters                    &moduli,
                       const dealii::AffineConstraints<double> &constraints,
                       MatrixType                              &matrix,
                       VectorType                              &rhs);
} // namespace hyperelastic
