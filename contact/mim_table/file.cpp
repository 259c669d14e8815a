// The MIM table's binary file: writing (atomically, core/atomic_file.hpp) and
// loading with every check of mim_table.hpp (magic, format version, content
// hash, solver id, parameters); layout in mim_table.hpp.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "contact/mim_table/mim_table.hpp"
#include "contact/mim_table/bytes.hpp"
#include "core/atomic_file.hpp"
#include "core/content_hash.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

using mim_table_detail::Bytes;
using mim_table_detail::kMagic;
using mim_table_detail::Reader;

void MimTable::save(const std::string& path) const {
  Bytes b;
  b.buf.append(kMagic, sizeof kMagic);
  b.put(kMimTableFormatVersion);
  const std::string id = kMimTableSolverId;
  b.put(static_cast<std::uint32_t>(id.size()));
  b.buf += id;
  b.put(spec_.nu);
  b.put(static_cast<std::int32_t>(spec_.grid));
  b.put(spec_.tolerance);
  b.put_vec(spec_.aob);
  b.put_vec(spec_.uxi);
  b.put_vec(spec_.ueta);
  b.put_vec(spec_.vpsi);
  b.put(static_cast<std::uint64_t>(values_.size()));
  b.buf.append(reinterpret_cast<const char*>(values_.data()), values_.size() * sizeof(double));
  b.put(fnv1a(b.buf.data(), b.buf.size()));
  try {
    write_file_atomically(path, b.buf);
  } catch (const InputError& e) {
    throw InputError(std::string("mim_table: ") + e.what());
  }
}

std::unique_ptr<MimTable> MimTable::load(const std::string& path, const MimTableSpec& expected) {
  const auto refuse = [&](const std::string& why) -> std::unique_ptr<MimTable> {
    throw InputError("mim_table: table file '" + path + "' " + why);
  };
  if (!std::filesystem::exists(path)) return refuse("does not exist");
  const std::string buf = read_own_file(path);
  if (buf.size() < sizeof kMagic + sizeof(std::uint64_t) || std::memcmp(buf.data(), kMagic, sizeof kMagic) != 0)
    return refuse("is not a railsim MIM table (bad magic or empty)");
  std::uint64_t stored = 0;
  std::memcpy(&stored, buf.data() + buf.size() - sizeof stored, sizeof stored);
  Reader r{buf, sizeof kMagic};
  const auto version = r.get<std::uint32_t>();
  if (r.ok && version != kMimTableFormatVersion)
    return refuse("has format version " + std::to_string(version) + ", expected " +
                  std::to_string(kMimTableFormatVersion));
  if (stored != fnv1a(buf.data(), buf.size() - sizeof stored))
    return refuse("is truncated or corrupt (content hash mismatch)");
  const auto idlen = r.get<std::uint32_t>();
  std::string id;
  if (r.ok && idlen < 1000 && r.pos + idlen <= buf.size()) {
    id.assign(buf.data() + r.pos, idlen);
    r.pos += idlen;
  } else {
    r.ok = false;
  }
  auto t = std::make_unique<MimTable>();
  MimTableSpec& s = t->spec_;
  s.nu = r.get<double>();
  s.grid = r.get<std::int32_t>();
  s.tolerance = r.get<double>();
  s.aob = r.get_vec();
  s.uxi = r.get_vec();
  s.ueta = r.get_vec();
  s.vpsi = r.get_vec();
  const auto nvals = r.get<std::uint64_t>();
  if (!r.ok || nvals != 3 * s.size() || r.pos + nvals * sizeof(double) + sizeof stored != buf.size())
    return refuse("is truncated or malformed");
  if (id != kMimTableSolverId) return refuse("was built by solver '" + id + "', expected '" + kMimTableSolverId + "'");
  if (std::abs(s.nu - expected.nu) > 1e-12)
    return refuse("was built for Poisson's ratio " + std::to_string(s.nu) + ", expected " + std::to_string(expected.nu));
  if (s.grid != expected.grid || s.tolerance != expected.tolerance || s.aob != expected.aob ||
      s.uxi != expected.uxi || s.ueta != expected.ueta || s.vpsi != expected.vpsi)
    return refuse("was built with other grid, tolerance or table nodes");
  t->values_.resize(nvals);
  std::memcpy(t->values_.data(), buf.data() + r.pos, nvals * sizeof(double));
  for (double v : s.aob) t->lnaob_.push_back(std::log(v));
  return t;
}

}  // namespace railsim::contact
