#include "kerf/dem/engine/checkpoint.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <new>
#include <variant>

#include "../../dem/engine/serial.hpp"
#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/procedures/calibration.hpp"
#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/error.hpp"

using kerf::dem::Checkpoint;

namespace {
Checkpoint small_checkpoint() {
  Checkpoint c;
  c.scene = kerf::Json{{"kind", "tension"}, {"description", "a test"}};
  c.summary = kerf::Json{{"steps", 12}};
  c.frames = {{0.5, {"frame_0000.vtp"}}};
  c.sample_index = 3;
  c.checkpoint_every = 2;
  c.scene_dir = "/tmp";
  c.specimen = std::string("KERFDEM3\0\1\2", 11);
  c.run = "KERFLAB1 state";
  return c;
}
}  // namespace

TEST_CASE("checkpoint: CRC-32 is the IEEE 802.3 one (published check value)", "[checkpoint]") {
  CHECK(kerf::dem::crc32("123456789") == 0xCBF43926u);
  CHECK(kerf::dem::crc32("") == 0u);
}

TEST_CASE("checkpoint: written and read back the same", "[checkpoint]") {
  const Checkpoint c = small_checkpoint();
  const Checkpoint back = Checkpoint::parse(c.bytes());
  CHECK(back.scene == c.scene);
  CHECK(back.summary == c.summary);
  CHECK(back.frames == c.frames);
  CHECK(back.sample_index == 3);
  CHECK(back.checkpoint_every == 2);
  CHECK(back.specimen == c.specimen);
  CHECK(back.run == c.run);
  CHECK(back.bytes() == c.bytes());
}

TEST_CASE("checkpoint: every single flipped bit is a ModelError", "[checkpoint]") {
  const std::string good = small_checkpoint().bytes();
  for (std::size_t bit = 0; bit < 8 * good.size(); ++bit) {
    std::string bad = good;
    bad[bit / 8] = static_cast<char>(bad[bit / 8] ^ (1 << (bit % 8)));
    CHECK_THROWS_AS(Checkpoint::parse(bad), kerf::ModelError);
  }
}

TEST_CASE("checkpoint: cut short, a byte too many, a wrapping length, another version: ModelError", "[checkpoint]") {
  const std::string good = small_checkpoint().bytes();
  for (std::size_t n = 0; n < good.size(); ++n) CHECK_THROWS_AS(Checkpoint::parse(good.substr(0, n)), kerf::ModelError);
  CHECK_THROWS_WITH(Checkpoint::parse(good + "x"), Catch::Matchers::Contains("damaged"));
  // A part's length of 2^64 - 8 with the file's length and checksum made right: refused, not wrapped.
  std::string wrapped = good.substr(0, good.size() - 4);
  const std::uint64_t huge = ~std::uint64_t{0} - 7;
  std::memcpy(wrapped.data() + 16, &huge, sizeof huge);
  const std::uint32_t crc = kerf::dem::crc32(wrapped);
  wrapped.append(reinterpret_cast<const char*>(&crc), sizeof crc);
  CHECK_THROWS_WITH(Checkpoint::parse(wrapped), Catch::Matchers::Contains("a length beyond its end"));
  std::string old = good;
  old.replace(0, 8, "KERFCKP1");
  CHECK_THROWS_WITH(Checkpoint::parse(old), Catch::Matchers::Contains("another kerf-dem version (KERFCKP1"));
  CHECK_THROWS_WITH(Checkpoint::parse("PNG....."), Catch::Matchers::Contains("not a kerf-dem checkpoint"));
}

// Regression of a fault fuzz_checkpoint found behind a valid checksum (docs/hardening.md).
TEST_CASE("checkpoint: an engine state with empty arrays reads back", "[checkpoint]") {
  using namespace kerf::dem;
  Simulation sim(Material{}, SimulationOptions{});  // no disks, joints, walls or cracks: every array empty
  const std::string good = sim.serialize();
  CHECK(Simulation::deserialize(good).serialize() == good);  // UBSan: no memcpy from a null data()
}

