// Block lower-triangular preconditioner of the mixed saddle-point tangent.
#include <hyperelastic/solvers/saddle_point_preconditioner.h>

#include <Epetra_Map.h>
#include <algorithm>

namespace hyperelastic
{
  using namespace dealii;

  SaddlePointPreconditioner::SaddlePointPreconditioner(
    const IndexSet     &owned,
    const IndexSet     &pressure,
    std::vector<double> shear_schur,
    const MPI_Comm      comm)
      : owned(owned)
      , pressure(pressure)
      , owned_u(owned.size())
      , shear_schur(std::move(shear_schur))
      , comm(comm)
  {
    unsigned int local = 0;
    for (const auto i : owned)
      {
        if (pressure.is_element(i))
          p_rows.push_back(local);
        else
          {
            u_rows.push_back(local);
            owned_u.add_index(i);
          }
        ++local;
      }
    owned_u.compress();
    AssertThrow(this->shear_schur.size() == p_rows.size(),
                ExcMessage("one Schur entry per owned pressure row"));
    r_u.reinit(owned_u, comm);
    y_u.reinit(owned_u, comm);
    full.reinit(owned, comm);
    product.reinit(owned, comm);
  }

  void
  SaddlePointPreconditioner::extract_displacement_block(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
    this->matrix              = &matrix;
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    // The tangent's pattern never changes: after the first extraction the
    // block keeps its object and pattern and gets new values (so that an
    // AMG hierarchy built on it can be refreshed in place).
    const bool       first = block == nullptr;
    const Epetra_Map map   = owned_u.make_trilinos_map(comm, false);
    if (first)
      block = std::make_unique<Epetra_CrsMatrix>(Copy, map, A.MaxNumEntries());
    std::vector<int>    columns;
    std::vector<double> values;
    for (const unsigned int row : u_rows)
      {
        int     n;
        double *row_values;
        int    *row_columns;
        A.ExtractMyRowView(row, n, row_values, row_columns);
        columns.clear();
        values.clear();
        for (int k = 0; k < n; ++k)
          {
            const int global = A.ColMap().GID(row_columns[k]);
            if (!pressure.is_element(global))
              {
                columns.push_back(global);
                values.push_back(row_values[k]);
              }
          }
        const int global_row = A.RowMap().GID(row);
        const int error      = first ? block->InsertGlobalValues(global_row,
                                                            columns.size(),
                                                            values.data(),
                                                            columns.data())
                                     : block->ReplaceGlobalValues(global_row,
                                                             columns.size(),
                                                             values.data(),
                                                             columns.data());
        // Insert may warn (> 0) about allocation; Replace must find all.
        AssertThrow(first ? error >= 0 : error == 0,
                    ExcMessage("extracting the displacement block failed "
                               "(Epetra error " +
                               std::to_string(error) + ")"));
      }
    if (first)
      block->FillComplete(map, map);
    // S_ii = (1/mu) (M_p)_ii + C_ii with C = -(pressure block) as assembled:
    // U*''(p) M, the stabilisation, MINI's condensed bubble.
    schur_inverse.resize(p_rows.size());
    for (std::size_t k = 0; k < p_rows.size(); ++k)
      {
        int     n;
        double *row_values;
        int    *row_columns;
        A.ExtractMyRowView(p_rows[k], n, row_values, row_columns);
        const int global_row = A.RowMap().GID(p_rows[k]);
        double    C_ii       = 0.;
        for (int j = 0; j < n; ++j)
          if (A.ColMap().GID(row_columns[j]) == global_row)
            C_ii = -row_values[j];
        schur_inverse[k] = 1. / (shear_schur[k] + std::max(C_ii, 0.));
      }
  }

  std::vector<double>
  SaddlePointPreconditioner::displacement_rows(const std::vector<double> &modes,
                                               const unsigned int n_modes) const
  {
    const std::size_t   n_owned = owned.n_elements();
    std::vector<double> rows(n_modes * u_rows.size());
    for (unsigned int m = 0; m < n_modes; ++m)
      for (std::size_t k = 0; k < u_rows.size(); ++k)
        rows[m * u_rows.size() + k] = modes[m * n_owned + u_rows[k]];
    return rows;
  }

  void
  SaddlePointPreconditioner::vmult(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    const double *s  = src.trilinos_vector()[0];
    double       *ru = r_u.trilinos_vector()[0];
    double       *yu = y_u.trilinos_vector()[0];
    double       *f  = full.trilinos_vector()[0];
    const double *Bf = product.trilinos_vector()[0];
    for (std::size_t k = 0; k < u_rows.size(); ++k)
      ru[k] = s[u_rows[k]];
    amg->vmult(y_u, r_u);
    // B y_u: the pressure rows of the full matrix times (y_u, 0).
    full = 0.;
    for (std::size_t k = 0; k < u_rows.size(); ++k)
      f[u_rows[k]] = yu[k];
    matrix->vmult(product, full);
    double *d = dst.trilinos_vector()[0];
    for (std::size_t k = 0; k < u_rows.size(); ++k)
      d[u_rows[k]] = yu[k];
    for (std::size_t k = 0; k < p_rows.size(); ++k)
      d[p_rows[k]] = schur_inverse[k] * (Bf[p_rows[k]] - s[p_rows[k]]);
  }
} // namespace hyperelastic
