// The scene's subsections Region 1 ... Region 8: a part of the mesh (the
// cells of a gmsh physical tag, or those whose centre satisfies a condition)
// with a material of its own (a nested subsection Material with exactly the
// entries of the top-level one) and, for dynamics, its own density. Cells in
// no region take the top-level Material. Which cells a region holds is
// decided on the mesh (mesh/cell_regions.h).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/materials/material_parameters.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  struct RegionParameters
  {
    /// Region 1 ... Region max_regions.
    static constexpr unsigned int max_regions = 8;

    /// k of 'Region k' (1 ... max_regions); region 0 is the top-level
    /// Material.
    unsigned int number = 0;
    /// 'Material id': the gmsh physical tag (volume in 3D, surface in 2D)
    /// of the region's cells; -1 if not given.
    int material_id = -1;
    /// 'Cells': a condition on the cell centre, an expression of x, y (, z)
    /// that is nonzero (true) for the region's cells; empty if not given.
    std::string cells;
    /// The nested subsection Material.
    MaterialParameters material;
    /// 'Density' if given (own_density); otherwise Time
    /// integration/Density applies.
    double density     = 0.;
    bool   own_density = false;

    /// "Region k".
    std::string
    name() const
    {
      return "Region " + std::to_string(number);
    }

    /// Declares the subsections Region 1 ... Region 8.
    static void
    declare(ParameterHandler &prm);

    /// The regions the scene uses (those with 'Material id' or 'Cells'),
    /// in their order. An InputError names the entry of an invalid value:
    /// both 'Material id' and 'Cells' given, a bad density, or any entry of
    /// the nested Material (named 'Region k/Material/...').
    static std::vector<RegionParameters>
    parse_all(ParameterHandler &prm);
  };

  /// Runs @p check (a scene check of one MaterialParameters) and names the
  /// region in its InputError: an entry 'Material/...' becomes
  /// 'Region k/Material/...'.
  template <typename Check>
  void
  check_in_region(const RegionParameters &region, Check &&check);

  /// Rethrows the InputError @p message of a check of @p region's material
  /// with the region's entries named.
  [[noreturn]] void
  rethrow_in_region(const RegionParameters &region, const std::string &message);

  template <typename Check>
  void
  check_in_region(const RegionParameters &region, Check &&check)
  {
    try
      {
        check(region.material);
      }
    catch (const InputError &e)
      {
        rethrow_in_region(region, e.what());
      }
  }
} // namespace hyperelastic
