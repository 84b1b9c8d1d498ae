// Report pages of the bounce commands (`bounce simulate`, `drop`, `contact-time`) and the
// contact-history figures the demo's bounce case study shares with them.
#pragma once

#include "app/bounce/bounce_simulate.hpp"
#include "bounce/contact.hpp"
#include "bounce/drop.hpp"
#include "bounce/flight.hpp"
#include "report/report.hpp"

#include <string>
#include <vector>

namespace tribolab::app {

/// One contact history drawn in the contact figures.
struct ContactCurve {
  std::string name;                           ///< legend entry, e.g. "seed's fitted law"
  std::vector<bounce::ContactSample> history;  ///< from simulate_contact
  report::Dash dash = report::Dash::Solid;
  std::string color;                          ///< empty = Plotly's cycle
};

/// Which histories add_contact_figures draws (each one figure, time in ms on x).
struct ContactPanels {
  bool vy = true, vx = true, omega = true, normal_force = true;
  bool tangential_force = true, penetration = true, energy = true;
};

/// Adds the contact-history figures of `curves` to `s`, titled "<title>: v_y" etc.; returns
/// the number of figures added. Energy: kinetic (translational, rotational), elastic
/// K d^(n+1)/(n+1), and mechanical (kinetic + elastic + m g (y - y_touch)) of the first curve.
/// `g` (m/s^2) is the gravity the histories were simulated with (the potential energy's).
int add_contact_figures(report::Section& s, const std::string& title, const bounce::Ball& ball, double g,
                        const std::vector<ContactCurve>& curves, const ContactPanels& panels = {});

/// The contact equations (rigid body with N(d, d_dot) and friction at the support point).
void add_contact_equations(report::Section& s, const bounce::NormalLaw& law);

/// Ball parameters as a table.
report::Table ball_table(const bounce::Ball& ball);

/// `bounce simulate --report`: in/out table, phases table and the histories. `r` is the
/// whole impact of `contacts` contacts (bounce::ImpactResult::whole).
report::Report bounce_simulate_report(const bounce::Ball& ball, const bounce::FrictionModel& friction,
                                      double g, const bounce::ContactResult& r,
                                      const std::vector<bounce::ContactSample>& history,
                                      std::size_t contacts = 1);

/// `bounce drop --report`: the centre's trajectory (needs DropResult::trajectory) and the apexes.
report::Report bounce_drop_report(const bounce::Ball& ball, const bounce::FrictionModel& friction,
                                  const bounce::DropRelease& release, const bounce::DropResult& r);

/// `bounce contact-time --report`: the gap y - Y(theta) from release to the first contact and
/// the orientation over the same time, as the workflow sampled them (bounce_contact_time).
report::Report bounce_contact_time_report(const bounce::Ball& ball, const bounce::BodyState& apex, int direction,
                                          const bounce::FlightResult& r, const std::vector<FlightSample>& samples);

}  // namespace tribolab::app
