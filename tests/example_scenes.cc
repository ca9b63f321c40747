// The example scenes of parameters/ against their stored CSV summaries
// (tests/reference/<scene>.csv): a refactoring must not change what a scene
// computes. Each scene runs briefly (SECTION/ENTRY=VALUE settings appended to
// it, e.g. a shorter end time), writes its CSV into a scratch folder, and
// every column is compared with the stored one to 1e-6 of its scale: the
// largest magnitude in the column, or for a vector component (reaction_1_x,
// point2_uy, momentum_z, ...) in all components of that vector, and at least
// 1e-3 (quantities of round-off size around zero are compared absolutely to
// 1e-9). A moment (reaction_moment_<id>_*, contact_moment_<k>_*) is held to
// at least its force's scale (reaction_<id>_*, contact_force_<k>_*) times
// the size of the deformed body (the largest extent of its bounding box):
// where the forces' moments cancel (a body squeezed between plates), the
// force's round-off is its scale. The header must be the same,
// column by column, and so must the number of rows. Columns that count solver
// work (linear and line-search iterations, the final residual, AMG set-ups)
// are not held:
// they follow round-off, the answer does not.
//
// Usage: mpirun -np N example_scenes SCENE.prm REFERENCE.csv
// [SECTION/ENTRY=VALUE ...]
//        with HYPERELASTIC_WRITE_REFERENCE=1 the reference is (re)written
//        instead of compared.
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/scene/parameters.h>
#include <hyperelastic/problem/problem.h>

#include "support/checker.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace hyperelastic;

namespace
{
  struct Table
  {
    std::vector<std::string>         header;
    std::vector<std::vector<double>> rows;
  };

  std::vector<std::string>
  split(const std::string &line, const char separator)
  {
    std::vector<std::string> fields;
    std::stringstream        in(line);
    std::string              field;
    while (std::getline(in, field, separator))
      fields.push_back(field);
    return fields;
  }

  Table
  read_csv(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("cannot read CSV file '" + file + "'");
    Table       table;
    std::string line;
    std::getline(in, line);
    table.header = split(line, ',');
    while (std::getline(in, line))
      if (!line.empty())
        {
          std::vector<double> row;
          for (const auto &field : split(line, ','))
            row.push_back(std::stod(field));
          table.rows.push_back(row);
        }
    return table;
  }

