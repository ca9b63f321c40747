// Cell averages of J, energy density and Cauchy stress for the VTU output.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>

#include <hyperelastic/assembly/material_point.h>
#include <hyperelastic/materials/model_capabilities.h>
#include <hyperelastic/output/cell_fields.h>

#include <cmath>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// The fields of @p n_cells cells, all zero (the sums start there).
    CellFields
    zero_fields(const unsigned int n_cells)
    {
      CellFields fields;
      fields.J.reinit(n_cells);
      fields.energy_density.reinit(n_cells);
      fields.von_mises.reinit(n_cells);
      for (auto &c : fields.cauchy)
        c.reinit(n_cells);
      return fields;
    }

    /// Whether a model of @p material varies with position (then the
    /// quadrature points are needed).
    template <int dim>
    bool
    any_depends_on_position(const MaterialRegions<dim> &material)
    {
      bool any_by_point = false;
      for (unsigned int r = 0; r < material.n_regions(); ++r)
        any_by_point = any_by_point || material.model(r).depends_on_position();
      return any_by_point;
    }

    /// Whether a model of @p material grows (then growth_J is written).
    template <int dim>
    bool
    any_grows(const MaterialRegions<dim> &material)
    {
      for (unsigned int r = 0; r < material.n_regions(); ++r)
        if (dynamic_cast<const GrowingMaterial *>(&material.model(r)))
          return true;
      return false;
    }

    /// The splits of each region's model of @p material and of its 3D twin
    /// in @p material3d, in the order of the regions, for the mixed
    /// formulation (none without @p mixed).
    template <int dim>
    void
    split_models(
      const MaterialRegions<dim>                         &material,
      const MaterialRegions<3>                           &material3d,
      const bool                                          mixed,
      std::vector<std::unique_ptr<VolumetricSplit<dim>>> &region_split,
      std::vector<std::unique_ptr<VolumetricSplit<3>>>   &region_split3d)
    {
      for (unsigned int r = 0; mixed && r < material.n_regions(); ++r)
        {
          region_split.push_back(material.model(r).volumetric_split());
          region_split3d.push_back(material3d.model(r).volumetric_split());
        }
    }

    /// Plane strain: the 3D F is diag(F, 1).
    template <int dim>
    Tensor<2, 3>
    three_dimensional(const Tensor<2, dim> &F)
    {
      Tensor<2, 3> F3 = unit_symmetric_tensor<3>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F3[i][j] = F[i][j];
      return F3;
    }

    /// Cell @p index's integrals of J and energy density over its
    /// @p volume made averages, and its Cauchy stress (the integral
    /// @p sigma) averaged into the components and the von Mises stress.
    void
    finish_cell(CellFields        &fields,
                const unsigned int index,
                const double       volume,
                Tensor<2, 3>       sigma)
    {
      fields.J[index] /= volume;
      fields.energy_density[index] /= volume;
      if (fields.growth_J.size() > 0)
        fields.growth_J[index] /= volume;
      sigma /= volume;
      const unsigned int pairs[6][2] = {
        {0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
      for (unsigned int c = 0; c < 6; ++c)
        fields.cauchy[c][index] = sigma[pairs[c][0]][pairs[c][1]];
      const Tensor<2, 3> dev =
        sigma - trace(sigma) / 3. * Tensor<2, 3>(unit_symmetric_tensor<3>());
      fields.von_mises[index] = std::sqrt(1.5 * scalar_product(dev, dev));
    }
  } // namespace

  template <int dim>
  CellFields
  compute_cell_fields(const DoFHandler<dim>               &dof_handler,
                      const Mapping<dim>                  &mapping,
                      const MaterialRegions<dim>          &material,
                      const MaterialRegions<3>            &material3d,
                      const TrilinosWrappers::MPI::Vector &u)
  {
    const unsigned int n_cells =
      dof_handler.get_triangulation().n_active_cells();
    CellFields fields = zero_fields(n_cells);
    if (any_grows(material))
      fields.growth_J.reinit(n_cells);

    const QGaussSimplex<dim> quadrature(dof_handler.get_fe().degree);
    // A model whose constants vary with position (fibre directions) is
    // evaluated at each quadrature point, with its 3D twin there.
    const bool any_by_point = any_depends_on_position(material);
    FEValues<dim>                    values(mapping,
                         dof_handler.get_fe(),
                         quadrature,
                         update_values | update_gradients | update_JxW_values |
                           (any_by_point ? update_quadrature_points
                                                            : update_default));
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      grad_u(quadrature.size());
    // Mixed formulation: the stress is P_iso + p J F^-T and the energy
    // density psi_iso + p (J - 1) - U*(p) (= psi where p = U'(J)), from the
    // pressure unknown; the full model may have kappa = infinity.
    const bool mixed = dof_handler.get_fe().n_components() > dim;
    // The splits of each region's model and of its 3D twin.
    std::vector<std::unique_ptr<VolumetricSplit<dim>>> region_split;
    std::vector<std::unique_ptr<VolumetricSplit<3>>>   region_split3d;
    split_models(material, material3d, mixed, region_split, region_split3d);
    std::unique_ptr<VolumetricSplit<dim>> point_split;
    std::unique_ptr<VolumetricSplit<3>>   point_split3d;
    // The model (and its 3D twin) at a point of a by_point model.
    std::unique_ptr<Material<dim>>   point_model;
    std::unique_ptr<Material<3>>     point_model3d;
    const FEValuesExtractors::Scalar pressure(dim);
    std::vector<double>              p(quadrature.size(), 0.);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          values[displacement].get_function_gradients(u, grad_u);
          if (mixed)
            values[pressure].get_function_values(u, p);
          const unsigned int    index      = cell->active_cell_index();
          const unsigned int    r          = material.region(index);
          const Material<dim>  &cell_model = material.model(r);
          const bool            by_point   = cell_model.depends_on_position();
          VolumetricSplit<dim> *split = mixed ? region_split[r].get() : nullptr;
          VolumetricSplit<3>   *split3d =
            mixed ? region_split3d[r].get() : nullptr;
          double       volume = 0.;
          Tensor<2, 3> sigma;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double         JxW = values.JxW(q);
              const Tensor<2, dim> F   = deformation_gradient_of(grad_u[q]);
              if (by_point)
                {
                  point_model =
                    cell_model.at_position(values.quadrature_point(q));
                  point_model3d = point_model->three_dimensional_twin();
                  if (mixed)
                    {
                      point_split   = point_model->volumetric_split();
                      point_split3d = point_model3d->volumetric_split();
                      split         = point_split.get();
                      split3d       = point_split3d.get();
                    }
                }
              const Material<dim> &model = by_point ? *point_model : cell_model;
              const Material<3>   &model3d =
                by_point ? *point_model3d : material3d.model(r);
              const Tensor<2, 3> F3 = three_dimensional(F);
              const double J = determinant(F);
              fields.J[index] += J * JxW;
              if (fields.growth_J.size() > 0)
                {
                  const auto *growing =
                    dynamic_cast<const GrowingMaterial *>(&model);
                  fields.growth_J[index] +=
                    (growing ? determinant(growing->growth_tensor()) : 1.) *
                    JxW;
                }
              // Cauchy stress sigma = P F^T / J.
              if (mixed)
                {
                  fields.energy_density[index] +=
                    (split->isochoric->energy_density(F) + p[q] * (J - 1.) -
                     split->volumetric.conjugate(p[q])) *
                    JxW;
                  sigma += (split3d->isochoric->first_piola_kirchhoff(F3) *
                              transpose(F3) / J +
                            p[q] * Tensor<2, 3>(unit_symmetric_tensor<3>())) *
                           JxW;
                }
              else
                {
                  fields.energy_density[index] += model.energy_density(F) * JxW;
                  sigma += model3d.first_piola_kirchhoff(F3) * transpose(F3) /
                           determinant(F3) * JxW;
                }
              volume += JxW;
            }
          finish_cell(fields, index, volume, sigma);
        }
    return fields;
  }

  template CellFields
  compute_cell_fields<2>(const DoFHandler<2> &,
                         const Mapping<2> &,
                         const MaterialRegions<2> &,
                         const MaterialRegions<3> &,
                         const TrilinosWrappers::MPI::Vector &);
  template CellFields
  compute_cell_fields<3>(const DoFHandler<3> &,
                         const Mapping<3> &,
                         const MaterialRegions<3> &,
                         const MaterialRegions<3> &,
                         const TrilinosWrappers::MPI::Vector &);
} // namespace hyperelastic
