// The exact solve on stiff unknowns around a preconditioner
// (StiffSubspaceCorrection, 'Linear solver/Exact solve on stiff
// couplings'), on a chain of unit springs with a few springs 1e6 times
// stiffer between distant unknowns (what a barrier adds between touching
// surfaces), distributed over the ranks of MPI_COMM_WORLD (ctest: 1 and 2):
// - around an exact inverse M = A^-1 the combination is A^-1 itself (1e-9
//   relative): I - B A = (I - S A)(I - M A)(I - S A) = 0;
// - around Jacobi it is symmetric (y.Bx = x.By, 1e-12 relative) and
//   positive (x.Bx > 0) for random vectors;
// - the block solve alone: A (S r) equals r on the stiff unknowns (1e-9).
// What it does for CG is asserted on contact scenes (contact.krylov).
//
// Usage: mpirun -np N stiff_subspace_correction
#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/solvers/stiff_subspace_correction.h>

#include "support/checker.h"

#include <cmath>
#include <random>

using namespace dealii;
using namespace hyperelastic;
using namespace hyperelastic::testing;

namespace
{
  constexpr unsigned int n         = 400;
  constexpr double       stiffness = 1e6;

  /// The stiff springs: (i, n - 1 - i) for a few i.
  std::vector<std::pair<unsigned int, unsigned int>>
  stiff_springs()
  {
    std::vector<std::pair<unsigned int, unsigned int>> springs;
    for (unsigned int i = 10; i < 190; i += 20)
      springs.emplace_back(i, n - 1 - i);
    return springs;
  }

  /// A chain of unit springs, held at unknown 0 by a unit spring to the
  /// ground, with the stiff springs added.
  void
  build(MatrixType &A, const IndexSet &owned, const MPI_Comm comm)
  {
    DynamicSparsityPattern pattern(n, n, owned);
    const auto             add_spring =
      [&](auto &&add, unsigned int i, unsigned int j, double k) {
        add(i, i, k);
        add(j, j, k);
        add(i, j, -k);
        add(j, i, -k);
      };
    const auto for_all = [&](auto &&add) {
      add(0, 0, 1.);
      for (unsigned int i = 0; i + 1 < n; ++i)
        add_spring(add, i, i + 1, 1.);
      for (const auto &[i, j] : stiff_springs())
        add_spring(add, i, j, stiffness);
    };
    for_all([&](unsigned int i, unsigned int j, double) {
      if (owned.is_element(i))
        pattern.add(i, j);
    });
    A.reinit(owned, owned, pattern, comm);
    for_all([&](unsigned int i, unsigned int j, double k) {
      if (owned.is_element(i))
        A.add(i, j, k);
    });
    A.compress(VectorOperation::add);
  }

  void
  random_fill(VectorType &v, std::mt19937 &generator)
  {
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (const auto i : v.locally_owned_elements())
      v(i) = uniform(generator);
    v.compress(VectorOperation::insert);
  }

  void
  run(Checker &check)
  {
    const MPI_Comm     comm    = MPI_COMM_WORLD;
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    IndexSet           owned(n);
    owned.add_range(n * rank / n_ranks, n * (rank + 1) / n_ranks);
    owned.compress();
    MatrixType A;
    build(A, owned, comm);

    IndexSet stiff(n);
    for (const auto &[i, j] : stiff_springs())
      for (const unsigned int k : {i, j})
        if (owned.is_element(k))
          stiff.add_index(k);
    stiff.compress();
    StiffSubspaceCorrection correction;
    correction.initialize(A, stiff);
    check.is_true("stiff subspace of " + std::to_string(correction.size()) +
                    " unknowns",
                  correction.active() &&
                    correction.size() == 2 * stiff_springs().size());

    std::mt19937 generator(7 + rank);
    VectorType   r(owned, comm), x(owned, comm), z(owned, comm),
      exact(owned, comm), y(owned, comm), Bx(owned, comm), By(owned, comm);
    random_fill(r, generator);

    // Around the exact inverse.
    SolverControl                  direct_control(1, 0);
    TrilinosWrappers::SolverDirect direct(direct_control);
    direct.initialize(A);
    const auto exact_inverse = [&](VectorType &out, const VectorType &in) {
      direct.solve(out, in);
    };
    exact_inverse(exact, r);
    correction.vmult(z, r, exact_inverse);
    z -= exact;
    check.at_most("around A^-1: B r - A^-1 r, relative",
                  z.l2_norm() / exact.l2_norm(),
                  1e-9);

    // Around Jacobi: symmetric and positive.
    VectorType inverse_diagonal(owned, comm);
    for (const auto i : owned)
      inverse_diagonal(i) = 1. / A.diag_element(i);
    inverse_diagonal.compress(VectorOperation::insert);
    const auto jacobi = [&](VectorType &out, const VectorType &in) {
      out = in;
      out.scale(inverse_diagonal);
    };
    double largest_asymmetry = 0., smallest_energy = 1.;
    for (unsigned int trial = 0; trial < 5; ++trial)
      {
        random_fill(x, generator);
        random_fill(y, generator);
        correction.vmult(Bx, x, jacobi);
        correction.vmult(By, y, jacobi);
        largest_asymmetry =
          std::max(largest_asymmetry,
                   std::abs(y * Bx - x * By) / (x.l2_norm() * Bx.l2_norm()));
        smallest_energy =
          std::min(smallest_energy, (x * Bx) / (x.l2_norm() * Bx.l2_norm()));
      }
    check.at_most("around Jacobi: |y.Bx - x.By| / (|x| |Bx|)",
                  largest_asymmetry,
                  1e-12);
    check.is_true("around Jacobi: x.Bx > 0 (smallest x.Bx / (|x| |Bx|) = " +
                    std::to_string(smallest_energy) + ")",
                  smallest_energy > 0.);

    // The block solve alone (around nothing): A z = r on the stiff rows.
    const auto nothing = [&](VectorType &out, const VectorType &) { out = 0.; };
    VectorType Az(owned, comm);
    correction.vmult(z, r, nothing);
    A.vmult(Az, z);
    double largest = 0., scale = 0.;
    for (const auto i : stiff)
      {
        largest = std::max(largest, std::abs(Az(i) - r(i)));
        scale   = std::max(scale, std::abs(r(i)));
      }
    largest = Utilities::MPI::max(largest, comm);
    scale   = Utilities::MPI::max(scale, comm);
    check.at_most("block solve: |A S r - r| on the stiff unknowns, relative",
                  largest / scale,
                  1e-9);
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Checker   check(Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
  const int status = run_and_report([&]() { run(check); }, MPI_COMM_WORLD);
  return check.exit_code(status);
}
