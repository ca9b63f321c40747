// The scene's Material subsection: the model and its elastic constants.
// Declared with pattern, default and documentation; parsed with the values
// checked (an invalid value is an InputError naming the entry).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/materials/material.h>

#include <string>

namespace hyperelastic
{
  using dealii::ParameterHandler;

  struct MaterialParameters
  {
    std::string    model;
    LameParameters lame;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };
} // namespace hyperelastic
