// Prints the registered material models, one per line as
//   NAME<TAB>linear|nonlinear<TAB>TAG
// (TAG: NAME with every character but letters replaced by '_', the form the
// ctest names use). Run at build time by tests/CMakeLists.txt to generate the
// per-model ctests (tests/model_tests.cmake), so that a newly registered
// model gets them without any CMake edit.
#include <hyperelastic/materials/material_registry.h>

#include <cctype>
#include <iostream>

int
main()
{
  for (const hyperelastic::MaterialModel &model :
       hyperelastic::material_models())
    {
      std::string tag = model.name;
      for (char &c : tag)
        if (!std::isalpha(static_cast<unsigned char>(c)))
          c = '_';
      std::cout << model.name << '\t'
                << (model.is_linear ? "linear" : "nonlinear") << '\t' << tag
                << '\n';
    }
  return 0;
}
