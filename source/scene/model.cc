// A scene as built (see the header): the mesh, regions, loads and dofs once,
// the materials, operator and terms as often as the constants change.
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/fe/fe_simplex_p.h>

#include <hyperelastic/contact/contact_layer.h>
#include <hyperelastic/formulation/formulation_registry.h>
#include <hyperelastic/materials/material_parameters.h>
#include <hyperelastic/materials/region_properties.h>
#include <hyperelastic/mesh/mesh.h>
#include <hyperelastic/scene/model.h>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  Model<dim>::Model(const Parameters &parameters, const MPI_Comm comm)
      : comm(comm)
      , formulation(create_formulation<dim>({parameters.problem,
                                             parameters.material,
                                             parameters.linear_solver,
                                             parameters.time_integration}))
      , triangulation(
          Utilities::MPI::n_mpi_processes(comm) == 1
            ? std::unique_ptr<Triangulation<dim>>(
                std::make_unique<SerialTriangulation<dim>>(comm))
            : std::make_unique<parallel::fullydistributed::Triangulation<dim>>(
                comm))
      , fe(formulation->finite_element())
      , mapping(FE_SimplexP<dim>(1))
      , dof_handler(*triangulation)
  {
  }

  template <int dim>
  std::vector<std::pair<std::string, double>>
  Model<dim>::build_mesh(
    const Parameters                                     &parameters,
    const std::function<void(BoundaryConditions<dim> &)> &load_editor)
  {
    MeshStatistics                       mesh_stats;
    std::set<dealii::types::boundary_id> mesh_ids =
      Utilities::MPI::n_mpi_processes(comm) == 1
        ? create_serial_mesh(parameters.mesh,
                             static_cast<SerialTriangulation<dim> &>(
                               *triangulation),
                             &mesh_stats)
        : create_mesh(
            parameters.mesh,
            static_cast<parallel::fullydistributed::Triangulation<dim> &>(
              *triangulation),
            &mesh_stats);
    std::vector<std::pair<std::string, double>> stages = {
      {"read", mesh_stats.read_time},
      {"order", mesh_stats.order_time},
      {"check", mesh_stats.check_time},
      {"build", mesh_stats.build_time},
      {"partition", mesh_stats.partition_time},
      {"wait", mesh_stats.wait_time},
      {"describe", mesh_stats.describe_time},
      {"distribute", mesh_stats.distribute_time}};
    generated_mesh = mesh_stats.generated_mesh;

    Timer timer;
    cell_regions = assign_cell_regions(*triangulation, parameters.regions);
    LoadingParameters loading = parameters.loading;
    boundary_regions =
      assign_boundary_regions(*triangulation, loading, mesh_ids);
    boundary_conditions =
      std::make_unique<BoundaryConditions<dim>>(loading, mesh_ids);
    if (load_editor)
      load_editor(*boundary_conditions);
    dof_handler.distribute_dofs(fe);
    pressure_dofs = formulation->pressure_dofs(dof_handler);
    stages.emplace_back("dofs", timer.wall_time());
    return stages;
  }

  template <int dim>
  void
  Model<dim>::build_materials(const Parameters    &parameters,
                              const bool           twins,
                              dealii::TimerOutput &timer)
  {
    // What refers to the old materials goes first.
    contact_reporter.reset();
    elasticity.reset();
    materials3d.reset();
    region_models3d.clear();
    material3d.reset();
    materials.reset();
    region_models.clear();

    material = create_material<dim>(parameters.material);
    std::vector<const Material<dim> *> models{material.get()};
    for (const RegionParameters &region : parameters.regions)
      {
        region_models.push_back(create_material<dim>(region.material));
        models.push_back(region_models.back().get());
      }
    materials =
      std::make_unique<MaterialRegions<dim>>(models, cell_regions.of_cell);
    if (twins)
      {
        material3d = material->three_dimensional_twin();
        std::vector<const Material<3> *> twin_models{material3d.get()};
        for (const auto &model : region_models)
          {
            region_models3d.push_back(model->three_dimensional_twin());
            twin_models.push_back(region_models3d.back().get());
          }
        materials3d = std::make_unique<MaterialRegions<3>>(
          materials->with_models(twin_models));
      }
    elasticity = std::make_unique<ElasticityOperator<dim>>(
      dof_handler,
      mapping,
      *materials,
      *boundary_conditions,
      parameters.problem.fast_p1_assembly,
      formulation->material_part(dof_handler, mapping, *materials));
    contact_reporter = add_contact_terms<dim>(
      {parameters.contact,
       parameters.loading.constants,
       dof_handler,
       boundary_moduli(*materials, cell_regions, *triangulation),
       parameters.time_integration.dynamic(),
       pressure_dofs.n_elements() > 0,
       timer},
      *elasticity);
  }

  template class Model<2>;
  template class Model<3>;
} // namespace hyperelastic
