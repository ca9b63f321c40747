// The scene's Loading subsection, its Dirichlet subsections and the sections of
// the registered boundary loads: declaration, documentation and validation of
// their entries.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/loads/load_terms.h>
#include <hyperelastic/loads/loading_parameters.h>

#include <algorithm>
#include <cmath>

namespace hyperelastic
{
  using namespace entry_patterns;

  namespace
  {
    /// 'Loading/Constants' (@p constants_text): 'name = number' pairs
    /// separated by ',', each name an identifier other than x, y, z, t and
    /// pi.
    void
    parse_constants(const std::string             &constants_text,
                    std::map<std::string, double> &constants)
    {
      for (const auto &pair :
           dealii::Utilities::split_string_list(constants_text, ','))
        {
          const auto        eq = pair.find('=');
          const std::string name =
            eq == std::string::npos
              ? ""
              : dealii::Utilities::trim(pair.substr(0, eq));
          double             value = 0;
          std::istringstream value_stream(
            eq == std::string::npos ? "" : pair.substr(eq + 1));
          value_stream >> value;
          if (name.empty() || value_stream.fail() || !std::isfinite(value) ||
              !(value_stream >> std::ws).eof())
            reject("Loading/Constants",
                   constants_text,
                   "expected 'name = number' pairs separated by ',', got '" +
                     pair + "'");
          const bool identifier =
            (std::isalpha(static_cast<unsigned char>(name[0])) ||
             name[0] == '_') &&
            std::all_of(name.begin(), name.end(), [](const char c) {
              return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
            });
          if (!identifier || name == "x" || name == "y" || name == "z" ||
              name == "t" || name == "pi")
            reject("Loading/Constants",
                   constants_text,
                   "'" + name +
                     "' cannot be a constant's name: use letters, digits and "
                     "'_' (starting with a letter), other than x, y, z, t and "
                     "pi");
          constants[name] = value;
        }
    }

    const char *const boundary_region_documentation =
      "The faces of this section selected by position instead of a "
      "'Boundary id' (for meshes that carry none): a condition on the "
      "reference centre of each boundary face, an expression of x, y(, z) and "
      "the Loading/Constants, e.g. 'y < 0.035' or 'abs(x - 1) < 1e-6 && y > "
      "0'. The faces it selects get a boundary id of their own at set-up (the "
      "run header lists them); a condition that selects no face, a face "
      "selected by two different conditions, or a condition that takes faces "
      "of a 'Boundary id' another section names is an input error. A "
      "section uses either 'Boundary id' or 'Boundary region'. Empty: the "
      "section names a 'Boundary id'.";

    /// The trimmed 'Boundary region' of the current subsection @p section,
    /// rejected if the section also sets 'Boundary id' (@p id >= 0).
    std::string
    boundary_region(ParameterHandler  &prm,
                    const std::string &section,
                    const int          id)
    {
      const std::string region =
        dealii::Utilities::trim(prm.get("Boundary region"));
      if (!region.empty() && id >= 0)
        reject(section + "/Boundary region",
               region,
               "the section also sets 'Boundary id' = " + std::to_string(id) +
                 ": use one of the two");
      return region;
    }
  } // namespace

  void
  LoadingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    prm.declare_entry("Number of load steps",
                      "10",
                      Integer(1),
                      "The load factor t goes from 0 to 1 in this many equal "
                      "steps (smaller ones where Newton needs them: see "
                      "'Load stepping'); every expression below may use t.");
    prm.declare_entry("Body force",
                      "",
                      Anything(),
                      "Force per unit reference volume: dim expressions of "
                      "x, y, (z,) t separated by ';' (for example '0; 0; "
                      "-0.1*t'). Empty: no body force.");
    prm.declare_entry("Constants",
                      "",
                      Anything(),
                      "Named constants usable in every expression, as "
                      "'name = value' pairs separated by ',' (for example "
                      "'L = 10, angle = 1.5708'). pi is always defined.");
    prm.leave_subsection();

