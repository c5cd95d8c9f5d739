// The field tables: reading with defaults and ranges, unknown keys, validation naming the key, the JSON
// round trip and the Markdown key reference.
#include "kerf/field_table.hpp"

#include <catch2/catch.hpp>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace {

enum class Shape { none, rectangular, trapezoidal };
constexpr std::string_view kShapeNames[] = {"none", "rectangular", "trapezoidal"};
constexpr kerf::EnumNames<Shape> kShapes{kShapeNames};

struct Params {
  double modulus_Pa = 70e9;
  double angle_rad = 0.5;
  int count = 2;
  bool check = true;
  Shape shape = Shape::none;
};

const kerf::FieldTable<Params>& table() {
  using namespace kerf;
  static const FieldTable<Params> t{
      number_field("modulus_GPa", units::kGPa, Range::positive(), "a modulus", &Params::modulus_Pa),
      number_field("angle_deg", units::kDeg, Range::closed(0.0, 90.0), "an angle", &Params::angle_rad),
      int_field("count", 1, 16, "a count", &Params::count), bool_field("check", "a flag", &Params::check),
      choice_field("shape", kShapes, "a shape", &Params::shape)};
  return t;
}

Params read(const kerf::Json& j) {
  kerf::ObjectReader r(j, "section");
  Params p = kerf::read_fields(r, table(), Params{});
  r.finish();
  return p;
}

}  // namespace

TEST_CASE("field table: absent keys keep the struct's defaults, present ones are converted to SI") {
  const Params d = read(kerf::Json::object());
  CHECK(d.modulus_Pa == 70e9);
  CHECK(d.count == 2);
  CHECK(d.shape == Shape::none);
  const Params p = read(
      kerf::Json{{"modulus_GPa", 2.5}, {"angle_deg", 30}, {"count", 5}, {"check", false}, {"shape", "trapezoidal"}});
  CHECK(p.modulus_Pa == 2.5e9);
  CHECK(p.angle_rad == 30 * std::numbers::pi / 180);  // the conversion the unit names, to the bit
  CHECK(p.count == 5);
  CHECK_FALSE(p.check);
  CHECK(p.shape == Shape::trapezoidal);
}

