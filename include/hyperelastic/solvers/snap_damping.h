// The damping energy of a damped snap step (pseudo-transient continuation,
// LoadStepper): c/2 (u - w)^T D (u - w) with D a diagonal metric (the lumped
// mass of unit density on the free unknowns, zero on prescribed ones and
// on pressures), c > 0 the step's damping (1 / h^2 of a pseudo time step h)
// and w the centre (the start of the sub-step). Its force c D (u - w) is
// added to the residual, c D to the tangent's diagonal, the energy to the
// total potential. Vector algebra only: the system owns it and calls it
// where it evaluates its own forces, tangent and energy.
#pragma once

#include <hyperelastic/base/linear_algebra.h>

namespace hyperelastic
{
  class SnapDamping
  {
  public:
    /// The metric @p diagonal (owned entries; zero where nothing is
    /// damped). Inactive (c = 0) until set().
    void
    initialize(const VectorType &diagonal);

    /// Whether initialize() was called.
    bool
    initialized() const
    {
      return diagonal.size() > 0;
    }

    /// Damping @p c (0: none) centred at @p centre (owned entries).
    void
    set(double c, const VectorType &centre);

    /// c of the current damping (0: inactive).
    double
    factor() const
    {
      return c;
    }

    /// Whether the damping acts (c > 0).
    bool
    active() const
    {
      return c > 0.;
    }

    /// Adds c D (@p u - w) to @p forces (owned entries of both; @p u may
    /// have ghost entries).
    void
    add_forces(const VectorType &u, VectorType &forces) const;

    /// The damping energy c/2 |@p u - w|_D^2 (collective).
    double
    energy(const VectorType &u) const;

    /// The l2 norm of the damping force c D (@p u - w) (collective).
    double
    force_norm(const VectorType &u) const;

    /// Adds c D to the diagonal of @p matrix and -c D (@p u - w) to
    /// @p rhs (the tangent and right-hand side of a linearization; D is
    /// zero on constrained rows, which stay as they are).
    void
    add_to_system(const VectorType &u,
                  MatrixType       &matrix,
                  VectorType       &rhs) const;

    /// The mean ratio of the @p matrix diagonal to D over the damped
    /// unknowns: the damping c at which c D matches the stiffness's
    /// diagonal on average (collective).
    double
    stiffness_ratio(const MatrixType &matrix) const;

  private:
    /// c D (u - w) into @p force (owned entries).
    void
    damping_force(const VectorType &u, VectorType &force) const;

    VectorType diagonal;
    VectorType centre;
    double     c = 0.;
  };
} // namespace hyperelastic
