// The one place the CSV column list is asserted: StepSummary::columns() with
// every optional group present (reactions and their moments on two boundary
// ids, two output
// points, the AMG set-up count, the pressure range, dynamics, a column added
// by a feature), in 2D
// and 3D, names in order and each value where its name says.
#include <hyperelastic/output/step_summary.h>

#include "support/checker.h"

#include <string>
#include <vector>

using namespace hyperelastic;

namespace
{
  template <int dim>
  void
  check(testing::Checker &checker, const std::vector<std::string> &expected)
  {
    StepSummary<dim> s;
    s.step              = 3;
    s.load_factor       = 0.75;
    s.newton_iterations = 4;
    s.linear_iterations = 40;
    s.residual          = 1e-12;
    s.energy            = 2.5;
    s.min_J             = 0.9;
    dealii::Tensor<1, dim> force;
    for (unsigned int d = 0; d < dim; ++d)
      force[d] = 10. + d;
    s.reactions = {{0, force}, {5, -force}};
    s.reaction_moments = {{0, dealii::Tensor<1, 3>({7., 8., 9.})},
                          {5, dealii::Tensor<1, 3>({-7., -8., -9.})}};
    for (unsigned int d = 0; d < dim; ++d)
      {
        s.deformed_min[d] = -1. - d;
        s.deformed_max[d] = 1. + d;
      }
    s.load_increment      = 0.25;
    s.cut_backs           = 1;
    s.backtracks          = 2;
    s.amg_setups          = 7;
    s.inverted_cells      = 0;
    s.point_displacements = {force, 2. * force};
    s.has_pressure        = true;
    s.pressure_min        = -3.;
    s.pressure_max        = 3.;
    s.dynamic             = true;
    s.kinetic_energy      = 0.5;
    s.linear_momentum     = dealii::Tensor<1, 3>({1., 2., 3.});
    s.angular_momentum    = dealii::Tensor<1, 3>({4., 5., 6.});
    s.more.push_back({"added_by_a_feature", 42.});

    const auto  columns = s.columns();
    std::string names, wanted;
    for (const auto &c : columns)
      names += c.name + " ";
    for (const auto &name : expected)
      wanted += name + " ";
    const std::string tag = std::to_string(dim) + "D: ";
    checker.is_true(tag + "column names and order", names == wanted);
    if (names != wanted)
      checker.note("got      " + names + "\nexpected " + wanted);
    const auto value = [&](const std::string &name) {
      for (const auto &c : columns)
        if (c.name == name)
          return c.value;
      return -1e300;
    };
    checker.close(tag + "step", value("step"), 3., 1., 1e-15);
    checker.close(tag + "reaction_5_y", value("reaction_5_y"), -11., 1., 1e-15);
    checker.close(tag + "reaction_moment_5_z",
                  value("reaction_moment_5_z"),
                  -9.,
                  1.,
                  1e-15);
    if (dim == 3)
      checker.close(tag + "reaction_moment_0_x",
                    value("reaction_moment_0_x"),
                    7.,
                    1.,
                    1e-15);
    checker.close(
      tag + "deformed_max_y", value("deformed_max_y"), 2., 1., 1e-15);
    checker.close(tag + "amg_setups", value("amg_setups"), 7., 1., 1e-15);
    checker.close(tag + "point2_ux", value("point2_ux"), 20., 1., 1e-15);
    checker.close(tag + "total_energy", value("total_energy"), 3., 1., 1e-15);
    checker.close(
      tag + "angular_momentum_z", value("angular_momentum_z"), 6., 1., 1e-15);
    checker.close(
      tag + "added_by_a_feature", value("added_by_a_feature"), 42., 1., 1e-15);
  }
} // namespace

int
main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  int exit_code;
  {
    testing::Checker               checker(true);
    const std::vector<std::string> head   = {"step",
                                             "load_factor",
                                             "newton_iterations",
                                             "linear_iterations",
                                             "residual",
                                             "energy",
                                             "min_J"};
    std::vector<std::string>       names2 = head;
    for (const std::string r : {"reaction_0_", "reaction_5_"})
      for (const std::string a : {"x", "y"})
        names2.push_back(r + a);
    for (const std::string r : {"reaction_moment_0_", "reaction_moment_5_"})
      names2.push_back(r + "z");
    for (const std::string a : {"x", "y"})
      {
        names2.push_back("deformed_min_" + a);
        names2.push_back("deformed_max_" + a);
      }
    for (const std::string n : {"load_increment",
                                "cut_backs",
                                "line_search_backtracks",
                                "amg_setups",
                                "inverted_cells",
                                "point1_ux",
                                "point1_uy",
                                "point2_ux",
                                "point2_uy",
                                "pressure_min",
                                "pressure_max",
                                "kinetic_energy",
                                "total_energy",
                                "momentum_x",
                                "momentum_y",
                                "angular_momentum_z",
                                "added_by_a_feature"})
      names2.push_back(n);
    check<2>(checker, names2);

    std::vector<std::string> names3 = head;
    for (const std::string r : {"reaction_0_", "reaction_5_"})
      for (const std::string a : {"x", "y", "z"})
        names3.push_back(r + a);
    for (const std::string r : {"reaction_moment_0_", "reaction_moment_5_"})
      for (const std::string a : {"x", "y", "z"})
        names3.push_back(r + a);
    for (const std::string a : {"x", "y", "z"})
      {
        names3.push_back("deformed_min_" + a);
        names3.push_back("deformed_max_" + a);
      }
    for (const std::string n :
         {"load_increment",     "cut_backs",          "line_search_backtracks",
          "amg_setups",         "inverted_cells",     "point1_ux",          "point1_uy",
          "point1_uz",          "point2_ux",          "point2_uy",
          "point2_uz",          "pressure_min",       "pressure_max",
          "kinetic_energy",     "total_energy",       "momentum_x",
          "momentum_y",         "momentum_z",         "angular_momentum_x",
          "angular_momentum_y", "angular_momentum_z", "added_by_a_feature"})
      names3.push_back(n);
    check<3>(checker, names3);
    exit_code = checker.exit_code();
  }
  MPI_Finalize();
  return exit_code;
}
