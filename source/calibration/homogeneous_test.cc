// Homogeneous laboratory tests of a material point (see the header).
#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/calibration/homogeneous_test.h>

#include <array>
#include <cmath>
#include <limits>

namespace hyperelastic
{
  namespace calibration
  {
    namespace
    {
      const std::array<std::pair<TestType, const char *>, 8> test_names = {
        {{TestType::uniaxial, "uniaxial"},
         {TestType::equibiaxial, "equibiaxial"},
         {TestType::planar, "planar"},
         {TestType::simple_shear, "simple shear"},
         {TestType::biaxial, "biaxial"},
         {TestType::volumetric, "volumetric"},
         {TestType::relaxation, "relaxation"},
         {TestType::scene, "scene"}}};

      constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

      /// The stretch tests: the measured direction o, the free direction f
      /// and dF_kk/da for the lateral stretch a.
      struct StretchTest
      {
        unsigned int          measured;
        unsigned int          free;
        std::array<double, 3> pattern;
      };

      StretchTest
      stretch_test(const TestState &state)
      {
        if (state.type == TestType::uniaxial ||
            state.type == TestType::relaxation)
          return {0, 1, {{0., 1., 1.}}};
        return {state.component, 2, {{0., 0., 1.}}};
      }

      /// The principal stretches with lateral stretch @p a.
      std::array<double, 3>
      stretches_with(const TestState &state, const double a)
      {
        const double l1 = state.stretch_1;
        switch (state.type)
          {
          case TestType::uniaxial:
          case TestType::relaxation:
            return {{l1, a, a}};
          case TestType::equibiaxial:
            return {{l1, l1, a}};
          case TestType::planar:
            return {{l1, 1., a}};
          default:
            return {{l1, state.stretch_2, a}};
          }
      }

      /// The lateral stretch that makes J = 1.
      double
      isochoric_lateral(const TestState &state)
      {
        const double l1 = state.stretch_1;
        switch (state.type)
          {
          case TestType::uniaxial:
          case TestType::relaxation:
            return 1. / std::sqrt(l1);
          case TestType::equibiaxial:
            return 1. / (l1 * l1);
          case TestType::planar:
            return 1. / l1;
          default:
            return 1. / (l1 * state.stretch_2);
          }
      }

      Tensor<2, 3>
      diagonal(const std::array<double, 3> &l)
      {
        Tensor<2, 3> F;
        for (unsigned int i = 0; i < 3; ++i)
          F[i][i] = l[i];
        return F;
      }

      /// sum_k A_iikk pattern_k: dP_ii/da.
      double
      lateral_slope(const StressTangent<3>      &A,
                    const unsigned int           i,
                    const std::array<double, 3> &pattern)
      {
        double slope = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          slope += A[i][i][k][k] * pattern[k];
        return slope;
      }

      /// The lateral stretch with P_ff = 0 (Newton from the isochoric one);
      /// NaN if Newton does not converge.
      double
      free_lateral(const Material<3> &material, const TestState &state)
      {
        const StretchTest test = stretch_test(state);
        double            a    = isochoric_lateral(state);
        for (unsigned int iteration = 0; iteration < 100; ++iteration)
          {
            Tensor<2, 3>     P;
            StressTangent<3> A;
            material.stress_and_tangent(diagonal(stretches_with(state, a)),
                                        P,
                                        A);
            const double slope = lateral_slope(A, test.free, test.pattern);
            if (!std::isfinite(P[test.free][test.free]) || !(slope > 0.))
              return not_a_number;
            const double step = -P[test.free][test.free] / slope;
            if (std::abs(step) <= 1e-14 * a)
              return a;
            a = a + step > 0. ? a + step : 0.5 * a;
          }
        return not_a_number;
      }

      Response
      shear_response(const Material<3>            &material,
                     const ConstantDerivatives<3> *derivatives,
                     const double                  g)
      {
        Tensor<2, 3> F = dealii::unit_symmetric_tensor<3>();
        F[0][1]        = g;
        Response response;
        response.value = material.first_piola_kirchhoff(F)[0][1];
        if (derivatives)
          for (const Tensor<2, 3> &dP : derivatives->stress_derivatives(F))
            response.derivatives.push_back(dP[0][1]);
        return response;
      }