namespace {
using namespace kerf::dem;
/// The bond laws registered in the other order: a build whose list was reordered.
using ReorderedBondLaw = std::variant<ParallelBondParams, FlatJointParams>;

template <class V, class Law>
V written_and_read(const Law& law) {
  std::string bytes;
  serial::put_law(bytes, law);
  serial::In io{bytes};
  V back = serial::get_law<V>(io);
  io.expect_end("law record");
  return back;
}

/// A material whose every law parameter differs from its default.
Material odd_material(const BondLaw& joint) {
  Material m;
  m.contact = LinearContactParams::validated({91e9, 2.7, 0.41});
  m.joint = joint;
  return m;
}
FlatJointParams odd_flat_joint() {
  FlatJointParams p;
  p.bond = {81e9, 2.2, 123.456e6, 201e6, 0.31, 0.8};
  p.residual_friction_coefficient = 0.33, p.n_elements = 4;
  return FlatJointParams::validated(p);
}
ParallelBondParams odd_parallel_bond() {
  ParallelBondParams p;
  p.bond = {77e9, 1.9, 99.9e6, 150e6, 0.2, 0.6};
  return ParallelBondParams::validated(p);
}

/// A law's record as put_law writes it, without the keys added after "KERFDEM8" (as that format's builds wrote it).
void put_record_before_weibull(std::string& out, legacy::LawRecord r) {
  std::erase_if(r.values, [](const auto& kv) { return legacy::key_added_later(kv.first); });
  serial::put_str(out, r.name);
  serial::put_raw(out, static_cast<std::uint64_t>(r.values.size()));
  for (const auto& [key, value] : r.values) {
    serial::put_str(out, key);
    serial::put_raw(out, value);
  }
}

/// The material's two laws as records (this build; and as "KERFDEM8" and "KERFCAL5" wrote them, without the
/// Weibull keys) and as raw variants of 4a34e1f ("KERFDEM6", "KERFCAL3"); `joint_index_at`: where in the raw bytes
/// the joint variant keeps its index.
struct LawBytes {
  std::string records, records8, raw;
  std::size_t joint_index_at;
};
LawBytes law_bytes(const Material& m) {
  LawBytes out;
  serial::put_law(out.records, m.contact);
  serial::put_law(out.records, m.joint);
  const auto record = [](const auto& law) {
    return std::visit([](const auto& p) { return serial::law_record(p); }, law);
  };
  put_record_before_weibull(out.records8, record(m.contact));
  put_record_before_weibull(out.records8, record(m.joint));
  const auto& c = std::get<LinearContactParams>(m.contact);
  const legacy::ContactLaw6 contact6 =
      legacy::Linear6{c.effective_modulus_Pa, c.stiffness_ratio, c.friction_coefficient};
  alignas(legacy::BondLaw6) unsigned char joint6[sizeof(legacy::BondLaw6)];
  std::memset(joint6, 0xAA, sizeof joint6);  // the padding and the index's place told apart
  if (const auto* f = std::get_if<FlatJointParams>(&m.joint))
    new (joint6) legacy::BondLaw6(legacy::FlatJoint6{f->bond.effective_modulus_Pa, f->bond.stiffness_ratio,
                                                     f->bond.tensile_strength_Pa, f->bond.cohesion_Pa,
                                                     f->bond.friction_angle_rad, f->residual_friction_coefficient,
                                                     f->n_elements, f->bond.radius_multiplier, f->tan_friction_angle});
  else {
    const auto& p = std::get<ParallelBondParams>(m.joint);
    const BondStiffnessStrength& b = p.bond;
    new (joint6) legacy::BondLaw6(legacy::ParallelBond6{b.effective_modulus_Pa, b.stiffness_ratio,
                                                        b.tensile_strength_Pa, b.cohesion_Pa, b.friction_angle_rad,
                                                        b.radius_multiplier, p.tan_friction_angle});
  }
  serial::put_raw(out.raw, contact6);
  // The variant keeps its index in the first byte past its largest alternative.
  out.joint_index_at = out.raw.size() + std::max(sizeof(legacy::FlatJoint6), sizeof(legacy::ParallelBond6));
  REQUIRE(joint6[out.joint_index_at - out.raw.size()] == m.joint.index());
  out.raw.append(reinterpret_cast<const char*>(joint6), sizeof joint6);
  return out;
}

/// An engine state of this build ("KERFDEM9") of a specimen without Weibull strengths as "KERFDEM8" wrote it: the
/// laws' records without the Weibull keys, and no strength factors at the end (an empty vector: its length, 0).
std::string as_kerfdem8(std::string now, const Simulation& sim) {
  REQUIRE(now.substr(0, 8) == "KERFDEM9");
  REQUIRE(sim.bonds().strength_factor.empty());
  const LawBytes laws = law_bytes(sim.material());
  const std::size_t at = now.find(laws.records);
  REQUIRE(at != std::string::npos);
  now.replace(at, laws.records.size(), laws.records8);
  REQUIRE(now.substr(now.size() - 8) == std::string(8, '\0'));
  now.resize(now.size() - 8);
  now.replace(0, 8, "KERFDEM8");
  return now;
}

/// An engine state of "KERFDEM8" of a law without damage as "KERFDEM7" wrote it: the same bytes without the bonds'
/// element damage at the end (an empty vector: its length, 0).
std::string as_kerfdem7(std::string now) {
  REQUIRE(now.substr(0, 8) == "KERFDEM8");
  REQUIRE(now.size() >= 16);
  REQUIRE(now.substr(now.size() - 8) == std::string(8, '\0'));
  now.resize(now.size() - 8);
  now.replace(0, 8, "KERFDEM7");
  return now;
}

/// `now` (this build's bytes holding `m`'s law records once) with the records replaced by the raw variants of
/// 4a34e1f and its leading tag by `old_tag`; `joint_index_at` receives the place of the joint's index.
std::string with_raw_laws(std::string now, const Material& m, std::string_view old_tag,
                          std::size_t* joint_index_at = nullptr) {
  const LawBytes laws = law_bytes(m);
  std::size_t at = now.find(laws.records);
  std::size_t size = laws.records.size();
  if (at == std::string::npos) at = now.find(laws.records8), size = laws.records8.size();  // a KERFDEM8 state's
  REQUIRE(at != std::string::npos);
  now.replace(at, size, laws.raw);
  now.replace(0, old_tag.size(), old_tag);
  if (joint_index_at) *joint_index_at = at + laws.joint_index_at;
  return now;
}
}  // namespace

