// The stiff block A_SS: rows of the stiff unknowns, columns among them
// (which ghost columns are stiff comes from their owners through the
// matrix's column map), gathered on every rank and factorized there by
// UMFPACK: it has a few hundred unknowns, and a solve then costs one
// gather of its right-hand side.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/stiff_subspace_correction.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Import.h>
#include <Epetra_Vector.h>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// Every rank's @p mine, concatenated in rank order.
    template <typename T>
    std::vector<T>
    gather_everywhere(const std::vector<T> &mine, const MPI_Comm comm)
    {
      std::vector<T> all;
      for (const std::vector<T> &part : Utilities::MPI::all_gather(comm, mine))
        all.insert(all.end(), part.begin(), part.end());
      return all;
    }

    /// The entries of A_SS in this rank's rows, in the block's numbering.
    struct Entries
    {
      std::vector<int>    rows, columns;
      std::vector<double> values;
    };

    /// The block's unknowns are numbered 0, 1, ... over the ranks in order,
    /// this rank's @p stiff from @p n_before on. Each stiff row holds its
    /// number + 1, carried to the columns that other ranks own.
    Entries
    block_entries(const MatrixType &A,
                  const IndexSet   &stiff,
                  const int         n_before)
    {
      const Epetra_CrsMatrix &M       = A.trilinos_matrix();
      const Epetra_Map       &row_map = M.RowMap();
      const Epetra_Map       &col_map = M.ColMap();
      Epetra_Vector           on_rows(row_map), on_columns(col_map);
      std::vector<int>        rows;
      rows.reserve(stiff.n_elements());
      for (const types::global_dof_index dof : stiff)
        {
          const int lid = row_map.LID(static_cast<int>(dof));
          AssertThrow(lid >= 0, ExcInternalError());
          on_rows[lid] = n_before + static_cast<int>(rows.size()) + 1;
          rows.push_back(lid);
        }
      Epetra_Import to_columns(col_map, row_map);
      on_columns.Import(on_rows, to_columns, Insert);

      Entries entries;
      for (const int lid : rows)
        {
          int     n;
          double *row_values;
          int    *row_columns;
          M.ExtractMyRowView(lid, n, row_values, row_columns);
          for (int k = 0; k < n; ++k)
            if (on_columns[row_columns[k]] != 0.)
              {
                entries.rows.push_back(static_cast<int>(on_rows[lid]) - 1);
                entries.columns.push_back(
                  static_cast<int>(on_columns[row_columns[k]]) - 1);
                entries.values.push_back(row_values[k]);
              }
        }
      return entries;
    }
  } // namespace

  void
  StiffSubspaceCorrection::initialize(const MatrixType &A,
                                      const IndexSet   &stiff_dofs)
  {
    const MPI_Comm comm = A.get_mpi_communicator();
    matrix              = &A;
    stiff               = stiff_dofs;
    counts = Utilities::MPI::all_gather(comm, int(stiff.n_elements()));
    offsets.assign(counts.size(), 0);
    for (unsigned int r = 1; r < counts.size(); ++r)
      offsets[r] = offsets[r - 1] + counts[r - 1];
    n_global = offsets.back() + counts.back();
    if (n_global == 0)
      return;
    const int n_before = offsets[Utilities::MPI::this_mpi_process(comm)];

    const Entries          mine        = block_entries(A, stiff, n_before);
    const std::vector<int> all_rows    = gather_everywhere(mine.rows, comm);
    const std::vector<int> all_columns = gather_everywhere(mine.columns, comm);
    const std::vector<double> all_values = gather_everywhere(mine.values, comm);

    DynamicSparsityPattern dsp(n_global, n_global);
    for (unsigned int k = 0; k < all_rows.size(); ++k)
      dsp.add(all_rows[k], all_columns[k]);
    block.clear();
    pattern.copy_from(dsp);
    block.reinit(pattern);
    for (unsigned int k = 0; k < all_rows.size(); ++k)
      block.add(all_rows[k], all_columns[k], all_values[k]);
    try
      {
        factorization.initialize(block);
      }
    catch (const std::exception &e)
      {
        throw ConvergenceFailure("the direct solve on the " +
                                 std::to_string(n_global) +
                                 " stiff unknowns of the preconditioner "
                                 "failed: " +
                                 exception_message(e));
      }
    block_vector.reinit(n_global);
  }

  void
  StiffSubspaceCorrection::add_correction(VectorType       &x,
                                          const VectorType &b) const
  {
    const MPI_Comm         comm = matrix->get_mpi_communicator();
    const Epetra_BlockMap &map  = b.trilinos_vector().Map();
    std::vector<double>    mine;
    mine.reserve(stiff.n_elements());
    for (const types::global_dof_index dof : stiff)
      mine.push_back(b.trilinos_vector()[0][map.LID(static_cast<int>(dof))]);
    MPI_Allgatherv(mine.data(),
                   static_cast<int>(mine.size()),
                   MPI_DOUBLE,
                   block_vector.data(),
                   counts.data(),
                   offsets.data(),
                   MPI_DOUBLE,
                   comm);
    factorization.solve(block_vector);
    unsigned int i = offsets[Utilities::MPI::this_mpi_process(comm)];
    for (const types::global_dof_index dof : stiff)
      x.trilinos_vector()[0][map.LID(static_cast<int>(dof))] +=
        block_vector[i++];
  }

  void
  StiffSubspaceCorrection::vmult(
    VectorType                                                  &z,
    const VectorType                                            &r,
    const std::function<void(VectorType &, const VectorType &)> &M) const
  {
    Assert(active(), ExcInternalError());
    if (residual.size() != r.size() ||
        residual.locally_owned_elements() != r.locally_owned_elements())
      {
        residual.reinit(r, true);
        product.reinit(r, true);
      }
    // z = S r
    z = 0.;
    add_correction(z, r);
    // z += M (r - A z)
    matrix->vmult(product, z);
    residual.equ(1., r);
    residual.add(-1., product);
    M(product, residual);
    z.add(1., product);
    // z += S (r - A z)
    matrix->vmult(product, z);
    residual.equ(1., r);
    residual.add(-1., product);
    add_correction(z, residual);
  }
} // namespace hyperelastic
