// The transpose of a distributed matrix, by Epetra's row-matrix transposer
// (it moves the entries of off-rank rows to their owners).
#include <hyperelastic/base/linear_algebra.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <Epetra_RowMatrixTransposer.h>
#include <memory>
#include <stdexcept>

namespace hyperelastic
{
  void
  transpose(const MatrixType &A, MatrixType &transposed)
  {
    const Epetra_CrsMatrix    &matrix = A.trilinos_matrix();
    Epetra_RowMatrixTransposer transposer(
      const_cast<Epetra_CrsMatrix *>(&matrix));
    Epetra_Map        rows(matrix.RowMap());
    Epetra_CrsMatrix *result = nullptr;
    if (transposer.CreateTranspose(true, result, &rows) != 0 ||
        result == nullptr)
      throw std::runtime_error("transpose: Epetra could not transpose the "
                               "matrix");
    const std::unique_ptr<Epetra_CrsMatrix> owned(result);
    transposed.reinit(*owned, true);
  }
} // namespace hyperelastic
