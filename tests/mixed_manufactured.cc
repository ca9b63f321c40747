// Convergence rates of the mixed formulation for an exactly incompressible
// solid (bulk modulus 'inf', the limit nu -> 0.5) against a manufactured
// solution: the motion phi = R(t pi/2) S_dim ... S_1 (X) composed of shears
// S_k (x_k += t a_k sin(pi c_k . X + d_k), the other coordinates fixed), so
// that J = 1 exactly, with the pressure p(X, t) = t p0 sin(pi e . X + f),
// and the body force b = -Div(P_iso + p cof F) = -(A_iso : grad F) -
// cof(F) grad p (the Piola identity Div cof F = 0), A_iso from the model's
// isochoric part (decoupled neo-Hookean, mu = 1). grad F comes from central
// differences of the analytic F (step 1e-5: error ~1e-10, far below the
// discretisation errors measured). Errors of u in L2 and the H1 seminorm and
// of p in L2 on meshes n, 2n, 4n ; the rates between the
// last two must be
//   P2/P1: u L2 3, u H1 2 (within 0.2 in 2D; at least 2.8 and 1.8 on the
//   pre-asymptotic 3D meshes 2, 4, 8), p L2 at least 1.8;
//   P1-bubble/P1 and P1/P1 stabilized: u L2 2, u H1 1 (as above), p L2
//   at least 1.5.
//
// Usage: mpirun -np N mixed_manufactured DIM ELEMENT
//   ELEMENT: mini | stabilized | taylor_hood
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/numerics/vector_tools.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"
#include "support/manufactured_motion.h" // rotation_matrix
#include "support/scene_text.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace hyperelastic;
using namespace hyperelastic::testing;
using namespace dealii;

namespace
{
  constexpr double mu = 1.;

  /// The shear-composed, rotated motion and the pressure.
  template <int dim>
  class IsochoricMotion
  {
  public:
    /// F = R Grad S_dim ... Grad S_1 (each shear's gradient is unit
    /// triangular: det = 1).
    Tensor<2, dim>
    deformation_gradient(const Point<dim> &X, const double t) const
    {
      Tensor<1, dim> x = X;
      Tensor<2, dim> F = unit_symmetric_tensor<dim>();
      for (unsigned int k = 0; k < dim; ++k)
        {
          // x_k += t a_k sin(pi c_k . x + d_k): gradient I + e_k (x) g.
          const Tensor<1, dim> g =
            t * a[k] * std::cos(M_PI * (c[k] * x) + d[k]) * M_PI * c[k];
          Tensor<2, dim> G = unit_symmetric_tensor<dim>();
          G[k] += g;
          F = G * F;
          x[k] += t * a[k] * std::sin(M_PI * (c[k] * x) + d[k]);
        }
      return rotation_matrix<dim>(t * theta) * F;
    }

    Tensor<1, dim>
    displacement(const Point<dim> &X, const double t) const
    {
      Tensor<1, dim> x = X;
      for (unsigned int k = 0; k < dim; ++k)
        x[k] += t * a[k] * std::sin(M_PI * (c[k] * x) + d[k]);
      return rotation_matrix<dim>(t * theta) * x - X;
    }

    /// dF_kL / dX_J as [k][L][J], by central differences.
    Tensor<3, dim>
    gradient_of_F(const Point<dim> &X, const double t) const
    {
      constexpr double h = 1e-5;
      Tensor<3, dim>   dF;
      for (unsigned int J = 0; J < dim; ++J)
        {
          Point<dim> plus = X, minus = X;
          plus[J] += h;
          minus[J] -= h;
          const Tensor<2, dim> D = (deformation_gradient(plus, t) -
                                    deformation_gradient(minus, t)) /
                                   (2. * h);
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int L = 0; L < dim; ++L)
              dF[k][L][J] = D[k][L];
        }
      return dF;
    }

    double
    pressure(const Point<dim> &X, const double t) const
    {
      return t * p0 * std::sin(M_PI * (e * X) + 0.4);
    }

    Tensor<1, dim>
    pressure_gradient(const Point<dim> &X, const double t) const
    {
      return t * p0 * std::cos(M_PI * (e * X) + 0.4) * M_PI * e;
    }

