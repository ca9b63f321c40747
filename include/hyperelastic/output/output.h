// What a run writes: per load step one .vtu per rank plus a .pvtu, a .pvd for
// the whole series (open it in ParaView), and a CSV summary with one row per
// converged load step.
#pragma once

#include <deal.II/base/data_out_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/data_out.h>

#include <hyperelastic/output/cell_fields.h>
#include <hyperelastic/output/output_parameters.h>
#include <hyperelastic/output/step_reporter.h>
#include <hyperelastic/output/step_summary.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class OutputWriter
  {
  public:
    /// Creates the output folder (collective; InputError if impossible).
    /// @p resumed_rows: a restart keeps the CSV's header and its first
    /// resumed_rows rows (those of the checkpointed steps) and appends;
    /// negative: a new CSV.
    OutputWriter(const OutputParameters &parameters,
                 MPI_Comm                comm,
                 int                     resumed_rows = -1);

    /// A vector field on the nodes besides the displacement
    /// (output/step_reporter.h).
    using NodalField = hyperelastic::NodalField;

    /// Writes <base>_<step>.<rank>.vtu, <base>_<step>.pvtu and rewrites
    /// <base>.pvd ('Write VTU'); with 'Write HDF5' <base>_<step>.h5 (and
    /// <base>_mesh.h5 the first time) and rewrites <base>.xdmf. @p u and
    /// the @p nodal fields must have ghost entries.
    void
    write_fields(unsigned int                                 step,
                 double                                       load_factor,
                 const dealii::DoFHandler<dim>               &dof_handler,
                 const dealii::Mapping<dim>                  &mapping,
                 const dealii::TrilinosWrappers::MPI::Vector &u,
                 const CellFields                            &fields,
                 const std::vector<NodalField>               &nodal = {});

    /// Appends one row to <base>.csv (rank 0 writes), after the header of
    /// the column names if the file is still empty.
    void
    write_summary(const std::vector<SummaryColumn> &columns);

    std::string
    csv_file() const;

    /// The .pvtu file of output step @p step.
    std::string
    pvtu_file(unsigned int step) const;

    /// The PVD's entries so far (time, .pvtu file), for a checkpoint.
    const std::vector<std::pair<double, std::string>> &
    series() const
    {
      return pvd_entries;
    }

    /// A restart: the PVD continues from @p entries.
    void
    resume_series(std::vector<std::pair<double, std::string>> entries)
    {
      pvd_entries = std::move(entries);
    }

    /// The XDMF index's entries so far, packed (for a checkpoint).
    std::string
    packed_xdmf_entries() const;

    /// A restart: the XDMF index continues from these entries.
    void
    resume_xdmf_entries(const std::string &packed);

  private:
    /// The VTU files of step @p step and the rewritten PVD.
    void
    write_vtu(const dealii::DataOut<dim> &data_out,
              unsigned int                step,
              double                      load_factor);

    /// The HDF5 files of step @p step and the rewritten XDMF index.
    void
    write_hdf5(const dealii::DataOut<dim> &data_out,
               unsigned int                step,
               double                      load_factor);

    const OutputParameters                      parameters;
    const MPI_Comm                              comm;
    std::vector<std::pair<double, std::string>> pvd_entries;
    std::vector<dealii::XDMFEntry>              xdmf_entries;
    std::ofstream                               csv;
  };
} // namespace hyperelastic