      /// pressure = -sigma_xx = -P_xx J^(-2/3) at F = J^(1/3) I.
      Response
      volumetric_response(const Material<3>            &material,
                          const ConstantDerivatives<3> *derivatives,
                          const double                  J)
      {
        const double       s = std::cbrt(J);
        const Tensor<2, 3> F =
          s * Tensor<2, 3>(dealii::unit_symmetric_tensor<3>());
        Response response;
        response.value = -material.first_piola_kirchhoff(F)[0][0] / (s * s);
        if (derivatives)
          for (const Tensor<2, 3> &dP : derivatives->stress_derivatives(F))
            response.derivatives.push_back(-dP[0][0] / (s * s));
        return response;
      }

      Response
      stretch_response(const Material<3>            &material,
                       const ConstantDerivatives<3> *derivatives,
                       const TestState              &state,
                       const bool                    incompressible)
      {
        const StretchTest test = stretch_test(state);
        const unsigned    o = test.measured, f = test.free;
        const double      a = incompressible ? isochoric_lateral(state)
                                             : free_lateral(material, state);
        Response          response;
        if (!std::isfinite(a))
          {
            response.value = not_a_number;
            if (derivatives)
              response.derivatives.assign(derivatives->constant_names().size(),
                                          not_a_number);
            return response;
          }
        const std::array<double, 3> l = stretches_with(state, a);
        const Tensor<2, 3>          F = diagonal(l);
        // Incompressible: the pressure that frees face f; compressible: P_ff
        // is 0 and a moves with the constants instead (dP/dF needed).
        Tensor<2, 3>     P;
        StressTangent<3> A;
        if (incompressible || !derivatives)
          P = material.first_piola_kirchhoff(F);
        else
          material.stress_and_tangent(F, P, A);
        const double ratio = l[f] / l[o];
        response.value = incompressible ? P[o][o] - ratio * P[f][f] : P[o][o];
        if (!derivatives)
          return response;
        const double coupling = incompressible
                                  ? 0.
                                  : lateral_slope(A, o, test.pattern) /
                                      lateral_slope(A, f, test.pattern);
        for (const Tensor<2, 3> &dP : derivatives->stress_derivatives(F))
          response.derivatives.push_back(incompressible
                                           ? dP[o][o] - ratio * dP[f][f]
                                           : dP[o][o] - coupling * dP[f][f]);
        return response;
      }
    } // namespace

    std::string
    test_type_names()
    {
      std::string names;
      for (const auto &entry : test_names)
        if (entry.first != TestType::scene)
          names += (names.empty() ? "" : "|") + std::string(entry.second);
      return names;
    }

    TestType
    test_type(const std::string &name)
    {
      for (const auto &entry : test_names)
        if (name == entry.second)
          return entry.first;
      throw InputError("unknown test '" + name + "'; the tests are " +
                       test_type_names());
    }

    std::string
    test_type_name(const TestType type)
    {
      for (const auto &entry : test_names)
        if (type == entry.first)
          return entry.second;
      return "";
    }

    Response
    homogeneous_response(const Material<3>            &material,
                         const ConstantDerivatives<3> *derivatives,
                         const TestState              &state,
                         const bool                    incompressible)
    {
      if (state.type == TestType::simple_shear)
        return shear_response(material, derivatives, state.stretch_1);
      if (state.type == TestType::volumetric)
        return volumetric_response(material, derivatives, state.stretch_1);
      return stretch_response(material, derivatives, state, incompressible);
    }

    bool
    isotropic_about_x(const Material<3> &material)
    {
      TestState state;
      state.stretch_1      = 1.5;
      const Tensor<2, 3> P = material.first_piola_kirchhoff(
        diagonal(stretches_with(state, isochoric_lateral(state))));
      return std::abs(P[1][1] - P[2][2]) <=
             1e-10 *
               (std::abs(P[1][1]) + std::abs(P[2][2]) + std::abs(P[0][0]));
    }

    std::vector<double>
    principal_stretches(const Material<3> &material,
                        const TestState   &state,
                        const bool         incompressible)
    {
      if (state.type == TestType::simple_shear)
        return {1., 1., 1.};
      if (state.type == TestType::volumetric)
        {
          const double s = std::cbrt(state.stretch_1);
          return {s, s, s};
        }
      const double                a = incompressible ? isochoric_lateral(state)
                                                     : free_lateral(material, state);
      const std::array<double, 3> l = stretches_with(state, a);
      return {l[0], l[1], l[2]};
    }
  } // namespace calibration
} // namespace hyperelastic
