// The implicit time-stepping schemes as vector algebra, knowing nothing of
// elements: for a step of length h from (u_n, v_n, a_n) the inertia term's
// scale c and target w (the step minimises c/2 |u - w|_M^2 + Psi(u) - W(u)),
// and after convergence the new velocity and acceleration.
//   backward Euler: M (u - u_n - h v_n) / h^2 + f_int(u) = f_ext,
//     v = (u - u_n) / h, a = (v - v_n) / h;
//   Newmark (beta = 1/4, gamma = 1/2): u_pred = u_n + h v_n + h^2/4 a_n,
//     4/h^2 M (u - u_pred) + f_int(u) = f_ext, a = 4/h^2 (u - u_pred),
//     v = v_n + h/2 (a_n + a).
//   implicit midpoint: the unknown is u at t_n + h/2 (loads there too),
//     4/h^2 M (u - u_n - h/2 v_n) + f_int(u) = f_ext(t_n + h/2), then
//     u_n+1 = 2 u - u_n, v = 2 (u_n+1 - u_n) / h - v_n, a = (v - v_n) / h.
// Forces held at the end of the step (contact: the barrier and friction at
// the end state) take the whole step's impulse h f_c(u_n+1) in every scheme:
// backward Euler and midpoint do so as they are; Newmark would average them
// over the step (the trapezoidal rule), which gains energy at a stiff
// barrier's impact, so it weighs them twice in the step's equations,
//   4/h^2 M (u - u_pred) + f_int(u) = f_ext + 2 f_c(u),
// keeps a_n+1 = 4/h^2 (u - u_pred) - 2 M^-1 f_c (the acceleration of the
// other forces) and v = v_n + h/2 (a_n + a_n+1) + h M^-1 f_c. The kinetic
// energy then changes by the trapezoidal work of the other forces plus
// f_c(u_n+1) . (u_n+1 - u_n), which for a barrier convex along the step is
// at most -(V(u_n+1) - V(u_n)): contact never adds energy (issue 41).
// The end velocity is affine in the solved u, v = kappa (u - d)
// (velocity_map): mass damping alpha M v(u) is absorbed by c and w,
// stiffness damping b K0 v(u) is a term of its own (stiffness_damping.h).
#pragma once

#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/dynamics/time_integration_parameters.h>

namespace hyperelastic
{
  class TimeIntegrator
  {
  public:
    TimeIntegrator(TimeScheme scheme, double mass_damping);

    /// The inertia term of the step of length @p h: @p c and @p w.
    void
    step_target(double            h,
                const VectorType &u_n,
                const VectorType &v_n,
                const VectorType &a_n,
                double           &c,
                VectorType       &w) const;

    /// The end-of-step velocity (implicit midpoint: the step's mean
    /// velocity) as an affine function of the solved u: v = @p kappa (u -
    /// @p d).
    void
    velocity_map(double            h,
                 const VectorType &u_n,
                 const VectorType &v_n,
                 double           &kappa,
                 VectorType       &d) const;

    /// The time at which the step from @p t_n to @p t_end solves its
    /// equations (implicit midpoint: half way; otherwise @p t_end).
    double
    evaluation_time(double t_n, double t_end) const
    {
      return scheme == TimeScheme::midpoint ? 0.5 * (t_n + t_end) : t_end;
    }

    /// The weight of the forces held at the end of the step (contact) in
    /// the step's equations: 2 for Newmark (the step's whole impulse; see
    /// above), 1 otherwise.
    double
    end_force_weight() const
    {
      return scheme == TimeScheme::newmark ? 2. : 1.;
    }

    /// The end state from the solved one, in place (implicit midpoint:
    /// u_n+1 = 2 u - u_n; otherwise unchanged).
    void
    end_state(const VectorType &u_n, VectorType &u) const
    {
      if (scheme == TimeScheme::midpoint)
        u.sadd(2., -1., u_n);
    }

    /// The velocity and acceleration at the end of the step that reached
    /// @p u from (u_n, v_n, a_n); @p v and @p a are overwritten (they may
    /// not alias the old ones).
    void
    finish_step(double            h,
                const VectorType &u_n,
                const VectorType &v_n,
                const VectorType &a_n,
                const VectorType &u,
                VectorType       &v,
                VectorType       &a) const;

  private:
    const TimeScheme scheme;
    const double     mass_damping;
  };
} // namespace hyperelastic
