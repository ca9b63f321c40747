// Each loading section of a scene becomes one EnergyTerm: a new kind of
// boundary load is registered here with one line.
#include <deal.II/base/exceptions.h>

#include <hyperelastic/loads/dead_loads.h>
#include <hyperelastic/loads/follower_pressure.h>
#include <hyperelastic/loads/load_terms.h>
#include <hyperelastic/loads/point_loads.h>

namespace hyperelastic
{
  namespace
  {
    template <int dim>
    using BoundaryTermFactory =
      std::unique_ptr<EnergyTerm<dim>> (*)(const BoundaryLoad<dim> &,
                                         const dealii::DoFHandler<dim> &,
                                         const dealii::Mapping<dim> &);

    template <int dim, typename Term>
    std::unique_ptr<EnergyTerm<dim>>
    make_boundary_term(const BoundaryLoad<dim>       &load,
                       const dealii::DoFHandler<dim> &dof_handler,
                       const dealii::Mapping<dim>    &mapping)
    {
      return std::make_unique<Term>(
        *load.value, load.id, load.subsection, dof_handler, mapping);
    }

    template <int dim>
    struct RegisteredBoundaryLoad
    {
      BoundaryLoadKind         kind;
      BoundaryTermFactory<dim> create;
    };

    /// The registry: one line per kind of boundary load.
    template <int dim>
    std::vector<RegisteredBoundaryLoad<dim>>
    registered_boundary_loads()
    {
      return {
        {DeadTraction<dim>::scene_kind(),
         &make_boundary_term<dim, DeadTraction<dim>>},
        {FollowerPressure<dim>::scene_kind(),
         &make_boundary_term<dim, FollowerPressure<dim>>},
      };
    }
  } // namespace

  const std::vector<BoundaryLoadKind> &
  boundary_load_kinds()
  {
    static const std::vector<BoundaryLoadKind> kinds = [] {
      std::vector<BoundaryLoadKind> list;
      for (const auto &entry : registered_boundary_loads<3>())
        list.push_back(entry.kind);
      return list;
    }();
    return kinds;
  }

  const BoundaryLoadKind &
  boundary_load_kind(const std::string &name)
  {
    for (const BoundaryLoadKind &kind : boundary_load_kinds())
      if (kind.name == name)
        return kind;
    AssertThrow(false,
                dealii::ExcMessage("no boundary load kind '" + name + "'"));
    return boundary_load_kinds().front();
  }

  template <int dim>
  std::vector<std::unique_ptr<EnergyTerm<dim>>>
  create_load_terms(const BoundaryConditions<dim> &bc,
                    const dealii::DoFHandler<dim> &dof_handler,
                    const dealii::Mapping<dim>    &mapping)
  {
    std::vector<std::unique_ptr<EnergyTerm<dim>>> terms;
    if (bc.body_force)
      terms.push_back(
        std::make_unique<BodyForce<dim>>(*bc.body_force, dof_handler, mapping));
    const auto registered = registered_boundary_loads<dim>();
    for (const BoundaryLoad<dim> &load : bc.boundary_loads)
      for (const auto &entry : registered)
        if (entry.kind.name == load.kind)
          terms.push_back(entry.create(load, dof_handler, mapping));
    if (!bc.point_loads.empty())
      terms.push_back(
        std::make_unique<PointLoads<dim>>(bc.point_loads, dof_handler));
    return terms;
  }

  template std::vector<std::unique_ptr<EnergyTerm<2>>>
  create_load_terms(const BoundaryConditions<2> &,
                    const dealii::DoFHandler<2> &,
                    const dealii::Mapping<2> &);
  template std::vector<std::unique_ptr<EnergyTerm<3>>>
  create_load_terms(const BoundaryConditions<3> &,
                    const dealii::DoFHandler<3> &,
                    const dealii::Mapping<3> &);
} // namespace hyperelastic
