// Calibration (issue 58): the Material block a fit writes, included in
// homogeneous 3D scenes of the uniaxial, equibiaxial, planar, biaxial,
// volumetric and simple shear tests, reproduces the fitted curve (the same
// stress function): each scene's end-face reaction per reference area against
// the fit's value at the stretch of every load step, relative to the curve's
// scale, 1e-8. The fit is compressible (the scenes' lateral faces are free), of
// a one-term Ogden model with its bulk modulus, from data the model made.
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/calibration/material_fit.h>
#include <hyperelastic/calibration/model_constants.h>
#include <hyperelastic/materials/material_parameters.h>

#include "support/checker.h"
#include "support/scene_run.h"

#include <cmath>
#include <sstream>

using namespace hyperelastic;
using namespace hyperelastic::calibration;

namespace
{
  std::string
  material_text(const double scale)
  {
    std::ostringstream out;
    out.precision(17);
    out << "subsection Material\n  set Model = Ogden\n  subsection Ogden\n"
        << "    set mu1 = " << 0.8 * scale
        << "\n    set alpha1 = " << 2.6 * scale
        << "\n    set mu2 = 0\n    set mu3 = 0\n"
        << "    set Bulk modulus = " << 12. * scale << "\n  end\nend\n";
    return out.str();
  }

  /// The scene: the unit cube on rollers at x = 0, y = 0, z = 0, stretched
  /// by the test's end displacements in 4 load steps to (l1, l2).
  std::string
  scene(const TestType     type,
        const double       l1,
        const double       l2,
        const std::string &material)
  {
    std::ostringstream out;
    out.precision(17);
    out << "subsection Problem\n  set Dimension = 3\nend\n"
        << "subsection Mesh\n  set Source = box\n  set Lower corner = 0, 0, 0\n"
        << "  set Upper corner = 1, 1, 1\n  set Subdivisions = 2, 2, 2\nend\n"
        << material
        << "subsection Loading\n  set Number of load steps = 4\nend\n"
        << "subsection Newton\n  set Relative residual tolerance = 1e-13\nend\n"
        << "subsection Output\n  set Write VTU = false\nend\n";
    int        k         = 0;
    const auto dirichlet = [&](const int          id,
                               const char        *component,
                               const std::string &displacement) {
      out << "subsection Dirichlet " << ++k << "\n  set Boundary id = " << id
          << "\n  set Components = " << component
          << "\n  set Displacement = " << displacement << "\nend\n";
    };
    if (type == TestType::simple_shear)
      {
        // Every face moved with u = (g y t, 0, 0).
        std::ostringstream shear;
        shear.precision(17);
        shear << l1 << " * y * t; 0; 0";
        for (int id = 0; id < 6; ++id)
          dirichlet(id, "x, y, z", shear.str());
        return out.str();
      }
    dirichlet(0, "x", "0");
    dirichlet(2, "y", "0");
    dirichlet(4, "z", "0");
    std::ostringstream x_end, y_end;
    x_end.precision(17);
    y_end.precision(17);
    x_end << (l1 - 1.) << " * t";
    y_end << (l2 - 1.) << " * t";
    dirichlet(1, "x", x_end.str());
    if (type == TestType::equibiaxial)
      dirichlet(3, "y", x_end.str());
    else if (type == TestType::planar)
      dirichlet(3, "y", "0");
    else if (type == TestType::biaxial)
      dirichlet(3, "y", y_end.str());
    else if (type == TestType::volumetric)
      {
        dirichlet(3, "y", x_end.str());
        dirichlet(5, "z", x_end.str());
      }
    return out.str();
  }

