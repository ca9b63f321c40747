// Serial mesh generation or reading, METIS partitioning and distribution.
#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>

#include <hyperelastic/error_handling.h>
#include <hyperelastic/mesh.h>

#include <fstream>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  set_box_boundary_ids(Triangulation<dim> &tria)
  {
    const BoundingBox<dim> box = GridTools::compute_bounding_box(tria);
    const double           tol = 1e-10 * box.side_length(0);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<dim> c = face->center();
            for (unsigned int d = 0; d < dim; ++d)
              {
                if (std::abs(c[d] - box.lower_bound(d)) < tol)
                  face->set_boundary_id(2 * d);
                else if (std::abs(c[d] - box.upper_bound(d)) < tol)
                  face->set_boundary_id(2 * d + 1);
              }
          }
  }

  namespace
  {
    template <int dim>
    void
    read_gmsh(const std::string &file_name, Triangulation<dim> &tria)
    {
      std::ifstream in(file_name);
      if (!in)
        throw InputError("cannot open mesh file '" + file_name +
                         "' (Mesh/File)");
      // deal.II's reader handles ASCII files only; say so rather than let it
      // fail on binary data.
      std::string keyword, version;
      int         file_type = 0;
      in >> keyword;
      if (keyword == "$MeshFormat")
        in >> version >> file_type;
      if (file_type != 0)
        throw InputError(
          "mesh file '" + file_name +
          "' is a binary gmsh file; save it as ASCII (gmsh "
          "option -format msh41 without -bin, or Mesh.Binary = 0)");
      in.clear();
      in.seekg(0);

      GridIn<dim> grid_in;
      grid_in.attach_triangulation(tria);
      try
        {
          grid_in.read_msh(in);
        }
      catch (const std::exception &e)
        {
          throw InputError("cannot read mesh file '" + file_name +
                           "' as a gmsh mesh of dimension " +
                           std::to_string(dim) + ": " + exception_message(e));
        }
      if (tria.n_active_cells() == 0)
        throw InputError("mesh file '" + file_name +
                         "' has no cells of dimension " + std::to_string(dim));
      for (const auto &cell : tria.active_cell_iterators())
        if (!cell->reference_cell().is_simplex())
          throw InputError("mesh file '" + file_name + "': cell " +
                           std::to_string(cell->active_cell_index()) +
                           " is not a simplex (hyperelastic needs " +
                           (dim == 2 ? "triangles" : "tetrahedra") + ")");
    }
  } // namespace

  template <int dim>
  std::set<types::boundary_id>
  create_mesh(const MeshParameters                           &parameters,
              parallel::fullydistributed::Triangulation<dim> &tria)
  {
    const MPI_Comm comm = tria.get_communicator();

    // Every rank builds the same serial mesh; it is dropped at the end of this
    // function, once each rank has extracted its own part.
    Triangulation<dim> serial;
    if (parameters.source == MeshSource::box)
      {
        Point<dim>                p1, p2;
        std::vector<unsigned int> repetitions(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            p1[d]          = parameters.lower_corner[d];
            p2[d]          = parameters.upper_corner[d];
            repetitions[d] = parameters.subdivisions[d];
          }
        GridGenerator::subdivided_hyper_rectangle_with_simplices(serial,
                                                                 repetitions,
                                                                 p1,
                                                                 p2);
        set_box_boundary_ids(serial);
      }
    else
      read_gmsh(parameters.file, serial);

    serial.refine_global(parameters.global_refinements);

    const std::vector<types::boundary_id> ids = serial.get_boundary_ids();

    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    if (n_ranks > 1)
      GridTools::partition_triangulation(n_ranks,
                                         serial,
                                         SparsityTools::Partitioner::metis);
    const auto description = TriangulationDescription::Utilities::
      create_description_from_triangulation(serial, comm);
    tria.create_triangulation(description);
    return std::set<types::boundary_id>(ids.begin(), ids.end());
  }

  template void
  set_box_boundary_ids(Triangulation<2> &);
  template void
  set_box_boundary_ids(Triangulation<3> &);
  template std::set<types::boundary_id>
  create_mesh(const MeshParameters &,
              parallel::fullydistributed::Triangulation<2> &);
  template std::set<types::boundary_id>
  create_mesh(const MeshParameters &,
              parallel::fullydistributed::Triangulation<3> &);
} // namespace hyperelastic
