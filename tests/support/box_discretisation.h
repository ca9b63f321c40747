// A generated box [0, length] x [0, 1] (x [0, 1]) of simplices with a vector
// FE_SimplexP(degree) field on the ranks of a communicator, and a tangent
// matrix of its full sparsity: the set-up shared by the tests that call
// ElasticityOperator directly.
#pragma once

#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <hyperelastic/assembly/elasticity_operator.h>
#include <hyperelastic/formulation/formulation_registry.h>
#include <hyperelastic/mesh/mesh.h>
#include <hyperelastic/scene/parameters.h>

#include <set>
#include <vector>

namespace hyperelastic::testing
{
  template <int dim>
  class BoxDiscretisation
  {
  public:
    /// @p cells_along: boxes along x; @p cells_across: along the other axes.
    BoxDiscretisation(const double       length,
                      const unsigned int cells_along,
                      const unsigned int cells_across,
                      const unsigned int degree,
                      const MPI_Comm     comm,
                      const bool         with_pressure = false)
        : comm(comm)
        , tria(comm)
        , boundary_ids(
            create_mesh(box(length, cells_along, cells_across), tria))
        , fe(finite_element(degree, with_pressure))
        , mapping(dealii::FE_SimplexP<dim>(1))
        , dof_handler(tria)
    {
      dof_handler.distribute_dofs(fe);
      owned = dof_handler.locally_owned_dofs();
      dealii::DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    }

    /// @p K with every coupling of the dofs (as Problem builds it).
    void
    reinit_matrix(MatrixType &K) const
    {
      dealii::DynamicSparsityPattern dsp(relevant);
      dealii::DoFTools::make_sparsity_pattern(dof_handler, dsp);
      dealii::SparsityTools::distribute_sparsity_pattern(dsp,
                                                         owned,
                                                         comm,
                                                         relevant);
      K.reinit(owned, owned, dsp, comm);
    }

    const MPI_Comm                                         comm;
    dealii::parallel::fullydistributed::Triangulation<dim> tria;
    const std::set<dealii::types::boundary_id>             boundary_ids;
    const dealii::FESystem<dim>                            fe;
    const dealii::MappingFE<dim>                           mapping;
    dealii::DoFHandler<dim>                                dof_handler;
    dealii::IndexSet                                       owned, relevant;

  private:
    /// The library's element of the displacement formulation of @p degree,
    /// or of the mixed one whose displacement has that degree (P1 or P2
    /// displacement with a P1 pressure).
    static dealii::FESystem<dim>
    finite_element(const unsigned int degree, const bool with_pressure)
    {
      Parameters parameters;
      parameters.problem.dimension   = dim;
      parameters.problem.fe_degree   = degree;
      parameters.problem.formulation = with_pressure ? "mixed" : "displacement";
      parameters.problem.mixed_element =
        degree == 2 ? MixedElement::taylor_hood : MixedElement::mini;
      return create_formulation<dim>({parameters.problem,
                                      parameters.material,
                                      parameters.linear_solver,
                                      parameters.time_integration})
        ->finite_element();
    }

    static MeshParameters
    box(const double       length,
        const unsigned int cells_along,
        const unsigned int cells_across)
    {
      MeshParameters mesh;
      mesh.lower_corner    = std::vector<double>(dim, 0.);
      mesh.upper_corner    = std::vector<double>(dim, 1.);
      mesh.upper_corner[0] = length;
      mesh.subdivisions    = std::vector<unsigned int>(dim, cells_across);
      mesh.subdivisions[0] = cells_along;
      return mesh;
    }
  };
} // namespace hyperelastic::testing