TEST_CASE("field table: unknown keys, ranges and choices are input errors naming the path") {
  const auto message = [](const kerf::Json& j) {
    try {
      read(j);
    } catch (const kerf::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message({{"modulus_GP", 1}}).find("section.modulus_GP") != std::string::npos);
  CHECK(message({{"modulus_GP", 1}}).find("did you mean 'modulus_GPa'") != std::string::npos);
  CHECK(message({{"modulus_GPa", 0}}).find("section.modulus_GPa = 0: expected a positive value in GPa") == 0);
  CHECK(message({{"angle_deg", 90.5}}).find("section.angle_deg") == 0);
  CHECK(message({{"count", 17}}).find("section.count = 17: expected an integer in [1, 16]") == 0);
  CHECK(message({{"shape", "rectangle"}}).find("did you mean 'rectangular'") != std::string::npos);
}

TEST_CASE("field table: check_fields names the key, with_path adds the JSON path") {
  Params p;
  p.count = 0;
  CHECK_THROWS_WITH(kerf::check_fields(table(), p), "count = 0: expected an integer in [1, 16]");
  CHECK_THROWS_WITH(kerf::with_path("material", [&] { kerf::check_fields(table(), p); }),
                    "material.count = 0: expected an integer in [1, 16]");
  p = Params{};
  p.modulus_Pa = -1e9;
  CHECK_THROWS_WITH(kerf::check_fields(table(), p), "modulus_GPa = -1: expected a positive value in GPa");
  CHECK_NOTHROW(kerf::check_fields(table(), Params{}));
}

TEST_CASE("field table: to_json reads back to the same struct, every key written") {
  Params p;
  p.modulus_Pa = 1.234567890123e9;
  p.angle_rad = 0.123456789;
  p.count = 7;
  p.check = false;
  p.shape = Shape::rectangular;
  const kerf::Json j = kerf::fields_to_json(table(), p);
  CHECK(j.size() == table().size());
  const Params q = read(j);
  CHECK(q.modulus_Pa == p.modulus_Pa);
  CHECK(q.angle_rad == Approx(p.angle_rad).epsilon(1e-15));
  CHECK(q.count == p.count);
  CHECK(q.check == p.check);
  CHECK(q.shape == p.shape);
}

TEST_CASE("field table: the Markdown reference has a row per key with its unit and default") {
  const std::string md = kerf::fields_markdown(table());
  CHECK(md.find("| `modulus_GPa` | GPa | a positive value | 70 | a modulus |") != std::string::npos);
  CHECK(md.find("| `count` | - | an integer in [1, 16] | 2 | a count |") != std::string::npos);
  CHECK(md.find("| `shape` | - | `none`, `rectangular`, `trapezoidal` | `none` | a shape |") != std::string::npos);
}

namespace {
struct Output {
  std::string name = "calibrated";
  unsigned free = 0b101;
};
constexpr std::string_view kFreeNames[] = {"modulus", "ratio", "strength"};
const kerf::FieldTable<Output>& output_table() {
  using namespace kerf;
  static const FieldTable<Output> t{
      text_field("name", "a file name", &Output::name,
                 [](const std::string& n) {
                   return n.empty() || n.find('/') != std::string::npos ? std::string("a file name") : std::string();
                 }),
      FlagsField<Output>{"free", kFreeNames, "what may change", [](const Output& o) { return o.free; },
                         [](Output& o, unsigned f) { o.free = f; }}};
  return t;
}
Output read_output(const kerf::Json& j) {
  kerf::ObjectReader r(j, "calibration");
  Output o = kerf::read_fields(r, output_table(), Output{});
  r.finish();
  return o;
}
}  // namespace

TEST_CASE("field table: texts with their check, and sets of names as flags") {
  CHECK(read_output(kerf::Json::object()).name == "calibrated");
  CHECK(read_output({{"name", "glass"}}).name == "glass");
  CHECK_THROWS_WITH(read_output({{"name", "a/b"}}), "calibration.name = a/b: expected a file name");
  CHECK(read_output({{"free", {"ratio", "strength"}}}).free == 0b110u);
  CHECK(read_output({{"free", kerf::Json::array()}}).free == 0u);
  CHECK_THROWS_WITH(read_output({{"free", {"ration"}}}),
                    Catch::Matchers::Contains("calibration.free = ration: expected one of") &&
                        Catch::Matchers::Contains("did you mean 'ratio'"));
  CHECK_THROWS_WITH(read_output({{"free", "ratio"}}), "calibration.free = ratio: expected a list of names");
  const Output o{"x", 0b011};
  const kerf::Json j = kerf::fields_to_json(output_table(), o);
  CHECK(j.at("free") == kerf::Json{"modulus", "ratio"});
  const Output back = read_output(j);
  CHECK(back.name == "x");
  CHECK(back.free == o.free);
  const std::string md = kerf::fields_markdown(output_table());
  CHECK_THAT(md, Catch::Matchers::Contains("| `name` | - | a file name | `calibrated` | a file name |"));
  CHECK_THAT(md, Catch::Matchers::Contains(
                     "| `free` | - | a list of `modulus`, `ratio`, `strength` | `modulus`, `strength` |"));
  CHECK(kerf::fields_markdown(output_table(), Output{}, false).rfind("| `name`", 0) == 0);  // rows only
}

namespace {
struct Lists {
  std::optional<double> ratio;  // optional, no default
  double speed_m_per_s = 0.0;   // must convert to a normal SI value
  std::vector<std::string> order = {"b"};
};
constexpr std::string_view kListNames[] = {"a", "b", "c"};
const kerf::FieldTable<Lists>& lists_table() {
  using namespace kerf;
  static const FieldTable<Lists> t{
      optional_number_field("ratio", units::kNone, Range::positive(), "a ratio", &Lists::ratio, "the other one's"),
      number_field("speed_mm", units::kMm, Range::non_negative(), "a length", &Lists::speed_m_per_s),
      NameListField<Lists>{"order", kListNames, "names in order", [](const Lists& l) { return l.order; },
                           [](Lists& l, const std::vector<std::string>& v) { l.order = v; }}};
  return t;
}
Lists read_lists(const kerf::Json& j, kerf::SiCheck si_check = kerf::SiCheck::on) {
  kerf::ObjectReader r(j, "models");
  Lists l;
  kerf::read_fields_into(r, lists_table(), l, si_check);
  r.finish();
  return l;
}
}  // namespace

TEST_CASE("field table: optional numbers, ordered name lists, values that leave SI") {
  const Lists none = read_lists(kerf::Json::object());
  CHECK(!none.ratio);
  CHECK(none.order == std::vector<std::string>{"b"});
  CHECK(read_lists({{"ratio", 0.5}}).ratio == 0.5);
  CHECK(read_lists({{"ratio", nullptr}}).ratio == std::nullopt);
  CHECK_THROWS_WITH(read_lists({{"ratio", 0}}), "models.ratio = 0: expected a positive value");
  // The order given is kept (a CSV's columns follow it); one name alone is a list of one.
  CHECK(read_lists({{"order", {"c", "a"}}}).order == std::vector<std::string>{"c", "a"});
  CHECK(read_lists({{"order", "c"}}).order == std::vector<std::string>{"c"});
  CHECK_THROWS_WITH(read_lists({{"order", {"a", "d"}}}),
                    Catch::Matchers::Contains("models.order = d: expected one of"));
  CHECK_THROWS_WITH(read_lists({{"order", {1}}}), Catch::Matchers::Contains("models.order = 1: expected one of"));
  CHECK_THROWS_WITH(read_lists({{"order", 3}}), "models.order = 3: expected a list of names");
  // With SiCheck::on (the analytic scenes) a value whose SI conversion underflows is refused, naming the key (as
  // ObjectReader::get_si does); off (the DEM's tables, the default) reads the plain conversion.
  CHECK_THROWS_WITH(
      read_lists({{"speed_mm", 1e-320}}),
      Catch::Matchers::Contains("models.speed_mm = ") && Catch::Matchers::Contains("stays a finite, non-zero number"));
  CHECK(read_lists({{"speed_mm", 1e-320}}, kerf::SiCheck::off).speed_m_per_s == kerf::units::mm_to_m(1e-320));
  CHECK(read_lists({{"speed_mm", 0}}).speed_m_per_s == 0.0);
  // Absent optional values: not checked, not written, documented by their text.
  CHECK_NOTHROW(kerf::check_fields(lists_table(), none));
  CHECK(!kerf::fields_to_json(lists_table(), none).contains("ratio"));
  CHECK(kerf::fields_to_json(lists_table(), read_lists({{"ratio", 2}})).at("ratio") == 2.0);
  const std::string md = kerf::fields_markdown(lists_table());
  CHECK_THAT(md, Catch::Matchers::Contains("| `ratio` | - | a positive value | the other one's | a ratio |"));
  CHECK_THAT(md, Catch::Matchers::Contains("| `order` | - | a list of `a`, `b`, `c` | `b` | names in order |"));
}

TEST_CASE("field table: a key declared twice, in the table or beside it, is the table's mistake, named") {
  using namespace kerf;
  CHECK_NOTHROW(check_unique_keys(table(), "section"));
  const std::string_view beside[] = {"transition"};
  CHECK_NOTHROW(check_unique_keys(table(), "section", beside));
  FieldTable<Params> twice = table();
  twice.push_back(number_field("angle_deg", units::kDeg, Range::any(), "the angle again", &Params::angle_rad));
  CHECK_THROWS_WITH(check_unique_keys(twice, "section"), "section: the key 'angle_deg' is declared twice");
  const std::string_view clash[] = {"transition", "count"};
  CHECK_THROWS_WITH(check_unique_keys(table(), "models", clash), "models: the key 'count' is declared twice");
}

TEST_CASE("field table: a member struct's table embedded in its holder, flags included") {
  struct Holder {
    int own = 1;
    Params part;
  };
  const kerf::FieldTable<Holder> t =
      kerf::embedded_fields(table(), &Holder::part, {kerf::int_field("own", 0, 9, "the holder's", &Holder::own)});
  REQUIRE(t.size() == table().size() + 1);
  const kerf::Json j{{"modulus_GPa", 3}, {"check", false}, {"shape", "rectangular"}, {"own", 4}};
  kerf::ObjectReader r(j, "s");
  const Holder h = kerf::read_fields(r, t, Holder{});
  r.finish();
  CHECK(h.part.modulus_Pa == 3e9);
  CHECK_FALSE(h.part.check);  // a flag through the member, as numbers, integers and choices
  CHECK(h.part.shape == Shape::rectangular);
  CHECK(h.own == 4);
  kerf::Json expected = kerf::fields_to_json(table(), h.part);
  expected["own"] = 4;
  CHECK(kerf::fields_to_json(t, h) == expected);
}
