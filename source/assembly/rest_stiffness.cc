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
    const MPI_Comm comm  = dof_handler.get_communicator();
    const IndexSet owned = dof_handler.locally_owned_dofs();
    const IndexSet relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    stiffness.reinit(owned, owned, dsp, comm);

    VectorType                rhs(owned, comm);
    AffineConstraints<double> none;
    none.close();
    assemble_rest_system(dof_handler, mapping, moduli, none, stiffness, rhs);
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
    const auto linear = create_material<dim>("linear elastic", moduli);
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
