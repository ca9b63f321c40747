// Backward Euler and Newmark (average acceleration) as targets of the
// incremental potential and velocity/acceleration updates.
#include <hyperelastic/dynamics/time_integrator.h>

namespace hyperelastic
{
  TimeIntegrator::TimeIntegrator(const TimeScheme scheme,
                                 const double     mass_damping)
      : scheme(scheme)
      , mass_damping(mass_damping)
  {
  }

  void
  TimeIntegrator::velocity_map(const double      h,
                               const VectorType &u_n,
                               const VectorType &v_n,
                               double           &kappa,
                               VectorType       &d) const
  {
    // Backward Euler v = (u - u_n) / h; midpoint (u the midpoint state)
    // v = 2 (u - u_n) / h; Newmark v = v_n + h/2 a_n + 2/h (u - u_n - h v_n
    // - h^2/4 a_n) = 2/h (u - (u_n + h/2 v_n)).
    d = u_n;
    if (scheme == TimeScheme::newmark)
      d.add(0.5 * h, v_n);
    kappa = scheme == TimeScheme::backward_euler ? 1. / h : 2. / h;
  }

  void
  TimeIntegrator::step_target(const double      h,
                              const VectorType &u_n,
                              const VectorType &v_n,
                              const VectorType &a_n,
                              double           &c,
                              VectorType       &w) const
  {
    // Inertia c_i/2 |u - w_i|_M^2: backward Euler c_i = 1/h^2, w_i = u_n +
    // h v_n; midpoint (for the midpoint state) 4/h^2, u_n + h/2 v_n; Newmark
    // 4/h^2, u_pred = u_n + h v_n + h^2/4 a_n.
    w = u_n;
    if (scheme == TimeScheme::backward_euler)
      w.add(h, v_n);
    else if (scheme == TimeScheme::midpoint)
      w.add(0.5 * h, v_n);
    else
      w.add(h, v_n, 0.25 * h * h, a_n);
    const double c_inertia =
      scheme == TimeScheme::backward_euler ? 1. / (h * h) : 4. / (h * h);
    c = c_inertia;
    if (!(mass_damping > 0.))
      return;
    // Mass damping alpha M v(u) = alpha kappa M (u - d): c_i/2 |u - w_i|^2 +
    // c_d/2 |u - d|^2 = c/2 |u - (c_i w_i + c_d d)/c|^2 + constant.
    double     kappa = 0.;
    VectorType d(u_n);
    velocity_map(h, u_n, v_n, kappa, d);
    const double c_damping = mass_damping * kappa;
    c                      = c_inertia + c_damping;
    w.sadd(c_inertia / c, c_damping / c, d);
  }

  void
  TimeIntegrator::finish_step(const double      h,
                              const VectorType &u_n,
                              const VectorType &v_n,
                              const VectorType &a_n,
                              const VectorType &u,
                              VectorType       &v,
                              VectorType       &a) const
  {
    if (scheme == TimeScheme::backward_euler ||
        scheme == TimeScheme::midpoint)
      {
        // v = (u - u_n) / h (midpoint: 2 (u - u_n) / h - v_n), a = (v -
        // v_n) / h.
        v = u;
        v.add(-1., u_n);
        if (scheme == TimeScheme::midpoint)
          v.sadd(2. / h, -1., v_n);
        else
          v *= 1. / h;
        a = v;
        a.add(-1., v_n);
        a *= 1. / h;
        return;
      }
    // a = 4/h^2 (u - u_n - h v_n - h^2/4 a_n), v = v_n + h/2 (a_n + a).
    a = u;
    a.add(-1., u_n, -h, v_n);
    a.add(-0.25 * h * h, a_n);
    a *= 4. / (h * h);
    v = v_n;
    v.add(0.5 * h, a_n, 0.5 * h, a);
  }
} // namespace hyperelastic
