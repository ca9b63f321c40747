// K0: the generic FEValues loops with linear elasticity at u = 0.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <hyperelastic/assembly/generic_assembler.h>
#include <hyperelastic/assembly/rest_stiffness.h>

namespace hyperelastic
{
  using namespace dealii;

  template <int dim>
  void
  assemble_rest_stiffness(const DoFHandler<dim> &dof_handler,
                          const Mapping<dim>    &mapping,
                          const LameParameters  &moduli,
                          MatrixType            &stiffness)
  {
    const auto linear = create_material<dim>("linear elastic", moduli);
    assemble_rest_stiffness(dof_handler,
                            mapping,
                            MaterialRegions<dim>(*linear),
                            stiffness);
  }

  template <int dim>
  void
  assemble_rest_stiffness(const DoFHandler<dim>      &dof_handler,
                          const Mapping<dim>         &mapping,
                          const MaterialRegions<dim> &materials,
                          MatrixType                 &stiffness)
  {
    // Linear elasticity with each region's rest moduli.
    std::vector<std::unique_ptr<Material<dim>>> linear;
    std::vector<const Material<dim> *>          models;
    for (unsigned int r = 0; r < materials.n_regions(); ++r)
      {
        linear.push_back(
          create_material<dim>("linear elastic",
                               materials.model(r).small_strain_moduli()));
        models.push_back(linear.back().get());
      }
    const MaterialRegions<dim> rest  = materials.with_models(models);
    const MPI_Comm             comm  = dof_handler.get_communicator();
    const IndexSet             owned = dof_handler.locally_owned_dofs();
    const IndexSet             relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    stiffness.reinit(owned, owned, dsp, comm);

    VectorType                rhs(owned, comm);
    AffineConstraints<double> none;
    none.close();
    const VectorType at_rest(
      owned, DoFTools::extract_locally_relevant_dofs(dof_handler), comm);
    GenericAssembler<dim>(dof_handler, mapping, rest)
      .system(at_rest, none, TangentProjection::none, stiffness, rhs);
  }

  template <int dim>
  void
  assemble_rest_system(const DoFHandler<dim>           &dof_handler,
                       const Mapping<dim>              &mapping,
                       const LameParameters            &moduli,
                       const AffineConstraints<double> &constraints,
                       MatrixType                      &matrix,
                       VectorType                      &rhs)
  {
    const auto       linear = create_material<dim>("linear elastic", moduli);
    const VectorType rest(dof_handler.locally_owned_dofs(),
                          DoFTools::extract_locally_relevant_dofs(dof_handler),
                          dof_handler.get_communicator());
    GenericAssembler<dim>(dof_handler, mapping, *linear)
      .system(rest, constraints, TangentProjection::none, matrix, rhs);
  }

  template void
  assemble_rest_stiffness<2>(const DoFHandler<2> &,
                             const Mapping<2> &,
                             const LameParameters &,
                             MatrixType &);
  template void
  assemble_rest_stiffness<3>(const DoFHandler<3> &,
                             const Mapping<3> &,
                             const LameParameters &,
                             MatrixType &);
  template void
  assemble_rest_stiffness<2>(const DoFHandler<2> &,
                             const Mapping<2> &,
                             const MaterialRegions<2> &,
                             MatrixType &);
  template void
  assemble_rest_stiffness<3>(const DoFHandler<3> &,
                             const Mapping<3> &,
                             const MaterialRegions<3> &,
                             MatrixType &);
  template void
  assemble_rest_system<2>(const DoFHandler<2> &,
                          const Mapping<2> &,
                          const LameParameters &,
                          const AffineConstraints<double> &,
                          MatrixType &,
                          VectorType &);
  template void
  assemble_rest_system<3>(const DoFHandler<3> &,
                          const Mapping<3> &,
                          const LameParameters &,
                          const AffineConstraints<double> &,
                          MatrixType &,
                          VectorType &);
} // namespace hyperelastic
