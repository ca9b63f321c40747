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
  TimeIntegrator::step_target(const double      h,
                              const VectorType &u_n,
                              const VectorType &v_n,
                              const VectorType &a_n,
                              double           &c,
                              VectorType       &w) const
  {
    VectorType damped(u_n);
    double     c_inertia = 0., c_damping = 0.;
    if (scheme == TimeScheme::backward_euler)
      {
        // Inertia 1/h^2 |u - (u_n + h v_n)|^2; damping force alpha M (u -
        // u_n) / h, i.e. alpha/h |u - u_n|^2 / 2.
        w = u_n;
        w.add(h, v_n);
        c_inertia = 1. / (h * h);
        c_damping = mass_damping / h;
      }
    else if (scheme == TimeScheme::midpoint)
      {
        // Inertia 4/h^2 |u - (u_n + h/2 v_n)|^2 / 2 for the midpoint state
        // u; damping alpha M 2 (u - u_n) / h.
        w = u_n;
        w.add(0.5 * h, v_n);
        c_inertia = 4. / (h * h);
        c_damping = 2. * mass_damping / h;
      }
    else
      {
        // Inertia 4/h^2 |u - u_pred|^2 / 2; damping alpha M v with v = v_n +
        // h/2 a_n + 2/h (u - u_pred): alpha 2/h |u - (u_pred - h/2 (v_n +
        // h/2 a_n))|^2 / 2.
        w = u_n;
        w.add(h, v_n, 0.25 * h * h, a_n);
        damped = w;
        damped.add(-0.5 * h, v_n, -0.25 * h * h, a_n);
        c_inertia = 4. / (h * h);
        c_damping = 2. * mass_damping / h;
      }
    c = c_inertia + c_damping;
    if (c_damping > 0.)
      {
        // c_i/2 |u - w|^2 + c_d/2 |u - d|^2 = c/2 |u - (c_i w + c_d d)/c|^2
        // + constant.
        w.sadd(c_inertia / c, c_damping / c, damped);
      }
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
