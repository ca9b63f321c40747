// The entry of a test executable that holds several test programs (the
// test groups of tests/CMakeLists.txt): the program is chosen by the name
// it is called by, argv[0] (build/tests/<program> is a link to its group's
// executable), or by a first argument naming it.
#pragma once

#include <cstring>
#include <iostream>
#include <map>
#include <string>

namespace hyperelastic::testing
{
  using ProgramMain = int (*)(int, char **);

  /// A program's main() called with the arguments given to it.
  inline int
  call_main(int (*program)(), int, char **)
  {
    return program();
  }

  inline int
  call_main(int (*program)(int, char **), int argc, char **argv)
  {
    return program(argc, argv);
  }

  /// Runs the program of @p programs named by argv[0]'s file name or, if
  /// that names none, by argv[1] (then shifted away); exit 2 with the list
  /// otherwise.
  inline int
  dispatch(int argc, char **argv, const std::map<std::string, ProgramMain> &programs)
  {
    const char *slash = std::strrchr(argv[0], '/');
    const auto  named = programs.find(slash ? slash + 1 : argv[0]);
    if (named != programs.end())
      return named->second(argc, argv);
    if (argc > 1)
      {
        const auto first = programs.find(argv[1]);
        if (first != programs.end())
          {
            argv[1] = argv[0];
            return first->second(argc - 1, argv + 1);
          }
      }
    std::cerr << "Usage: " << argv[0] << " PROGRAM [ARGUMENTS]: the test "
              << "programs of this executable are";
    for (const auto &[name, program] : programs)
      std::cerr << " " << name;
    std::cerr << " (or call build/tests/PROGRAM)" << std::endl;
    return 2;
  }
} // namespace hyperelastic::testing
