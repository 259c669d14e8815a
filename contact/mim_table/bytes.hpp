// Little-endian byte writer and bounds-checked reader of the MIM table's binary
// file (mim_table/file.cpp) and of its parameter hash (mim_table/spec.cpp);
// the layout of the file is described in mim_table.hpp. Internal to contact/.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace railsim::contact::mim_table_detail {

inline constexpr char kMagic[8] = {'R', 'S', 'M', 'I', 'M', 'T', 'A', 'B'};

// Appends values in memory order (little-endian on every supported host).
struct Bytes {
  std::string buf;
  template <class T>
  void put(const T& v) {
    buf.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void put_vec(const std::vector<double>& v) {
    put(static_cast<std::uint32_t>(v.size()));
    buf.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
};
// Reads back what Bytes wrote; ok = false once a read would pass the end.
struct Reader {
  const std::string& buf;
  std::size_t pos = 0;
  bool ok = true;
  template <class T>
  T get() {
    T v{};
    if (pos + sizeof(T) > buf.size()) {
      ok = false;
      return v;
    }
    std::memcpy(&v, buf.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  std::vector<double> get_vec() {
    const auto n = get<std::uint32_t>();
    std::vector<double> v;
    if (!ok || n > 100000 || pos + n * sizeof(double) > buf.size()) {
      ok = false;
      return v;
    }
    v.resize(n);
    std::memcpy(v.data(), buf.data() + pos, n * sizeof(double));
    pos += n * sizeof(double);
    return v;
  }
};

}  // namespace railsim::contact::mim_table_detail
