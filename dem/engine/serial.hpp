#pragma once
// Byte-level helpers for the checkpoints (the engine state, LabTestRun, CutRun, calibration evaluations): raw
// values and vectors with a length prefix, native endianness (a checkpoint is read back by the same build), the
// contact laws as records by name (a law list may be reordered or grow without misreading a checkpoint), and a
// parameter struct by the keys of its field tables (put_fields, get_fields).
// Internal to dem/.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "../laws/legacy_laws.hpp"
#include "kerf/dem/laws/contact_laws.hpp"
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
inline void put_str(std::string& out, const std::string& s) {
  put_vec(out, std::vector<char>(s.begin(), s.end()));
}

template <class T>
struct is_variant : std::false_type {};
template <class... T>
struct is_variant<std::variant<T...>> : std::true_type {};

template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};

struct In;
template <class V>
void put_law(std::string& out, const V& law);
template <class V>
V get_law(In& io);

/// Writes fields in order: a string or vector with its length prefix, a law (a variant of the registry) as its
/// record by name (put_law), anything else as raw bytes. A state
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
    else if constexpr (is_variant<T>::value)
      put_law(s, v);
    else
      put_raw(s, v);
  }
};

struct In {
  std::string_view b;
  std::size_t at = 0;
  /// The laws are stored as raw variants in the layout of 4a34e1f (legacy_laws.hpp): the formats before
  /// "KERFDEM7" and "KERFCAL4".
  bool raw_laws = false;
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
    } else if constexpr (is_variant<T>::value) {
      v = get_law<T>(*this);
    } else {
      raw(v);
    }
  }
};

/// Checks the format tag at the start of `bytes` (a name and a version digit, like "KERFCUT2") against the
/// versions this build reads (`tags`, the same name each, the newest first) and returns a reader just after it;
/// `version` receives the index of the tag found. A tag of the same name with another version is refused by
/// name (ModelError, exit 3), so that a user knows the file is old rather than foreign; `what` names the file
/// kind in the messages.
inline In open_tagged(std::string_view bytes, std::initializer_list<std::string_view> tags, const std::string& what,
                      std::size_t* version = nullptr) {
  const std::string_view newest = *tags.begin();
  const std::string_view head = bytes.substr(0, newest.size());
  std::size_t k = 0;
  for (const std::string_view tag : tags) {
    if (head == tag) {
      if (version) *version = k;
      return In{bytes, tag.size()};
    }
    ++k;
  }
  if (head.size() == newest.size() && head.substr(0, newest.size() - 1) == newest.substr(0, newest.size() - 1)) {
    throw ModelError("dem", fmt::format("a {} of another kerf-dem version ({}, this one reads {}): start the run again",
                                        what, head, fmt::join(tags, " or ")));
  }
  throw ModelError("dem", "not a kerf-dem " + what);
}
inline In open_tagged(std::string_view bytes, std::string_view tag, const std::string& what) {
  return open_tagged(bytes, {tag}, what);
}

// --- a field of a table as a record holds it ---

/// Fields a record holds as a number: a real number in SI (to the bit), an integer, a flag.
template <class S, class F>
constexpr bool kNumberInRecord =
    std::is_same_v<F, NumberField<S>> || std::is_same_v<F, IntField<S>> || std::is_same_v<F, BoolField<S>>;

/// Sets a number, integer or flag field from its value in a record; `corrupt(why)` is the error of an integer
/// that is none or out of its range (checked before the conversion, which would be undefined).
template <class S, class F, class Corrupt>
void set_from_record(const F& f, S& s, double value, const Corrupt& corrupt) {
  if constexpr (std::is_same_v<F, NumberField<S>>) {
    f.set(s, value);
  } else if constexpr (std::is_same_v<F, IntField<S>>) {
    if (!(value >= f.lo && value <= f.hi) || value != std::trunc(value))
      throw corrupt(std::string(f.key) + " is not an integer in [" + std::to_string(f.lo) + ", " +
                    std::to_string(f.hi) + "]");
    f.set(s, static_cast<int>(value));
  } else {
    f.set(s, value != 0);
  }
}

// --- the laws as records: the registry name, then each key of the law's field table with its SI value ---