    for (unsigned int i = 1; i <= max_dirichlet; ++i)
      {
        prm.enter_subsection("Dirichlet " + std::to_string(i));
        prm.declare_entry("Boundary id",
                          "-1",
                          Integer(-1),
                          "Boundary id on which the displacement is "
                          "prescribed; -1 leaves this slot unused (unless "
                          "'Boundary region' is set).");
        prm.declare_entry("Boundary region",
                          "",
                          Anything(),
                          boundary_region_documentation);
        prm.declare_entry("Components",
                          "x, y, z",
                          MultipleSelection("x|y|z"),
                          "Displacement components that are prescribed; the "
                          "others stay free (so 'x' on a face x = const is a "
                          "symmetry roller). The default is 'x, y' in 2D.");
        prm.declare_entry("Displacement",
                          "0; 0; 0",
                          Anything(),
                          "One expression of x, y, (z,) t per listed "
                          "component, separated by ';': the displacement of "
                          "the reference point (x, y, z) at load factor t. "
                          "The default is '0; 0' in 2D.");
        prm.declare_entry("Vertex",
                          "",
                          Anything(),
                          "Reference coordinates 'x, y[, z]' of one mesh "
                          "vertex of this boundary: only that vertex is "
                          "constrained (displacement control of a point, "
                          "the counterpart of a 'Point load'). Empty: every "
                          "vertex of the boundary.");
        prm.leave_subsection();
      }
    for (unsigned int i = 1; i <= max_point_loads; ++i)
      {
        prm.enter_subsection("Point load " + std::to_string(i));
        prm.declare_entry("Point",
                          "",
                          Anything(),
                          "Reference coordinates 'x, y[, z]' of the mesh "
                          "vertex that carries the force (a point that is "
                          "no vertex is an input error). Empty: this slot is "
                          "unused.");
        prm.declare_entry("Force",
                          "0; 0; 0",
                          Anything(),
                          "The nodal force: dim expressions of t (and x, y, "
                          "z, evaluated at the point) separated by ';' (the "
                          "default '0; 0' in 2D). A dead load: its "
                          "direction does not follow the body.");
        prm.leave_subsection();
      }
    for (const BoundaryLoadKind &kind : boundary_load_kinds())
      for (unsigned int i = 1; i <= kind.max_sections; ++i)
        {
          prm.enter_subsection(kind.name + " " + std::to_string(i));
          prm.declare_entry("Boundary id",
                            "-1",
                            Integer(-1),
                            kind.id_documentation);
          prm.declare_entry("Boundary region",
                            "",
                            Anything(),
                            boundary_region_documentation);
          prm.declare_entry(kind.name,
                            kind.default_value,
                            Anything(),
                            kind.value_documentation);
          prm.leave_subsection();
        }
  }

  void
  LoadingParameters::parse(ParameterHandler &prm, const unsigned int dim)
  {
    prm.enter_subsection("Loading");
    n_load_steps                     = prm.get_integer("Number of load steps");
    body_force                       = split_expressions(prm.get("Body force"));
    const std::string constants_text = prm.get("Constants");
    prm.leave_subsection();

    parse_constants(constants_text, constants);

    for (unsigned int i = 1; i <= max_dirichlet; ++i)
      {
        const std::string section = "Dirichlet " + std::to_string(i);
        prm.enter_subsection(section);
        const int         id     = prm.get_integer("Boundary id");
        const std::string region = boundary_region(prm, section, id);
        if (id >= 0 || !region.empty())
          {
            DirichletCondition c;
            c.boundary_id     = std::max(id, 0);
            c.boundary_region = region;
            c.subsection      = section;
            // The 3D defaults (x, y, z held at 0) become 2D ones in 2D.
            const std::string components_text =
              list_for_dimension(prm.get("Components"), "x, y, z", dim, ',');
            const std::string displacement_text =
              list_for_dimension(prm.get("Displacement"), "0; 0; 0", dim, ';');
            for (const auto &name :
                 dealii::Utilities::split_string_list(components_text))
              {
                if (std::count(c.components.begin(),
                               c.components.end(),
                               component_index(name)) > 0)
                  reject(section + "/Components",
                         components_text,
                         "component " + name + " is listed twice");
                c.components.push_back(component_index(name));
              }
            c.expressions = split_expressions(displacement_text);
            if (c.components.empty())
              reject(section + "/Components",
                     components_text,
                     "list at least one of x, y, z");
            if (c.expressions.size() != c.components.size())
              reject(section + "/Displacement",
                     displacement_text,
                     "needs one expression per listed component (" +
                       std::to_string(c.components.size()) +
                       "), separated by ';'");
            const std::string vertex = prm.get("Vertex");
            if (!dealii::Utilities::trim(vertex).empty())
              {
                c.vertex = parse_coordinates(vertex);
                if (c.vertex.empty())
                  reject(section + "/Vertex",
                         vertex,
                         "expected the coordinates 'x, y[, z]' of a vertex");
              }
            dirichlet.push_back(c);
          }
        prm.leave_subsection();
      }
    for (const BoundaryLoadKind &kind : boundary_load_kinds())
      for (unsigned int i = 1; i <= kind.max_sections; ++i)
        {
          const std::string section = kind.name + " " + std::to_string(i);
          prm.enter_subsection(section);
          const int         id     = prm.get_integer("Boundary id");
          const std::string region = boundary_region(prm, section, id);
          if (id >= 0 || !region.empty())
            boundary_loads.push_back(
              {kind.name,
               static_cast<dealii::types::boundary_id>(std::max(id, 0)),
               split_expressions(prm.get(kind.name)),
               section,
               region});
          prm.leave_subsection();
        }
    for (unsigned int i = 1; i <= max_point_loads; ++i)
      {
        const std::string section = "Point load " + std::to_string(i);
        prm.enter_subsection(section);
        const std::string point = prm.get("Point");
        if (!dealii::Utilities::trim(point).empty())
          {
            PointLoadSection load;
            load.point = parse_coordinates(point);
            if (load.point.empty())
              reject(section + "/Point",
                     point,
                     "expected the coordinates 'x, y[, z]' of a vertex");
            load.expressions = split_expressions(
              list_for_dimension(prm.get("Force"), "0; 0; 0", dim, ';'));
            load.subsection  = section;
            point_loads.push_back(load);
          }
        prm.leave_subsection();
      }
  }

  void
  LoadingParameters::check_dimension(const unsigned int dim) const
  {
    const auto size = [](const auto &v) { return std::to_string(v.size()); };
    if (!body_force.empty() && body_force.size() != dim)
      reject("Loading/Body force",
             size(body_force) + " expressions",
             "needs " + std::to_string(dim) + " expressions separated by ';'");
    for (const auto &c : dirichlet)
      {
        for (const unsigned int component : c.components)
          if (component >= dim)
            reject(c.subsection + "/Components",
                   "z",
                   "there is no z component in 2D");
        if (!c.vertex.empty() && c.vertex.size() != dim)
          reject(c.subsection + "/Vertex",
                 size(c.vertex) + " coordinates",
                 "needs " + std::to_string(dim));
      }
    for (const auto &p : point_loads)
      {
        if (p.point.size() != dim)
          reject(p.subsection + "/Point",
                 size(p.point) + " coordinates",
                 "needs " + std::to_string(dim));
        if (p.expressions.size() != dim)
          reject(p.subsection + "/Force",
                 size(p.expressions) + " expressions",
                 "needs " + std::to_string(dim) +
                   " expressions separated by ';'");
      }
    for (const auto &c : boundary_loads)
      {
        const bool vector_valued = boundary_load_kind(c.kind).vector_valued;
        if (vector_valued && c.expressions.size() != dim)
          reject(c.subsection + "/" + c.kind,
                 size(c.expressions) + " expressions",
                 "needs " + std::to_string(dim) +
                   " expressions separated by ';'");
        if (!vector_valued && c.expressions.size() != 1)
          reject(c.subsection + "/" + c.kind,
                 size(c.expressions) + " expressions",
                 "needs one expression");
      }
  }

  void
  LoadingParameters::check_dirichlet_conflicts() const
  {
    // Two conditions on the same id and component contradict each other.
    for (unsigned int a = 0; a < dirichlet.size(); ++a)
      for (unsigned int b = a + 1; b < dirichlet.size(); ++b)
        if (dirichlet[a].boundary_region == dirichlet[b].boundary_region &&
            (!dirichlet[a].boundary_region.empty() ||
             dirichlet[a].boundary_id == dirichlet[b].boundary_id))
          for (const unsigned int ca : dirichlet[a].components)
            for (const unsigned int cb : dirichlet[b].components)
              if (ca == cb &&
                  (dirichlet[a].vertex.empty() || dirichlet[b].vertex.empty() ||
                   dirichlet[a].vertex == dirichlet[b].vertex))
                {
                  const bool by_region = !dirichlet[b].boundary_region.empty();
                  reject(dirichlet[b].subsection +
                           (by_region ? "/Boundary region" : "/Boundary id"),
                         by_region ? dirichlet[b].boundary_region
                                   : std::to_string(dirichlet[b].boundary_id),
                         "component " + std::string(1, "xyz"[ca]) +
                           " of this boundary " +
                           (by_region ? "region" : "id") +
                           " is already prescribed in " +
                           dirichlet[a].subsection);
                }
  }
} // namespace hyperelastic
