// Reproducible random vectors for the test programs.
#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <random>

namespace hyperelastic::testing
{
  /// Random entries in [-amplitude, amplitude] on the owned entries, the same
  /// on any number of ranks (each seeded by its global index).
  inline void
  fill_random(dealii::TrilinosWrappers::MPI::Vector &v,
              const double                           amplitude,
              const unsigned int                     seed)
  {
    for (const auto i : v.locally_owned_elements())
      {
        std::mt19937                           rng(seed * 1000003u + i);
        std::uniform_real_distribution<double> d(-amplitude, amplitude);
        v(i) = d(rng);
      }
    v.compress(dealii::VectorOperation::insert);
  }
} // namespace hyperelastic::testing
