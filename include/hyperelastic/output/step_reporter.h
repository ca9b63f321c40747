// What a part of the program reports about a run, through one interface: the
// lines it adds to the run's header, its CSV columns for each converged step,
// the nodal fields it adds to the written frames and the lines on its cost
// after the run. The time-stepping driver, the step post-processor and the
// contact layer implement it; Problem calls the reporters in a fixed order and
// knows none of them by type. Each reporter writes only its own columns.
#pragma once

#include <hyperelastic/base/linear_algebra.h>
#include <hyperelastic/output/step_summary.h>

#include <ostream>
#include <string>
#include <vector>

namespace hyperelastic
{
  /// A converged state as the reporters see it.
  struct ReportedState
  {
    /// The displacement (and pressures), ghosted.
    const VectorType &u;
    /// f_int - f_ext (owned entries): on supported dofs, the support forces.
    const VectorType &residual_forces;
    /// The load factor, or the time.
    double t;
  };

  /// A vector field on the nodes besides the displacement ("velocity" in
  /// dynamics, "contact_force" with contact), ghosted; the reporter that
  /// gives it keeps the values until the frame is written.
  struct NodalField
  {
    std::string       name;
    const VectorType *values;
  };

  template <int dim>
  class StepReporter
  {
  public:
    virtual ~StepReporter() = default;

    /// Lines for the run's header (what the part does, its settings).
    virtual void
    print_header(std::ostream &out) const
    {
      (void)out;
    }

    /// Adds the part's columns (and summary fields) at the converged
    /// @p state to @p summary. Collective.
    virtual void
    add_columns(const ReportedState &state, StepSummary<dim> &summary) = 0;

    /// Adds the part's nodal fields at @p state to @p fields. Collective.
    virtual void
    add_nodal_fields(const ReportedState &state, std::vector<NodalField> &fields)
    {
      (void)state, (void)fields;
    }

    /// Lines on where the part's time went, after the run (rank 0's).
    virtual void
    print_cost(std::ostream &out) const
    {
      (void)out;
    }
  };
} // namespace hyperelastic
