// Each loading section of a scene becomes one LoadTerm: a new kind of load is
// registered here with one line.
#include <hyperelastic/loads/dead_loads.h>
#include <hyperelastic/loads/follower_pressure.h>
#include <hyperelastic/loads/load_terms.h>

namespace hyperelastic
{
  template <int dim>
  std::vector<std::unique_ptr<LoadTerm<dim>>>
  create_load_terms(const BoundaryConditions<dim> &bc,
                    const dealii::DoFHandler<dim> &dof_handler,
                    const dealii::Mapping<dim>    &mapping)
  {
    std::vector<std::unique_ptr<LoadTerm<dim>>> terms;
    if (bc.body_force)
      terms.push_back(
        std::make_unique<BodyForce<dim>>(*bc.body_force, dof_handler, mapping));
    for (const auto &t : bc.tractions)
      terms.push_back(std::make_unique<DeadTraction<dim>>(
        *t.traction, t.id, t.subsection, dof_handler, mapping));
    for (const auto &p : bc.pressures)
      terms.push_back(std::make_unique<FollowerPressure<dim>>(
        *p.pressure, p.id, p.subsection, dof_handler, mapping));
    return terms;
  }

  template std::vector<std::unique_ptr<LoadTerm<2>>>
  create_load_terms(const BoundaryConditions<2> &,
                    const dealii::DoFHandler<2> &,
                    const dealii::Mapping<2> &);
  template std::vector<std::unique_ptr<LoadTerm<3>>>
  create_load_terms(const BoundaryConditions<3> &,
                    const dealii::DoFHandler<3> &,
                    const dealii::Mapping<3> &);
} // namespace hyperelastic
