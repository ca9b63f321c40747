// The constants a fit varies, as the scene entries that hold them: the
// entries of the model's own subsection Material/<model> (Ogden's mu1,
// alpha1, ...), or for a Lame-based model the pair that 'Material/Elastic
// constants' selects (Young's modulus and Poisson's ratio, Shear modulus and
// Lame lambda, Shear modulus and Bulk modulus). A trial set of values is
// written into the parameter handler and parsed by MaterialParameters, so
// the model built is exactly the one a scene with these entries builds, and
// a value the model rejects (a negative modulus, Ogden's mu alpha <= 0) is
// inadmissible for the fit. The derivatives of the stress with respect to
// the free entries are the model's ConstantDerivatives, converted from
// (mu, lambda) to the selected pair for the Lame-based models.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/materials/material.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace hyperelastic
{
  namespace calibration
  {
    class ModelConstants
    {
    public:
      /// @p prm holds a parsed Material subsection (copied: every trial
      /// set of values is parsed in a handler of its own, so that a
      /// rejected one leaves nothing behind). @p free_names: the free entries (empty: all but the
      /// volumetric one). An InputError names 'Fit/Free constants' for an
      /// entry the model does not have, or the volumetric one when
      /// @p incompressible, and Material/Model for a model that cannot be
      /// fitted.
      ModelConstants(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &free_names,
                     bool                            incompressible);

      /// The free entries' names and their values in the parameter file.
      const std::vector<std::string> &
      names() const;
      std::vector<double>
      start() const;

      /// The model with the free entries set to @p values; null if the
      /// model rejects them.
      std::unique_ptr<Material<3>>
      material(const std::vector<double> &values) const;

      /// d(model constant)/d(free entry) at @p values, rows in the order of
      /// the model's ConstantDerivatives::constant_names().
      std::vector<std::vector<double>>
      chain(const std::vector<double> &values) const;

      /// material() and chain() together (one parse).
      std::unique_ptr<Material<3>>
      material_and_chain(const std::vector<double>        &values,
                         std::vector<std::vector<double>> &d) const;

      /// A 'subsection Material' block with the model, the pair selector
      /// (Lame-based models) and every entry of the model, each once, the
      /// free ones at @p values.
      void
      write_material_block(std::ostream              &out,
                           const std::vector<double> &values) const;

      /// The model's name.
      const std::string &
      model() const;

    private:
      /// The parameter file's entries (PRM text), read into every trial
      /// handler.
      std::string               file_text;
      std::string               model_name;
      /// Lame-based: 'Material/Elastic constants'; empty otherwise.
      std::string               pair;
      /// Every entry of the model (its subsection's, or the pair), and the
      /// volumetric one among them.
      std::vector<std::string>  all_entries;
      std::string               volumetric_entry;
      std::vector<std::string>  free;
      /// The volumetric entry's text in the file, and a finite stand-in
      /// when it is 'inf' (incompressible fits: J = 1 leaves it idle).
      std::string               volumetric_text;

      /// A handler with the file's Material subsection, the free entries
      /// at @p values and the volumetric stand-in.
      std::unique_ptr<dealii::ParameterHandler>
      handler(const std::vector<double> &values) const;
      /// chain() from a handler at the values.
      std::vector<std::vector<double>>
      chain(dealii::ParameterHandler &prm) const;
      /// An entry of the model in @p prm.
      std::string
      get(dealii::ParameterHandler &prm, const std::string &entry) const;
      /// The stand-in value of the volumetric entry; empty if none.
      std::string volumetric_stand_in;
    };
  } // namespace calibration
} // namespace hyperelastic
