// libFuzzer target: loading a kerf-dem checkpoint (docs/hardening.md).
//
// The first byte chooses the layer: even, the bytes are a whole checkpoint.bin (its header, length and CRC-32
// are checked first, so almost every input stops there); odd, the rest is a payload that the target wraps in
// a valid checkpoint (a correct length and checksum) so that the readers of the head and of the engine, test,
// cut and calibration states behind the checksum are fuzzed too. Every outcome must be a checkpoint or a
// ModelError / InputError: a crash, a sanitizer report or another exception is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "kerf/dem/engine/checkpoint.hpp"
#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/procedures/calibration.hpp"
#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/dem/procedures/lab_test.hpp"
#include "kerf/error.hpp"

namespace {
void load(const std::string& bytes) {
  const kerf::dem::Checkpoint c = kerf::dem::Checkpoint::parse(bytes);
  // Each state reader on both payloads: they refuse a foreign tag before reading anything else.
  for (const std::string* part : {&c.specimen, &c.run}) {
    try {
      (void)kerf::dem::Simulation::deserialize(*part);
    } catch (const kerf::ModelError&) {
    }
    try {
      (void)kerf::dem::LabTestRun::deserialize(*part);
    } catch (const kerf::ModelError&) {
    }
    try {
      (void)kerf::dem::CutRun::deserialize(*part);
    } catch (const kerf::ModelError&) {
    }
    try {
      (void)kerf::dem::deserialize_evaluations(*part);
    } catch (const kerf::ModelError&) {
    }
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] % 2 == 1) {
      // The payload as the three parts' bytes: re-frame it with a right length and checksum.
      kerf::dem::Checkpoint framed;
      const std::size_t third = bytes.size() / 3;
      framed.scene = kerf::Json::object();
      framed.specimen = bytes.substr(0, 2 * third);
      framed.run = bytes.substr(2 * third);
      std::string whole = framed.bytes();
      load(whole);
    } else {
      load(bytes);
    }
  } catch (const kerf::ModelError&) {
  } catch (const kerf::InputError&) {
  }
  return 0;
}