using legacy::LawRecord;

/// The law's record: its name and every field of its table (numbers in SI, to the bit; integers and flags as
/// numbers). Derived members (tan phi) are not stored: validated() derives them again on reading.
template <class P>
LawRecord law_record(const P& p) {
  LawRecord r{std::string(P::kName), {}};
  for (const auto& field : P::fields()) {
    std::visit(
        [&](const auto& f) {
          using F = std::decay_t<decltype(f)>;
          if constexpr (kNumberInRecord<P, F>)
            r.values.emplace_back(std::string(f.key), static_cast<double>(f.get(p)));
          else
            throw std::logic_error("a law field of a kind the checkpoints cannot store: " + std::string(f.key));
        },
        field);
  }
  return r;
}

/// The law of list V that `r` names, every field of its table set from the record and validated; ModelError
/// (exit 3) when V has no law of that name, a key is missing, unknown or repeated, or a value is out of range.
template <class V>
V law_from_record(const LawRecord& r) {
  auto corrupt = [&](const std::string& why) -> ModelError {
    return ModelError("dem", "corrupt checkpoint (the law '" + r.name + "': " + why + ")");
  };
  V law;
  try {
    law = law_by_name<V>(r.name, "law");
  } catch (const InputError&) {
    throw corrupt(fmt::format("an unknown law; this build has {}", fmt::join(law_names<V>(), ", ")));
  }
  std::visit(
      [&](auto& p) {
        using P = std::decay_t<decltype(p)>;
        std::size_t used = 0;
        for (const auto& field : P::fields()) {
          std::visit(
              [&](const auto& f) {
                using F = std::decay_t<decltype(f)>;
                const auto it =
                    std::find_if(r.values.begin(), r.values.end(), [&](const auto& kv) { return kv.first == f.key; });
                if (it == r.values.end()) {
                  if (legacy::key_added_later(f.key)) return;  // an older record: the default, that build's law
                  throw corrupt("no value for " + std::string(f.key));
                }
                ++used;
                if constexpr (kNumberInRecord<P, F>) set_from_record(f, p, it->second, corrupt);
              },
              field);
        }
        if (used != r.values.size()) throw corrupt("keys this build's law does not have, or a key twice");
        try {
          p = P::validated(p);
        } catch (const InputError& e) {
          throw corrupt(e.what());
        }
      },
      law);
  return law;
}

template <class V>
void put_law(std::string& out, const V& law) {
  const LawRecord r = std::visit([](const auto& p) { return law_record(p); }, law);
  put_str(out, r.name);
  put_raw(out, static_cast<std::uint64_t>(r.values.size()));
  for (const auto& [key, value] : r.values) {
    put_str(out, key);
    put_raw(out, value);
  }
}

/// The old formats' raw variant of list V (a bond or a contact law list), translated by name.
template <class V>
V get_legacy_law(In& io) {
  using Legacy =
      std::conditional_t<BondLawParams<std::variant_alternative_t<0, V>>, legacy::BondLaw6, legacy::ContactLaw6>;
  Legacy old;
  io.raw(old);
  // An index beyond its alternatives would make every visit undefined (found by fuzz_checkpoint behind a
  // valid checksum).
  if (old.index() >= std::variant_size_v<Legacy>) throw ModelError("dem", "corrupt checkpoint (an unknown law)");
  return law_from_record<V>(std::visit([](const auto& p) { return legacy::record_of(p); }, old));
}

template <class V>
V get_law(In& io) {
  if (io.raw_laws) return get_legacy_law<V>(io);
  LawRecord r;
  std::uint64_t n = 0;
  io(r.name, n);
  if (n > io.b.size() - io.at) throw ModelError("dem", "corrupt checkpoint (a length beyond its end)");
  r.values.resize(static_cast<std::size_t>(n));
  for (auto& [key, value] : r.values) io(key, value);
  return law_from_record<V>(r);
}

// --- a parameter struct by the keys of its tables: each field as "section.key" with its value ---

/// A table of S and the scene section whose keys it holds ("cut", "tool", ...).
template <class S>
struct SectionFields {
  std::string_view section;
  const FieldTable<S>& table;
};

