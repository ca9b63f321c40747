// The laboratory tests a fit is made from (uniaxial, equibiaxial, planar,
// simple shear, general biaxial, volumetric), as homogeneous deformations of
// a 3D material point: the model's own P(F) and dP/dF give the measured
// quantity and, with ConstantDerivatives, its exact derivatives with respect
// to the model's constants.
//
// Principal stretches along x, y, z; the stress measured is nominal (force
// per reference area), P_xx (P_yy for the second stress of a biaxial test).
//   uniaxial      (l, a, a)          traction-free y and z
//   equibiaxial   (l, l, a)          traction-free z
//   planar        (l, 1, a)          traction-free z (pure shear: y held)
//   biaxial       (l1, l2, a)        traction-free z
//   simple shear  F = I + g e_x e_y  P_xy measured, no lateral freedom
//   volumetric    F = J^(1/3) I      pressure -sigma_xx = -P_xx J^(-2/3)
//   relaxation    a uniaxial stretch held from time 0: here its long-term
//                 (equilibrium) stress; the Prony factor is the fit's
//                 (calibration/material_fit.h)
// Incompressible: J = 1 fixes a, and a pressure p F^-T is added so that the
// free face carries no traction: N = P_oo - (l_f / l_o) P_ff (o the
// measured, f the free direction). Simple shear is isochoric with
// (F^-T)_xy = 0, so p does not enter P_xy. Compressible: a solves
// P_ff(a) = 0 by Newton with dP/dF, and the implicit function theorem gives
// da/dc = -(dP_ff/dc) / (dP_ff/da).
#pragma once

#include <hyperelastic/materials/material.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  namespace calibration
  {
    enum class TestType
    {
      uniaxial,
      equibiaxial,
      planar,
      simple_shear,
      biaxial,
      volumetric,
      relaxation,
      scene ///< a whole scene's CSV column (no homogeneous response)
    };

    /// "uniaxial | equibiaxial | planar | simple shear | biaxial |
    /// volumetric | relaxation" (a parameter pattern, in this order).
    std::string
    test_type_names();

    /// The test called @p name (one of test_type_names()).
    TestType
    test_type(const std::string &name);

    /// The name of @p type, as a fit file writes it.
    std::string
    test_type_name(TestType type);

    /// One measured value: the controlled stretch(es) (for simple shear the
    /// shear g, for a volumetric test J) and which stress of a biaxial test.
    struct TestState
    {
      TestType     type      = TestType::uniaxial;
      double       stretch_1 = 1.;
      double       stretch_2 = 1.; ///< biaxial only
      unsigned int component = 0;  ///< biaxial: 0 = P_xx, 1 = P_yy
      double       time      = 0.; ///< relaxation: time since the jump
    };

    /// The model's measured quantity at @p state, and its derivatives with
    /// respect to the constants of @p derivatives (the model's
    /// ConstantDerivatives; null: no derivatives). NaN if the model is
    /// undefined there or the lateral stretch cannot be solved.
    struct Response
    {
      double              value = 0.;
      std::vector<double> derivatives;
    };

    Response
    homogeneous_response(const Material<3>            &material,
                         const ConstantDerivatives<3> *derivatives,
                         const TestState              &state,
                         bool                          incompressible);

    /// True if @p material responds alike in y and z to a stretch along x
    /// (P_yy = P_zz at diag(1.5, 1.5^-1/2, 1.5^-1/2), to 1e-10 of their
    /// size), so that a uniaxial test's lateral stretches are equal, as the
    /// tests here assume. Not so for fibres off the x axis.
    bool
    isotropic_about_x(const Material<3> &material);

    /// The principal stretches (x, y, z) of @p state in equilibrium (for
    /// simple shear: 1, 1, 1); NaN if the lateral stretch cannot be solved.
    std::vector<double>
    principal_stretches(const Material<3> &material,
                        const TestState   &state,
                        bool               incompressible);
  } // namespace calibration
} // namespace hyperelastic
