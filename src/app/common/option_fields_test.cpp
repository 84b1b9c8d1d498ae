// The option declarations (app/common/option_fields.hpp): groups reach nested members, ranges name
// the field, the schema reads defaults from the struct, result keys' companion rules.
#include "app/common/option_fields.hpp"

#include "app/bounce/bounce_simulate.hpp"

#include <gtest/gtest.h>

#include <set>

namespace tribolab::app {
namespace {

struct Inner {
  double x = 1.5;  ///< m
};
struct Outer {
  Inner inner;
  std::optional<double> k;
  int count = 3;
  std::string model = "B";
};

Fields<Inner> inner_fields() {
  Fields<Inner> f;
  f.add("x", &Inner::x, "m", "a length").in(PhysicalRange{0, 10, "m"});
  return f;
}

Fields<Outer> outer_fields() {
  Fields<Outer> f;
  f.add("k", &Outer::k, "N/m", "a stiffness").in(PhysicalRange{0, 1e3, "N/m", true});
  f.add("count", &Outer::count, "", "a count").in(PhysicalRange{1, 5, ""}).needed();
  f.add("model", &Outer::model, "", "a law").one_of({"A", "B"});
  f.group(&Outer::inner, inner_fields());
  return f;
}

TEST(OptionFields, GroupFieldsReachTheNestedMember) {
  static const Fields<Outer> fields = outer_fields();
  Outer o;
  const Field<Outer>* x = fields.find("x");
  ASSERT_NE(x, nullptr);
  *std::get<double*>(x->ref(o)) = 7;
  EXPECT_EQ(o.inner.x, 7);
}

TEST(OptionFields, RangeErrorsNameTheField) {
  static const Fields<Outer> fields = outer_fields();
  Outer o;
  EXPECT_NO_THROW(check_ranges(o, fields));  // k unset: not checked
  o.inner.x = 11;
  try {
    check_ranges(o, fields);
    FAIL() << "x = 11 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message([](std::string_view f) { return "<" + std::string(f) + ">"; }),
              "<x>: 11 m is outside the physical range [0, 10] m");
    EXPECT_EQ(std::string(e.what()), "x: 11 m is outside the physical range [0, 10] m");
  }
  o.inner.x = 1;
  o.k = 0;  // lo_open
  EXPECT_THROW(check_ranges(o, fields), InputError);
}

TEST(OptionFields, SchemaReadsDefaultsFromTheStruct) {
  const nlohmann::json s = fields_schema(outer_fields());
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[0]["name"], "k");
  EXPECT_EQ(s[0]["type"], "number");
  EXPECT_TRUE(s[0]["nullable"].get<bool>());
  EXPECT_TRUE(s[0]["default"].is_null());
  EXPECT_TRUE(s[0]["range"]["lo_open"].get<bool>());
  EXPECT_EQ(s[1]["type"], "integer");
  EXPECT_EQ(s[1]["default"], 3);
  EXPECT_TRUE(s[1]["required"].get<bool>());
  EXPECT_EQ(s[2]["choices"], nlohmann::json({"A", "B"}));
  EXPECT_EQ(s[3]["default"], 1.5);
  EXPECT_EQ(s[3]["unit"], "m");
}

TEST(OptionFields, ResultKeysCoverCompanionsAndWildcards) {
  const ResultKeys k = {{"mu", "", ""}, {"a", "m/s^2", ""}, {"theta_deg", "deg", ""}, {"parts.*", "J", ""}, {"fit.v0", "m/s", ""}};
  ASSERT_NE(find_result_key(k, "sigma_a"), nullptr);
  EXPECT_EQ(find_result_key(k, "sigma_a")->unit, "m/s^2");
  EXPECT_EQ(find_result_key(k, "a_ci95")->unit, "m/s^2");
  EXPECT_EQ(find_result_key(k, "theta_ci95_deg")->unit, "deg");
  EXPECT_EQ(find_result_key(k, "parts.total")->unit, "J");
  EXPECT_EQ(find_result_key(k, "fit.sigma_v0")->unit, "m/s");
  EXPECT_EQ(find_result_key(k, "fit.ci95.v0")->unit, "m/s");
  EXPECT_EQ(find_result_key(k, "b"), nullptr);        // undeclared: no unit guessed
  EXPECT_EQ(find_result_key(k, "parts"), nullptr);    // the wildcard is for keys below it
  const ResultKeys named = {{"tracks.*.median_px", "px", ""}, {"tracks.*.rows", "", ""}};
  ASSERT_NE(find_result_key(named, "tracks.ball.A.median_px"), nullptr);  // a track name with a dot
  EXPECT_EQ(find_result_key(named, "tracks.ball.A.median_px")->unit, "px");
  EXPECT_EQ(find_result_key(named, "tracks.median_px"), nullptr);  // the name is not optional
}

TEST(OptionFields, BounceCommandsDeclareEachFieldOnce) {
  // One name, one field: a name declared twice would bind two flags to one member.
  auto unique = [](const auto& fields) {
    std::set<std::string> names;
    for (const auto& f : fields) EXPECT_TRUE(names.insert(f.name).second) << f.name;
    return names.size();
  };
  EXPECT_EQ(unique(bounce_contact_time_fields()), 11u);  // 5 + 4 ball + report, plotly
  EXPECT_GT(unique(bounce_simulate_fields()), 20u);
  EXPECT_GT(unique(bounce_drop_fields()), 20u);
}

}  // namespace
}  // namespace tribolab::app
