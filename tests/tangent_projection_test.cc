// Unit test of include/hyperelastic/materials/tangent_projection.h, the
// projection of dP/dF onto the positive semi-definite (PSD) cone used by a
// projected Newton method. In 2D and 3D:
//   a. PSD tangents (linear elastic; neo-Hookean and St. Venant-Kirchhoff in
//      moderate tension) are unchanged, to 1e-12 relative;
//   b. neo-Hookean and St. Venant-Kirchhoff tangents under strong compression
//      (F = diag(0.3, 1, 1) and random F with one principal stretch in
//      [0.2, 0.4]) have a negative eigenvalue before and none below
//      -1e-12 |A| after;
//   c. the Jacobi eigen-decomposition reconstructs random symmetric matrices
//      (4 x 4, 9 x 9, 12 x 12, some with a prescribed, repeated or zero
//      spectrum) to 1e-13, with orthonormal eigenvectors and the prescribed
//      eigenvalues;
//   d. the projection R of M is the nearest PSD matrix: the eigenvalues of R
//      are max(eigenvalues of M, 0), and R satisfies the optimality conditions
//      of min |R - M|_F over PSD R: R >= 0, R - M >= 0 (the correction only
//      adds), R (R - M) = 0, |R - M|_F = |negative eigenvalues of M|;
//   e. the P1 element stiffness B^T A B of a random simplex is indefinite
//      with the compressed tangent and PSD with the projected one;
//   f. a non-symmetric input is symmetrised, a NaN tangent stays NaN.
// One PASS/FAIL line per check with the worst measured value; exits 1 if any
// check fails.

#include <deal.II/base/tensor.h>

#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/tangent_projection.h>

