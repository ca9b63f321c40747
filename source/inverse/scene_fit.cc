// A fit through a whole scene (see the header).
#include <deal.II/base/mpi.h>

#include <hyperelastic/base/error_handling.h>
#include <hyperelastic/base/parameter_tools.h>
#include <hyperelastic/calibration/run_fit.h>
#include <hyperelastic/materials/material_parameters.h>
#include <hyperelastic/problem/problem.h>
#include <hyperelastic/inverse/scene_fit.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

namespace hyperelastic
{
  using namespace calibration;

  namespace
  {
    /// The scene file's Material subsection in @p prm (its other entries
    /// skipped).
    void
    read_scene_material(const std::string &scene, dealii::ParameterHandler &prm)
    {
      MaterialParameters::declare(prm);
      std::ifstream in(scene);
      if (!in)
        throw InputError("cannot open scene file '" + scene + "'");
      try
        {
          prm.parse_input(in, scene, "", true);
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError(exception_message(e));
        }
    }

    /// The scene read, checked for a fit, and set to land on the data's
    /// load factors and to write only its CSV summary, into the fit's
    /// output directory as <Base name>_scene.csv.
    Parameters
    prepared_scene(const FitParameters &fit, const TestData &data)
    {
      Parameters scene;
      scene.read(fit.scene);
      const std::string where = "Fit/Scene";
      if (scene.time_integration.dynamic())
        reject(where,
               fit.scene,
               "a fit through a scene needs a quasi-static "
               "scene (Time integration/Scheme = quasi-static)");
      if (!scene.regions.empty())
        reject(where,
               fit.scene,
               "a fit through a scene fits the scene's one "
               "Material; this scene has regions");
      if (scene.load_stepping.method != LoadControl::load_control)
        reject(where,
               fit.scene,
               "a fit through a scene needs load control "
               "('Load stepping/Method = load control')");
      if (data.states.back().stretch_1 > 1.)
        reject("Fit/Scene data",
               data.file,
               "load factors beyond 1: the scene "
               "ends at t = 1");
      scene.load_stepping.stops.clear();
      for (const TestState &state : data.states)
        scene.load_stepping.stops.push_back(state.stretch_1);
      scene.output.directory        = fit.directory;
      scene.output.base_name        = fit.base_name + "_scene";
      scene.output.write_vtu        = false;
      scene.output.write_hdf5       = false;
      scene.output.write_mesh       = false;
      scene.output.surface_format   = SurfaceFormat::none;
      scene.output.checkpoint_every = 0;
      return scene;
    }

    /// The scene built once and run with trial constants.
    template <int dim>
    class SceneRuns
    {
    public:
      SceneRuns(const Parameters    &scene,
                const TestData      &data,
                const FitParameters &fit,
                const MPI_Comm       comm)
          : scene(scene)
          , problem(scene, comm, false)
          , data(data)
          , column(fit.scene_column)
          , reaction(fit.scene_reaction)
      {
        if (reaction && reaction->component >= dim)
          reaction.reset();
      }

      /// The column at the data's load factors (the scene's stops, in the
      /// data's order) with the Material @p material; false if a step
      /// failed. With @p adjoint (and a reaction column), also the
      /// column's derivatives with respect to the model's constants at each
      /// load factor (sensitivities(); empty where the adjoint does not
      /// apply).
      bool
      values(const MaterialParameters &material,
             std::vector<double>      &out,
             const bool                adjoint = false)
      {
        problem.rebuild_materials(material, scene.regions);
        ++runs;
        derivatives.assign(data.states.size(), {});
        problem.set_step_observer([&](const StepSummary<dim> &row) {
          if (adjoint && reaction && row.stop)
            derivatives[*row.stop] =
              problem.reaction_sensitivities(reaction->boundary_id,
                                             reaction->component);
        });
        try
          {
            problem.run();
          }
        catch (const ConvergenceFailure &)
          {
            return false;
          }
        out.assign(data.states.size(), 0.);
        std::vector<bool> landed(data.states.size(), false);
        for (const StepSummary<dim> &row : problem.summaries())
          if (row.stop)
            {
              out[*row.stop]    = value_of(row);
              landed[*row.stop] = true;
            }
        if (std::count(landed.begin(), landed.end(), true) !=
            long(landed.size()))
          throw std::logic_error("a scene run did not stop at every load "
                                 "factor of the data");
        return true;
      }

