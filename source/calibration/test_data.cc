// Reading a test's CSV file (see the header).
#include <deal.II/base/utilities.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/calibration/test_data.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace hyperelastic
{
  namespace calibration
  {
    namespace
    {
      std::vector<std::string>
      split_row(const std::string &line)
      {
        std::vector<std::string> fields;
        for (const std::string &field :
             dealii::Utilities::split_string_list(line, ','))
          fields.push_back(dealii::Utilities::trim(field));
        return fields;
      }

      /// A CSV file's header and data rows (blank lines and lines starting
      /// with '#' skipped), each with the "<kind> file '...' line N" its
      /// messages start with.
      struct CsvRow
      {
        std::string              where;
        std::vector<std::string> fields;
      };

      struct CsvFile
      {
        CsvRow              header; ///< no fields: the file has no header
        std::vector<CsvRow> rows;
      };

      CsvFile
      read_csv(const std::string &file, const std::string &kind)
      {
        std::ifstream in(file);
        if (!in)
          throw InputError("cannot open " + kind + " file '" + file + "'");
        CsvFile     csv;
        std::string line;
        for (unsigned int number_of_line = 1; std::getline(in, line);
             ++number_of_line)
          {
            const std::string text = dealii::Utilities::trim(line);
            if (text.empty() || text[0] == '#')
              continue;
            CsvRow row{kind + " file '" + file + "' line " +
                         std::to_string(number_of_line),
                       split_row(text)};
            if (csv.header.fields.empty())
              csv.header = row;
            else
              csv.rows.push_back(row);
          }
        return csv;
      }

      double
      number(const std::string &text, const std::string &where)
      {
        std::size_t used  = 0;
        double      value = 0.;
        try
          {
            value = std::stod(text, &used);
          }
        catch (...)
          {
            used = 0;
          }
        if (used == 0 || used != text.size() || !std::isfinite(value))
          throw InputError(where + ": '" + text + "' is not a finite number");
        return value;
      }

      /// An input error if @p row has fewer fields than @p needed.
      void
      check_length(const CsvRow &row, const std::size_t needed)
      {
        if (row.fields.size() < needed)
          throw InputError(row.where + ": " +
                           std::to_string(row.fields.size()) +
                           " values, the header has more columns");
      }

      /// The states and measured values of one data row.
      void
      add_row(TestData                  &data,
              const std::vector<double> &v,
              const double               held_stretch,
              const std::string         &where)
      {
        const bool shear      = data.type == TestType::simple_shear;
        const bool relaxation = data.type == TestType::relaxation;
        if (!shear && !relaxation && !(v[0] > 0.))
          throw InputError(where + ": " + required_columns(data.type)[0] +
                           " must be positive");
        if (relaxation && v[0] < 0.)
          throw InputError(where + ": time must not be negative");
        TestState state;
        state.type      = data.type;
        state.stretch_1 = v[0];
        if (relaxation)
          {
            state.stretch_1 = held_stretch;
            state.time      = v[0];
          }
        if (data.type == TestType::biaxial)
          {
            if (!(v[1] > 0.))
              throw InputError(where + ": stretch_2 must be positive");
            state.stretch_2 = v[1];
            for (unsigned int c = 0; c < 2; ++c)
              {
                state.component = c;
                data.states.push_back(state);
                data.measured.push_back(v[2 + c]);
              }
            return;
          }
        data.states.push_back(state);
        data.measured.push_back(v[1]);
      }

      /// Field @p c of @p row as a number (check_length() first).
      double
      field(const CsvRow &row, const unsigned int c)
      {
        check_length(row, c + 1);
        return number(row.fields[c], row.where);
      }
    } // namespace

    std::vector<std::string>
    required_columns(const TestType type)
    {
      switch (type)
        {
        case TestType::biaxial:
          return {"stretch_1",
                  "stretch_2",
                  "nominal_stress_1",
                  "nominal_stress_2"};
        case TestType::simple_shear:
          return {"shear", "nominal_shear_stress"};
        case TestType::volumetric:
          return {"J", "pressure"};
        case TestType::relaxation:
          return {"time", "nominal_stress"};
        default:
          return {"stretch", "nominal_stress"};
        }
    }

    TestData
    read_test_data(const std::string &file,
                   const TestType     type,
                   const double       held_stretch)
    {
      const CsvFile csv = read_csv(file, "test data");
      TestData      data;
      data.type                             = type;
      data.file                             = file;
      const std::vector<std::string> wanted = required_columns(type);
      const auto                    &header = csv.header.fields;
      std::vector<unsigned int>      column;
      for (const std::string &name : wanted)
        {
          if (header.empty())
            break;
          const auto found = std::find(header.begin(), header.end(), name);
          if (found == header.end())
            throw InputError(csv.header.where + ": the header has no column '" +
                             name + "' (a " + test_type_name(type) +
                             " test needs the columns " + listed(wanted) + ")");
          column.push_back(found - header.begin());
        }
      for (const CsvRow &row : csv.rows)
        {
          std::vector<double> values;
          for (const unsigned int c : column)
            values.push_back(field(row, c));
          add_row(data, values, held_stretch, row.where);
        }
      if (data.states.empty())
        throw InputError("test data file '" + file + "' has no data rows" +
                         (column.empty() ? " (and no header)" : ""));
      return data;
    }

    TestData
    read_scene_data(const std::string &file, std::string &column)
    {
      const CsvFile csv = read_csv(file, "scene data");
      TestData      data;
      data.type = TestType::scene;
      data.file = file;
      column.clear();
      const auto &header = csv.header.fields;
      const auto  t = std::find(header.begin(), header.end(), "load_factor");
      if (!header.empty() && (t == header.end() || header.size() < 2))
        throw InputError(csv.header.where +
                         ": the header needs the columns load_factor and one "
                         "column of the scene's CSV (for example "
                         "reaction_2_z)");
      const unsigned int t_column = t - header.begin();
      const unsigned int y_column = t_column == 0 ? 1 : 0;
      if (!header.empty())
        column = header[y_column];
      for (const CsvRow &row : csv.rows)
        {
          check_length(row, std::max(t_column, y_column) + 1);
          TestState state;
          state.type      = TestType::scene;
          state.stretch_1 = number(row.fields[t_column], row.where);
          if (!(state.stretch_1 > 0.) ||
              (!data.states.empty() &&
               !(state.stretch_1 > data.states.back().stretch_1)))
            throw InputError(row.where + ": load factors must be positive and "
                                         "strictly increasing");
          data.states.push_back(state);
          data.measured.push_back(number(row.fields[y_column], row.where));
        }
      if (data.states.empty())
        throw InputError("scene data file '" + file + "' has no data rows");
      return data;
    }
  } // namespace calibration
} // namespace hyperelastic
