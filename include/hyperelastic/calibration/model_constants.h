// The constants a fit varies, as the scene entries that hold them: the
// entries of the model's own subsection Material/<model> (Ogden's mu1,
// alpha1, ...), or for a Lame-based model the pair that 'Material/Elastic
// constants' selects (Young's modulus and Poisson's ratio, Shear modulus and
// Lame lambda, Shear modulus and Bulk modulus); and with
// Material/Viscoelasticity the lists 'Weights' and 'Relaxation times' of
// the Prony series (each name stands for its whole list).
//
// A trial set of values is written into a fresh parameter handler holding
// the file's Material subsection and parsed by MaterialParameters, so the
// model built is exactly the one a scene with these entries builds, and a
// value the model rejects (a negative modulus, Ogden's mu alpha <= 0) is
// inadmissible for the fit; that parse is the only one a trial costs, and
// its MaterialParameters go to a scene as they are (parameters(): numbers
// in, numbers out, no block of text written and read again). material() is
// the equilibrium (long-term) model; the Prony series comes separately
// (prony()), and parameters() wraps it around the equilibrium model. The
// derivatives of the stress with respect to the free entries are the
// model's ConstantDerivatives, converted from (mu, lambda) to the selected
// pair for the Lame-based models (chain()).
//
// The values of a fit: the model's free entries first, then the free
// weights, then the free relaxation times.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hyperelastic/materials/material.h>
#include <hyperelastic/materials/material_parameters.h>

#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace hyperelastic
{
  namespace calibration
  {
    /// A Prony series: weights beta_j and relaxation times tau_j.
    struct PronySeries
    {
      std::vector<double> weights, times;
    };

    class ModelConstants
    {
    public:
      /// @p prm holds a parsed Material subsection (copied: every trial set
      /// of values is parsed in a handler of its own, so that a rejected
      /// one leaves nothing behind). @p free_names: the free entries
      /// (empty: all but the volumetric one, and the Prony series if
      /// @p relaxation_data). An InputError names 'Fit/Free constants' for
      /// an entry the model does not have, the volumetric one when
      /// @p incompressible, or the Prony lists without viscoelasticity, and
      /// Material/Model for a model that cannot be fitted.
      ModelConstants(dealii::ParameterHandler       &prm,
                     const std::vector<std::string> &free_names,
                     bool                            incompressible,
                     bool                            relaxation_data = false);

      /// A name per value: the entries, then 'Weights 1', ...,
      /// 'Relaxation times 1', ...
      const std::vector<std::string> &
      names() const;
      /// The values in the parameter file.
      std::vector<double>
      start() const;

      /// The (equilibrium) model at @p values; null if the model rejects
      /// them or the Prony series is inadmissible (a negative weight, a
      /// time <= 0).
      std::unique_ptr<Material<3>>
      material(const std::vector<double> &values) const;

      /// material() and, in @p d, d(model constant)/d(free entry) at
      /// @p values: rows in the order of the model's
      /// ConstantDerivatives::constant_names(), a column per free entry of
      /// the model (not the Prony values).
      std::unique_ptr<Material<3>>
      material_and_chain(const std::vector<double>        &values,
                         std::vector<std::vector<double>> &d) const;

      /// The scene's Material at @p values, as a scene with these entries
      /// parses it (the Prony series at @p values wrapped around the
      /// equilibrium model); none where material() would be null. With
      /// @p d, also material_and_chain()'s chain.
      std::optional<MaterialParameters>
      parameters(const std::vector<double>        &values,
                 std::vector<std::vector<double>> *d = nullptr) const;

      /// The trial sets of values parsed so far (each one parse of the
      /// trial handler: what a trial costs in text).
      unsigned int
      trial_parses() const;

      /// The Prony series at @p values (empty without viscoelasticity).
      PronySeries
      prony(const std::vector<double> &values) const;

      /// Where weight j and time j are among the values (-1: fixed).
      const std::vector<int> &
      weight_columns() const;
      const std::vector<int> &
      time_columns() const;

      /// A 'subsection Material' block with the model, the pair selector
      /// (Lame-based models), every entry of the model, each once, and the
      /// Prony series, the free ones at @p values.
      void
      write_material_block(std::ostream              &out,
                           const std::vector<double> &values) const;

      /// The model's name.
      const std::string &
      model() const;

    private:
      /// The parameter file's entries (PRM text), read into every trial
      /// handler.
      std::string file_text;
      std::string model_name;
      /// Lame-based: 'Material/Elastic constants'; empty otherwise.
      std::string pair;
      /// Every entry of the model (its subsection's, or the pair), and the
      /// volumetric one among them.
      std::vector<std::string> all_entries;
      std::string              volumetric_entry;
      /// The free entries of the model, and every value's name.
      std::vector<std::string> free, value_names;
      /// The volumetric entry's text in the file, and a finite stand-in
      /// when it is 'inf' (incompressible fits: J = 1 leaves it idle).
      std::string volumetric_text, volumetric_stand_in;
      /// The file's Prony series and duration text, its parsed
      /// viscoelasticity entries; the free columns.
      PronySeries            file_prony;
      ViscoelasticParameters file_viscoelasticity;
      std::string      duration_text;
      std::vector<int> weight_column, time_column;

      /// Sorts the free names into the model's entries and the Prony lists.
      void
      select_free(const std::vector<std::string> &free_names,
                  bool                            incompressible,
                  bool                            relaxation_data);
      /// A handler with the file's Material subsection, the model's free
      /// entries at @p values, the volumetric stand-in and no
      /// viscoelasticity (the equilibrium model).
      std::unique_ptr<dealii::ParameterHandler>
      handler(const std::vector<double> &values) const;
      /// The handler material_and_chain() parses every trial in: made by
      /// handler() once and reused, since each trial sets every free entry;
      /// dropped when a rejected trial leaves it inside a subsection.
      mutable std::unique_ptr<dealii::ParameterHandler> trial_handler;
      mutable unsigned int                              n_trial_parses = 0;
      /// The trial handler at @p values parsed (null: rejected), and the
      /// chain into @p d.
      std::optional<MaterialParameters>
      parsed_trial(const std::vector<double>        &values,
                   std::vector<std::vector<double>> &d) const;
      /// Writes the model's free entries at @p values into @p prm, and the
      /// volumetric stand-in.
      void
      set_free(dealii::ParameterHandler  &prm,
               const std::vector<double> &values) const;
      /// chain() from a handler at the values.
      std::vector<std::vector<double>>
      chain(dealii::ParameterHandler &prm) const;
      /// An entry of the model in @p prm.
      std::string
      get(dealii::ParameterHandler &prm, const std::string &entry) const;
    };
  } // namespace calibration
} // namespace hyperelastic