  double
  column(const StepSummary<3> &summary, const std::string &name)
  {
    for (const auto &c : summary.columns())
      if (c.name == name)
        return c.value;
    return std::nan("");
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                               root =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  testing::Checker check(root);

  // Data of the exact constants, a compressible fit from 10 % away.
  dealii::ParameterHandler exact_prm;
  MaterialParameters::declare(exact_prm);
  exact_prm.parse_input_from_string(material_text(1.));
  const ModelConstants  exact(exact_prm,
                             {"mu1", "alpha1", "Bulk modulus"},
                             false);
  std::vector<TestData> data;
  for (const TestType type : {TestType::uniaxial,
                              TestType::equibiaxial,
                              TestType::planar,
                              TestType::biaxial,
                              TestType::volumetric,
                              TestType::simple_shear})
    {
      TestData test;
      test.index = data.size() + 1;
      test.type  = type;
      for (unsigned int i = 0; i < 8; ++i)
        for (unsigned int c = 0; c < (type == TestType::biaxial ? 2 : 1); ++c)
          {
            TestState state;
            state.type      = type;
            state.stretch_1 = type == TestType::volumetric     ? 0.86 + 0.03 * i
                              : type == TestType::simple_shear ? 0.1 * i
                                                               : 0.8 + 0.1 * i;
            state.stretch_2 = 1.2;
            state.component = c;
            test.states.push_back(state);
          }
      test.measured =
        model_values(*exact.material(exact.start()), {}, {test}, false)[0];
      data.push_back(test);
    }
  dealii::ParameterHandler start_prm;
  MaterialParameters::declare(start_prm);
  start_prm.parse_input_from_string(material_text(1.1));
  const ModelConstants constants(start_prm,
                                 {"mu1", "alpha1", "Bulk modulus"},
                                 false);
  const FitResult      result = fit_material(constants, data, false, 1);
  std::ostringstream   block;
  constants.write_material_block(block, result.values);
  const auto fitted = constants.material(result.values);

  check.section("fitted material block in homogeneous scenes: end-face "
                "reaction per area against the fitted curve (relative, "
                "1e-8)");
  for (const TestType type : {TestType::uniaxial,
                              TestType::equibiaxial,
                              TestType::planar,
                              TestType::biaxial,
                              TestType::volumetric,
                              TestType::simple_shear})
    {
      // Volumetric: every face moved to J = 0.9 (pressure = -P_xx / s^2).
      // Simple shear: every face moved to g = 0.8; the top face's x
      // reaction is P_xy (the P_xx of the faces x = 0 and 1 at its edges
      // cancel on the symmetric mesh).
      const bool   volumetric = type == TestType::volumetric;
      const bool   shear      = type == TestType::simple_shear;
      const double l1         = volumetric ? std::cbrt(0.9) : shear ? 0.8 : 1.6;
      const double l2         = 1.2;
      const auto   problem =
        testing::run_scene<3>(scene(type, l1, l2, block.str()));
      double worst = 0., scale = 0.;
      for (const StepSummary<3> &row : problem->summaries())
        for (unsigned int c = 0; c < (type == TestType::biaxial ? 2 : 1); ++c)
          {
            TestState state;
            state.type      = type;
            const double s  = 1. + (l1 - 1.) * row.load_factor;
            state.stretch_1 = volumetric ? s * s * s
                              : shear    ? l1 * row.load_factor
                                         : s;
            state.stretch_2 = 1. + (l2 - 1.) * row.load_factor;
            state.component = c;
            TestData one;
            one.type           = type;
            one.states         = {state};
            const double curve = model_values(*fitted, {}, {one}, false)[0][0];
            const double reaction = column(row,
                                           shear    ? "reaction_3_x"
                                           : c == 0 ? "reaction_1_x"
                                                    : "reaction_3_y") *
                                    (volumetric ? -1. / (s * s) : 1.);
            worst = std::max(worst, std::abs(reaction - curve));
            scale = std::max(scale, std::abs(curve));
          }
      check.at_most(test_type_name(type) + ": |reaction - fitted| / scale, "
                                           "4 load steps",
                    worst / scale,
                    1e-8);
    }

  check.section("relaxation: a fitted Prony series in a held uniaxial "
                "stretch of an incompressible (mixed, Bulk modulus = inf) "
                "3D scene against the fitted curve (relative, 1e-8)");
  {
    // Yeoh with two processes; relaxation data at stretch 1.4 from the
    // model itself, fitted from 10 % away with J = 1.
    const auto viscoelastic_text = [](const double scale) {
      std::ostringstream out;
      out.precision(17);
      out << "subsection Material\n  set Model = Yeoh\n  subsection Yeoh\n"
          << "    set C10 = 0.5\n    set C20 = 0\n    set C30 = 0\n"
          << "    set Bulk modulus = inf\n  end\n"
          << "  subsection Viscoelasticity\n    set Weights = " << 0.6 * scale
          << ", " << 0.3 * scale
          << "\n    set Relaxation times = " << 0.5 * scale << ", "
          << 4. * scale << "\n    set Quasi-static duration = 2\n  end\nend\n";
      return out.str();
    };
    const double stretch = 1.4, jump = 0.01;
    TestData     relaxation;
    relaxation.index = 1;
    relaxation.type  = TestType::relaxation;
    for (unsigned int i = 0; i < 12; ++i)
      {
        TestState state;
        state.type      = TestType::relaxation;
        state.stretch_1 = stretch;
        state.time      = 0.2 * i;
        relaxation.states.push_back(state);
      }
    dealii::ParameterHandler exact_prm, start_prm;
    MaterialParameters::declare(exact_prm);
    MaterialParameters::declare(start_prm);
    exact_prm.parse_input_from_string(viscoelastic_text(1.));
    start_prm.parse_input_from_string(viscoelastic_text(1.1));
    const ModelConstants exact_series(exact_prm,
                                      {"Weights", "Relaxation times"},
                                      true,
                                      true);
    relaxation.measured =
      model_values(*exact_series.material(exact_series.start()),
                   exact_series.prony(exact_series.start()),
                   {relaxation},
                   true)[0];
    const ModelConstants series(start_prm,
                                {"Weights", "Relaxation times"},
                                true,
                                true);
    const FitResult      fit = fit_material(series, {relaxation}, true, 1);
    std::ostringstream   block;
    series.write_material_block(block, fit.values);
    // The stretch applied within the first step (to t = 0.01, a stop: 0.02
    // of time), then held: rows at t = 0.01 + k/4 and 1, times since the
    // jump 2 (t - 0.01). The program takes the jump with the factor g_j =
    // exp(-dt / (2 tau_j)) of its step (materials/viscoelasticity.h) and is
    // exact after it: the fitted series with beta_j g_j.
    std::ostringstream text;
    text.precision(17);
    text << "subsection Problem\n  set Dimension = 3\n"
         << "  set Formulation = mixed\nend\n"
         << "subsection Mesh\n  set Source = box\n"
         << "  set Lower corner = 0, 0, 0\n  set Upper corner = 1, 1, 1\n"
         << "  set Subdivisions = 2, 2, 2\nend\n"
         << block.str()
         << "subsection Loading\n  set Number of load steps = 4\nend\n"
         << "subsection Load stepping\n  set Stop at load factors = " << jump
         << "\nend\n"
         << "subsection Newton\n  set Relative residual tolerance = 1e-13\n"
         << "end\n"
         << "subsection Output\n  set Write VTU = false\nend\n"
         << "subsection Dirichlet 1\n  set Boundary id = 0\n"
         << "  set Components = x\n  set Displacement = 0\nend\n"
         << "subsection Dirichlet 2\n  set Boundary id = 2\n"
         << "  set Components = y\n  set Displacement = 0\nend\n"
         << "subsection Dirichlet 3\n  set Boundary id = 4\n"
         << "  set Components = z\n  set Displacement = 0\nend\n"
         << "subsection Dirichlet 4\n  set Boundary id = 1\n"
         << "  set Components = x\n  set Displacement = " << stretch - 1.
         << " * min(t / " << jump << ", 1)\nend\n";
    const auto   problem = testing::run_scene<3>(text.str());
    double       worst = 0., scale = 0.;
    unsigned int rows = 0;
    for (const StepSummary<3> &row : problem->summaries())
      if (row.load_factor > jump)
        {
          TestData one       = relaxation;
          one.states         = {relaxation.states[0]};
          one.states[0].time = 2. * (row.load_factor - jump);
          PronySeries jumped = series.prony(fit.values);
          for (unsigned int j = 0; j < jumped.weights.size(); ++j)
            jumped.weights[j] *= std::exp(-2. * jump / (2. * jumped.times[j]));
          const double curve = model_values(*series.material(fit.values),
                                            jumped,
                                            {one},
                                            true)[0][0];
          worst =
            std::max(worst, std::abs(column(row, "reaction_1_x") - curve));

          scale = std::max(scale, std::abs(curve));
          ++rows;
        }
    check.is_true("4 rows after the jump", rows == 4);
    check.at_most("relaxation: |reaction - fitted| / scale",
                  worst / scale,
                  1e-8);
  }
  return check.exit_code(0, MPI_COMM_WORLD);
}