  /// The scene text with @p settings ("Section/Sub/Entry=value") appended:
  /// a later 'set' of the same entry wins.
  std::string
  with_settings(std::string text, const std::vector<std::string> &settings)
  {
    for (const auto &setting : settings)
      {
        const auto equal = setting.find('=');
        const auto slash = setting.rfind('/', equal);
        if (equal == std::string::npos || slash == std::string::npos)
          throw InputError("'" + setting + "' is not SECTION/ENTRY=VALUE");
        const auto sections = split(setting.substr(0, slash), '/');
        text += "\n";
        for (const auto &s : sections)
          text += "subsection " + s + "\n";
        text += "set " + setting.substr(slash + 1, equal - slash - 1) + " = " +
                setting.substr(equal + 1) + "\n";
        for (unsigned int i = 0; i < sections.size(); ++i)
          text += "end\n";
      }
    return text;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm comm  = MPI_COMM_WORLD;
  const bool     root  = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  const bool     write = std::getenv("HYPERELASTIC_WRITE_REFERENCE") != nullptr;
  testing::Checker checker(root);

  const int status = run_and_report(
    [&]() {
      if (argc < 3)
        throw InputError("usage: example_scenes SCENE.prm REFERENCE.csv "
                         "[SECTION/ENTRY=VALUE ...]");
      const std::string scene     = argv[1];
      const std::string reference = argv[2];
      const std::string name =
        std::filesystem::path(scene).stem().string();
      const std::string folder = "example_scenes_output/" + name;

      std::ifstream in(scene);
      if (!in)
        throw InputError("cannot open scene file '" + scene + "'");
      std::stringstream text;
      text << in.rdbuf();
      std::vector<std::string> settings(argv + 3, argv + argc);
      settings.push_back("Output/Directory=" + folder);
      settings.push_back("Output/Base name=" + name);
      settings.push_back("Output/Write VTU=false");
      settings.push_back("Output/Verbose=false");

      Parameters parameters;
      parameters.read_from_string(with_settings(text.str(), settings),
                                  std::filesystem::path(scene)
                                    .parent_path()
                                    .string(),
                                  scene);
      run_scene(parameters, comm);

      if (!root)
        return;
      const std::string csv = folder + "/" + name + ".csv";
      if (write)
        {
          std::filesystem::copy_file(
            csv,
            reference,
            std::filesystem::copy_options::overwrite_existing);
          std::cout << "wrote " << reference << std::endl;
          return;
        }
      const Table computed = read_csv(csv);
      const Table stored   = read_csv(reference);

      // The column list, asserted name by name.
      std::string computed_header, stored_header;
      for (const auto &c : computed.header)
        computed_header += c + " ";
      for (const auto &c : stored.header)
        stored_header += c + " ";
      checker.is_true("CSV columns: " + stored_header,
                      computed_header == stored_header);
      checker.close("rows",
                    computed.rows.size(),
                    stored.rows.size(),
                    1.,
                    0.5);
      if (computed_header != stored_header ||
          computed.rows.size() != stored.rows.size())
        return;

      const std::set<std::string> solver_work = {"linear_iterations",
                                                 "line_search_backtracks",
                                                 "residual",
                                                 "amg_setups"};
      // The components of one vector (reaction_1_x, _y, _z; point2_ux, ...)
      // share one scale: a component that is round-off next to the others
      // is held to the vector's size.
      const auto vector_of = [](const std::string &name) {
        const char last = name.back();
        const char before = name.size() > 1 ? name[name.size() - 2] : ' ';
        return (last == 'x' || last == 'y' || last == 'z') &&
                   (before == '_' || before == 'u') ?
                 name.substr(0, name.size() - 1) :
                 name;
      };
      std::map<std::string, double> scales;
      for (unsigned int c = 0; c < stored.header.size(); ++c)
        for (const auto &row : stored.rows)
          {
            double &scale = scales[vector_of(stored.header[c])];
            scale         = std::max(scale, std::abs(row[c]));
          }
      // A moment's scale is at least its force's times the body's size.
      double size = 0.;
      for (const char axis : {'x', 'y', 'z'})
        {
          const auto low  = std::find(stored.header.begin(),
                                     stored.header.end(),
                                     std::string("deformed_min_") + axis),
                     high = std::find(stored.header.begin(),
                                      stored.header.end(),
                                      std::string("deformed_max_") + axis);
          if (low != stored.header.end() && high != stored.header.end())
            for (const auto &row : stored.rows)
              size = std::max(size,
                              row[high - stored.header.begin()] -
                                row[low - stored.header.begin()]);
        }
      for (const auto &[moment, force] :
           {std::pair<std::string, std::string>("reaction_moment_",
                                                "reaction_"),
            std::pair<std::string, std::string>("contact_moment_",
                                                "contact_force_")})
        for (auto &[name, scale] : scales)
          if (name.rfind(moment, 0) == 0)
            scale = std::max(scale,
                             scales[force + name.substr(moment.size())] * size);
      for (unsigned int c = 0; c < stored.header.size(); ++c)
        {
          if (solver_work.count(stored.header[c]))
            continue;
          double worst = 0.;
          for (unsigned int r = 0; r < stored.rows.size(); ++r)
            worst = std::max(worst,
                             std::abs(computed.rows[r][c] - stored.rows[r][c]));
          // Quantities of round-off size around zero: absolute 1e-9.
          checker.at_most(stored.header[c] + ": largest difference / scale",
                          worst /
                            std::max(scales[vector_of(stored.header[c])], 1e-3),
                          1e-6);
        }
    },
    comm);
  if (write)
    return status;
  return checker.exit_code(status, comm);
}
