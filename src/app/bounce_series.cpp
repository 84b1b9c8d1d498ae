#include "app/bounce_series.hpp"

#include <cmath>

namespace tribolab::app {
namespace {

using nlohmann::json;
using namespace tribolab::analysis;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json mean_json(const WeightedMean& m) {
  return {{"n", m.n}, {"mean", num(m.mean)}, {"sigma", num(m.sigma)}, {"sigma_scaled", num(m.sigma_scaled)},
          {"chi2", num(m.chi2)}, {"dof", m.dof}, {"p_value", num(m.p_value)}};
}

json above_json(const AboveOne& a) { return {{"n", a.n}, {"above", a.above}, {"significant", a.significant}}; }

json energy_json(const bounce::KineticEnergy& e) {
  return {{"translational", e.translational_x + e.translational_y}, {"rotational", e.rotational}, {"total", e.total()}};
}

}  // namespace

json bounce_series_json(const BounceSeriesSummary& s, const std::vector<BounceSeriesPoint>& points,
                        const std::vector<std::string>& files, const BounceSeriesOptions& o) {
  json bins = json::array();
  for (const auto& b : s.bins) {
    bins.push_back({{"low_deg", b.low_deg}, {"high_deg", b.high_deg}, {"centre_deg", b.centre_deg}, {"n", b.n},
                    {"e_velocity", mean_json(b.e_velocity)}, {"e_min", b.e_min}, {"e_max", b.e_max},
                    {"n_above_one", b.n_above_one}});
  }
  json outliers = json::array();
  for (const auto& out : s.outliers) outliers.push_back({{"file", files[out.run]}, {"reason", out.reason}});
  json pts = json::array();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    pts.push_back({{"file", files[i]},
                   {"collision_angle_deg", num(p.collision_angle_deg)},
                   {"sigma_collision_angle_deg", num(p.sigma_collision_angle_deg)},
                   {"theta_deg", num(p.theta_deg)},
                   {"e_velocity", num(p.e_velocity)},
                   {"sigma_e_velocity", num(p.sigma_e_velocity)},
                   {"e_height", num(p.e_height)},
                   {"sigma_e_height", num(p.sigma_e_height)},
                   {"energy_pre", energy_json(p.energy_pre)},
                   {"energy_post", energy_json(p.energy_post)},
                   {"mean_normal_force", num(p.mean_normal_force)},
                   {"sigma_mean_normal_force", num(p.sigma_mean_normal_force)},
                   {"contact_point_vx", num(p.contact_point_vx)},
                   {"contact_point_vy", num(p.contact_point_vy)},
                   {"contact_point_speed", num(p.contact_point_speed)},
                   {"sigma_contact_point_speed", num(p.sigma_contact_point_speed)}});
  }
  auto named_run = [&](std::size_t i) {
    return json{{"file", files[i]}, {"contact_point_speed", num(points[i].contact_point_speed)},
                {"collision_angle_deg", num(points[i].collision_angle_deg)}};
  };
  return {{"e_velocity", mean_json(s.e_velocity)},
          {"e_height", mean_json(s.e_height)},
          {"above_one", {{"z", o.z_above_one}, {"velocity", above_json(s.above_one_velocity)},
                         {"height", above_json(s.above_one_height)}}},
          {"bin_width_deg", o.bin_width_deg},
          {"bins", bins},
          {"energy_ratio_mean", num(s.energy_ratio_mean)},
          {"n_energy_gain", s.n_energy_gain},
          {"mean_normal_force", {{"n", s.n_force}, {"mean", num(s.force_mean)}, {"sd", num(s.force_sd)},
                                 {"e_correlation", num(s.force_e_correlation)}}},
          {"contact_point", {{"fastest", named_run(s.fastest_contact_run)}, {"slowest", named_run(s.slowest_contact_run)}}},
          {"outliers", outliers},
          {"points", pts}};
}

}  // namespace tribolab::app
