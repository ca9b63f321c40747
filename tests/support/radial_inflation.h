// An independent reference for the inflation of a thick hollow cylinder in
// plane strain (dim = 2) or a thick spherical shell (dim = 3), inner radius
// A, outer radius B, made of an isotropic hyperelastic model: the radial
// boundary-value problem solved by shooting with RK4, from nothing but the
// model's P and dP/dF at diagonal F.
//
// With r(R) the deformed radius, the principal stretches are
// l_r = r'(R) and l_t = r / R (dim - 1 of them), F = diag(l_r, l_t, ...),
// and equilibrium in the reference configuration reads
//   dP_rR/dR + (dim - 1) (P_rR - P_tT) / R = 0.
// With dl_t/dR = (l_r - l_t) / R this gives an ODE for (r, l_r):
//   dl_r/dR = [(dim - 1)(P_tT - P_rR) / R - (dim - 1) A_rrtt (l_r - l_t) / R]
//             / A_rrrr,
// where A_rrrr = dP_rR/dl_r and A_rrtt = dP_rR/dl_t (each tangential
// stretch). At the inner surface the follower pressure p gives Cauchy
// sigma_rr = -p, i.e. P_rR = -p l_t^(dim - 1); at the outer surface r(B) is
// prescribed. The unknown inner radius r(A) is found by the secant method.
#pragma once

#include <hyperelastic/materials/material.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hyperelastic::testing
{
  template <int dim>
  class RadialInflation
  {
  public:
    RadialInflation(const Material<dim> &material,
                    const double         A,
                    const double         B,
                    const double         pressure,
                    const double         outer_radius,
                    const unsigned int   steps = 20000)
        : material(material)
        , A(A)
        , B(B)
        , pressure(pressure)
        , steps(steps)
    {
      // Secant iteration on r(A) for r(B) = outer_radius.
      double x0 = A * outer_radius / B, x1 = 1.01 * x0;
      double f0 = shoot(x0) - outer_radius, f1 = shoot(x1) - outer_radius;
      // Stops at round-off: when r(B) no longer changes with r(A).
      for (int k = 0; k < 60 && std::abs(f1) > 1e-14 * B && f1 != f0; ++k)
        {
          // A secant step, at most 5 % of the radius (far from the root
          // the map is strongly nonlinear).
          const double step =
            std::clamp(-f1 * (x1 - x0) / (f1 - f0), -0.05 * x1, 0.05 * x1);
          const double x2 = x1 + step;
          x0              = x1;
          f0              = f1;
          x1              = x2;
          f1              = shoot(x1) - outer_radius;
        }
      if (!(std::abs(f1) <= 1e-11 * B))
        throw std::runtime_error(
          "RadialInflation: shooting did not converge (r(B) off by " +
          std::to_string(f1) + ")");
      inner = x1;
    }

    /// The deformed inner radius r(A).
    double
    inner_radius() const
    {
      return inner;
    }

  private:
    /// P_rR, P_tT, A_rrrr and A_rrtt (summed over the tangential stretches)
    /// at F = diag(l_r, l_t, ...).
    void
    radial_stress(const double l_r,
                  const double l_t,
                  double      &P_r,
                  double      &P_t,
                  double      &A_rr,
                  double      &A_rt) const
    {
      Tensor<2, dim> F;
      F[0][0] = l_r;
      for (unsigned int d = 1; d < dim; ++d)
        F[d][d] = l_t;
      Tensor<2, dim>     P;
      StressTangent<dim> T;
      material.stress_and_tangent(F, P, T);
      P_r  = P[0][0];
      P_t  = P[1][1];
      A_rr = T[0][0][0][0];
      A_rt = T[0][0][1][1];
    }

    /// The l_r with P_rR(l_r, l_t) = -p l_t^(dim-1): Newton from l_t, kept
    /// positive (P_rR grows with l_r).
    double
    inner_radial_stretch(const double l_t) const
    {
      double l_r = l_t;
      for (int k = 0; k < 200; ++k)
        {
          double P_r, P_t, A_rr, A_rt;
          radial_stress(l_r, l_t, P_r, P_t, A_rr, A_rt);
          const double f = P_r + pressure * std::pow(l_t, dim - 1);
          if (std::abs(f) < 1e-15)
            break;
          const double next = l_r - f / A_rr;
          l_r               = next > 0. ? next : 0.5 * l_r;
        }
      return l_r;
    }

    /// d(r, l_r)/dR.
    void
    rhs(const double R,
        const double r,
        const double l_r,
        double      &dr,
        double      &dl) const
    {
      const double l_t = r / R;
      double       P_r, P_t, A_rr, A_rt;
      radial_stress(l_r, l_t, P_r, P_t, A_rr, A_rt);
      dr = l_r;
      dl = (dim - 1) * ((P_t - P_r) - A_rt * (l_r - l_t)) / (R * A_rr);
    }

    /// r(B) for the inner radius r(A) = @p r_inner.
    double
    shoot(const double r_inner) const
    {
      double       r = r_inner, l = inner_radial_stretch(r_inner / A);
      const double h = (B - A) / steps;
      for (unsigned int k = 0; k < steps; ++k)
        {
          const double R = A + k * h;
          double       k1r, k1l, k2r, k2l, k3r, k3l, k4r, k4l;
          rhs(R, r, l, k1r, k1l);
          rhs(R + h / 2, r + h / 2 * k1r, l + h / 2 * k1l, k2r, k2l);
          rhs(R + h / 2, r + h / 2 * k2r, l + h / 2 * k2l, k3r, k3l);
          rhs(R + h, r + h * k3r, l + h * k3l, k4r, k4l);
          r += h / 6 * (k1r + 2 * k2r + 2 * k3r + k4r);
          l += h / 6 * (k1l + 2 * k2l + 2 * k3l + k4l);
        }
      return r;
    }

    const Material<dim> &material;
    const double         A, B, pressure;
    const unsigned int   steps;
    double               inner = 0.;
  };
} // namespace hyperelastic::testing
