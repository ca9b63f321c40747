// Boundary ids for the faces selected by the scene's 'Boundary region'
// conditions, and the input errors of those conditions against the mesh.
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/mesh/boundary_regions.h>

#include <algorithm>
#include <map>
#include <memory>
#include <sstream>

namespace hyperelastic
{
  using namespace dealii;

  namespace
  {
    /// The entry "<section>/Boundary region" = '<condition>', for messages.
    std::string
    entry_of(const BoundaryRegions::Region &region)
    {
      return "scene entry '" + region.sections.front() +
             "/Boundary region' = '" + region.condition + "'";
    }

    /// The condition of @p region as a function of the point; InputError
    /// naming the entry if it does not parse.
    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    face_condition(const BoundaryRegions::Region       &region,
                   const std::map<std::string, double> &constants)
    {
      const std::string variables = dim == 2 ? "x,y" : "x,y,z";
      auto              function  = std::make_unique<FunctionParser<dim>>(1);
      try
        {
          function->initialize(variables, region.condition, constants);
          // muparser reports unknown names on the first evaluation.
          function->value(Point<dim>());
        }
      catch (...)
        {
          throw InputError(entry_of(region) +
                           ": cannot parse the condition (an expression of " +
                           variables +
                           " and the Loading/Constants, e.g. 'y < 0.035')");
        }
      return function;
    }

    /// The union over the ranks of @p comm of the sets @p local.
    std::set<types::boundary_id>
    union_over_ranks(const std::set<types::boundary_id> &local,
                     const MPI_Comm                      comm)
    {
      std::set<types::boundary_id> all;
      for (const std::vector<types::boundary_id> &ids :
           Utilities::MPI::all_gather(
             comm, std::vector<types::boundary_id>(local.begin(), local.end())))
        all.insert(ids.begin(), ids.end());
      return all;
    }

    /// The distinct conditions of @p loading's sections, in the order of
    /// the sections, each with the sections using it (ids still 0);
    /// @p named_ids: the ids the sections name directly, each with the
    /// first section naming it.
    BoundaryRegions
    distinct_regions(const LoadingParameters                   &loading,
                     std::map<types::boundary_id, std::string> &named_ids)
    {
      BoundaryRegions result;
      const auto      add = [&](const std::string       &condition,
                           const std::string       &section,
                           const types::boundary_id id) {
        if (condition.empty())
          {
            named_ids.emplace(id, section);
            return;
          }
        auto region = std::find_if(result.regions.begin(),
                                   result.regions.end(),
                                   [&](const BoundaryRegions::Region &r) {
                                     return r.condition == condition;
                                   });
        if (region == result.regions.end())
          result.regions.push_back({condition, 0, 0, {section}});
        else
          region->sections.push_back(section);
      };
      for (const DirichletCondition &c : loading.dirichlet)
        add(c.boundary_region, c.subsection, c.boundary_id);
      for (const BoundaryLoadSection &c : loading.boundary_loads)
        add(c.boundary_region, c.subsection, c.boundary_id);
      return result;
    }