      /// The adjoint's derivatives of the last run with adjoint = true,
      /// per data point (model constants' order); empty if it does not
      /// apply (not a reaction column, or Problem::reaction_sensitivities()
      /// declined).
      std::vector<std::vector<double>>
      sensitivities() const
      {
        for (const std::vector<double> &d : derivatives)
          if (d.empty())
            return {};
        return derivatives;
      }

      /// Scene runs, and Jacobians the adjoint gave (for the summary).
      unsigned int runs = 0, adjoint_jacobians = 0;

    private:
      const Parameters                &scene;
      Problem<dim>                     problem;
      const TestData                  &data;
      const std::string                column;
      std::optional<ReactionColumn>    reaction;
      std::vector<std::vector<double>> derivatives;

      /// The column in @p row: a support's reaction by its boundary id and
      /// component, any other column by its name.
      double
      value_of(const StepSummary<dim> &row) const
      {
        if (reaction)
          for (const auto &[id, force] : row.reactions)
            if (id == reaction->boundary_id)
              return force[reaction->component];
        std::string names;
        for (const SummaryColumn &c : row.columns())
          {
            if (c.name == column)
              return c.value;
            names += (names.empty() ? "" : ", ") + c.name;
          }
        throw InputError("scene data file '" + data.file +
                         "': the scene's CSV has no column '" + column +
                         "'; its columns are " + names);
      }
    };

    /// How the Jacobian is made: the adjoint where it applies (else
    /// differences), only the adjoint (J empty where it does not apply),
    /// only differences.
    enum class Gradient
    {
      automatic,
      adjoint,
      differences
    };

    /// The residuals at @p x and their Jacobian: by the adjoint of the
    /// converged equilibria (Problem::reaction_sensitivities() through the
    /// chain to the free entries) where it applies, otherwise by central
    /// differences of whole runs, r(x +- h e_k), h = 1e-6 |x_k| (1e-6
    /// where x_k = 0), one-sided where a side fails.
    template <int dim>
    bool
    scene_residuals(SceneRuns<dim>                   &runs,
                    const ModelConstants             &constants,
                    const std::vector<double>        &measured,
                    const std::vector<double>        &x,
                    std::vector<double>              &r,
                    std::vector<std::vector<double>> &J,
                    const Gradient method = Gradient::automatic)
    {
      const auto at = [&](const std::vector<double> &values,
                          std::vector<double>       &out) {
        const auto material = constants.parameters(values);
        return material && runs.values(*material, out);
      };
      std::vector<double>              centre;
      std::vector<std::vector<double>> chain;
      const auto material = constants.parameters(x, &chain);
      if (!material ||
          !runs.values(*material, centre, method != Gradient::differences))
        return false;
      r.resize(measured.size());
      for (unsigned int i = 0; i < measured.size(); ++i)
        r[i] = centre[i] - measured[i];
      J.assign(measured.size(), std::vector<double>(x.size(), 0.));
      const auto adjoint = runs.sensitivities();
      if (!adjoint.empty() && adjoint[0].size() == chain.size() &&
          chain[0].size() == x.size())
        {
          ++runs.adjoint_jacobians;
          for (unsigned int i = 0; i < measured.size(); ++i)
            for (unsigned int m = 0; m < chain.size(); ++m)
              for (unsigned int k = 0; k < x.size(); ++k)
                J[i][k] += adjoint[i][m] * chain[m][k];
          return true;
        }
      if (method == Gradient::adjoint)
        J.clear();
      for (unsigned int k = 0; k < x.size() && method != Gradient::adjoint; ++k)
        {
          const double        h  = 1e-6 * (x[k] != 0. ? std::abs(x[k]) : 1.);
          std::vector<double> up = x, down = x, r_up, r_down;
          up[k] += h;
          down[k] -= h;
          const bool has_up = at(up, r_up), has_down = at(down, r_down);
          if (!has_up && !has_down)
            return false;
          for (unsigned int i = 0; i < measured.size(); ++i)
            J[i][k] = has_up && has_down ? (r_up[i] - r_down[i]) / (2. * h)
                      : has_up           ? (r_up[i] - centre[i]) / h
                                         : (centre[i] - r_down[i]) / h;
        }
      return true;
    }

    /// The free constants of the scene's Material subsection (read into
    /// @p prm).
    std::unique_ptr<ModelConstants>
    scene_constants(const FitParameters      &parameters,
                    dealii::ParameterHandler &prm)
    {
      read_scene_material(parameters.scene, prm);
      return fit_constants(prm,
                           parameters,
                           parameters.data,
                           false,
                           "scene file '" + parameters.scene + "'");
    }

