#pragma once
// What a killed kerf-dem run needs to continue: the scene as run, the summary so far, the frames written,
// the sample reached, the specimen and the run's own state (written atomically to OUT/checkpoint.bin every
// --checkpoint-every samples; a calibration writes one after every evaluation).
//
//   Checkpoint c{doc, summary, frames, sample_index, every, scene_dir, specimen.serialize(), run.serialize(),
//                options.provenance};
//   write_checkpoint(out, c);
//   Checkpoint again = read_checkpoint(out);   // InputError when OUT holds none
//
// Format "KERFCKP2": the magic (a name and a version digit), the file's length (native 64 bits), three parts,
// each a native 64-bit length and its bytes: the JSON head (scene, summary, frames, sample_index,
// checkpoint_every, scene_dir and, when the run has one, provenance), the specimen, the run; last the CRC-32 (IEEE
// 802.3, boost::crc_32_type) of every byte before it. A file that is damaged (a flipped bit, cut short, a byte too
// many) or of another version is a ModelError (exit 3), read before anything in it is used.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kerf/json_reader.hpp"

namespace kerf::dem {

/// The VTK frames written so far: per frame its time and its files (for the .pvd collection).
using FrameList = std::vector<std::pair<double, std::vector<std::string>>>;

struct Checkpoint {
  Json scene, summary;
  FrameList frames;
  int sample_index = 0, checkpoint_every = 0;
  std::string scene_dir, specimen, run;
  /// The run's provenance (RunOptions::provenance; in the JSON head, null in a checkpoint written without it).
  Json provenance;

  std::string bytes() const;
  /// ModelError when the bytes are not a checkpoint, of another version, or damaged in any way.
  static Checkpoint parse(const std::string& bytes);
};

/// The CRC-32 of the checkpoints (IEEE 802.3: crc32("123456789") = 0xCBF43926).
std::uint32_t crc32(std::string_view bytes);

/// Writes DIR/checkpoint.bin atomically.
void write_checkpoint(const std::filesystem::path& dir, const Checkpoint& c);
/// Reads DIR/checkpoint.bin; InputError naming DIR when there is none.
Checkpoint read_checkpoint(const std::filesystem::path& dir);
/// Removes DIR/checkpoint.bin (a finished run has nothing to resume).
void remove_checkpoint(const std::filesystem::path& dir);

}  // namespace kerf::dem
