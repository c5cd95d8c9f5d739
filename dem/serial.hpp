#pragma once
// Byte-level helpers for the checkpoints (the engine state, LabTestRun, CutRun, calibration evaluations): raw
// values and vectors with a length prefix, native endianness (a checkpoint is read back by the same build).
// Internal to dem/.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "kerf/error.hpp"

namespace kerf::dem::serial {

// The formats write counts (std::size_t) as 8 bytes and flags (bool) as 1 byte, as earlier builds did.
static_assert(sizeof(std::size_t) == sizeof(std::uint64_t), "counts are 8 bytes in the checkpoint formats");
static_assert(sizeof(bool) == 1, "flags are one byte each in the checkpoint formats");

template <class T>
void put_raw(std::string& out, const T& v) {
  static_assert(std::is_trivially_copyable_v<T>);
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
void put_vec(std::string& out, const std::vector<T>& v) {
  static_assert(std::is_trivially_copyable_v<T>);
  put_raw(out, static_cast<std::uint64_t>(v.size()));
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}
inline void put_str(std::string& out, const std::string& s) { put_vec(out, std::vector<char>(s.begin(), s.end())); }

template <class T>
struct is_variant : std::false_type {};
template <class... T>
struct is_variant<std::variant<T...>> : std::true_type {};

template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};

/// Writes fields in order: a string or vector with its length prefix, anything else as raw bytes. A state
/// class lists its fields once, in a template `state_fields(self, io)`, and calls it with Out to write and
/// In to read, so the two directions cannot drift apart.
struct Out {
  std::string& s;
  template <class... T>
  void operator()(const T&... v) {
    (one(v), ...);
  }

 private:
  template <class T>
  void one(const T& v) {
    if constexpr (std::is_same_v<T, std::string>)
      put_str(s, v);
    else if constexpr (is_vector<T>::value)
      put_vec(s, v);
    else
      put_raw(s, v);
  }
};

struct In {
  std::string_view b;
  std::size_t at = 0;
  void take(void* d, std::size_t n) {
    if (at > b.size() || n > b.size() - at) throw ModelError("dem", "truncated checkpoint");  // cannot wrap
    if (n == 0) return;  // an empty vector's data() may be null, and memcpy's pointers must not be (found by fuzzing)
    std::memcpy(d, b.data() + at, n);
    at += n;
  }
  template <class T>
  void raw(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);  // a vector goes through vec()
    take(&v, sizeof(T));
  }
  template <class T>
  void vec(std::vector<T>& v) {
    std::uint64_t n = 0;
    raw(n);
    if (at > b.size() || n > (b.size() - at) / (sizeof(T) > 0 ? sizeof(T) : 1))
      throw ModelError("dem", "corrupt checkpoint (a length beyond its end)");
    v.resize(static_cast<std::size_t>(n));
    take(v.data(), v.size() * sizeof(T));
  }
  void str(std::string& s) {
    std::vector<char> c;
    vec(c);
    s.assign(c.begin(), c.end());
  }
  /// Reads fields in the order Out wrote them.
  template <class... T>
  void operator()(T&... v) {
    (one(v), ...);
  }
  /// Throws unless every byte was read.
  void expect_end(const char* what) const {
    if (at != b.size()) throw ModelError("dem", std::string(what) + " has trailing bytes");
  }

 private:
  template <class T>
  void one(T& v) {
    if constexpr (std::is_same_v<T, std::string>) {
      str(v);
    } else if constexpr (is_vector<T>::value) {
      vec(v);
    } else {
      raw(v);
      // A variant (a contact law) is stored whole, its index with it: an index beyond its alternatives would
      // make every visit undefined (found by fuzz_checkpoint behind a valid checksum).
      if constexpr (is_variant<T>::value) {
        if (v.index() >= std::variant_size_v<T>) throw ModelError("dem", "corrupt checkpoint (an unknown law)");
      }
    }
  }
};

/// Checks the format tag at the start of `bytes` (a name and a version digit, like "KERFCUT2") and returns a
/// reader just after it. A tag of the same name with another version is refused by name, so that a user
/// knows the file is old rather than foreign; `what` names the file kind in the messages.
inline In open_tagged(std::string_view bytes, std::string_view tag, const std::string& what) {
  const std::string_view head = bytes.substr(0, tag.size());
  if (head.size() == tag.size() && head != tag && head.substr(0, tag.size() - 1) == tag.substr(0, tag.size() - 1))
    throw ModelError("dem", "a " + what + " of another kerf-dem version (" + std::string(head) + ", this one reads " +
                                std::string(tag) + "): start the run again");
  if (head != tag) throw ModelError("dem", "not a kerf-dem " + what);
  return In{bytes, tag.size()};
}

}  // namespace kerf::dem::serial