TEST_CASE("checkpoint: a law is stored by its name, and reads back the same in a reordered law list", "[checkpoint]") {
  const FlatJointParams fj = odd_flat_joint();
  const ParallelBondParams pb = odd_parallel_bond();
  CHECK(written_and_read<BondLaw>(BondLaw(fj)) == BondLaw(fj));
  CHECK(written_and_read<BondLaw>(BondLaw(pb)) == BondLaw(pb));
  // Written by this build's list, read by a build that registers the laws in the other order, and back.
  const ReorderedBondLaw fj_reordered = written_and_read<ReorderedBondLaw>(BondLaw(fj));
  REQUIRE(std::holds_alternative<FlatJointParams>(fj_reordered));
  CHECK(std::get<FlatJointParams>(fj_reordered) == fj);
  const ReorderedBondLaw pb_reordered = written_and_read<ReorderedBondLaw>(BondLaw(pb));
  REQUIRE(std::holds_alternative<ParallelBondParams>(pb_reordered));
  CHECK(std::get<ParallelBondParams>(pb_reordered) == pb);
  CHECK(written_and_read<BondLaw>(pb_reordered) == BondLaw(pb));
  // The default law's derived member is what validated() derives (a record does not store it).
  CHECK(FlatJointParams::validated(FlatJointParams{}) == FlatJointParams{});
  CHECK(ParallelBondParams::validated(ParallelBondParams{}) == ParallelBondParams{});
}

