// The material of every cell: the scene's models (0: the top-level Material,
// k: Region k's, materials/region_parameters.h) and the region of each cell
// (mesh/cell_regions.h). A small value that the assemblers, the cell fields
// and the solver's set-up copy; it does not own the models. A single
// Material converts to it (one region, no per-cell table), so that code and
// tests with one material for the whole mesh pass that material as before,
// and the P1 kernel's hot loop looks at no table then.
#pragma once

#include <hyperelastic/materials/material.h>

#include <algorithm>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class MaterialRegions
  {
  public:
    /// One material for the whole mesh.
    MaterialRegions(const Material<dim> &material)
        : models{&material}
    {
    }

    /// @p models[r] for the cells with region r (@p of_cell by active cell
    /// index, empty: region 0 everywhere).
    MaterialRegions(std::vector<const Material<dim> *> models,
                    std::vector<unsigned char>         of_cell)
        : models(std::move(models))
        , of_cell(std::move(of_cell))
    {
    }

    /// The model of the cell with active index @p cell.
    const Material<dim> &
    operator()(const unsigned int cell) const
    {
      return of_cell.empty() ? *models[0] : *models[of_cell[cell]];
    }

    /// The region of the cell with active index @p cell (0: top-level).
    unsigned int
    region(const unsigned int cell) const
    {
      return of_cell.empty() ? 0 : of_cell[cell];
    }

    unsigned int
    n_regions() const
    {
      return models.size();
    }

    /// The model of region @p r.
    const Material<dim> &
    model(const unsigned int r) const
    {
      return *models[r];
    }

    /// The top-level Material (region 0).
    const Material<dim> &
    top() const
    {
      return *models[0];
    }

    /// The region of each cell (empty: one region).
    const std::vector<unsigned char> &
    cell_regions() const
    {
      return of_cell;
    }

    /// The same regions with other models (@p models[r] for region r; the
    /// isochoric parts of the mixed formulation, the 3D twins).
    template <int other_dim>
    MaterialRegions<other_dim>
    with_models(std::vector<const Material<other_dim> *> other) const
    {
      return MaterialRegions<other_dim>(std::move(other), of_cell);
    }

    /// Whether every region's model is linear (one solve is the answer).
    bool
    is_linear() const
    {
      return std::all_of(models.begin(), models.end(), [](const auto *m) {
        return m->is_linear();
      });
    }

    /// Whether every region's model is defined for inverted cells.
    bool
    defined_for_inverted_elements() const
    {
      return std::all_of(models.begin(), models.end(), [](const auto *m) {
        return m->defined_for_inverted_elements();
      });
    }

    /// Whether some region's model has history or depends on position
    /// (then the assemblers keep a model per quadrature point).
    bool
    any_per_point() const
    {
      return std::any_of(models.begin(), models.end(), [](const auto *m) {
        return m->has_history() || m->depends_on_position();
      });
    }

    /// Whether some region's model has history.
    bool
    any_history() const
    {
      return std::any_of(models.begin(), models.end(), [](const auto *m) {
        return m->has_history();
      });
    }

    /// The rest moduli of the stiffest region (largest lambda + 2 mu, the
    /// P-wave modulus): the scale of round-off estimates and of the
    /// automatic contact stiffness.
    LameParameters
    stiffest_moduli() const
    {
      LameParameters stiffest = models[0]->small_strain_moduli();
      for (const auto *m : models)
        {
          const LameParameters l = m->small_strain_moduli();
          if (l.lambda + 2. * l.mu > stiffest.lambda + 2. * stiffest.mu)
            stiffest = l;
        }
      return stiffest;
    }

    /// The largest rest shear modulus of the regions.
    double
    largest_shear_modulus() const
    {
      double mu = 0.;
      for (const auto *m : models)
        mu = std::max(mu, m->small_strain_moduli().mu);
      return mu;
    }

    /// The rest moduli of the softest region (smallest shear modulus).
    LameParameters
    softest_moduli() const
    {
      LameParameters softest = models[0]->small_strain_moduli();
      for (const auto *m : models)
        if (m->small_strain_moduli().mu < softest.mu)
          softest = m->small_strain_moduli();
      return softest;
    }

  private:
    std::vector<const Material<dim> *> models;
    std::vector<unsigned char>         of_cell;
  };
} // namespace hyperelastic