    template <int dim>
    std::array<std::vector<std::vector<double>>, 2>
    jacobians(const FitParameters &parameters,
              const Parameters    &scene,
              const MPI_Comm       comm)
    {
      dealii::ParameterHandler prm;
      const auto               constants = scene_constants(parameters, prm);
      const TestData          &data      = parameters.data[0];
      SceneRuns<dim>           runs(scene, data, parameters, comm);
      std::array<std::vector<std::vector<double>>, 2> J;
      std::vector<double>                             r;
      for (const Gradient method : {Gradient::adjoint, Gradient::differences})
        scene_residuals(runs,
                        *constants,
                        data.measured,
                        constants->start(),
                        r,
                        J[method == Gradient::adjoint ? 0 : 1],
                        method);
      return J;
    }

    template <int dim>
    FitResult
    fit(const FitParameters &parameters,
        const Parameters    &scene,
        const std::string   &fit_file,
        const MPI_Comm       comm)
    {
      const auto               begin = std::chrono::steady_clock::now();
      const TestData          &data  = parameters.data[0];
      dealii::ParameterHandler prm;
      const auto               fitted    = scene_constants(parameters, prm);
      const ModelConstants    &constants = *fitted;
      SceneRuns<dim>           runs(scene, data, parameters, comm);
      LeastSquaresProblem      problem;
      problem.evaluate = [&](const std::vector<double>        &x,
                             std::vector<double>              &r,
                             std::vector<std::vector<double>> &J) {
        return scene_residuals(runs, constants, data.measured, x, r, J);
      };
      FitReport report;
      report.model          = constants.model();
      report.names          = constants.names();
      report.data           = parameters.data;
      report.incompressible = false;
      report.result =
        multi_start_fit(problem, constants.start(), parameters.starts);
      if (!std::isfinite(report.result.cost))
        throw InputError("fit file '" + fit_file +
                         "': the scene's steps "
                         "fail for every start (check the starting "
                         "constants in the scene's Material subsection)");
      // The fitted scene once more: its summary is <Base name>_scene.csv.
      std::vector<double> values;
      runs.values(*constants.parameters(report.result.values), values);
      report.fitted       = {values};
      report.stretch_2    = {std::vector<double>(values.size(), 0.)};
      const auto material = constants.material(report.result.values);
      report.stability    = drucker_stability(*material,
                                           false,
                                           parameters.stability_lowest,
                                           parameters.stability_highest);
      std::ostringstream note;
      note << "through the scene " << parameters.scene << " (column "
           << parameters.scene_column << " at " << data.states.size()
           << " load factors): Jacobian "
           << (runs.adjoint_jacobians > 0
                 ? "by the adjoint of the converged equilibria (one solve per "
                   "data point)"
                 : "by central differences of whole scene runs (the adjoint "
                   "needs a reaction column, no contact, no history and a "
                   "model with constant derivatives)")
           << ", " << runs.runs << " scene runs in all ("
           << constants.trial_parses() << " trial constants parsed)";
      report.notes = {note.str()};
      report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin)
          .count();
      report_fit(parameters, report, constants, *material, false, comm);
      return report.result;
    }
  } // namespace

  namespace
  {
    /// prepared_scene() with its input errors naming @p fit_file.
    Parameters
    scene_of(const FitParameters &parameters, const std::string &fit_file)
    {
      try
        {
          return prepared_scene(parameters, parameters.data[0]);
        }
      catch (const InputError &e)
        {
          const std::string what = e.what();
          throw InputError(what.rfind("scene file", 0) == 0
                             ? what
                             : "fit file '" + fit_file + "': " + what);
        }
    }
  } // namespace

  std::array<std::vector<std::vector<double>>, 2>
  scene_jacobians(const FitParameters &parameters, const MPI_Comm comm)
  {
    const Parameters scene = scene_of(parameters, "(test)");
    return scene.problem.dimension == 2 ? jacobians<2>(parameters, scene, comm)
                                        : jacobians<3>(parameters, scene, comm);
  }

  FitResult
  fit_through_scene(const FitParameters &parameters,
                    const std::string   &fit_file,
                    const MPI_Comm       comm)
  {
    const Parameters scene = scene_of(parameters, fit_file);
    // Collective errors (a failed step is a rejected trial; an input error
    // ends the fit) leave the problem first, as run_scene does.
    return scene.problem.dimension == 2
             ? fit<2>(parameters, scene, fit_file, comm)
             : fit<3>(parameters, scene, fit_file, comm);
  }
} // namespace hyperelastic