    /// Gives every boundary face of the cells this rank sees (a face of a
    /// ghost cell too: its id matters to the assembly of its neighbours'
    /// ranks) the id of the region whose @p condition it satisfies, and
    /// counts the owned ones; @p taken[r]: the ids region r took over,
    /// @p local_ids: the ids of the owned boundary faces afterwards.
    /// Returns the message of the first face two conditions select, or "".
    template <int dim>
    std::string
    mark_region_faces(
      Triangulation<dim>                                      &triangulation,
      BoundaryRegions                                         &result,
      const std::vector<std::unique_ptr<FunctionParser<dim>>> &condition,
      std::vector<std::set<types::boundary_id>>               &taken,
      std::set<types::boundary_id>                            &local_ids)
    {
      std::string problem;
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          if (cell->is_artificial())
            continue;
          for (const unsigned int f : cell->face_indices())
            {
              if (!cell->at_boundary(f))
                continue;
              const auto       face   = cell->face(f);
              const Point<dim> centre = face->center();
              int              chosen = -1;
              for (unsigned int r = 0; r < result.regions.size(); ++r)
                if (condition[r]->value(centre) != 0.)
                  {
                    if (chosen >= 0 && problem.empty())
                      {
                        std::ostringstream where;
                        where << entry_of(result.regions[r])
                              << ": the boundary face with centre (" << centre
                              << ") is also selected by "
                              << entry_of(result.regions[chosen])
                              << ": a face has one boundary id (make the "
                                 "conditions exclusive, or use the same "
                                 "condition in both sections)";
                        problem = where.str();
                      }
                    chosen = r;
                  }
              if (chosen >= 0)
                {
                  taken[chosen].insert(face->boundary_id());
                  face->set_boundary_id(result.regions[chosen].id);
                  if (cell->is_locally_owned())
                    ++result.regions[chosen].n_faces;
                }
              if (cell->is_locally_owned())
                local_ids.insert(face->boundary_id());
            }
        }
      return problem;
    }
  } // namespace

  template <int dim>
  BoundaryRegions
  assign_boundary_regions(Triangulation<dim>           &triangulation,
                          LoadingParameters            &loading,
                          std::set<types::boundary_id> &mesh_ids)
  {
    // The distinct conditions in the order of the sections, and the ids
    // the sections name directly.
    std::map<types::boundary_id, std::string> named_ids;
    BoundaryRegions result = distinct_regions(loading, named_ids);
    if (result.regions.empty())
      return result;

    // New ids above every id of the mesh and of the scene (every rank holds
    // the same sets: the same ids everywhere).
    types::boundary_id next = 0;
    for (const types::boundary_id id : mesh_ids)
      next = std::max<types::boundary_id>(next, id + 1);
    for (const auto &named : named_ids)
      next = std::max<types::boundary_id>(next, named.first + 1);
    std::vector<std::unique_ptr<FunctionParser<dim>>> condition;
    for (BoundaryRegions::Region &region : result.regions)
      {
        region.id = next++;
        condition.push_back(face_condition<dim>(region, loading.constants));
      }

    const MPI_Comm comm = triangulation.get_communicator();
    std::vector<std::set<types::boundary_id>> taken(result.regions.size());
    std::set<types::boundary_id>              local_ids;
    const std::string                         problem =
      mark_region_faces(triangulation, result, condition, taken, local_ids);
    throw_input_error_of_first_rank(problem, comm);

    for (unsigned int r = 0; r < result.regions.size(); ++r)
      {
        BoundaryRegions::Region &region = result.regions[r];
        region.n_faces = Utilities::MPI::sum(region.n_faces, comm);
        if (region.n_faces == 0)
          throw InputError(entry_of(region) +
                           ": the condition selects no boundary face (no "
                           "boundary face centre satisfies it)");
        for (const types::boundary_id old : union_over_ranks(taken[r], comm))
          if (named_ids.count(old) > 0)
            throw InputError(
              entry_of(region) + ": the condition takes faces of boundary id " +
              std::to_string(old) + ", which '" + named_ids.at(old) +
              "/Boundary id' names: a face has one boundary id (select those "
              "faces by a condition in both sections, or none by one)");
      }
    mesh_ids = union_over_ranks(local_ids, comm);

    for (const BoundaryRegions::Region &region : result.regions)
      {
        for (DirichletCondition &c : loading.dirichlet)
          if (c.boundary_region == region.condition)
            c.boundary_id = region.id;
        for (BoundaryLoadSection &c : loading.boundary_loads)
          if (c.boundary_region == region.condition)
            c.boundary_id = region.id;
      }
    return result;
  }

  template BoundaryRegions
  assign_boundary_regions(Triangulation<2> &,
                          LoadingParameters &,
                          std::set<types::boundary_id> &);
  template BoundaryRegions
  assign_boundary_regions(Triangulation<3> &,
                          LoadingParameters &,
                          std::set<types::boundary_id> &);
} // namespace hyperelastic
