// 64-bit FNV-1a content hash (Fowler, Noll, Vo; "FNV-1a", IETF draft
// draft-eastlake-fnv, 2019): h = offset basis; for every byte b:
// h = (h XOR b) * prime, with offset basis 14695981039346656037 and prime
// 1099511628211 (mod 2^64).
//
// Used for cache keys and file checksums (profiles, contact tables, MIM
// tables): fast and stable across runs and machines of the same byte order,
// not a cryptographic hash. Doubles are hashed by their bytes, so 0.0 and -0.0
// differ, as do two NaNs with different payloads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace railsim {

inline constexpr std::uint64_t kFnv1aOffsetBasis = 14695981039346656037ull;
inline constexpr std::uint64_t kFnv1aPrime = 1099511628211ull;

// Hash of n bytes at data, continuing from `seed` (the offset basis for a fresh hash).
inline std::uint64_t fnv1a(const void* data, std::size_t n, std::uint64_t seed = kFnv1aOffsetBasis) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t h = seed;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= kFnv1aPrime;
  }
  return h;
}

// Incremental form: feed bytes, values and strings in order, read value().
class ContentHash {
 public:
  ContentHash& bytes(const void* data, std::size_t n) {
    h_ = fnv1a(data, n, h_);
    return *this;
  }
  // A trivially copyable value by its bytes (double, integers, ...).
  template <class T>
  ContentHash& value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "hash trivially copyable values only");
    return bytes(&v, sizeof v);
  }
  ContentHash& text(std::string_view s) { return bytes(s.data(), s.size()); }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = kFnv1aOffsetBasis;
};

}  // namespace railsim
