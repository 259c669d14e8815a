// MIM table parameters: the standard table, the check of its axes and the
// parameter hash that names the cache file (64-bit FNV-1a, core/content_hash.hpp,
// of the axes, nu, grid, tolerance, format version and solver id: the same
// bytes as before the split, so existing cache files keep their names);
// see mim_table.hpp.
#include <string>
#include <vector>

#include "contact/mim_table/mim_table.hpp"
#include "contact/mim_table/bytes.hpp"
#include "core/content_hash.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {

std::vector<double> uniform(double lo, double hi, int n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / (n - 1);
  return v;
}

bool ascending(const std::vector<double>& v) {
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!(v[i] > v[i - 1])) return false;
  return true;
}

}  // namespace

MimTableSpec MimTableSpec::standard() {
  MimTableSpec s;
  s.aob = {0.2, 0.3, 0.45, 0.7, 1.0, 1.4, 2.2, 3.3, 5.0};
  s.uxi = uniform(0.0, 0.9, 13);  // xi' up to 9 (far into full slip)
  s.ueta = uniform(0.0, 0.9, 13);
  s.vpsi = uniform(-0.9, 0.9, 37);
  s.grid = 28;  // FFT sizes 64 x (64 ... 320): fast; MIM within about 1 % of mu N of grid 60
  return s;
}

void MimTableSpec::check() const {
  const auto bad = [](const std::string& m) { throw InputError("mim_table: " + m); };
  if (aob.empty() || uxi.empty() || ueta.empty() || vpsi.empty()) bad("every table axis needs at least one node");
  if (!ascending(aob) || !ascending(uxi) || !ascending(ueta) || !ascending(vpsi)) bad("axis nodes must ascend");
  if (aob.front() <= 0.0) bad("a/b nodes must be positive");
  if (uxi.front() != 0.0 || ueta.front() != 0.0 || uxi.back() >= 1.0 || ueta.back() >= 1.0)
    bad("u(xi'), u(eta') nodes must start at 0 and stay below 1");
  if (vpsi.front() <= -1.0 || vpsi.back() >= 1.0) bad("v(psi') nodes must lie in (-1, 1)");
  if (!(nu > 0.0 && nu <= 0.5)) bad("nu must lie in (0, 0.5]");
  if (grid < 4 || grid > 4000) bad("grid must lie in [4, 4000]");
  if (!(tolerance > 0.0 && tolerance <= 0.1)) bad("tolerance must lie in (0, 0.1]");
}

std::uint64_t MimTableSpec::hash() const {
  mim_table_detail::Bytes b;
  b.put_vec(aob);
  b.put_vec(uxi);
  b.put_vec(ueta);
  b.put_vec(vpsi);
  b.put(nu);
  b.put(grid);
  b.put(tolerance);
  b.put(kMimTableFormatVersion);
  b.buf += kMimTableSolverId;
  return fnv1a(b.buf.data(), b.buf.size());
}

}  // namespace railsim::contact
