// The region of each cell and the input errors of the regions against the
// mesh.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/cell_regions.h>

#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// The condition 'Cells' of @p region as a function of the point;
    /// InputError naming the entry if it does not parse.
    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    cell_condition(const RegionParameters &region)
    {
      const std::string variables = dim == 2 ? "x,y" : "x,y,z";
      auto              function  = std::make_unique<FunctionParser<dim>>(1);
      try
        {
          function->initialize(variables,
                               region.cells,
                               std::map<std::string, double>());
          // muparser reports unknown names on the first evaluation.
          function->value(Point<dim>());
        }
      catch (...)
        {
          throw InputError("scene entry '" + region.name() + "/Cells' = '" +
                           region.cells +
                           "': cannot parse the condition (an expression of " +
                           variables + ", e.g. 'x > 0.5')");
        }
      return function;
    }

    /// The physical tags of the cells over all ranks, as text.
    template <int dim>
    std::string
    mesh_tags(const Triangulation<dim> &triangulation)
    {
      std::set<unsigned int> local;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          local.insert(cell->material_id());
      std::set<unsigned int> all;
      for (const std::vector<unsigned int> &tags :
           Utilities::MPI::all_gather(triangulation.get_communicator(),
                                      std::vector<unsigned int>(local.begin(),
                                                                local.end())))
        all.insert(tags.begin(), tags.end());
      std::string text;
      for (const unsigned int t : all)
        text += (text.empty() ? "" : ", ") + std::to_string(t);
      return text;
    }
  } // namespace

  template <int dim>
  CellRegions
  assign_cell_regions(const Triangulation<dim>            &triangulation,
                      const std::vector<RegionParameters> &regions)
  {
    CellRegions result;
    result.n_cells.assign(regions.size() + 1, 0);
    const MPI_Comm comm = triangulation.get_communicator();
    if (regions.empty())
      {
        result.n_cells[0] = triangulation.n_global_active_cells();
        return result;
      }
    // Every rank parses the same text: the same verdict everywhere.
    std::vector<std::unique_ptr<FunctionParser<dim>>> condition(regions.size());
    for (unsigned int r = 0; r < regions.size(); ++r)
      if (!regions[r].cells.empty())
        condition[r] = cell_condition<dim>(regions[r]);

    result.of_cell.assign(triangulation.n_active_cells(), 0);
    std::string overlap;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        const Point<dim> centre = cell->center();
        for (unsigned int r = 0; r < regions.size(); ++r)
          {
            const bool in =
              condition[r] ? condition[r]->value(centre) != 0.
                           : int(cell->material_id()) == regions[r].material_id;
            if (!in)
              continue;
            const unsigned int before =
              result.of_cell[cell->active_cell_index()];
            if (before != 0 && cell->is_locally_owned() && overlap.empty())
              {
                std::ostringstream where;
                where << "the cell with centre (" << centre
                      << ") is selected by two regions, '"
                      << regions[before - 1].name() << "' and '"
                      << regions[r].name()
                      << "': a cell belongs to one region at most (make the "
                         "conditions exclusive)";
                overlap = where.str();
              }
            result.of_cell[cell->active_cell_index()] = r + 1;
          }
        if (cell->is_locally_owned())
          ++result.n_cells[result.of_cell[cell->active_cell_index()]];
      }
    throw_input_error_of_first_rank(overlap, comm);
    MPI_Allreduce(MPI_IN_PLACE,
                  result.n_cells.data(),
                  static_cast<int>(result.n_cells.size()),
                  MPI_UNSIGNED_LONG_LONG,
                  MPI_SUM,
                  comm);

    for (unsigned int r = 0; r < regions.size(); ++r)
      if (result.n_cells[r + 1] == 0)
        {
          const RegionParameters &region = regions[r];
          if (region.material_id >= 0)
            throw InputError("scene entry '" + region.name() +
                             "/Material id' = '" +
                             std::to_string(region.material_id) +
                             "': the mesh has no cell with this physical "
                             "tag (its cells' tags: " +
                             mesh_tags(triangulation) + ")");
          throw InputError("scene entry '" + region.name() + "/Cells' = '" +
                           region.cells +
                           "': the region selects no cell (no cell centre "
                           "satisfies the condition)");
        }
    return result;
  }

  template CellRegions
  assign_cell_regions(const Triangulation<2> &,
                      const std::vector<RegionParameters> &);
  template CellRegions
  assign_cell_regions(const Triangulation<3> &,
                      const std::vector<RegionParameters> &);
} // namespace hyperelastic
