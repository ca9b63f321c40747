// The scene's Problem subsection: declaration, documentation and validation
// of its entries.
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/formulation/formulation_parameters.h>
#include <hyperelastic/formulation/formulation_registry.h>
#include <hyperelastic/materials/material_parameters.h>

namespace hyperelastic
{
  using namespace entry_patterns;

  void
  ProblemParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    prm.declare_entry("Dimension",
                      "3",
                      Integer(2, 3),
                      "Space dimension: 2 (plane strain, triangles) or 3 "
                      "(tetrahedra).");
    prm.declare_entry("Finite element degree",
                      "1",
                      Integer(1, 2),
                      "Polynomial degree of the simplex Lagrange element: 1 "
                      "(P1, linear) or 2 (P2, quadratic).");
    prm.declare_entry(
      "Assembly",
      "automatic",
      Selection("automatic|generic"),
      "'automatic': P1 forces, tangent and energy from the precomputed P1 "
      "kernel (hat-function gradients and volumes stored per cell, values "
      "written straight into the matrix rows), P2 from FEValues. 'generic': "
      "FEValues for every degree (several times slower for P1; the reference "
      "the kernel is tested against).");
    std::string documentation =
      "How the unknowns and the material part are formulated:";
    for (const FormulationKind &kind : formulation_kinds())
      documentation += "\n'" + kind.name + "': " + kind.documentation;
    prm.declare_entry("Formulation",
                      "displacement",
                      Selection(formulation_names()),
                      documentation);
    prm.declare_entry(
      "Mixed element",
      "P1-bubble/P1",
      Selection("P1-bubble/P1|P1/P1 stabilized|P2/P1"),
      "The displacement/pressure pair of 'Formulation = mixed': "
      "'P1-bubble/P1' (MINI: P1 plus a cell bubble, condensed on the cell, "
      "so the system holds P1 unknowns only), 'P1/P1 stabilized' (equal "
      "order with Dohrmann-Bochev pressure-projection stabilisation "
      "-1/mu int (p - Pi0 p)(q - Pi0 q)), 'P2/P1' (Taylor-Hood). All are "
      "inf-sup stable in 2D and 3D.");
    prm.declare_entry(
      "Reference",
      "as meshed",
      Selection("as meshed|loaded"),
      "'as meshed': the mesh is the body's reference (unloaded) "
      "configuration. 'loaded': the mesh is the deformed configuration under "
      "the scene's loads at t = 1 (an imaged organ, a part measured under "
      "load); the run first finds the reference configuration whose forward "
      "solution reproduces it (backward-displacement fixed point with Aitken "
      "relaxation: a forward solve per iteration), writes it to "
      "Output/Directory as <Base name>_reference.msh (ASCII gmsh 4.1, the "
      "mesh file's tags) and then runs the scene from it. Needs a gmsh .msh "
      "mesh file without global refinements; not with contact, checkpoints "
      "or a restart.");
    prm.declare_entry("Reference tolerance",
                      "1e-8",
                      Double(1e-15, 1e-2),
                      "'Reference = loaded': the iteration stops where every "
                      "vertex of the forward solution lies within this "
                      "fraction of the mesh's diagonal of its place in the "
                      "loaded mesh.");
    prm.declare_entry("Reference iterations",
                      "50",
                      Integer(1, 1000),
                      "'Reference = loaded': at most this many forward "
                      "solves; not reaching the tolerance is a convergence "
                      "failure.");
    prm.leave_subsection();
  }

  void
  ProblemParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Problem");
    dimension                 = prm.get_integer("Dimension");
    fe_degree                 = prm.get_integer("Finite element degree");
    fast_p1_assembly          = prm.get("Assembly") == "automatic";
    formulation               = prm.get("Formulation");
    const std::string element = prm.get("Mixed element");
    mixed_element             = element == "P2/P1" ? MixedElement::taylor_hood
                                : element == "P1/P1 stabilized" ? MixedElement::stabilized
                                                                : MixedElement::mini;
    reference_loaded     = prm.get("Reference") == "loaded";
    reference_tolerance  = prm.get_double("Reference tolerance");
    reference_iterations = prm.get_integer("Reference iterations");
    prm.leave_subsection();
  }

  void
  resolve_formulation(ProblemParameters        &problem,
                      const MaterialParameters &material)
  {
    // 'Material/Model = stiffness warping' is an alias of the stiffness
    // warping formulation with the corotational model.
    if (material.stiffness_warping)
      {
        if (problem.formulation == "mixed")
          reject("Problem/Formulation",
                 "mixed",
                 "'Material/Model = stiffness warping' works with the "
                 "displacement formulation only");
        problem.formulation = "stiffness warping";
      }
    const FormulationKind &kind = formulation_kind(problem.formulation);
    if (kind.displacement_degree)
      problem.fe_degree = kind.displacement_degree(problem);
  }
} // namespace hyperelastic