#include "support/checker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
  using namespace hyperelastic;
  using dealii::Tensor;

  double
  infinity()
  {
    return std::numeric_limits<double>::infinity();
  }

  // The shared reporter; the dimension leads each row.
  hyperelastic::testing::Checker checker(true);

  /// Passes if measured <= tolerance (a NaN fails).
  void
  check_below(const int          dim,
              const std::string &what,
              const double       measured,
              const double       tolerance)
  {
    checker.at_most(std::to_string(dim) + "D  " + what, measured, tolerance);
  }

  /// Passes if measured < bound (a NaN fails).
  void
  check_less(const int          dim,
             const std::string &what,
             const double       measured,
             const double       bound)
  {
    checker.below(std::to_string(dim) + "D  " + what, measured, bound);
  }

  void
  check_true(const int dim, const std::string &what, const bool pass)
  {
    checker.is_true(std::to_string(dim) + "D  " + what, pass);
  }

  // ------------------------------------------------------- small matrices

  template <std::size_t n>
  double
  frobenius_norm(const SmallMatrix<n> &a)
  {
    double s = 0.;
    for (const auto &row : a)
      for (const double x : row)
        s += x * x;
    return std::sqrt(s);
  }

  template <std::size_t n>
  SmallMatrix<n>
  difference(const SmallMatrix<n> &a, const SmallMatrix<n> &b)
  {
    SmallMatrix<n> d;
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        d[r][c] = a[r][c] - b[r][c];
    return d;
  }

  template <std::size_t n>
  SmallMatrix<n>
  product(const SmallMatrix<n> &a, const SmallMatrix<n> &b)
  {
    SmallMatrix<n> p{};
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t k = 0; k < n; ++k)
        for (std::size_t c = 0; c < n; ++c)
          p[r][c] += a[r][k] * b[k][c];
    return p;
  }

  template <std::size_t n>
  SmallMatrix<n>
  transposed(const SmallMatrix<n> &a)
  {
    SmallMatrix<n> t;
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        t[r][c] = a[c][r];
    return t;
  }

  /// Sorted eigenvalues (ascending).
  template <std::size_t n>
  std::array<double, n>
  eigenvalues_of(const SmallMatrix<n> &a)
  {
    std::array<double, n> lambda;
    SmallMatrix<n>        V;
    jacobi_eigen_decomposition<n>(a, lambda, V);
    std::sort(lambda.begin(), lambda.end());
    return lambda;
  }

  template <std::size_t n>
  double
  smallest_eigenvalue_of(const SmallMatrix<n> &a)
  {
    return eigenvalues_of(a)[0];
  }

  /// Random orthogonal matrix (Gram-Schmidt of a Gaussian matrix, done
  /// twice for orthogonality to round-off).
  template <std::size_t n>
  SmallMatrix<n>
  random_orthogonal(std::mt19937 &rng)
  {
    std::normal_distribution<double> normal;
    SmallMatrix<n>                   q;
    for (auto &row : q)
      for (double &x : row)
        x = normal(rng);
    for (std::size_t k = 0; k < n; ++k)
      for (unsigned int pass = 0; pass < 2; ++pass)
        {
          for (std::size_t j = 0; j < k; ++j)
            {
              double dot = 0.;
              for (std::size_t r = 0; r < n; ++r)
                dot += q[r][k] * q[r][j];
              for (std::size_t r = 0; r < n; ++r)
                q[r][k] -= dot * q[r][j];
            }
          double norm = 0.;
          for (std::size_t r = 0; r < n; ++r)
            norm += q[r][k] * q[r][k];
          norm = std::sqrt(norm);
          for (std::size_t r = 0; r < n; ++r)
            q[r][k] /= norm;
        }
    return q;
  }

  /// Q diag(d) Q^T.
  template <std::size_t n>
  SmallMatrix<n>
  with_spectrum(const SmallMatrix<n> &Q, const std::array<double, n> &d)
  {
    SmallMatrix<n> a{};
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        for (std::size_t k = 0; k < n; ++k)
          a[r][c] += Q[r][k] * d[k] * Q[c][k];
    return a;
  }

  template <std::size_t n>
  SmallMatrix<n>
  random_symmetric(std::mt19937 &rng)
  {
    std::uniform_real_distribution<double> uniform(-1., 1.);
    SmallMatrix<n>                         a;
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = r; c < n; ++c)
        a[r][c] = a[c][r] = uniform(rng);
    return a;
  }

  // ------------------------------------------------------- tensors

  template <int dim>
  double
  norm(const StressTangent<dim> &A)
  {
    double s = 0.;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int J = 0; J < dim; ++J)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int L = 0; L < dim; ++L)
            s += A[i][J][k][L] * A[i][J][k][L];
    return std::sqrt(s);
  }

  template <int dim>
  Tensor<2, dim>
  diagonal(const std::array<double, 3> &s)
  {
    Tensor<2, dim> F;
    for (unsigned int d = 0; d < dim; ++d)
      F[d][d] = s[d];
    return F;
  }

  /// Q1 diag(s) Q2 with random rotations Q1, Q2 (det +1): s[0] in
  /// [0.2, 0.4] (strong compression), the others in [0.7, 1.3].
  template <int dim>
  Tensor<2, dim>
  random_compressed_F(std::mt19937 &rng)
  {
    std::uniform_real_distribution<double> strong(0.2, 0.4);
    std::uniform_real_distribution<double> mild(0.7, 1.3);
    Tensor<2, dim>                         Q[2];
    for (auto &q : Q)
      {
        const SmallMatrix<dim> o = random_orthogonal<dim>(rng);
        for (unsigned int r = 0; r < dim; ++r)
          for (unsigned int c = 0; c < dim; ++c)
            q[r][c] = o[r][c];
        if (determinant(q) < 0.)
          q[0] *= -1.;
      }
    Tensor<2, dim> S;
    S[0][0] = strong(rng);
    for (unsigned int d = 1; d < dim; ++d)
      S[d][d] = mild(rng);
    return Q[0] * S * Q[1];
  }

  /// The matrix M[(iJ)][(kL)] = A[i][J][k][L], without symmetrising.
  template <int dim>
  TangentMatrix<dim>
  tangent_matrix(const StressTangent<dim> &A)
  {
    constexpr std::size_t n = dim * dim;
    TangentMatrix<dim>    M;
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        M[r][c] = A[r / dim][r % dim][c / dim][c % dim];
    return M;
  }

  // ------------------------------------------------------- checks

  constexpr unsigned int n_random = 50;

  template <int dim>
  void
  check_psd_tangents_unchanged(const LameParameters &lame)
  {
    struct Case
    {
      std::string        name;
      StressTangent<dim> A;
    };
    std::vector<Case> cases;
    cases.push_back(
      {"linear_elastic_tangent", linear_elastic_tangent<dim>(lame)});
    const Tensor<2, dim> F_tension = diagonal<dim>({{1.2, 1.1, 1.05}});
    Tensor<2, dim>       F_sheared = F_tension;
    F_sheared[0][1]                = 0.1;
    for (const std::string model : {"neo-Hookean", "St. Venant-Kirchhoff"})
      {
        const auto material = create_material<dim>(model, lame);
        cases.push_back({model + ", F = diag(1.2, 1.1, 1.05)",
                         material->stress_tangent(F_tension)});
        cases.push_back(
          {model + ", same + 0.1 shear", material->stress_tangent(F_sheared)});
      }
    for (const Case &c : cases)
      {
        const double min_before = smallest_eigenvalue(c.A);
        // Precondition: PSD to round-off (the linear elastic tangent has
        // exact zero eigenvalues, the rotations).
        check_less(dim,
                   "a. " + c.name + ": -min eig / |A| before",
                   -min_before / norm(c.A),
                   1e-14);
        StressTangent<dim> P = c.A;
        project_to_positive_semidefinite(P);
        check_below(dim,
                    "a. " + c.name + ": |proj(A) - A| / |A|",
                    norm(StressTangent<dim>(P - c.A)) / norm(c.A),
                    1e-12);
      }
  }

  template <int dim>
  void
  check_compressed_tangents(const LameParameters &lame)
  {
    std::mt19937 rng(2024 + dim);
    for (const std::string model : {"neo-Hookean", "St. Venant-Kirchhoff"})
      {
        const auto material = create_material<dim>(model, lame);
        std::vector<Tensor<2, dim>> Fs;
        Fs.push_back(diagonal<dim>({{0.3, 1., 1.}}));
        for (unsigned int s = 0; s < n_random; ++s)
          Fs.push_back(random_compressed_F<dim>(rng));

        // Worst over the samples: the least negative smallest eigenvalue
        // before, the most negative one after (both relative to |A|).
        double worst_before = -infinity(), worst_after = -infinity();
        double diag_before = 0., diag_after = 0.;
        for (unsigned int s = 0; s < Fs.size(); ++s)
          {
            StressTangent<dim> A      = material->stress_tangent(Fs[s]);
            const double       scale  = norm(A);
            const double       before = smallest_eigenvalue(A) / scale;
            project_to_positive_semidefinite(A);
            const double after = -smallest_eigenvalue(A) / scale;
            if (s == 0)
              {
                diag_before = before;
                diag_after  = after;
              }
            else
              {
                worst_before = std::max(worst_before, before);
                worst_after  = std::max(worst_after, after);
              }
          }
        check_less(dim,
                   "b. " + model + ", F = diag(0.3,1,1): min eig / |A| before",
                   diag_before,
                   -1e-3);
        check_below(dim,
                    "b. " + model +
                      ", F = diag(0.3,1,1): -min eig / |A| after projection",
                    diag_after,
                    1e-12);
        check_less(dim,
                   "b. " + model + ", " + std::to_string(n_random) +
                     " random compressed F: max of min eig / |A| before",
                   worst_before,
                   -1e-3);
        check_below(dim,
                    "b. " + model + ", " + std::to_string(n_random) +
                      " random compressed F: -min eig / |A| after",
                    worst_after,
                    1e-12);
      }
  }

  template <std::size_t n>
  void
  check_eigen_decomposition(const int dim)
  {
    std::mt19937                           rng(7 + n);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    double       reconstruction = 0., orthogonality = 0., spectrum = 0.;
    unsigned int max_sweeps = 0;
    const auto   record     = [&](const SmallMatrix<n> &a) {
      std::array<double, n> lambda;
      SmallMatrix<n>        V;
      max_sweeps =
        std::max(max_sweeps, jacobi_eigen_decomposition<n>(a, lambda, V));
      std::array<double, n> ones;
      ones.fill(1.);
      const double scale = std::max(frobenius_norm(a), 1e-300);
      reconstruction =
        std::max(reconstruction,
                 frobenius_norm(difference(with_spectrum(V, lambda), a)) /
                   scale);
      SmallMatrix<n> identity{};
      for (std::size_t k = 0; k < n; ++k)
        identity[k][k] = 1.;
      orthogonality =
        std::max(orthogonality,
                 frobenius_norm(
                   difference(product(transposed(V), V), identity)));
    };

    for (unsigned int s = 0; s < n_random; ++s)
      record(random_symmetric<n>(rng));
    // Known spectra: distinct, repeated (as in the linear elastic tangent),
    // with zeros, with a wide range of magnitudes, and the zero matrix.
    for (unsigned int s = 0; s < n_random; ++s)
      {
        std::array<double, n> d;
        for (std::size_t k = 0; k < n; ++k)
          switch (s % 4)
            {
            case 0:
              d[k] = uniform(rng);
              break;
            case 1:
              d[k] = k % 3 == 0 ? 2. : (k % 3 == 1 ? -0.5 : 1.);
              break;
            case 2:
              d[k] = k < n / 2 ? 0. : uniform(rng);
              break;
            default:
              d[k] = std::pow(10., 8. * uniform(rng)) * (k % 2 ? 1. : -1.);
            }
        const SmallMatrix<n> a = with_spectrum(random_orthogonal<n>(rng), d);
        record(a);
        std::sort(d.begin(), d.end());
        const std::array<double, n> lambda = eigenvalues_of(a);
        for (std::size_t k = 0; k < n; ++k)
          spectrum =
            std::max(spectrum, std::abs(lambda[k] - d[k]) / frobenius_norm(a));
      }
    record(SmallMatrix<n>{});

    const std::string size = std::to_string(n) + "x" + std::to_string(n);
    check_below(dim,
                "c. " + size + ": |V diag(lambda) V^T - M| / |M|, " +
                  std::to_string(2 * n_random + 1) + " matrices",
                reconstruction,
                1e-13);
    check_below(dim, "c. " + size + ": |V^T V - I|", orthogonality, 1e-13);
    check_below(dim,
                "c. " + size + ": |lambda - prescribed spectrum| / |M|",
                spectrum,
                1e-13);
    check_below(dim,
                "c. " + size + ": Jacobi sweeps (most over all matrices)",
                max_sweeps,
                20);
  }

  /// d. for the matrix M of one tangent A (not necessarily symmetric).
  template <int dim>
  void
  nearest_psd_errors(const StressTangent<dim> &A, double errors[4])
  {
    constexpr std::size_t    n = dim * dim;
    const TangentMatrix<dim> M = symmetric_tangent_matrix(A);
    StressTangent<dim>       P = A;
    project_to_positive_semidefinite(P);
    const TangentMatrix<dim> R     = symmetric_tangent_matrix(P);
    const TangentMatrix<dim> Z     = difference(R, M);
    const double             scale = frobenius_norm(M);

    const std::array<double, n> lambda_M = eigenvalues_of(M);
    const std::array<double, n> lambda_R = eigenvalues_of(R);
    double                      spectrum = 0., negative_part = 0.;
    for (std::size_t k = 0; k < n; ++k)
      {
        spectrum =
          std::max(spectrum, std::abs(lambda_R[k] - std::max(lambda_M[k], 0.)));
        if (lambda_M[k] < 0.)
          negative_part += lambda_M[k] * lambda_M[k];
      }
    errors[0] = std::max(errors[0], spectrum / scale);
    errors[1] = std::max(errors[1], -smallest_eigenvalue_of(Z) / scale);
    errors[2] =
      std::max(errors[2], frobenius_norm(product(R, Z)) / (scale * scale));
    errors[3] =
      std::max(errors[3],
               std::abs(frobenius_norm(Z) - std::sqrt(negative_part)) / scale);
  }

  template <int dim>
  void
  check_nearest_psd(const LameParameters &lame)
  {
    constexpr std::size_t n = dim * dim;
    std::mt19937          rng(99 + dim);
    double                errors[4] = {0., 0., 0., 0.};
    unsigned int          n_cases   = 0;
    for (unsigned int s = 0; s < n_random; ++s, ++n_cases)
      nearest_psd_errors<dim>(
        tangent_from_matrix<dim>(random_symmetric<n>(rng)), errors);
    for (const std::string model : {"neo-Hookean", "St. Venant-Kirchhoff"})
      {
        const auto material = create_material<dim>(model, lame);
        for (unsigned int s = 0; s < n_random; ++s, ++n_cases)
          nearest_psd_errors<dim>(
            material->stress_tangent(random_compressed_F<dim>(rng)), errors);
      }
    const std::string cases = std::to_string(n_cases) + " tangents";
    check_below(dim,
                "d. eig(R) = max(eig(M), 0): max error / |M|, " + cases,
                errors[0],
                1e-13);
    check_below(dim,
                "d. R - M is PSD: -min eig(R - M) / |M|",
                errors[1],
                1e-13);
    check_below(dim,
                "d. complementarity |R (R - M)| / |M|^2",
                errors[2],
                1e-13);
    check_below(dim,
                "d. |R - M| = |negative eigenvalues of M|: error / |M|",
                errors[3],
                1e-13);
  }

  /// e. P1 element stiffness B^T M B of a random simplex (volume factor
  /// dropped): dof (a, k) is component k of node a, and
  /// B[(kL)][(a, k)] = dN_a/dX_L.
  template <int dim>
  void
  check_element_stiffness(const LameParameters &lame)
  {
    constexpr std::size_t                  n_dofs = dim * (dim + 1);
    constexpr std::size_t                  n      = dim * dim;
    std::mt19937                           rng(5 + dim);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    double worst_before = -infinity(), worst_after = 0.;
    for (const std::string model : {"neo-Hookean", "St. Venant-Kirchhoff"})
      {
        const auto material = create_material<dim>(model, lame);
        for (unsigned int s = 0; s < n_random; ++s)
          {
            // edges[d] = X_{d+1} - X_0 (unit edges plus noise). With
            // X = X_0 + edges^T xi and N_{d+1} = xi_d, grad N_{d+1} is row d
            // of edges^-T; N_0 = 1 - sum of the others.
            Tensor<2, dim> edges;
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int e = 0; e < dim; ++e)
                edges[d][e] = (d == e ? 1. : 0.) + 0.3 * uniform(rng);
            const Tensor<2, dim>                G = invert(transpose(edges));
            std::array<Tensor<1, dim>, dim + 1> grad;
            for (unsigned int a = 1; a <= dim; ++a)
              grad[a] = G[a - 1];
            for (unsigned int a = 1; a <= dim; ++a)
              grad[0] -= grad[a];

            StressTangent<dim> A =
              material->stress_tangent(random_compressed_F<dim>(rng));
            for (unsigned int pass = 0; pass < 2; ++pass)
              {
                if (pass == 1)
                  project_to_positive_semidefinite(A);
                const TangentMatrix<dim> M = symmetric_tangent_matrix(A);
                SmallMatrix<n_dofs>      K{};
                for (std::size_t I = 0; I < n_dofs; ++I)
                  for (std::size_t J = 0; J < n_dofs; ++J)
                    for (std::size_t r = 0; r < n; ++r)
                      for (std::size_t c = 0; c < n; ++c)
                        {
                          // B[r][I] with r = (k, L), I = (a, k').
                          const double B_rI =
                            r / dim == I % dim ? grad[I / dim][r % dim] : 0.;
                          const double B_cJ =
                            c / dim == J % dim ? grad[J / dim][c % dim] : 0.;
                          K[I][J] += B_rI * M[r][c] * B_cJ;
                        }
                const double min_eig =
                  smallest_eigenvalue_of(K) / frobenius_norm(K);
                if (pass == 0)
                  worst_before = std::max(worst_before, min_eig);
                else
                  worst_after = std::max(worst_after, -min_eig);
              }
          }
      }
    check_less(dim,
               "e. P1 stiffness, compressed: max of min eig(K) / |K| before",
               worst_before,
               -1e-3);
    check_below(dim,
                "e. P1 stiffness, projected tangent: -min eig(K) / |K|",
                worst_after,
                1e-12);
  }

  template <int dim>
  void
  check_symmetrisation_and_nan(const LameParameters &lame)
  {
    constexpr std::size_t                  n = dim * dim;
    std::mt19937                           rng(11 + dim);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    TangentMatrix<dim>                     M;
    for (auto &row : M)
      for (double &x : row)
        x = uniform(rng);
    StressTangent<dim> A = tangent_from_matrix<dim>(M);
    StressTangent<dim> S =
      tangent_from_matrix<dim>(symmetric_tangent_matrix(A));
    project_to_positive_semidefinite(A);
    project_to_positive_semidefinite(S);
    const TangentMatrix<dim> R         = tangent_matrix(A);
    double                   asymmetry = 0.;
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        asymmetry = std::max(asymmetry, std::abs(R[r][c] - R[c][r]));
    check_below(dim,
                "f. non-symmetric input: max |R - R^T| of the result",
                asymmetry,
                0.);
    check_below(dim,
                "f. non-symmetric input: |proj(A) - proj(sym A)| / |A|",
                norm(StressTangent<dim>(A - S)) / norm(S),
                1e-14);

    StressTangent<dim> nan_tangent =
      create_material<dim>("neo-Hookean", lame)
        ->stress_tangent(diagonal<dim>({{-0.5, 1., 1.}}));
    project_to_positive_semidefinite(nan_tangent);
    check_true(dim,
               "f. neo-Hookean tangent at J < 0 (NaN) stays NaN",
               std::isnan(nan_tangent[0][0][0][0]));
  }

  template <int dim>
  void
  run()
  {
    const LameParameters lame = LameParameters::from_young_poisson(1., 0.3);
    checker.section(std::to_string(dim) + "D (mu = " + std::to_string(lame.mu) +
                    ", lambda = " + std::to_string(lame.lambda) + ")");
    check_psd_tangents_unchanged<dim>(lame);
    check_compressed_tangents<dim>(lame);
    check_eigen_decomposition<dim * dim>(dim);
    check_nearest_psd<dim>(lame);
    check_element_stiffness<dim>(lame);
    check_symmetrisation_and_nan<dim>(lame);
  }
} // namespace

int
main()
{
  try
    {
      run<2>();
      run<3>();
      // The 12 x 12 size of a P1 tetrahedron's stiffness (check e).
      check_eigen_decomposition<12>(3);
    }
  catch (const std::exception &e)
    {
      checker.is_true(std::string("no exception (") + e.what() + ")", false);
      return checker.exit_code(1);
    }
  return checker.exit_code();
}