    IsochoricMotion()
    {
      const double cc[3][3] = {{0., 1., 0.5}, {0.5, 0., 1.}, {1., 0.5, 0.}};
      for (unsigned int k = 0; k < dim; ++k)
        {
          for (unsigned int j = 0; j < dim; ++j)
            c[k][j] = cc[k][j];
          e[k] = 0.7 + 0.3 * k;
        }
      if (dim == 2)
        {
          c[0][1] = 1.; // x += a sin(pi y + d)
          c[1][0] = 1.; // y += a sin(pi x + d)
        }
    }

  private:
    static constexpr double theta = M_PI / 2.;
    const double            a[3]  = {0.06, 0.05, 0.04};
    const double            d[3]  = {0.3, 1.1, 0.7};
    static constexpr double p0    = 0.3;
    Tensor<1, dim>          c[dim];
    Tensor<1, dim>          e;
  };

  /// The exact (u, p) at t = 1 as one function of dim + 1 components.
  template <int dim>
  class ExactSolution : public Function<dim>
  {
  public:
    ExactSolution()
        : Function<dim>(dim + 1)
    {
    }

    double
    value(const Point<dim> &X, const unsigned int c) const override
    {
      return c < dim ? motion.displacement(X, 1.)[c] : motion.pressure(X, 1.);
    }

    Tensor<1, dim>
    gradient(const Point<dim> &X, const unsigned int c) const override
    {
      if (c == dim)
        return motion.pressure_gradient(X, 1.);
      Tensor<1, dim> g = motion.deformation_gradient(X, 1.)[c];
      g[c] -= 1.;
      return g;
    }

  private:
    IsochoricMotion<dim> motion;
  };

  /// The exact displacement at the current time, for the Dirichlet data.
  template <int dim>
  class BoundaryDisplacement : public Function<dim>
  {
  public:
    BoundaryDisplacement()
        : Function<dim>(dim)
    {
    }

    double
    value(const Point<dim> &X, const unsigned int c) const override
    {
      return motion.displacement(X, this->get_time())[c];
    }

  private:
    IsochoricMotion<dim> motion;
  };

  /// The exact traction P N on the box face with boundary id @p id (x_k = 0
  /// for id = 2k, outward normal -e_k; x_k = 1 for id = 2k + 1, normal e_k),
  /// P = P_iso(F) + p cof F.
  template <int dim>
  class ExactTraction : public Function<dim>
  {
  public:
    ExactTraction(const Material<dim> &isochoric, const unsigned int id)
        : Function<dim>(dim)
        , isochoric(isochoric)
        , k(id / 2)
        , sign(id % 2 == 1 ? 1. : -1.)
    {
    }

    void
    vector_value(const Point<dim> &X, Vector<double> &traction) const override
    {
      const double         t = this->get_time();
      const Tensor<2, dim> F = motion.deformation_gradient(X, t);
      const Tensor<2, dim> P = isochoric.first_piola_kirchhoff(F) +
                               motion.pressure(X, t) * determinant(F) *
                                 transpose(invert(F));
      for (unsigned int i = 0; i < dim; ++i)
        traction[i] = sign * P[i][k];
    }

  private:
    const Material<dim>       &isochoric;
    const unsigned int         k;
    const double               sign;
    const IsochoricMotion<dim> motion;
  };

  /// b = -(A_iso : grad F) - cof(F) grad p.
  template <int dim>
  class BodyForce : public Function<dim>
  {
  public:
    explicit BodyForce(const Material<dim> &isochoric)
        : Function<dim>(dim)
        , isochoric(isochoric)
    {
    }

    void
    vector_value(const Point<dim> &X, Vector<double> &b) const override
    {
      const double             t  = this->get_time();
      const Tensor<2, dim>     F  = motion.deformation_gradient(X, t);
      const StressTangent<dim> A  = isochoric.stress_tangent(F);
      const Tensor<3, dim>     dF = motion.gradient_of_F(X, t);
      const Tensor<2, dim>     cofactor = determinant(F) * transpose(invert(F));
      const Tensor<1, dim>     cof_grad_p =
        cofactor * motion.pressure_gradient(X, t);
      for (unsigned int i = 0; i < dim; ++i)
        {
          b[i] = -cof_grad_p[i];
          for (unsigned int J = 0; J < dim; ++J)
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int L = 0; L < dim; ++L)
                b[i] -= A[i][J][k][L] * dF[k][L][J];
        }
    }

  private:
    const Material<dim>       &isochoric;
    const IsochoricMotion<dim> motion;
  };

  struct Errors
  {
    unsigned int n, dofs;
    double       u_l2, u_h1, p_l2;
  };

  template <int dim>
  Errors
  solve(const std::string &element, const unsigned int n)
  {
    const bool        three = dim == 3;
    const std::string N     = std::to_string(n);
    std::string       text =
      subsection("Problem",
                 entry("Dimension", std::to_string(dim)) +
                   entry("Formulation", "mixed") +
                   entry("Mixed element", element)) +
      subsection("Mesh",
                 entry("Lower corner", three ? "0, 0, 0" : "0, 0") +
                   entry("Upper corner", three ? "1, 1, 1" : "1, 1") +
                   entry("Subdivisions",
                         three ? N + ", " + N + ", " + N : N + ", " + N)) +
      subsection("Material",
                 entry("Model", "decoupled neo-Hookean") +
                   entry("Elastic constants", "shear and bulk modulus") +
                   entry("Shear modulus", "1") + entry("Bulk modulus", "inf")) +
      subsection("Loading", entry("Number of load steps", "4")) +
      // GMRES with the block preconditioner, to 1e-10.
      tight_solver("cg") +
      subsection("Output",
                 entry("Write VTU", "false") + entry("Verbose", "false") +
                   entry("Directory", "mixed_manufactured_output"));
    // The exact displacement on the faces x_k = 0 (3D P2/P1: x = 0 and y = 0
    // only: with all three, the tetrahedron at the origin has every
    // displacement unknown prescribed and a spurious pressure mode), the
    // exact traction on the others (displacements prescribed everywhere
    // would leave the pressure of an exactly incompressible solid free up
    // to a constant). Placeholders, replaced below.
    const unsigned int n_clamped = three && element == "P2/P1" ? 2 : dim;
    unsigned int       slot      = 0;
    for (unsigned int id = 0; id < 2 * dim; ++id)
      if (id % 2 == 0 && id / 2 < n_clamped)
        text += dirichlet(id / 2 + 1,
                          id,
                          three ? "x, y, z" : "x, y",
                          three ? "0; 0; 0" : "0; 0");
      else
        text += subsection("Traction " + std::to_string(++slot),
                           entry("Boundary id", std::to_string(id)) +
                             entry("Traction", three ? "0; 0; 0" : "0; 0"));
    Parameters parameters;
    parameters.read_from_string(text);
    const auto   material = create_material<dim>(parameters.material);
    const auto   split    = material->volumetric_split();
    Problem<dim> problem(parameters, MPI_COMM_WORLD, false);
    problem.set_load_editor([&](BoundaryConditions<dim> &bc) {
      for (auto &d : bc.dirichlet)
        d.displacement = std::make_unique<BoundaryDisplacement<dim>>();
      for (auto &load : bc.boundary_loads)
        load.value =
          std::make_unique<ExactTraction<dim>>(*split->isochoric, load.id);
      bc.body_force = std::make_unique<BodyForce<dim>>(*split->isochoric);
    });
    problem.run();

    const DoFHandler<dim>   &dof_handler = problem.get_dof_handler();
    const MappingFE<dim>     mapping(FE_SimplexP<dim>(1));
    const QGaussSimplex<dim> quadrature(4);
    const ExactSolution<dim> exact;
    const ComponentSelectFunction<dim> u_only(std::make_pair(0u, unsigned(dim)),
                                              dim + 1);
    const ComponentSelectFunction<dim> p_only(dim, dim + 1);
    Errors errors{n, static_cast<unsigned int>(dof_handler.n_dofs()), 0., 0., 0.};
    Vector<double> cellwise(dof_handler.get_triangulation().n_active_cells());
    const auto     error = [&](const VectorTools::NormType norm,
                           const Function<dim>        &weight) {
      VectorTools::integrate_difference(mapping,
                                        dof_handler,
                                        problem.solution(),
                                        exact,
                                        cellwise,
                                        quadrature,
                                        norm,
                                        &weight);
      return VectorTools::compute_global_error(dof_handler.get_triangulation(),
                                               cellwise,
                                               norm);
    };
    errors.u_l2 = error(VectorTools::L2_norm, u_only);
    errors.u_h1 = error(VectorTools::H1_seminorm, u_only);
    errors.p_l2 = error(VectorTools::L2_norm, p_only);
    return errors;
  }

  template <int dim>
  void
  check_rates(const std::string &element, Checker &checker, const bool print)
  {
    const bool          taylor_hood = element == "P2/P1";
    const std::vector<unsigned int> sizes =
      dim == 2 ? std::vector<unsigned int>{4, 8, 16} :
                 std::vector<unsigned int>{2, 4, 8};
    std::vector<Errors> rows;
    for (const unsigned int n : sizes)
      rows.push_back(solve<dim>(element, n));
    if (print)
      {
        std::cout << dim << "D " << element << " (incompressible):\n"
                  << "     n    unknowns      u L2 error  rate      u H1 error"
                     "  rate      p L2 error  rate\n";
        for (unsigned int i = 0; i < rows.size(); ++i)
          {
            std::cout << std::setw(6) << rows[i].n << std::setw(12)
                      << rows[i].dofs;
            const double now[3]  = {rows[i].u_l2, rows[i].u_h1, rows[i].p_l2};
            for (unsigned int k = 0; k < 3; ++k)
              {
                std::cout << std::scientific << std::setprecision(4)
                          << std::setw(16) << now[k] << std::fixed
                          << std::setprecision(2) << std::setw(6);
                if (i > 0)
                  {
                    const double before[3] = {rows[i - 1].u_l2,
                                              rows[i - 1].u_h1,
                                              rows[i - 1].p_l2};
                    std::cout << std::log2(before[k] / now[k]);
                  }
                else
                  std::cout << "";
              }
            std::cout << std::defaultfloat << '\n';
          }
      }
    const Errors     &a = rows[rows.size() - 2], &b = rows.back();
    const std::string tag = std::to_string(dim) + "D " + element + " ";
    const double      u_l2 = std::log2(a.u_l2 / b.u_l2);
    const double      u_h1 = std::log2(a.u_h1 / b.u_h1);
    const double      p_l2 = std::log2(a.p_l2 / b.p_l2);
    const double      k    = taylor_hood ? 2. : 1.;
    if (dim == 2)
      {
        checker.at_most(tag + "|u L2 rate - " + std::to_string(int(k + 1)) +
                          "|",
                        std::abs(u_l2 - (k + 1.)),
                        0.2);
        checker.at_most(tag + "|u H1 rate - " + std::to_string(int(k)) + "|",
                        std::abs(u_h1 - k),
                        0.2);
      }
    else
      {
        // 3D meshes 2, 4, 8 are pre-asymptotic (P2/P1 converges faster
        // than its order there): at least the optimal rates.
        checker.at_least(tag + "u L2 rate", u_l2, k + 1. - 0.2);
        checker.at_least(tag + "u H1 rate", u_h1, k - 0.2);
      }
    if (taylor_hood)
      checker.at_least(tag + "p L2 rate", p_l2, 2. - 0.2);
    else
      checker.at_least(tag + "p L2 rate", p_l2, 1.5);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool print = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  if (argc < 3)
    {
      if (print)
        std::cerr << "usage: mixed_manufactured DIM mini|stabilized|taylor_hood\n";
      return 1;
    }
  const int         dim  = std::stoi(argv[1]);
  const std::string name = argv[2];
  const std::string element = name == "mini"       ? "P1-bubble/P1" :
                              name == "stabilized" ? "P1/P1 stabilized" :
                                                     "P2/P1";
  Checker   checker(print);
  const int status = run_and_report(
    [&]() {
      if (dim == 2)
        check_rates<2>(element, checker, print);
      else
        check_rates<3>(element, checker, print);
    },
    MPI_COMM_WORLD);
  return checker.exit_code(status);
}
