// A scene as built: the mesh with its regions and boundary regions, the
// formulation's element and dofs, the loads, the materials of the regions,
// and the operator with its terms (the scene's loads, contact). A run
// (Problem) drives it. The materials, and the operator and terms that
// depend on them, can be built anew with other constants (a calibration's
// trials) on the same mesh, dofs and loads.
#pragma once

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/assembly/material_regions.h>
#include <hyperelastic/formulation/formulation.h>
#include <hyperelastic/loads/boundary_conditions.h>
#include <hyperelastic/materials/material.h>
#include <hyperelastic/mesh/boundary_regions.h>
#include <hyperelastic/mesh/cell_regions.h>
#include <hyperelastic/output/step_reporter.h>
#include <hyperelastic/scene/parameters.h>

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace hyperelastic
{
  template <int dim>
  class Model
  {
  public:
    /// The formulation of @p parameters and an empty mesh on @p comm.
    Model(const Parameters &parameters, MPI_Comm comm);

    /// Builds the mesh of 'Mesh', its regions and boundary regions, the
    /// loads (then edited by @p load_editor, if any) and the dofs.
    /// Returns the stages' wall times (MeshStatistics' and "dofs").
    /// Collective.
    std::vector<std::pair<std::string, double>>
    build_mesh(
      const Parameters                                     &parameters,
      const std::function<void(BoundaryConditions<dim> &)> &load_editor);

    /// (Re)builds the materials of the top-level @p material and the
    /// @p regions (the same regions as the mesh's, with any constants),
    /// their 3D twins where @p twins (plane-strain stress output), and the
    /// operator with the scene's terms. Collective.
    void
    build_materials(const Parameters    &parameters,
                    bool                 twins,
                    dealii::TimerOutput &timer);

    const MPI_Comm                          comm;
    const std::unique_ptr<Formulation<dim>> formulation;
    /// Fully distributed on several ranks; on one, a SerialTriangulation
    /// (built in about half the time, the same cells in the same order).
    const std::unique_ptr<dealii::Triangulation<dim>> triangulation;
    const dealii::FESystem<dim>                       fe;
    const dealii::MappingFE<dim>                      mapping;
    dealii::DoFHandler<dim>                           dof_handler;
    /// The formulation's pressure unknowns (none: empty).
    dealii::IndexSet pressure_dofs;
    /// The run header's lines about a mesh generated from a surface.
    std::string generated_mesh;
    /// The region of each cell; the faces selected by 'Boundary region'
    /// conditions and their ids.
    CellRegions                              cell_regions;
    BoundaryRegions                          boundary_regions;
    std::unique_ptr<BoundaryConditions<dim>> boundary_conditions;

    /// The top-level Material (region 0), the models of Region 1 ... in
    /// the scene's order, and both as the material of every cell.
    std::unique_ptr<Material<dim>>              material;
    std::vector<std::unique_ptr<Material<dim>>> region_models;
    std::unique_ptr<MaterialRegions<dim>>       materials;
    /// The same models in 3D, for the plane-strain stress in the output
    /// (null unless asked for), region 0 first.
    std::unique_ptr<Material<3>>              material3d;
    std::vector<std::unique_ptr<Material<3>>> region_models3d;
    std::unique_ptr<MaterialRegions<3>>       materials3d;
    /// The operator: the material part and the scene's terms.
    std::unique_ptr<ElasticityOperator<dim>> elasticity;
    /// What the contact terms report (null without contact).
    std::unique_ptr<StepReporter<dim>> contact_reporter;
  };
} // namespace hyperelastic
