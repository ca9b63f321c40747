// What a contact term measures at a converged state for the step's summary
// (the contact layer, contact/contact_layer.h, writes the columns).
#pragma once

#include <hyperelastic/output/step_summary.h>

#include <limits>
#include <vector>

namespace hyperelastic
{
  struct ContactMeasures
  {
    /// The force each obstacle exerts on the body, as columns
    /// contact_force_<k>_<axis> (obstacles only).
    std::vector<SummaryColumn> forces;
    /// The smallest distance of a vertex (pair) to what it may touch
    /// (self contact: capped at d_hat).
    double min_distance = std::numeric_limits<double>::infinity();
    /// The number of pairs closer than d_hat.
    double active_pairs = 0.;
  };
} // namespace hyperelastic