TEST_CASE("checkpoint: a law record of an unknown name, a missing key or a value out of range is a ModelError",
          "[checkpoint]") {
  std::string bytes;
  serial::put_law(bytes, BondLaw(odd_parallel_bond()));
  std::string unknown = bytes;
  unknown.replace(8, 13, "parallel_bind");  // after the name's length
  serial::In io{unknown};
  CHECK_THROWS_WITH(serial::get_law<BondLaw>(io), Catch::Matchers::Contains("the law 'parallel_bind': an unknown law"));
  // A bond law's record read into the contact law list: no law of that name there.
  std::string fj;
  serial::put_law(fj, BondLaw(odd_flat_joint()));
  serial::In as_contact{fj};
  CHECK_THROWS_AS(serial::get_law<ContactLaw>(as_contact), kerf::ModelError);
  legacy::LawRecord r = std::visit([](const auto& p) { return serial::law_record(p); }, BondLaw(odd_flat_joint()));
  r.values.pop_back();
  CHECK_THROWS_WITH(serial::law_from_record<BondLaw>(r), Catch::Matchers::Contains("no value for"));
  r = serial::law_record(odd_flat_joint());
  r.values.front().second = -1;  // a negative modulus
  CHECK_THROWS_AS(serial::law_from_record<BondLaw>(r), kerf::ModelError);
}

TEST_CASE(
    "checkpoint: engine states of KERFDEM8 (no strength factors), KERFDEM7 (also no element damage) and KERFDEM6 "
    "(also the laws as raw variants) read the same state, and another version is refused naming it",
    "[checkpoint]") {
  for (const BondLaw& joint : {BondLaw(odd_flat_joint()), BondLaw(odd_parallel_bond())}) {
    Simulation sim(odd_material(joint), SimulationOptions{});
    const int a = sim.add_particle(0, 0, 10e-6), b = sim.add_particle(19e-6, 0, 10e-6);
    sim.install_bond(a, b);
    sim.initialise();
    sim.run(3);
    const std::string v8 = as_kerfdem8(sim.serialize(), sim);
    const Simulation old8 = Simulation::deserialize(v8);
    CHECK(same_micro_parameters(old8.material(), sim.material()));
    CHECK(old8.serialize() == sim.serialize());  // the Weibull keys' defaults, every factor 1: this build's state
    const std::string v7 = as_kerfdem7(v8);
    const Simulation old7 = Simulation::deserialize(v7);
    CHECK(same_micro_parameters(old7.material(), sim.material()));
    CHECK(old7.serialize() == sim.serialize());  // written again in this build's format, byte for byte
    const Simulation old6 = Simulation::deserialize(with_raw_laws(v7, sim.material(), "KERFDEM6"));
    CHECK(same_micro_parameters(old6.material(), sim.material()));
    CHECK(old6.serialize() == sim.serialize());
  }
  const Simulation sim(odd_material(odd_parallel_bond()), SimulationOptions{});
  std::size_t index_at = 0;
  std::string bad =
      with_raw_laws(as_kerfdem7(as_kerfdem8(sim.serialize(), sim)), sim.material(), "KERFDEM6", &index_at);
  bad[index_at] = static_cast<char>(std::variant_size_v<legacy::BondLaw6>);
  CHECK_THROWS_WITH(Simulation::deserialize(bad), Catch::Matchers::Contains("an unknown law"));
  std::string older = sim.serialize();
  older.replace(0, 8, "KERFDEM5");
  CHECK_THROWS_WITH(
      Simulation::deserialize(older),
      Catch::Matchers::Contains(
          "another kerf-dem version (KERFDEM5, this one reads KERFDEM9 or KERFDEM8 or KERFDEM7 or KERFDEM6)"));
  // A state whose law state does not match its elements (a flat joint's with a state) is corrupt.
  // (The element state is the last vector but one: the joints' strength factors follow it.)
  std::string damaged = sim.serialize();
  damaged.resize(damaged.size() - 16);
  serial::put_vec(damaged, std::vector<double>{0.5});
  serial::put_vec(damaged, std::vector<double>{});
  CHECK_THROWS_WITH(Simulation::deserialize(damaged), Catch::Matchers::Contains("element state does not match"));
  // Strength factors for joints that are not there: corrupt too.
  std::string factors = sim.serialize();
  factors.resize(factors.size() - 8);
  serial::put_vec(factors, std::vector<double>{1.5});
  CHECK_THROWS_WITH(Simulation::deserialize(factors), Catch::Matchers::Contains("strength factors do not match"));
}

