// The checkpoint file of a kerf-dem run (kerf/dem/checkpoint.hpp).
#include "kerf/dem/checkpoint.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include "kerf/error.hpp"
#include "kerf/io.hpp"

namespace kerf::dem {

namespace {
constexpr std::string_view kMagic = "KERFCKP1";
}  // namespace

std::string Checkpoint::bytes() const {
  const Json head{{"scene", scene}, {"summary", summary}, {"frames", frames}, {"sample_index", sample_index},
                  {"checkpoint_every", checkpoint_every}, {"scene_dir", scene_dir}};
  std::string out(kMagic);
  const std::string head_text = head.dump();
  for (const std::string* part : {&head_text, &specimen, &run}) {
    const auto n = static_cast<std::uint64_t>(part->size());
    out.append(reinterpret_cast<const char*>(&n), sizeof n);
    out += *part;
  }
  return out;
}

Checkpoint Checkpoint::parse(const std::string& bytes) {
  if (bytes.compare(0, kMagic.size(), kMagic) != 0)
    throw ModelError("kerf-dem", "checkpoint.bin is not a kerf-dem checkpoint");
  std::size_t at = kMagic.size();
  std::string parts[3];
  for (auto& part : parts) {
    std::uint64_t n = 0;
    if (at + sizeof n > bytes.size()) throw ModelError("kerf-dem", "truncated checkpoint");
    std::memcpy(&n, bytes.data() + at, sizeof n);
    at += sizeof n;
    if (at + n > bytes.size()) throw ModelError("kerf-dem", "truncated checkpoint");
    part = bytes.substr(at, static_cast<std::size_t>(n));
    at += static_cast<std::size_t>(n);
  }
  const Json head = Json::parse(parts[0]);
  Checkpoint c;
  c.scene = head.at("scene");
  c.summary = head.at("summary");
  c.frames = head.at("frames").get<FrameList>();
  c.sample_index = head.at("sample_index");
  c.checkpoint_every = head.at("checkpoint_every");
  c.scene_dir = head.at("scene_dir");
  c.specimen = std::move(parts[1]);
  c.run = std::move(parts[2]);
  return c;
}

void write_checkpoint(const std::filesystem::path& dir, const Checkpoint& c) {
  write_file_atomically(dir / "checkpoint.bin", c.bytes());
}

Checkpoint read_checkpoint(const std::filesystem::path& dir) {
  std::ifstream in(dir / "checkpoint.bin", std::ios::binary);
  if (!in) throw InputError("DIR", dir.string(), "a directory with a checkpoint.bin written by --checkpoint-every");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return Checkpoint::parse(bytes);
}

void remove_checkpoint(const std::filesystem::path& dir) {
  std::error_code ignored;
  std::filesystem::remove(dir / "checkpoint.bin", ignored);
}

}  // namespace kerf::dem
