// The checkpoint file of a kerf-dem run (kerf/dem/engine/checkpoint.hpp).
#include "kerf/dem/engine/checkpoint.hpp"

#include <fmt/format.h>

#include <boost/crc.hpp>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include "kerf/error.hpp"
#include "kerf/io.hpp"
#include "serial.hpp"

namespace kerf::dem {

namespace {
// 2: the file's length after the magic and a CRC-32 of every byte before it at the end.
constexpr std::string_view kMagic = "KERFCKP2";
constexpr std::size_t kCrcBytes = sizeof(std::uint32_t);

void put_u64(std::string& out, std::uint64_t n) {
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
}

/// The corruption of a checkpoint: exit 3 with what was found, never a crash or a different run.
[[noreturn]] void damaged(const std::string& why) {
  throw ModelError("kerf-dem", "checkpoint.bin is damaged (" + why + "): start the run again");
}
}  // namespace

std::uint32_t crc32(std::string_view bytes) {
  boost::crc_32_type crc;
  crc.process_bytes(bytes.data(), bytes.size());
  return crc.checksum();
}

std::string Checkpoint::bytes() const {
  const Json head{{"scene", scene},
                  {"summary", summary},
                  {"frames", frames},
                  {"sample_index", sample_index},
                  {"checkpoint_every", checkpoint_every},
                  {"scene_dir", scene_dir},
                  {"provenance", provenance}};
  const std::string head_text = head.dump(-1, ' ', false, Json::error_handler_t::replace);
  std::string out(kMagic);
  put_u64(out, 0);  // the length, below
  for (const std::string* part : {&head_text, &specimen, &run}) {
    put_u64(out, part->size());
    out += *part;
  }
  const std::uint64_t length = out.size() + kCrcBytes;
  std::memcpy(out.data() + kMagic.size(), &length, sizeof length);
  const std::uint32_t crc = crc32(out);
  out.append(reinterpret_cast<const char*>(&crc), sizeof crc);
  return out;
}

Checkpoint Checkpoint::parse(const std::string& bytes) {
  serial::In io = serial::open_tagged(bytes, kMagic, "checkpoint");
  std::uint64_t length = 0;
  io(length);
  if (length != bytes.size()) damaged(fmt::format("{} bytes where its header says {}", bytes.size(), length));
  std::uint32_t stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - kCrcBytes, kCrcBytes);
  const std::string_view body = std::string_view(bytes).substr(0, bytes.size() - kCrcBytes);
  if (crc32(body) != stored) damaged("its CRC-32 does not match its contents");
  io.b = body;  // the parts end where the checksum begins
  std::string parts[3];
  for (auto& part : parts) io(part);
  io.expect_end("checkpoint");
  Checkpoint c;
  try {
    const Json head = parse_json_text(parts[0], "checkpoint.bin");
    c.scene = head.at("scene");
    c.summary = head.at("summary");
    c.frames = head.at("frames").get<FrameList>();
    c.sample_index = head.at("sample_index");
    c.checkpoint_every = head.at("checkpoint_every");
    c.scene_dir = head.at("scene_dir");
    c.provenance = head.value("provenance", Json());  // absent from the checkpoints of kerf before it
  } catch (const std::exception& e) {
    damaged(fmt::format("its head: {}", e.what()));
  }
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
  if (in.bad()) throw ModelError("kerf-dem", fmt::format("cannot read '{}'", (dir / "checkpoint.bin").string()));
  return Checkpoint::parse(bytes);
}

void remove_checkpoint(const std::filesystem::path& dir) {
  std::error_code ignored;
  std::filesystem::remove(dir / "checkpoint.bin", ignored);
}

}  // namespace kerf::dem
