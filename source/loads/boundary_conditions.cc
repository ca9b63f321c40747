// Parsing of load and support expressions and the Dirichlet constraints.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/numbers.h>
#include <deal.II/numerics/vector_tools.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/loads/boundary_conditions.h>

#include <cmath>
#include <iostream>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    std::string
    list_ids(const std::set<boundary_id> &ids)
    {
      std::string s;
      for (const auto id : ids)
        s += (s.empty() ? "" : ", ") + std::to_string(id);
      return s.empty() ? "none" : s;
    }
  } // namespace

  template <int dim>
  BoundaryConditions<dim>::BoundaryConditions(
    const LoadingParameters     &loading,
    const std::set<boundary_id> &mesh_ids)
  {
    const auto check_id = [&](const boundary_id  id,
                              const std::string &section) {
      if (mesh_ids.count(id) == 0)
        throw InputError(
          "scene entry '" + section + "/Boundary id' = " + std::to_string(id) +
          ": the mesh has no boundary with this id; its boundary "
          "ids are " +
          list_ids(mesh_ids));
    };

    const auto point_of = [](const std::vector<double> &x) {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = x[d];
      return p;
    };
    for (const auto &c : loading.dirichlet)
      {
        check_id(c.boundary_id, c.subsection);
        std::vector<std::string> expressions(dim, "0");
        std::vector<bool>        mask(dim, false);
        for (unsigned int i = 0; i < c.components.size(); ++i)
          {
            expressions[c.components[i]] = c.expressions[i];
            mask[c.components[i]]        = true;
          }
        dirichlet.push_back(
          {c.boundary_id,
           ComponentMask(mask),
           parse_vector_function<dim>(expressions,
                                      loading.constants,
                                      c.subsection + "/Displacement"),
           c.subsection,
           std::nullopt});
        if (!c.vertex.empty())
          dirichlet.back().vertex = point_of(c.vertex);
      }
    for (const auto &c : loading.point_loads)
      point_loads.push_back(
        {point_of(c.point),
         parse_vector_function<dim>(c.expressions,
                                    loading.constants,
                                    c.subsection + "/Force"),
         c.subsection});
    for (const auto &c : loading.boundary_loads)
      {
        check_id(c.boundary_id, c.subsection);
        boundary_loads.push_back(
          {c.kind,
           c.boundary_id,
           parse_vector_function<dim>(c.expressions,
                                      loading.constants,
                                      c.subsection + "/" + c.kind),
           c.subsection});
      }
    if (!loading.body_force.empty())
      body_force = parse_vector_function<dim>(loading.body_force,
                                              loading.constants,
                                              "Loading/Body force");
  }

  namespace
  {
    /// A displacement function with zeros appended for the other components
    /// of the element (the pressure of the mixed formulation).
    template <int dim>
    class PaddedFunction : public Function<dim>
    {
    public:
      PaddedFunction(const Function<dim> &displacement,
                     const unsigned int   n_components)
          : Function<dim>(n_components)
          , displacement(displacement)
      {
      }

      double
      value(const Point<dim> &x, const unsigned int c) const override
      {
        return c < dim ? displacement.value(x, c) : 0.;
      }

      void
      vector_value(const Point<dim> &x, Vector<double> &values) const override
      {
        values = 0.;
        for (unsigned int c = 0; c < dim; ++c)
          values[c] = displacement.value(x, c);
      }

    private:
      const Function<dim> &displacement;
    };
  } // namespace

  namespace
  {
    /// The prescribed values of the dofs of the one boundary vertex of a
    /// 'Vertex' condition at load factor @p t; @p missing becomes 0 if this
    /// rank has the vertex.
    template <int dim>
    void
    vertex_values(const DoFHandler<dim>                     &dof_handler,
                  const DirichletBoundary<dim>              &d,
                  std::map<types::global_dof_index, double> &values,
                  int                                       &missing)
    {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial() && cell->at_boundary())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                cell->face(f)->boundary_id() == d.id)
              for (const unsigned int v : cell->face(f)->vertex_indices())
                if (is_vertex_at(cell->face(f)->vertex(v),
                                 *d.vertex,
                                 cell->diameter()))
                  {
                    missing = 0;
                    for (unsigned int c = 0; c < dim; ++c)
                      if (d.mask[c])
                        values[cell->face(f)->vertex_dof_index(v, c)] =
                          d.displacement->value(*d.vertex, c);
                  }
    }
  } // namespace

  template <int dim>
  void
  BoundaryConditions<dim>::make_constraints(
    const Mapping<dim>                  &mapping,
    const DoFHandler<dim>               &dof_handler,
    const IndexSet                      &relevant_dofs,
    const double                         t,
    const TrilinosWrappers::MPI::Vector &current_ghosted,
    const bool                           homogeneous,
    AffineConstraints<double>           &constraints) const
  {
    constraints.clear();
    constraints.reinit(relevant_dofs);
    std::vector<int> non_finite(dirichlet.size(), 0);
    // 1 until a rank finds the vertex of a 'Vertex' condition.
    std::vector<int> missing_vertex(dirichlet.size(), 1);
    for (unsigned int k = 0; k < dirichlet.size(); ++k)
      {
        const auto                               &d = dirichlet[k];
        std::map<types::global_dof_index, double> values;
        d.displacement->set_time(t);
        // The mixed formulation's pressure component is never prescribed.
        const unsigned int n_components = dof_handler.get_fe().n_components();
        const PaddedFunction<dim> padded(*d.displacement, n_components);
        std::vector<bool>         mask(n_components, false);
        for (unsigned int c = 0; c < dim; ++c)
          mask[c] = d.mask[c];
        if (d.vertex)
          vertex_values(dof_handler, d, values, missing_vertex[k]);
        else
          VectorTools::interpolate_boundary_values(
            mapping,
            dof_handler,
            std::map<types::boundary_id, const Function<dim> *>{
              {d.id, n_components == dim ? d.displacement.get() : &padded}},
            values,
            ComponentMask(mask));
        for (const auto &[dof, value] : values)
          if (!homogeneous && !std::isfinite(value))
            non_finite[k] = 1;
        for (const auto &[dof, value] : values)
          if (!constraints.is_constrained(dof))
            {
              constraints.add_line(dof);
              if (!homogeneous)
                {
                  constraints.set_inhomogeneity(dof,
                                                value - current_ghosted(dof));
                }
            }
      }
    constraints.close();
    // Evaluated on each rank's own boundary: agree before anyone throws.
    for (int &flag : non_finite)
      flag = Utilities::MPI::max(flag, dof_handler.get_communicator());
    for (unsigned int k = 0; k < dirichlet.size(); ++k)
      if (dirichlet[k].vertex &&
          Utilities::MPI::min(missing_vertex[k],
                              dof_handler.get_communicator()) != 0)
        {
          std::ostringstream point;
          point << *dirichlet[k].vertex;
          throw InputError(
            "scene entry '" + dirichlet[k].subsection + "/Vertex' = '" +
            point.str() + "': no vertex of boundary id " +
            std::to_string(dirichlet[k].id) + " lies at this point");
        }
    for (unsigned int k = 0; k < dirichlet.size(); ++k)
      if (non_finite[k] != 0)
        throw InputError("scene entry '" + dirichlet[k].subsection +
                         "/Displacement' is not a finite number at load "
                         "factor t = " +
                         std::to_string(t) +
                         " (a division by zero or similar)");
  }

  template struct BoundaryConditions<2>;
  template struct BoundaryConditions<3>;
} // namespace hyperelastic
