// A fit's measured data: one CSV file per test (calibration/homogeneous_test.h
// for the tests), read with every error naming the file and the line.
//   uniaxial, equibiaxial, planar: stretch, nominal_stress
//   biaxial:       stretch_1, stretch_2, nominal_stress_1, nominal_stress_2
//   simple shear:  shear, nominal_shear_stress
//   volumetric:    J, pressure (pressure = -mean Cauchy stress: positive
//                  in compression)
//   relaxation:    time, nominal_stress (uniaxial, at a held stretch)
// A header row names the columns (in any order; others are ignored); lines
// starting with '#' and blank lines are skipped.
#pragma once

#include <hyperelastic/calibration/homogeneous_test.h>

#include <string>
#include <vector>

namespace hyperelastic
{
  namespace calibration
  {
    struct TestData
    {
      unsigned int index = 0; ///< k of the subsection Fit/Data k
      TestType     type  = TestType::uniaxial;
      std::string  file;
      double       weight = 1.;
      /// One entry per measured stress value (a biaxial point gives two).
      std::vector<TestState> states;
      std::vector<double>    measured;
    };

    /// The columns a test's file must have, in the order above.
    std::vector<std::string>
    required_columns(TestType type);

    /// Reads @p file (a path) for a test of @p type (a relaxation test at
    /// the held stretch @p held_stretch); an InputError names the file and
    /// line for a missing column, a value that is not a number, a stretch
    /// (or J) <= 0, a negative time, or a file without data rows.
    TestData
    read_test_data(const std::string &file,
                   TestType           type,
                   double             held_stretch = 1.);
    /// A scene fit's data (Fit/Scene data): columns load_factor and one
    /// CSV column of the scene, whose name goes to @p column; load factors
    /// positive and strictly increasing. States of type scene with the
    /// load factor as stretch_1. InputErrors name the file and line.
    TestData
    read_scene_data(const std::string &file, std::string &column);
  } // namespace calibration
} // namespace hyperelastic
