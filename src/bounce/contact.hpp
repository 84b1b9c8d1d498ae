// One contact of the ellipse with the floor, from first touch (gap 0) to separation:
// rigid-body equations with a normal law N(d, d_dot) at the support point and a friction
// model there (docs/theory.md#bounce-contact):
//   m x'' = f,   m y'' = N - m g,   I theta'' = X N + Y f,
// with the support point at (X, -Y) from the centre, d = Y(theta) - y, d_dot = -(vy + omega X),
// slip velocity v_t = vx + omega Y.
//
// simulate_contact() allocates nothing unless a history buffer is passed: a sweep may call
// it millions of times from many threads (it has no shared state).
#pragma once

#include "bounce/flight.hpp"
#include "bounce/friction.hpp"
#include "bounce/geometry.hpp"
#include "bounce/normal_law.hpp"
#include "bounce/phase_integrator.hpp"
#include "numerics/units.hpp"

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace tribolab::bounce {

/// Which compiled solver simulate_contact() runs (numerics/cpu_dispatch.hpp).
enum class ContactKernel {
  /// The build's baseline code: the same bits on every CPU the build runs on (shipped demo
  /// data, the demo's check that they are what make.sh makes, stored test values).
  reproducible,
  /// The x86-64-v3 code (FMA) where the CPU has it, else the baseline: ~8 % faster per contact
  /// (docs/benchmarks.md, "Issue 15, sixth pass"); the results differ from the baseline's in the
  /// last bits, and by up to ~the tolerance where rounding flips a step. `bounce sweep` runs it.
  fastest,
};

struct ContactOptions {
  double g = kDefaultG;  ///< gravitational acceleration during the contact, m/s^2 (0 allowed)
  /// Integrator tolerances. The defaults (1e-10 abs and rel) give outgoing velocities to
  /// ~1e-9 m/s; the `accuracy` helper below scales them.
  PhaseOptions integrator{};
  double max_duration = 1.0;    ///< give up (status max_duration) after this contact time, s
  std::size_t max_phases = 10'000;  ///< stick/slip phase changes before giving up
  ContactKernel kernel = ContactKernel::reproducible;  ///< the compiled solver to run

  std::string validate() const;  ///< empty when valid
};

/// Options with both tolerances set to `tol` (e.g. 1e-6 fast, 1e-12 reference).
ContactOptions contact_options_with_tolerance(double tol);

enum class PhaseKind {
  slip_positive,  ///< sliding with v_t > 0 (friction -mu N)
  slip_negative,  ///< sliding with v_t < 0 (friction +mu N)
  stick,          ///< Coulomb stick (v_t = 0) or elastic tangential stick (spring model)
  smooth,         ///< a single smooth law: regularised friction, or mu = 0
};
std::string_view to_string(PhaseKind k);

struct ContactPhase {
  PhaseKind kind = PhaseKind::smooth;
  double t_start = 0;  ///< s from first touch
  double t_end = 0;    ///< s from first touch
};

/// Kinetic energy split by kind, J.
struct KineticEnergy {
  double translational_x = 0;  ///< m vx^2 / 2, J
  double translational_y = 0;  ///< m vy^2 / 2, J
  double rotational = 0;       ///< I omega^2 / 2, J
  double total() const { return translational_x + translational_y + rotational; }
};
KineticEnergy kinetic_energy(const Ball& ball, const BodyState& s);

enum class ContactStatus {
  separated,     ///< the support point left the floor (d returned to 0)
  max_duration,  ///< still in contact after max_duration (e.g. the ball came to rest)
  failed,        ///< integrator failure or too many phase changes (see message)
};
std::string_view to_string(ContactStatus s);

/// One history sample (caller-provided buffer; one per accepted step and per event).
struct ContactSample {
  double t = 0;       ///< s from first touch
  BodyState state;    ///< centre position (x from the touch's x), orientation and velocities
  double d = 0;       ///< penetration, m
  double d_dot = 0;   ///< penetration rate, m/s
  double N = 0;       ///< normal force, N
  double f = 0;       ///< tangential force on the ball, N (+x)
  double v_t = 0;     ///< slip velocity of the contact point, m/s
  PhaseKind phase = PhaseKind::smooth;
};

inline constexpr std::size_t kMaxStoredPhases = 32;

struct ContactResult {
  ContactStatus status = ContactStatus::separated;
  std::string_view message = "separated";  ///< static text, no allocation
  BodyState in;                 ///< state at first touch (x = 0, y = Y(theta))
  BodyState out;                ///< state at separation
  double restitution = 0;       ///< e = -vy_out / vy_in (NaN when vy_in = 0)
  double contact_duration = 0;  ///< first touch to separation, s
  double peak_force = 0;        ///< max N, N (refined between samples by a parabola)
  double t_peak = 0;            ///< time of the peak force, s
  double max_penetration = 0;   ///< max d, m (refined between samples by a parabola)
  double impulse_normal = 0;    ///< integral of N dt = m (vy_out - vy_in) + m g T, N s
  double impulse_tangential = 0;  ///< integral of f dt = m (vx_out - vx_in), N s
  double v_in_normal = 0;       ///< approach speed of the contact point at touch, m/s
  double v_t_in = 0;            ///< slip velocity at touch, m/s
  double v_t_out = 0;           ///< slip velocity at separation, m/s
  KineticEnergy energy_in, energy_out;  ///< J
  double work_gravity = 0;        ///< work of gravity during the contact, J
  double dissipated_normal = 0;   ///< energy taken by normal damping (and force clamping), J
  double dissipated_friction = 0; ///< work done against the tangential force, J (incl. spring energy lost)
  double energy_residual = 0;     ///< E_in + W_gravity - E_out - dissipated - U(d_end), J (~ tolerance)
  NormalLaw law;                  ///< the law used (D resolved from a restitution if given)
  std::array<ContactPhase, kMaxStoredPhases> phases{};  ///< first kMaxStoredPhases phases
  std::size_t n_phases = 0;       ///< number of phases (may exceed the stored ones)
  std::size_t steps = 0;          ///< accepted integrator steps
  std::size_t rhs_calls = 0;      ///< right-hand-side evaluations
};

/// Simulates one contact starting at first touch in state `touch` (its y is ignored: the
/// contact starts at gap 0, y = Y(theta); x is kept). The contact point must approach the
/// floor (vy + omega X < 0). Throws InputError for invalid input. When `history` is not
/// null it is cleared and filled with samples. options.kernel chooses the compiled solver.
ContactResult simulate_contact(const Ball& ball, const NormalLaw& law, const FrictionModel& friction,
                               const BodyState& touch, const ContactOptions& options = {},
                               std::vector<ContactSample>* history = nullptr);

namespace detail {
/// The solver of simulate_contact() compiled for the build's baseline target and, where
/// TRIBOLAB_HAVE_X86_64_V3, for x86-64-v3 (call that one only when
/// numerics::cpu_level_supported() says so); both ignore options.kernel. For tests.
ContactResult simulate_contact_baseline(const Ball& ball, const NormalLaw& law, const FrictionModel& friction,
                                        const BodyState& touch, const ContactOptions& options,
                                        std::vector<ContactSample>* history);
ContactResult simulate_contact_x86_64_v3(const Ball& ball, const NormalLaw& law, const FrictionModel& friction,
                                         const BodyState& touch, const ContactOptions& options,
                                         std::vector<ContactSample>* history);
}  // namespace detail

/// As above, resolving `spec` (restitution -> damping) for this impact first.
ContactResult simulate_contact(const Ball& ball, const NormalLawSpec& spec,
                               const FrictionModel& friction, const BodyState& touch,
                               const ContactOptions& options = {},
                               std::vector<ContactSample>* history = nullptr);

}  // namespace tribolab::bounce
