#include "io/sweep_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "numerics/error.hpp"
#include "sweep/synthetic.hpp"

namespace tribolab::io {
namespace {

SweepHeader header_4d() {
  SweepHeader h;
  h.grid.axes = {sweep::Axis{sweep::Quantity::speed, 4, 8, 2},
                 sweep::Axis{sweep::Quantity::theta_deg, 100, 170, 15},
                 sweep::Axis{sweep::Quantity::ratio, 0.1, 12.5, 11}};
  h.grid.fixed_mu = 0.45;
  h.shard = sweep::Shard{1, 3};
  h.outputs = {"vx", "vy", "omega_out", "e"};
  h.model = "hunt-crossley K=1.01e5 n=1.51 | D=6.04e4";  // may contain the separator
  return h;
}

TEST(SweepNumber, ShortestFormReadsBackToTheSameDouble) {
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<std::uint64_t> bits;
  int checked = 0;
  while (checked < 100000) {
    const std::uint64_t b = bits(rng);
    double v;
    std::memcpy(&v, &b, sizeof v);
    if (!std::isfinite(v)) continue;
    const std::string s = format_number_exact(v);
    const double back = std::strtod(s.c_str(), nullptr);
    ASSERT_EQ(std::memcmp(&back, &v, sizeof v), 0) << s;
    ++checked;
  }
  EXPECT_EQ(format_number_exact(0.1), "0.1");
  EXPECT_EQ(format_number_exact(170), "170");
  EXPECT_EQ(format_number_exact(std::nan("")), "nan");
  EXPECT_EQ(format_number_exact(-std::nan("")), "nan");  // one spelling for every NaN
}

TEST(SweepHeader, FormatsAndParsesBack) {
  const SweepHeader h = header_4d();
  const std::string line = format_header(h);
  EXPECT_EQ(line,
            "# tribolab-sweep v2 | shard 1/3 | grid speed=4:8:2 theta_deg=100:170:15 "
            "ratio=0.1:12.5:11 | fixed mu=0.45 | outputs vx vy omega_out e | model "
            "hunt-crossley K=1.01e5 n=1.51 | D=6.04e4\n");
  const SweepHeader back = parse_header(line.substr(0, line.size() - 1), "f.csv:1");
  EXPECT_EQ(format_header(back), line);
  EXPECT_EQ(back.grid.axes, h.grid.axes);
  EXPECT_EQ(back.shard, h.shard);
  EXPECT_EQ(back.outputs, h.outputs);
  EXPECT_EQ(back.model, h.model);
  EXPECT_EQ(format_columns(h), "theta_deg,omega,vx,vy,omega_out,e,speed,ratio\n");
}

TEST(SweepHeader, RejectsOtherFilesAndVersionsWithTheLocation) {
  auto message = [](const std::string& line) {
    try {
      parse_header(line, "f.csv:1");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("theta_deg,omega,vx").find("f.csv:1: not a tribolab sweep file"), std::string::npos);
  EXPECT_NE(message("# tribolab-sweep v3 | shard 0/1").find("version 3 is not supported"), std::string::npos);
  EXPECT_NE(message("# tribolab-sweep v0 | shard 0/1").find("version 0 is not supported"), std::string::npos);
  std::string good = format_header(header_4d());
  good.pop_back();
  std::string bad = good;
  bad.replace(bad.find("15 "), 2, "0");
  EXPECT_NE(message(bad).find("count must be at least 1"), std::string::npos);
  bad = good;
  bad.replace(bad.find("1/3"), 3, "3/3");
  EXPECT_NE(message(bad).find("shard index"), std::string::npos);
  bad = good;
  bad.replace(bad.find("| model "), 8, "| mode ");
  EXPECT_NE(message(bad).find("no 'model' field"), std::string::npos);
  bad = good;
  bad.replace(bad.find("speed=4"), 7, "speed=+4");
  EXPECT_NE(message(bad).find("canonical form"), std::string::npos);
}

TEST(SweepHeader, ReadsVersion1Files) {
  // Files written before the whole-impact outputs (v1, at most 8 outputs) are still read;
  // a header with more outputs than its version allows is not.
  std::string v1 = format_header(header_4d());
  v1.pop_back();
  v1.replace(v1.find(" v2 "), 4, " v1 ");
  const SweepHeader back = parse_header(v1, "old.csv:1");
  EXPECT_EQ(back.outputs, header_4d().outputs);
  EXPECT_EQ(back.model, header_4d().model);
  SweepHeader wide = header_4d();
  wide.outputs = {"a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k"};
  std::string line = format_header(wide);
  line.pop_back();
  EXPECT_EQ(parse_header(line, "new.csv:1").outputs.size(), 11u);
  line.replace(line.find(" v2 "), 4, " v1 ");
  EXPECT_THROW(parse_header(line, "old.csv:1"), InputError);
}

TEST(SweepLines, CheckAcceptsItsOwnLinesAndRejectsOthers) {
  const SweepHeader h = header_4d();
  const sweep::CellModel m = sweep::synthetic::wave_model();
  std::vector<sweep::CellInput> in;
  std::vector<double> out;
  for (std::int64_t k = 0; k < 5; ++k) {
    in.push_back(h.grid.cell(h.shard.global(k)));
    const sweep::CellOutputs o = m.evaluate(in.back());
    out.insert(out.end(), o.begin(), o.begin() + 4);
  }
  out[2] = std::nan("");  // a failed cell is written and read back as nan
  std::string text;
  append_cell_lines(text, h.grid, sweep::ChunkView{0, 5, in.data(), out.data(), 4});
  const std::vector<std::string> lines = [&] {
    std::vector<std::string> v;
    std::size_t start = 0, pos;
    while ((pos = text.find('\n', start)) != std::string::npos) {
      v.push_back(text.substr(start, pos - start));
      start = pos + 1;
    }
    return v;
  }();
  ASSERT_EQ(lines.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    double values[4];
    check_cell_line(lines[k], h.grid, in[k], 4, values, "f.csv:3");
    for (int j = 0; j < 4; ++j) {
      const double expect = out[k * 4 + static_cast<std::size_t>(j)];
      if (std::isnan(expect)) {
        EXPECT_TRUE(std::isnan(values[j]));
      } else {
        EXPECT_EQ(values[j], expect);
      }
    }
  }
  EXPECT_THROW(check_cell_line(lines[1], h.grid, in[0], 4, nullptr, "f.csv:3"), InputError);
  EXPECT_THROW(check_cell_line(lines[0] + ",1", h.grid, in[0], 4, nullptr, "f.csv:3"), InputError);
  std::string broken = lines[0];
  broken.replace(broken.find(',', broken.find(',') + 1) + 1, 1, "x");
  EXPECT_THROW(check_cell_line(broken, h.grid, in[0], 4, nullptr, "f.csv:3"), InputError);
}

}  // namespace
}  // namespace tribolab::io
