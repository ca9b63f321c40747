// HDF5/XDMF output (issue 31; 'Output/Write HDF5'): the unit box
// stretched homogeneously (rollers x = 0, y = 0, z = 0, the face x = 1
// pulled to 1.3 in two load steps), x = diag(l) X with l from the CSV's
// deformed extents. The files are read back with the HDF5 library:
//   hdf5_output DIM DEGREE   <base>.xdmf lists frames 0, 1, 2 with the
//       mesh's simplices (Triangle / Tetrahedron, as many as cells);
//       <base>_mesh.h5 holds (dim + 1) nodes per cell; at every node of
//       <base>_0002.h5 the displacement is (l - 1) X and J = l1 l2 (l3) to
//       the Float32 rounding of deal.II's patches (1.2e-7 relative; the
//       errors are 0 or one rounding); P2 is written at its vertices.
// (The VTU files hold the same Float32 values; the comparison against the
// exact field is the stronger check.)
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>

#include <hdf5.h>

#include "support/checker.h"
#include "support/dimension_main.h"
#include "support/scene_run.h"
#include "support/scene_text.h"
#include "support/stretched_box.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using namespace dealii;
  using namespace hyperelastic;
  using namespace hyperelastic::testing;

  /// A dataset of doubles: its values (row-major) and dimensions.
  struct Dataset
  {
    std::vector<double>  values;
    std::vector<hsize_t> dims;
  };

  Dataset
  read_dataset(const std::string &file, const std::string &name)
  {
    Dataset     d;
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0)
      throw std::runtime_error("cannot open '" + file + "'");
    const hid_t set = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
    if (set < 0)
      throw std::runtime_error("no dataset '" + name + "' in '" + file + "'");
    const hid_t space = H5Dget_space(set);
    d.dims.resize(H5Sget_simple_extent_ndims(space));
    H5Sget_simple_extent_dims(space, d.dims.data(), nullptr);
    hsize_t n = 1;
    for (const hsize_t k : d.dims)
      n *= k;
    d.values.resize(n);
    H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT,
            d.values.data());
    H5Sclose(space);
    H5Dclose(set);
    H5Fclose(f);
    return d;
  }

  template <int dim>
  void
  check(Checker &checker, const unsigned int degree)
  {
    const bool        three = dim == 3;
    const std::string dir   = "hdf5_output_" + std::to_string(dim) + "d_p" +
                            std::to_string(degree) + "_np" +
                            std::to_string(Utilities::MPI::n_mpi_processes(
                              MPI_COMM_WORLD));
    const auto problem = run_scene<dim>(stretched_unit_box(
      dim,
      three ? "2, 2, 2" : "3, 3",
      entry("Directory", dir) + entry("Base name", "box") +
        entry("Write HDF5", "true"),
      entry("Finite element degree", std::to_string(degree))));
    MPI_Barrier(MPI_COMM_WORLD);
    const std::string tag =
      std::to_string(dim) + "D P" + std::to_string(degree) + ": ";
    const unsigned int n_cells =
      problem->get_dof_handler().get_triangulation().n_global_active_cells();
    const std::array<double, 3> l = box_stretches(problem->summaries().back());

    // The XDMF index.
    std::ifstream      in(dir + "/box.xdmf");
    std::ostringstream text;
    text << in.rdbuf();
    const std::string xdmf = text.str();
    unsigned int      frames = 0;
    for (std::size_t at = xdmf.find("<Time Value"); at != std::string::npos;
         at             = xdmf.find("<Time Value", at + 1))
      ++frames;
    checker.is_true(tag + "the XDMF index lists 3 frames (" +
                      std::to_string(frames) + ")",
                    frames == 3);
    const std::string topology =
      std::string("TopologyType=\"") + (three ? "Tetrahedron" : "Triangle") +
      "\" NumberOfElements=\"" + std::to_string(n_cells) + "\"";
    checker.is_true(tag + "XDMF topology: " + topology,
                    xdmf.find(topology) != std::string::npos);
    checker.is_true(tag + "one HDF5 file per frame and the mesh once",
                    std::filesystem::exists(dir + "/box_mesh.h5") &&
                      std::filesystem::exists(dir + "/box_0000.h5") &&
                      std::filesystem::exists(dir + "/box_0002.h5") &&
                      !std::filesystem::exists(dir + "/box_0003.h5"));

    const Dataset nodes = read_dataset(dir + "/box_mesh.h5", "/nodes");
    const Dataset u     = read_dataset(dir + "/box_0002.h5", "/displacement");
    const Dataset J     = read_dataset(dir + "/box_0002.h5", "/J");
    const hsize_t n     = nodes.dims[0], width = nodes.dims[1];
    checker.is_true(tag + "(dim + 1) nodes per cell: " + std::to_string(n),
                    n == n_cells * (dim + 1) && u.dims[0] == n &&
                      J.dims[0] == n);
    double error_u = 0., error_J = 0.;
    const double exact_J = l[0] * l[1] * l[2];
    for (hsize_t k = 0; k < n; ++k)
      {
        for (unsigned int d = 0; d < dim; ++d)
          error_u = std::max(error_u,
                             std::abs(u.values[k * u.dims[1] + d] -
                                      (l[d] - 1.) * nodes.values[k * width + d]));
        error_J = std::max(error_J, std::abs(J.values[k] - exact_J));
      }
    // deal.II's patches hold Float32 values: the files have the float
    // nearest to each value (relative 2^-24 = 6e-8).
    checker.at_most(tag + "displacement at every node = (l - 1) X, to "
                          "Float32 (relative to the largest |u| = l - 1)",
                    error_u / (l[0] - 1.),
                    1.2e-7);
    checker.at_most(tag + "J at every node = l1 l2 l3, to Float32",
                    error_J / exact_J,
                    1.2e-7);
  }
} // namespace

int
main(int argc, char **argv)
{
  return run_for_dimension(
    argc, argv, 1, [&](const int dim, Checker &checker, bool) {
      const unsigned int degree = argc > 2 ? std::atoi(argv[2]) : 1;
      dim == 2 ? check<2>(checker, degree) : check<3>(checker, degree);
    });
}