namespace {
/// A log as "KERFCAL4" wrote it: each evaluation's record without the toughness's two numbers at its end.
std::string as_kerfcal4(const std::vector<CalibrationEvaluation>& log) {
  REQUIRE(serialize_evaluations({}).substr(0, 8) == "5LACFREK");  // "KERFCAL5" as a little-endian u64
  std::string out;
  serial::Out io{out};
  io(std::uint64_t{0x4b45524643414c34}, static_cast<std::uint64_t>(log.size()));  // "KERFCAL4", the count
  for (const auto& e : log) {
    const std::string one = serialize_evaluations({e});
    out += one.substr(16, one.size() - 16 - 2 * sizeof(double));
  }
  return out;
}
}  // namespace

TEST_CASE("checkpoint: a calibration log of KERFCAL4 (no toughness) reads the same evaluations, K_IC 0",
          "[checkpoint]") {
  std::vector<CalibrationEvaluation> log(2);
  log[0].material = odd_material(odd_parallel_bond());
  log[1].material = odd_material(odd_flat_joint());
  log[0].macro = {70e9, 0.22, 40e6, 600e6};
  log[1].index = 1;
  log[1].max_relative_error = 0.25;
  const std::vector<CalibrationEvaluation> back = deserialize_evaluations(as_kerfcal4(log));
  REQUIRE(back.size() == 2);
  CHECK(serialize_evaluations(back) == serialize_evaluations(log));
  // A log of this build keeps the toughness's numbers.
  log[1].macro.fracture_toughness_Pa_sqrt_m = 0.77e6 / 3;
  log[1].toughness_error = 1.0 / 7;
  const std::vector<CalibrationEvaluation> now = deserialize_evaluations(serialize_evaluations(log));
  CHECK(now[1].macro.fracture_toughness_Pa_sqrt_m == log[1].macro.fracture_toughness_Pa_sqrt_m);
  CHECK(now[1].toughness_error == log[1].toughness_error);
  CHECK(now[0].macro.fracture_toughness_Pa_sqrt_m == 0);
}

TEST_CASE("checkpoint: a calibration log of KERFCAL3 (the laws as raw variants) reads the same laws", "[checkpoint]") {
  std::vector<CalibrationEvaluation> log(2);
  log[0].material = odd_material(odd_parallel_bond());
  log[1].material = odd_material(odd_flat_joint());
  log[0].macro = {70e9, 0.22, 40e6, 600e6};
  log[1].index = 1;
  // One evaluation at a time, so that each record is found where its raw variant goes.
  const std::string now = as_kerfcal4(log);
  std::string old = with_raw_laws(now, log[0].material, "\x33\x4c\x41\x43\x46\x52\x45\x4b");  // "KERFCAL3" as a u64
  old = with_raw_laws(old, log[1].material, "\x33\x4c\x41\x43\x46\x52\x45\x4b");
  const std::vector<CalibrationEvaluation> back = deserialize_evaluations(old);
  REQUIRE(back.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) CHECK(same_micro_parameters(back[k].material, log[k].material));
  CHECK(serialize_evaluations(back) == serialize_evaluations(log));
}

namespace {
using kerf::dem::CutParams;
/// The cut's section tables as tables of CutParams (each through its section's member), as the cut's state has them.
const std::array<kerf::dem::serial::SectionFields<CutParams>, 4>& cut_tables() {
  using kerf::embedded_fields;
  static const kerf::FieldTable<CutParams> cut = embedded_fields(kerf::dem::cut_fields(), &CutParams::cut),
                                           tool = embedded_fields(kerf::dem::tool_fields(), &CutParams::tool),
                                           grooves = embedded_fields(kerf::dem::groove_fields(), &CutParams::grooves),
                                           window =
                                               embedded_fields(kerf::dem::active_window_fields(), &CutParams::window);
  static const std::array<kerf::dem::serial::SectionFields<CutParams>, 4> t{
      {{"cut", cut}, {"tool", tool}, {"grooves", grooves}, {"active_window", window}}};
  return t;
}
/// Every field of the cut's tables as one text: key, then the value's bits (numbers) or index (choices).
std::string cut_fields_text(const CutParams& p) {
  std::string text;
  for (const auto& sf : cut_tables())
    for (const auto& field : sf.table)
      std::visit(
          [&](const auto& f) {
            text += std::string(sf.section) + "." + std::string(f.key) + "=";
            const auto v = f.get(p);
            using V = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<V, double>) {
              std::uint64_t bits = 0;
              std::memcpy(&bits, &v, sizeof v);
              text += std::to_string(bits) + ";";
            } else if constexpr (std::is_integral_v<V>) {
              text += std::to_string(static_cast<long long>(v)) + ";";
            }  // no other kind of field in the cut's tables (put_fields would refuse one)
          },
          field);
  return text;
}
}  // namespace

