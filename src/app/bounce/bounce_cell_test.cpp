#include "app/bounce/bounce_cell.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "bounce/contact.hpp"
#include "bounce/impact.hpp"
#include "numerics/error.hpp"

namespace tribolab::app {
namespace {

using namespace tribolab::bounce;

sweep::CellInput cell_input(double theta_deg, double omega, double speed = 4, double mu = 0.5) {
  sweep::CellInput in;
  in.theta_deg = theta_deg;
  in.omega = omega;
  in.speed = speed;
  in.mu = mu;
  return in;
}

/// Bitwise equality of two outputs (NaN equal to NaN of the same bits): "the same cell".
bool same_bits(const sweep::CellOutputs& a, const sweep::CellOutputs& b, std::size_t n) {
  return std::memcmp(a.data(), b.data(), n * sizeof(double)) == 0;
}

// A few cells of the seed's figure-53 map (collision angle 100-170 deg, spin 30-50 rad/s,
// 4 and 8 m/s) and one with friction swept.
const std::vector<sweep::CellInput> kCells = {cell_input(100, 30), cell_input(135, 40), cell_input(170, 50),
                                              cell_input(120, 45, 8), cell_input(150, 35, 4, 0.2)};

// The cell against the contact solver called directly, as docs/theory.md#sweeps defines it:
// the collision angle at touch, vy = -speed, the whole impact then its first phase. Bit for
// bit: the model adds no arithmetic of its own.
TEST(BounceCell, ComputesTheWholeImpactOfTheCoreBitForBit) {
  const BounceCell cell = make_bounce_cell(BounceCellOptions{});
  const sweep::CellModel model = bounce_cell_model(cell);
  ASSERT_EQ(model.output_names.size(), 11u);
  for (const sweep::CellInput& in : kCells) {
    BodyState s;
    s.theta = theta_for_collision_angle(Ball{}, in.theta_deg, 1);
    s.vy = -in.speed;
    s.omega = in.omega;
    FrictionModel f;
    f.mu = in.mu;
    ImpactOptions io;
    io.contact = contact_options_with_tolerance(1e-6);
    io.contact.kernel = ContactKernel::fastest;  // a sweep's cells run the fastest solver (docs/design.md#cpu-dispatch)
    const ImpactResult r = simulate_impact(Ball{}, NormalLawSpec{}, f, s, io);
    ASSERT_EQ(r.status, ImpactStatus::free_flight);
    const sweep::CellOutputs out = model.evaluate(in);
    const sweep::CellOutputs expected{r.whole.out.vx, r.whole.out.vy, r.whole.out.omega, r.whole.restitution,
                                      static_cast<double>(r.contacts), r.whole.contact_duration,
                                      r.first.out.vx, r.first.out.vy, r.first.out.omega, r.first.restitution,
                                      r.first.contact_duration};
    EXPECT_TRUE(same_bits(out, expected, 11)) << "theta " << in.theta_deg << " omega " << in.omega;
    EXPECT_TRUE(std::isfinite(out[3]) && out[3] > 0);
  }
}

// The three users of the model: `bounce sweep` (defaults), the bench (first contact phase,
// tol 1e-6 at its default setting) and the demo (tol 1e-8, clockwise spin). The bench's cell
// is the command's first-phase columns; the demo's cell at spin w is the command's cell at
// omega = -w with the demo's tolerance.
TEST(BounceCell, CommandDemoAndBenchComputeTheSameCellBitForBit) {
  const BounceCell command = make_bounce_cell(BounceCellOptions{});
  const BounceCell bench = make_bounce_cell(BounceCellOptions{}, BounceCellKind::contact);
  BounceCellOptions demo_options;
  demo_options.law.tol = 1e-8;
  demo_options.spin_sign = -1;
  const BounceCell demo = make_bounce_cell(demo_options);
  BounceCellOptions command_at_demo_tol;
  command_at_demo_tol.law.tol = 1e-8;
  const BounceCell command8 = make_bounce_cell(command_at_demo_tol);
  for (const sweep::CellInput& in : kCells) {
    const sweep::CellOutputs c = command(in), b = bench(in);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(std::memcmp(&b[k], &c[6 + k], sizeof(double)), 0) << k;
    sweep::CellInput mirrored = in;
    mirrored.omega = -in.omega;
    EXPECT_TRUE(same_bits(demo(in), command8(mirrored), 11)) << in.theta_deg;
    EXPECT_FALSE(same_bits(demo(in), command8(in), 11));  // the spin sense matters
  }
}

// A sweep file's header is read back without a command-line parser: every recorded option
// returns, the rebuilt model writes the same line and computes the same cells.
TEST(BounceCell, DescriptionReadsBackToTheSameModelWithoutCli) {
  std::vector<BounceCellOptions> cases(5);
  cases[1].law.restitution = 0.8;
  cases[1].law.friction = "regularized";
  cases[1].law.slip_scale = 0.02;
  cases[1].vx = -0.7;
  cases[2].law.model = "hertz";
  cases[2].law.friction = "spring";
  cases[2].law.k_t = 3e4;
  cases[2].law.c_t = 1.5;
  cases[2].g = 0;
  cases[2].angle = "orientation";
  cases[3].ball.ball.mass = 0.5;
  cases[3].ball.ball.a = 0.15;
  cases[3].law.tol = 1e-9;
  cases[4].spin_sign = -1;
  for (const BounceCellOptions& o : cases) {
    for (BounceCellKind kind : {BounceCellKind::impact, BounceCellKind::contact}) {
      const BounceCell cell = make_bounce_cell(o, kind);
      const std::string line = cell.description();
      const ParsedBounceCell p = parse_bounce_cell_description(line);
      EXPECT_EQ(p.kind, kind);
      EXPECT_EQ(p.options.angle, o.angle);
      EXPECT_EQ(p.options.vx, o.vx);
      EXPECT_EQ(p.options.g, o.g);
      EXPECT_EQ(p.options.spin_sign, o.spin_sign);
      EXPECT_EQ(p.options.law.tol, o.law.tol);
      EXPECT_EQ(p.options.ball.ball.mass, o.ball.ball.mass);
      const sweep::CellModel back = bounce_cell_model_from_description(line);
      EXPECT_EQ(back.description, line);
      EXPECT_EQ(back.output_names, bounce_cell_outputs(kind));
      const sweep::CellInput in = o.angle == "orientation" ? cell_input(30, 40) : cell_input(135, 40);
      EXPECT_TRUE(same_bits(back.evaluate(in), cell(in), back.output_names.size())) << line;
    }
  }
  // The line files of earlier versions hold (as cli/bounce_sweep_cmd.cpp wrote it): unchanged.
  EXPECT_EQ(make_bounce_cell(BounceCellOptions{}).description(),
            "bounce-impact angle=collision vx=0 a=0.145 b=0.095 mass=0.435 inertia=0.0041 law=hunt-crossley "
            "K=101054 n=1.51 D=60423 friction=coulomb g=9.8 tol=1e-06");
}

std::string message_of(const std::string& description) {
  try {
    bounce_cell_model_from_description(description);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(BounceCell, ForeignOrDamagedDescriptionsAreRefusedNamingTheProblem) {
  const std::string good = make_bounce_cell(BounceCellOptions{}).description();
  EXPECT_NE(message_of("synthetic wave").find("report: cannot rebuild the physics of the sweep file (not a "
                                              "bounce-impact or bounce-contact sweep)"),
            std::string::npos);
  EXPECT_NE(message_of(good + " colour=red").find("unknown field 'colour=red'"), std::string::npos);
  std::string bad_number = good;
  bad_number.replace(bad_number.find("K=101054"), 8, "K=1o1054");
  EXPECT_NE(message_of(bad_number).find("cannot rebuild"), std::string::npos) << message_of(bad_number);
  EXPECT_NE(message_of("bounce-impact angle=collision").find("does not read back to the same options"),
            std::string::npos);
  EXPECT_NE(message_of("bounce-impact angle=sideways").find("angle: unknown angle convention"), std::string::npos);
  EXPECT_EQ(message_of(good), "no error");
}

TEST(BounceCell, InvalidOptionsNameTheOption) {
  BounceCellOptions o;
  o.vx = 1e9;
  EXPECT_THROW(make_bounce_cell(o), InputError);
  o = {};
  o.g = -1;
  try {
    make_bounce_cell(o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("g", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace tribolab::app
