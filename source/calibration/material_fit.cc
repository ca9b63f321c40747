// The least-squares fit of a model to test data (see the header).
#include <deal.II/lac/full_matrix.h>

#include <hyperelastic/calibration/levenberg_marquardt.h>
#include <hyperelastic/calibration/material_fit.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>

namespace hyperelastic
{
  namespace calibration
  {
    namespace
    {
      /// r and J of the weighted residuals at @p values; false if the model
      /// rejects them or is undefined at a data point.
      bool
      residuals(const ModelConstants             &constants,
                const std::vector<TestData>      &data,
                const bool                        incompressible,
                const std::vector<double>        &values,
                std::vector<double>              &r,
                std::vector<std::vector<double>> &J)
      {
        std::vector<std::vector<double>> chain;
        const auto material = constants.material_and_chain(values, chain);
        if (!material)
          return false;
        const auto *derivatives =
          dynamic_cast<const ConstantDerivatives<3> *>(material.get());
        const PronySeries series = constants.prony(values);
        r.clear();
        J.clear();
        for (const TestData &test : data)
          {
            const double root_weight = std::sqrt(test.weight);
            for (unsigned int i = 0; i < test.states.size(); ++i)
              {
                const TestState &state    = test.states[i];
                const Response   response = homogeneous_response(*material,
                                                               derivatives,
                                                               state,
                                                               incompressible);
                if (!std::isfinite(response.value))
                  return false;
                // A relaxation test: N(t) = N_eq (1 + sum_j beta_j
                // exp(-t / tau_j)).
                double              factor = 1.;
                std::vector<double> decay(series.weights.size(), 0.);
                if (state.type == TestType::relaxation)
                  for (unsigned int j = 0; j < decay.size(); ++j)
                    {
                      decay[j] = std::exp(-state.time / series.times[j]);
                      factor += series.weights[j] * decay[j];
                    }
                r.push_back(root_weight *
                            (factor * response.value - test.measured[i]));
                std::vector<double> row(values.size(), 0.);
                for (unsigned int m = 0; m < chain.size(); ++m)
                  for (unsigned int k = 0; k < chain[m].size(); ++k)
                    row[k] += root_weight * factor * response.derivatives[m] *
                              chain[m][k];
                for (unsigned int j = 0; j < decay.size(); ++j)
                  {
                    const int    w   = constants.weight_columns()[j];
                    const int    t   = constants.time_columns()[j];
                    const double tau = series.times[j];
                    if (w >= 0)
                      row[w] += root_weight * decay[j] * response.value;
                    if (t >= 0)
                      row[t] += root_weight * series.weights[j] * decay[j] *
                                state.time / (tau * tau) * response.value;
                  }
                J.push_back(row);
              }
          }
        return true;
      }

      /// sqrt of the diagonal of (J^T J)^-1 times the residual variance.
      std::vector<double>
      standard_errors(const std::vector<double>              &r,
                      const std::vector<std::vector<double>> &J)
      {
        const unsigned int  n = J.empty() ? 0 : J[0].size();
        std::vector<double> errors(n, std::nan(""));
        if (r.size() <= n)
          return errors;
        dealii::FullMatrix<double> M(n, n);
        double                     squares = 0.;
        for (unsigned int k = 0; k < r.size(); ++k)
          {
            squares += r[k] * r[k];
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                M(i, j) += J[k][i] * J[k][j];
          }
        try
          {
            M.gauss_jordan();
          }
        catch (...)
          {
            return errors;
          }
        const double variance = squares / (r.size() - n);
        for (unsigned int i = 0; i < n; ++i)
          errors[i] = std::sqrt(std::max(M(i, i), 0.) * variance);
        return errors;
      }
    } // namespace

    FitResult
    multi_start_fit(const LeastSquaresProblem &problem,
                    const std::vector<double> &origin,
                    const unsigned int         starts)
    {
      std::mt19937                           random(2026);
      std::uniform_real_distribution<double> exponent(-std::log(3.),
                                                      std::log(3.));
      FitResult                              best;
      best.cost = std::numeric_limits<double>::infinity();
      for (unsigned int s = 0; s < std::max(starts, 1u); ++s)
        {
          std::vector<double> start = origin;
          if (s > 0)
            for (double &value : start)
              value *= std::exp(exponent(random));
          const LeastSquaresResult result = levenberg_marquardt(problem, start);
          best.iterations += result.iterations;
          best.starts_converged += result.converged ? 1 : 0;
          if (result.cost < best.cost)
            {
              best.cost   = result.cost;
              best.values = result.x;
            }
        }
      if (!std::isfinite(best.cost))
        return best;
      std::vector<double>              r;
      std::vector<std::vector<double>> J;
      problem.evaluate(best.values, r, J);
      best.standard_errors = standard_errors(r, J);
      return best;
    }

    FitResult
    fit_material(const ModelConstants        &constants,
                 const std::vector<TestData> &data,
                 const bool                   incompressible,
                 const unsigned int           starts)
    {
      LeastSquaresProblem problem;
      problem.evaluate = [&](const std::vector<double>        &x,
                             std::vector<double>              &r,
                             std::vector<std::vector<double>> &J) {
        return residuals(constants, data, incompressible, x, r, J);
      };
      return multi_start_fit(problem, constants.start(), starts);
    }

    std::vector<TestData>
    curve_states(const std::vector<TestData> &data)
    {
      const unsigned int    n = 100;
      std::vector<TestData> curves;
      for (const TestData &test : data)
        {
          TestData curve;
          curve.index = test.index;
          curve.type  = test.type;
          // Groups of states along which one quantity varies: its range.
          std::map<std::pair<unsigned int, double>, std::pair<double, double>>
            groups;
          for (const TestState &state : test.states)
            {
              const bool   biaxial = test.type == TestType::biaxial;
              const double x       = biaxial ? state.stretch_2
                                     : test.type == TestType::relaxation
                                       ? state.time
                                       : state.stretch_1;
              const auto   key =
                std::make_pair(state.component, biaxial ? state.stretch_1 : 0.);
              auto found = groups.find(key);
              if (found == groups.end())
                groups[key] = {x, x};
              else
                found->second = {std::min(found->second.first, x),
                                 std::max(found->second.second, x)};
            }
          for (const auto &[key, range] : groups)
            for (unsigned int i = 0; i <= n; ++i)
              {
                TestState    state = test.states[0];
                const double x =
                  range.first + (range.second - range.first) * i / n;
                state.component = key.first;
                if (test.type == TestType::biaxial)
                  {
                    state.stretch_1 = key.second;
                    state.stretch_2 = x;
                  }
                else if (test.type == TestType::relaxation)
                  state.time = x;
                else
                  state.stretch_1 = x;
                curve.states.push_back(state);
              }
          curves.push_back(curve);
        }
      return curves;
    }

    std::vector<std::vector<double>>
    model_values(const Material<3>           &material,
                 const PronySeries           &prony,
                 const std::vector<TestData> &data,
                 const bool                   incompressible)
    {
      std::vector<std::vector<double>> values;
      for (const TestData &test : data)
        {
          values.emplace_back();
          for (const TestState &state : test.states)
            {
              double factor = 1.;
              if (state.type == TestType::relaxation)
                for (unsigned int j = 0; j < prony.weights.size(); ++j)
                  factor +=
                    prony.weights[j] * std::exp(-state.time / prony.times[j]);
              values.back().push_back(
                factor *
                homogeneous_response(material, nullptr, state, incompressible)
                  .value);
            }
        }
      return values;
    }
  } // namespace calibration
} // namespace hyperelastic