/// Writes every field of `sections` for `s`: the numbers (reals in SI, to the bit; integers and flags as numbers)
/// as (key, value) records, then the choices as (key, name). Derived from the tables, so a field added to a table
/// is stored without a new format; a kind of field a record cannot hold is a logic error (a table of the build).
template <class S, std::size_t N>
void put_fields(std::string& out, const std::array<SectionFields<S>, N>& sections, const S& s) {
  std::vector<std::pair<std::string, double>> numbers;
  std::vector<std::pair<std::string, std::string>> choices;
  for (const SectionFields<S>& sf : sections)
    for (const auto& field : sf.table)
      std::visit(
          [&](const auto& f) {
            using F = std::decay_t<decltype(f)>;
            std::string key = std::string(sf.section) + "." + std::string(f.key);
            if constexpr (std::is_same_v<F, NumberField<S>>) {
              if (f.has && !f.has(s)) {  // an optional number left out: NaN, read back as the struct's default
                numbers.emplace_back(std::move(key), std::numeric_limits<double>::quiet_NaN());
                return;
              }
            }
            if constexpr (kNumberInRecord<S, F>)
              numbers.emplace_back(std::move(key), static_cast<double>(f.get(s)));
            else if constexpr (std::is_same_v<F, ChoiceField<S>>)
              choices.emplace_back(std::move(key), std::string(f.names[static_cast<std::size_t>(f.get(s))]));
            else
              throw std::logic_error("a field of a kind the checkpoints cannot store: " + key);
          },
          field);
  put_raw(out, static_cast<std::uint64_t>(numbers.size()));
  for (const auto& [key, value] : numbers) put_str(out, key), put_raw(out, value);
  put_raw(out, static_cast<std::uint64_t>(choices.size()));
  for (const auto& [key, name] : choices) put_str(out, key), put_str(out, name);
}

/// Reads what put_fields wrote into `s`: each field of `sections` from its record; a field the record lacks (one
/// added to a table after it was written) keeps its value in `s`, the default. A key this build does not have, a
/// key twice, an integer out of range or a choice's unknown name is a corrupt `what` (ModelError, exit 3).
template <class S, std::size_t N>
void get_fields(In& io, const std::array<SectionFields<S>, N>& sections, S& s, const std::string& what) {
  const auto corrupt = [&](const std::string& why) { return ModelError("dem", "corrupt " + what + " (" + why + ")"); };
  const auto count = [&] {
    std::uint64_t n = 0;
    io(n);
    if (n > io.b.size() - io.at) throw corrupt("a length beyond its end");
    return static_cast<std::size_t>(n);
  };
  std::vector<std::pair<std::string, double>> numbers(count());
  for (auto& [key, value] : numbers) io(key, value);
  std::vector<std::pair<std::string, std::string>> choices(count());
  for (auto& [key, name] : choices) io(key, name);
  std::size_t used = 0;
  const auto find = [&](auto& list, const std::string& key) {
    const auto it = std::find_if(list.begin(), list.end(), [&](const auto& kv) { return kv.first == key; });
    used += it != list.end();
    return it;
  };
  for (const SectionFields<S>& sf : sections)
    for (const auto& field : sf.table)
      std::visit(
          [&](const auto& f) {
            using F = std::decay_t<decltype(f)>;
            const std::string key = std::string(sf.section) + "." + std::string(f.key);
            if constexpr (kNumberInRecord<S, F>) {
              const auto it = find(numbers, key);
              if constexpr (std::is_same_v<F, NumberField<S>>)
                if (it != numbers.end() && f.has && std::isnan(it->second)) return;  // left out: the default
              if (it != numbers.end()) set_from_record(f, s, it->second, corrupt);
            } else if constexpr (std::is_same_v<F, ChoiceField<S>>) {
              if (const auto it = find(choices, key); it != choices.end()) {
                const auto name = std::find(f.names.begin(), f.names.end(), it->second);
                if (name == f.names.end()) throw corrupt(key + " = '" + it->second + "', not a name this build has");
                f.set(s, static_cast<int>(name - f.names.begin()));
              }
            }
          },
          field);
  if (used != numbers.size() + choices.size()) throw corrupt("keys this build does not have, or a key twice");
}

}  // namespace kerf::dem::serial
