#include "kerf/dem/checkpoint.hpp"

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <new>
#include <variant>

#include "kerf/dem/simulation.hpp"
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

// Regressions of the two faults fuzz_checkpoint found behind a valid checksum (docs/hardening.md).
TEST_CASE("checkpoint: an engine state with empty arrays reads back; a law index beyond the laws is a ModelError",
          "[checkpoint]") {
  using namespace kerf::dem;
  Simulation sim(Material{}, SimulationOptions{});  // no disks, joints, walls or cracks: every array empty
  const std::string good = sim.serialize();
  CHECK(Simulation::deserialize(good).serialize() == good);  // UBSan: no memcpy from a null data()
  // Where the stored joint law keeps its alternative's index: a variant built over a known fill byte.
  alignas(BondLaw) unsigned char buffer[sizeof(BondLaw)];
  std::memset(buffer, 0xAA, sizeof buffer);
  new (buffer) BondLaw(ParallelBondParams{});
  std::size_t index_at = sizeof buffer;
  for (std::size_t k = std::max(sizeof(FlatJointParams), sizeof(ParallelBondParams)); k < sizeof buffer; ++k)
    if (buffer[k] == 1) index_at = k;
  REQUIRE(index_at < sizeof buffer);
  // The state begins: tag, density, the contact law, the joint law (serial.hpp writes each whole).
  const std::size_t joint_at = 8 + sizeof(double) + sizeof(ContactLaw);
  REQUIRE(static_cast<unsigned char>(good[joint_at + index_at]) == 0);  // the default material's flat joint
  std::string bad = good;
  bad[joint_at + index_at] = static_cast<char>(std::variant_size_v<BondLaw>);
  CHECK_THROWS_WITH(Simulation::deserialize(bad), Catch::Matchers::Contains("an unknown law"));
}
