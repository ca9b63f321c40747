// ParaView files (VTU/PVTU/PVD) and the per-step CSV summary.
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/numerics/data_out.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/output/output.h>

#include <boost/serialization/vector.hpp>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  OutputWriter<dim>::OutputWriter(const OutputParameters &parameters,
                                  const MPI_Comm          comm,
                                  const int               resumed_rows)
      : parameters(parameters)
      , comm(comm)
  {
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code ec;
        std::filesystem::create_directories(parameters.directory, ec);
        if (ec)
          error = "cannot create output folder '" + parameters.directory +
                  "' (Output/Directory): " + ec.message();
        else if (resumed_rows < 0)
          {
            csv.open(csv_file());
            if (!csv)
              error = "cannot write '" + csv_file() + "' (Output/Directory)";
          }
        else
          {
            // The header and the checkpointed steps' rows; rows of steps
            // after the checkpoint (a run that went on and then stopped)
            // go, the resumed run writes them again.
            std::ifstream            in(csv_file());
            std::vector<std::string> lines;
            for (std::string line;
                 lines.size() < std::size_t(resumed_rows) + 1 &&
                 std::getline(in, line);)
              lines.push_back(line);
            in.close();
            if (lines.size() < std::size_t(resumed_rows) + 1)
              error = "cannot restart the summary '" + csv_file() +
                      "': it has " +
                      std::to_string(lines.empty() ? 0 : lines.size() - 1) +
                      " rows, the checkpoint " + std::to_string(resumed_rows);
            else
              {
                csv.open(csv_file(), std::ios::trunc);
                for (const std::string &line : lines)
                  csv << line << '\n';
                csv.flush();
                if (!csv)
                  error =
                    "cannot write '" + csv_file() + "' (Output/Directory)";
              }
          }
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
  }

  template <int dim>
  std::string
  OutputWriter<dim>::csv_file() const
  {
    return parameters.directory + "/" + parameters.base_name + ".csv";
  }

  template <int dim>
  std::string
  OutputWriter<dim>::pvtu_file(const unsigned int step) const
  {
    // The name deal.II's write_vtu_with_pvtu_record gives with 4 digits.
    return parameters.directory + "/" + parameters.base_name + "_" +
           Utilities::int_to_string(step, 4) + ".pvtu";
  }

  template <int dim>
  void
  OutputWriter<dim>::write_fields(const unsigned int     step,
                                  const double           load_factor,
                                  const DoFHandler<dim> &dof_handler,
                                  const Mapping<dim>    &mapping,
                                  const TrilinosWrappers::MPI::Vector &u,
                                  const CellFields                    &fields,
                                  const std::vector<NodalField>       &nodal)
  {
    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    // The displacement, and the pressure of the mixed formulation.
    std::vector<std::string> field_names(dim, "displacement");
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(dim,
                     DataComponentInterpretation::component_is_part_of_vector);
    if (dof_handler.get_fe().n_components() > dim)
      {
        field_names.emplace_back("pressure");
        interpretation.push_back(
          DataComponentInterpretation::component_is_scalar);
      }
    data_out.add_data_vector(u,
                             field_names,
                             DataOut<dim>::type_dof_data,
                             interpretation);
    for (const NodalField &field : nodal)
      {
        // A vector on the displacement dofs (the mixed formulation's
        // pressure dofs carry a zero scalar '<name>_p').
        std::vector<std::string> names(dim, field.name);
        if (dof_handler.get_fe().n_components() > dim)
          names.push_back(field.name + "_p");
        data_out.add_data_vector(*field.values,
                                 names,
                                 DataOut<dim>::type_dof_data,
                                 interpretation);
      }
    data_out.add_data_vector(fields.J, "J", DataOut<dim>::type_cell_data);
    data_out.add_data_vector(fields.energy_density,
                             "energy_density",
                             DataOut<dim>::type_cell_data);
    data_out.add_data_vector(fields.von_mises,
                             "von_Mises_stress",
                             DataOut<dim>::type_cell_data);
    const char *names[6] = {"cauchy_xx",
                            "cauchy_yy",
                            "cauchy_zz",
                            "cauchy_xy",
                            "cauchy_xz",
                            "cauchy_yz"};
    for (unsigned int c = 0; c < 6; ++c)
      if (dim == 3 || c < 4)
        data_out.add_data_vector(fields.cauchy[c],
                                 names[c],
                                 DataOut<dim>::type_cell_data);
    if (fields.region.size() > 0)
      data_out.add_data_vector(fields.region,
                               "region",
                               DataOut<dim>::type_cell_data);
    if (fields.growth_J.size() > 0)
      data_out.add_data_vector(fields.growth_J,
                               "growth_J",
                               DataOut<dim>::type_cell_data);
    Vector<float> rank(dof_handler.get_triangulation().n_active_cells());
    rank = static_cast<float>(Utilities::MPI::this_mpi_process(comm));
    data_out.add_data_vector(rank, "mpi_rank", DataOut<dim>::type_cell_data);
    // P2: every cell becomes one quadratic VTK cell (6-node triangle,
    // 10-node tetrahedron) whose mid-edge nodes carry the mid-edge values,
    // so ParaView shows the field and the deformed edges as the element
    // has them. P1: linear cells.
    const unsigned int degree = dof_handler.get_fe().degree;
    data_out.build_patches(mapping, degree > 1 && parameters.write_vtu ? 2 : 1);
    if (parameters.write_vtu)
      write_vtu(data_out, step, load_factor);
    if (!parameters.write_hdf5)
      return;
    // deal.II 9.4's HDF5 writer fails on quadratic simplex patches: P2 is
    // written at its vertices.
    if (degree > 1 && parameters.write_vtu)
      data_out.build_patches(mapping, 1);
    write_hdf5(data_out, step, load_factor);
  }

  template <int dim>
  void
  OutputWriter<dim>::write_hdf5(const DataOut<dim> &data_out,
                                const unsigned int  step,
                                const double        load_factor)
  {
    // Every cell with its own vertices (as in the VTU files), so that the
    // cell fields keep their value per cell.
    DataOutBase::DataOutFilter filter(
      DataOutBase::DataOutFilterFlags(false, true));
    data_out.write_filtered_data(filter);
    const std::string folder = parameters.directory + "/";
    const std::string mesh   = parameters.base_name + "_mesh.h5";
    const std::string fields =
      parameters.base_name + "_" + Utilities::int_to_string(step, 4) + ".h5";
    data_out.write_hdf5_parallel(
      filter, xdmf_entries.empty(), folder + mesh, folder + fields, comm);
    xdmf_entries.push_back(
      data_out.create_xdmf_entry(filter, mesh, fields, load_factor, comm));
    const std::string xdmf = folder + parameters.base_name + ".xdmf";
    data_out.write_xdmf_file(xdmf_entries, xdmf + ".partial", comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code ec;
        std::filesystem::rename(xdmf + ".partial", xdmf, ec);
      }
  }

  template <int dim>
  std::string
  OutputWriter<dim>::packed_xdmf_entries() const
  {
    const std::vector<char> bytes = Utilities::pack(xdmf_entries, false);
    return std::string(bytes.begin(), bytes.end());
  }

  template <int dim>
  void
  OutputWriter<dim>::resume_xdmf_entries(const std::string &packed)
  {
    xdmf_entries = Utilities::unpack<std::vector<XDMFEntry>>(
      std::vector<char>(packed.begin(), packed.end()), false);
  }

  template <int dim>
  void
  OutputWriter<dim>::write_vtu(const DataOut<dim> &data_out,
                               const unsigned int  step,
                               const double        load_factor)
  {
    const std::string pvtu = data_out.write_vtu_with_pvtu_record(
      parameters.directory + "/", parameters.base_name, step, comm, 4);
    pvd_entries.emplace_back(load_factor, pvtu);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        // Written then renamed: a run killed meanwhile leaves the last
        // complete series.
        const std::string pvd_file =
          parameters.directory + "/" + parameters.base_name + ".pvd";
        {
          std::ofstream pvd(pvd_file + ".partial");
          DataOutBase::write_pvd_record(pvd, pvd_entries);
        }
        std::error_code ec;
        std::filesystem::rename(pvd_file + ".partial", pvd_file, ec);
      }
  }

  template <int dim>
  void
  OutputWriter<dim>::write_summary(const std::vector<SummaryColumn> &columns)
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    if (csv.tellp() == 0)
      {
        for (const auto &column : columns)
          csv << (&column == &columns.front() ? "" : ",") << column.name;
        csv << '\n';
      }
    csv << std::setprecision(16);
    for (const auto &column : columns)
      csv << (&column == &columns.front() ? "" : ",") << column.value;
    csv << std::endl;
  }

  template class OutputWriter<2>;
  template class OutputWriter<3>;
} // namespace hyperelastic