TEST_CASE(
    "checkpoint: a parameter struct stored by the keys of its tables reads back every field to the bit "
    "(the cut's, KERFCUT8 and on)",
    "[checkpoint]") {
  namespace serial = kerf::dem::serial;
  // Every field off its default: numbers with many digits, integers at their top, flags flipped, the last choice.
  CutParams p;
  int k = 0;
  for (const auto& sf : cut_tables())
    for (const auto& field : sf.table)
      std::visit(
          [&](const auto& f) {
            using F = std::decay_t<decltype(f)>;
            ++k;
            if constexpr (std::is_same_v<F, kerf::NumberField<CutParams>>)
              f.set(p, 1e-3 * k + 1.0 / 3);
            else if constexpr (std::is_same_v<F, kerf::IntField<CutParams>>)
              f.set(p, f.hi);
            else if constexpr (std::is_same_v<F, kerf::BoolField<CutParams>>)
              f.set(p, !f.get(CutParams{}));
            else if constexpr (std::is_same_v<F, kerf::ChoiceField<CutParams>>)
              f.set(p, static_cast<int>(f.names.size()) - 1);
          },
          field);
  REQUIRE(cut_fields_text(p) != cut_fields_text(CutParams{}));
  std::string bytes;
  serial::put_fields(bytes, cut_tables(), p);
  CutParams q;
  serial::In in{bytes};
  serial::get_fields(in, cut_tables(), q, "test record");
  in.expect_end("test record");
  CHECK(cut_fields_text(q) == cut_fields_text(p));
  // A record without a field (one added to a table later) leaves its default; an unknown key, a key twice or an
  // unknown choice name is a corrupt record.
  const auto record = [](std::vector<std::pair<std::string, double>> numbers,
                         std::vector<std::pair<std::string, std::string>> choices) {
    std::string b;
    serial::put_raw(b, static_cast<std::uint64_t>(numbers.size()));
    for (const auto& [key, v] : numbers) serial::put_str(b, key), serial::put_raw(b, v);
    serial::put_raw(b, static_cast<std::uint64_t>(choices.size()));
    for (const auto& [key, v] : choices) serial::put_str(b, key), serial::put_str(b, v);
    return b;
  };
  const auto read = [](const std::string& b) {
    CutParams r;
    serial::In io{b};
    serial::get_fields(io, cut_tables(), r, "test record");
    return r;
  };
  const CutParams one = read(record({{"cut.depth_of_cut_mm", 2e-4}}, {}));
  CHECK(one.cut.depth_of_cut_m == 2e-4);
  CHECK(one.cut.length_m == CutParams{}.cut.length_m);
  CHECK(read(record({}, {{"grooves.shape", "trapezoidal"}})).grooves.shape == kerf::dem::GrooveShape::trapezoidal);
  CHECK_THROWS_WITH(read(record({{"cut.no_such_key", 1}}, {})), Catch::Contains("keys this build does not have"));
  CHECK_THROWS_WITH(read(record({{"cut.depth_of_cut_mm", 1}, {"cut.depth_of_cut_mm", 2}}, {})),
                    Catch::Contains("a key twice"));
  CHECK_THROWS_WITH(read(record({}, {{"grooves.shape", "round"}})), Catch::Contains("not a name this build has"));
  CHECK_THROWS_AS(read(record({{"tool.edge_segments", 0.5}}, {})), kerf::ModelError);
}
