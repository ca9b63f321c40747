// The subsections Region 1 ... Region 8: declaration, documentation and
// validation of their entries.
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/materials/region_parameters.h>

#include <cmath>

namespace hyperelastic
{
  using namespace entry_patterns;

  void
  RegionParameters::declare(ParameterHandler &prm)
  {
    for (unsigned int k = 1; k <= max_regions; ++k)
      {
        prm.enter_subsection("Region " + std::to_string(k));
        prm.declare_entry(
          "Material id",
          "",
          Anything(),
          "The region's cells: those with this gmsh physical tag (a "
          "physical volume in 3D, a physical surface in 2D); a non-negative "
          "integer the mesh must have. Empty: not used (then 'Cells' "
          "selects the cells). A region uses 'Material id' or 'Cells', not "
          "both; a region with neither is not used.");
        prm.declare_entry(
          "Cells",
          "",
          Anything(),
          "The region's cells: those whose centre satisfies this condition, "
          "an expression of x, y (and z in 3D) that is true (nonzero), for "
          "example 'x > 0.5' or 'x^2 + y^2 < 1'. For generated boxes and "
          "mesh files alike. Empty: not used.");
        prm.declare_entry(
          "Density",
          "",
          Anything(),
          "The region's mass density (implicit dynamics), > 0. Empty: "
          "'Time integration/Density'.");
        MaterialParameters::declare(prm);
        prm.leave_subsection();
      }
  }

  std::vector<RegionParameters>
  RegionParameters::parse_all(ParameterHandler &prm)
  {
    std::vector<RegionParameters> regions;
    for (unsigned int k = 1; k <= max_regions; ++k)
      {
        RegionParameters r;
        r.number                  = k;
        const std::string section = r.name();
        prm.enter_subsection(section);
        const std::string id  = dealii::Utilities::trim(prm.get("Material id"));
        r.cells               = dealii::Utilities::trim(prm.get("Cells"));
        const std::string rho = dealii::Utilities::trim(prm.get("Density"));
        const bool        used = !id.empty() || !r.cells.empty();
        if (!id.empty() && !r.cells.empty())
          reject(section + "/Material id",
                 id,
                 "a region is given by 'Material id' or by 'Cells', not "
                 "both ('" +
                   section + "/Cells' = '" + r.cells + "')");
        if (!id.empty())
          {
            char      *end   = nullptr;
            const long value = std::strtol(id.c_str(), &end, 10);
            if (*end != '\0' || value < 0 ||
                value >= long(dealii::numbers::invalid_material_id))
              reject(section + "/Material id",
                     id,
                     "must be a gmsh physical tag, an integer from 0 to " +
                       std::to_string(
                         int(dealii::numbers::invalid_material_id) - 1));
            r.material_id = int(value);
          }
        if (!rho.empty())
          {
            char *end = nullptr;
            r.density = std::strtod(rho.c_str(), &end);
            if (*end != '\0' || !(r.density > 0.) || !std::isfinite(r.density))
              reject(section + "/Density", rho, "must be a positive number");
            r.own_density = true;
          }
        if (used)
          try
            {
              r.material.section = section + "/Material";
              r.material.parse(prm);
            }
          catch (const InputError &e)
            {
              rethrow_in_region(r, e.what());
            }
        prm.leave_subsection();
        if (used)
          regions.push_back(std::move(r));
      }
    return regions;
  }

  void
  rethrow_in_region(const RegionParameters &region, const std::string &message)
  {
    // The material's own messages name 'Material/<entry>'.
    std::string       text = message;
    const std::string from = "'Material/";
    const std::string to   = "'" + region.name() + "/Material/";
    for (std::size_t at = text.find(from); at != std::string::npos;
         at             = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
    if (text == message)
      text += " (the model of '" + region.name() + "/Material')";
    throw InputError(text);
  }
} // namespace hyperelastic
