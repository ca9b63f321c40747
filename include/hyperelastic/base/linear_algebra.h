// The distributed vector and matrix types every concern shares, and the
// small operations on them that several concerns need: a dot product over
// the owned entries and the row-wise Dirichlet condensation of a matrix
// contribution (constrained rows left alone, constrained columns moved to
// the right-hand side with their prescribed values), and the transpose of a
// distributed matrix (an adjoint solve).
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <limits>
#include <stdexcept>
#include <vector>

namespace hyperelastic
{
  using VectorType = dealii::TrilinosWrappers::MPI::Vector;
  using MatrixType = dealii::TrilinosWrappers::SparseMatrix;

  /// The value Dirichlet @p constraints prescribe for @p dof, NaN where it
  /// is free. Throws for a constraint with entries.
  inline double
  prescribed_value(const dealii::AffineConstraints<double> &constraints,
                   const dealii::types::global_dof_index    dof)
  {
    if (!constraints.is_constrained(dof))
      return std::numeric_limits<double>::quiet_NaN();
    const auto *entries = constraints.get_constraint_entries(dof);
    if (entries != nullptr && !entries->empty())
      throw std::logic_error("only Dirichlet constraints are supported");
    return constraints.get_inhomogeneity(dof);
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
        moved += values[j] * prescribed_value(constraints, columns[j]);
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

  /// @p transposed = A^T with A's row partition (A square, its rows and
  /// columns partitioned alike). Collective.
  void
  transpose(const MatrixType &A, MatrixType &transposed);

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
