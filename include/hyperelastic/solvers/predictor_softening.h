// A capability that only some nonlinear systems have: a gentler predictor
// where the tangent's own would invert cells (a large prescribed increment,
// the tangent's linear extension far outside its range). Newton asks for it
// where the tangent policy wants it, after a predictor's solve.
#pragma once

namespace hyperelastic
{
  // capability interface
  class PredictorSoftening
  {
  public:
    virtual ~PredictorSoftening() = default;

    /// Called after NonlinearSystem::solve_linearization() of a predictor
    /// (the linearization that imposed the constraint increment): if its
    /// update would invert cells of a state that has none, the system may
    /// replace it by a gentler extension of the increment into the body.
    /// Returns whether it did; @p linear_iterations gets the Krylov
    /// iterations spent on trying.
    virtual bool
    soften_predictor(unsigned int &linear_iterations) = 0;
  };
} // namespace hyperelastic
