// Families of closed-form curves over one parameter (seed 000, figures 五, 六, 七): the same
// launch repeated for several values of v0, phi or mu with the others fixed.
#pragma once

#include "incline/closed_form.hpp"
#include "incline/params.hpp"

#include <string>
#include <vector>

namespace tribolab::incline {

enum class FamilyParameter { v0, phi, mu };

const char* to_string(FamilyParameter p);

struct FamilyOptions {
  Parameters base;                 ///< the fixed parameters
  FamilyParameter vary = FamilyParameter::v0;
  std::vector<double> values;      ///< values of the varied parameter (SI: m/s, rad, 1)
  double t_end = 0;                ///< s; 0 = the largest default_duration() of the members
  int samples = 500;               ///< samples per curve, evenly spaced in [0, t_end]

  std::string validate() const;
};

struct FamilyMember {
  double value = 0;                ///< of the varied parameter (SI)
  Parameters parameters;
  Prediction prediction;
  std::vector<State> trajectory;   ///< closed form at the common sample times
};

struct Family {
  double t_end = 0;                ///< s
  std::vector<FamilyMember> members;
};

/// Default simulated duration, s: 1.25 t_stop when the disc stops (t_stop > 0); else
/// 2 v0 / alpha (twice the time friction alone would need to stop it) when mu > 0 and
/// v0 > 0; else 1 s.
double default_duration(const Parameters& p);

/// Evaluates the family. Throws InputError for invalid options or member parameters.
Family make_family(const FamilyOptions& options);

}  // namespace tribolab::incline
