// The scene's Loading subsection, its Dirichlet subsections and the sections
// of the boundary loads ("Traction 1", "Pressure 1", ...: one kind per
// registered boundary load term, loads/load_terms.h).
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <map>
#include <string>
#include <vector>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  /// A displacement prescribed on one boundary id for some components.
  struct DirichletCondition
  {
    /// The faces: a boundary id of the mesh, or (boundary_region not empty)
    /// the id that assign_boundary_regions() gives the faces of the region.
    dealii::types::boundary_id boundary_id = 0;
    std::vector<unsigned int>  components;  ///< 0 = x, 1 = y, 2 = z
    std::vector<std::string>   expressions; ///< one per entry of components
    std::string                subsection;  ///< for error messages
    /// Reference coordinates of the one vertex of the boundary that is
    /// constrained ("Vertex"); empty: the whole boundary.
    std::vector<double> vertex;
    /// 'Boundary region': a condition on the face centre (an expression of
    /// x, y, z); empty: the section names a 'Boundary id'.
    std::string boundary_region;
  };

  /// A force on one mesh vertex ("Point load 1", ...).
  struct PointLoadSection
  {
    std::vector<double>      point;       ///< reference coordinates
    std::vector<std::string> expressions; ///< dim expressions of x, y, (z,) t
    std::string              subsection;  ///< "Point load 1", for messages
  };

  /// How a kind of boundary load appears in a scene: the sections
  /// "<name> 1" ... "<name> <max_sections>", each with the entries
  /// "Boundary id" and "<name>" (the value: dim expressions separated by ';'
  /// if vector_valued, else one). Each boundary EnergyTerm class describes its
  /// kind (scene_kind()); loads/load_terms.cc lists the kinds.
  struct BoundaryLoadKind
  {
    std::string  name;
    unsigned int max_sections  = 4;
    bool         vector_valued = true;
    std::string  default_value;
    /// Documentation of "Boundary id" and of the value entry.
    std::string id_documentation;
    std::string value_documentation;
  };

  /// One used section of a boundary load (a boundary id >= 0 or a
  /// boundary region).
  struct BoundaryLoadSection
  {
    std::string                kind; ///< BoundaryLoadKind::name
    dealii::types::boundary_id boundary_id = 0;
    /// The value entry split at ';' (dim of them for a vector-valued kind).
    std::vector<std::string> expressions;
    std::string              subsection; ///< "Traction 1", for messages
    /// As DirichletCondition::boundary_region.
    std::string boundary_region;
  };

  struct LoadingParameters
  {
    unsigned int                    n_load_steps = 10;
    std::vector<std::string>        body_force; ///< empty: no body force
    std::map<std::string, double>   constants;
    std::vector<DirichletCondition> dirichlet;
    /// The used sections of every registered kind, kind by kind in the
    /// order of boundary_load_kinds().
    std::vector<BoundaryLoadSection> boundary_loads;
    std::vector<PointLoadSection>    point_loads;

    static constexpr unsigned int max_dirichlet   = 8;
    static constexpr unsigned int max_point_loads = 4;

    static void
    declare(ParameterHandler &prm);
    /// The Loading, Dirichlet and load sections for a scene of dimension
    /// @p dim (the 3D defaults of Dirichlet's Components and Displacement
    /// and of a Point load's Force become 2D ones in 2D).
    void
    parse(ParameterHandler &prm, unsigned int dim);
    /// The numbers of coordinates and expressions against Problem/Dimension
    /// @p dim (body force, Dirichlet components and vertices, point loads,
    /// boundary loads).
    void
    check_dimension(unsigned int dim) const;
    /// No two Dirichlet conditions prescribe the same component of the same
    /// boundary id or boundary region (and vertex).
    void
    check_dirichlet_conflicts() const;
  };
} // namespace hyperelastic
