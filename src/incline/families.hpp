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
  /// s; 0 = each member on its own time scale, [0, default_duration()] (a member near k = 1
  /// takes thousands of times longer to stop than its neighbours)
  double t_end = 0;
  int samples = 500;               ///< samples per curve, evenly spaced in [0, t_end]

  std::string validate() const;
};

struct FamilyMember {
  double value = 0;                ///< of the varied parameter (SI)
  Parameters parameters;
  Prediction prediction;
  double t_end = 0;                ///< s, the end of this member's samples
  std::vector<State> trajectory;   ///< closed form at `samples` times evenly over [0, t_end]
};

struct Family {
  double t_end = 0;                ///< s, the longest member's
  std::vector<FamilyMember> members;
  /// Members near k = 1 (|k - 1| < 0.02), where the slide changes character (k < 1 stops,
  /// k >= 1 never does) and the stop time grows without bound.
  std::vector<std::string> warnings;
};

/// Default simulated duration, s: 1.25 t_stop when the disc stops (t_stop > 0); else
/// 2 v0 / alpha (twice the time friction alone would need to stop it) when mu > 0 and
/// v0 > 0; else 1 s.
double default_duration(const Parameters& p);

/// Evaluates the family. Throws InputError for invalid options or member parameters.
Family make_family(const FamilyOptions& options);

}  // namespace tribolab::incline
