// The regions' stiffness contrast, boundary moduli and densities (see the
// header).
#include <deal.II/base/mpi.h>

#include <hyperelastic/assembly/assembly_tools.h>
#include <hyperelastic/materials/region_properties.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hyperelastic
{
  template <int dim>
  double
  stiffness_contrast(const MaterialRegions<dim> &materials,
                     const CellRegions          &cell_regions)
  {
    // The small-strain stiffness lambda + 2 mu of each region with cells
    // (an incompressible region's is infinite: its own stiffness then
    // comes from the mixed formulation's pressure, and mu decides).
    double smallest = std::numeric_limits<double>::infinity(), largest = 0.;
    for (unsigned int r = 0; r < materials.n_regions(); ++r)
      if (cell_regions.n_cells.empty() || cell_regions.n_cells[r] > 0)
        {
          const LameParameters m = materials.model(r).small_strain_moduli();
          const double         stiffness =
            std::isfinite(m.lambda) ? m.lambda + 2. * m.mu : 2. * m.mu;
          smallest = std::min(smallest, stiffness);
          largest  = std::max(largest, stiffness);
        }
    return smallest > 0. ? largest / smallest : 1.;
  }

  template <int dim>
  LameParameters
  boundary_moduli(const MaterialRegions<dim>       &materials,
                  const CellRegions                &cell_regions,
                  const dealii::Triangulation<dim> &triangulation)
  {
    if (materials.n_regions() == 1)
      return materials.model(0).small_strain_moduli();
    // The regions with a cell at the boundary (where contact acts).
    std::vector<double> touches(materials.n_regions(), 0.);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        touches[cell_regions(cell->active_cell_index())] = 1.;
    touches = summed_over_ranks(touches, triangulation.get_communicator());
    std::vector<const Material<dim> *> on_boundary;
    for (unsigned int r = 0; r < touches.size(); ++r)
      if (touches[r] > 0.)
        on_boundary.push_back(&materials.model(r));
    return MaterialRegions<dim>(on_boundary, {}).stiffest_moduli();
  }

  std::vector<double>
  region_densities(const std::vector<RegionParameters> &regions,
                   const double                         density)
  {
    std::vector<double> densities;
    if (regions.empty())
      return densities;
    densities.push_back(density);
    for (const RegionParameters &region : regions)
      densities.push_back(region.own_density ? region.density : density);
    return densities;
  }

  template double
  stiffness_contrast(const MaterialRegions<2> &, const CellRegions &);
  template double
  stiffness_contrast(const MaterialRegions<3> &, const CellRegions &);
  template LameParameters
  boundary_moduli(const MaterialRegions<2> &,
                  const CellRegions &,
                  const dealii::Triangulation<2> &);
  template LameParameters
  boundary_moduli(const MaterialRegions<3> &,
                  const CellRegions &,
                  const dealii::Triangulation<3> &);
} // namespace hyperelastic
