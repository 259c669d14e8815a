// Reduction factors on Kalker's creep coefficients; see reduction.hpp.
#include "contact/reduction.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/errors.hpp"

namespace railsim::contact {

const std::vector<ReductionPreset>& reduction_presets() {
  static const std::vector<ReductionPreset> presets = {
      {"none", {1.0, 1.0, 1.0}, "Kalker's theory, no reduction"},
      {"elastic_fe", {0.72, 0.56, 0.56}, "Toumi 2016, finite elements, elastic (k23 = k22)"},
      {"elastoplastic_fe", {0.63, 0.46, 0.46}, "Toumi 2016, finite elements, elasto-plastic R900A"},
      {"third_body", {0.5, 0.5, 0.5}, "Toumi 2016, third-body layer h = 125 um, G3 = 820 MPa"},
  };
  return presets;
}

namespace {

std::string allowed_text() {
  std::string s;
  for (const auto& p : reduction_presets()) s += std::string(p.name) + ", ";
  return s + "one number k (uniform), or k11,k22,k23";
}

bool parse_double(std::string_view s, double& out) {
  std::string str(s);
  std::size_t used = 0;
  try {
    out = std::stod(str, &used);
  } catch (const std::exception&) {
    return false;
  }
  while (used < str.size() && std::isspace(static_cast<unsigned char>(str[used]))) ++used;
  return used == str.size() && std::isfinite(out);
}

}  // namespace

void check_reduction(const ReductionFactors& k, const std::string& where) {
  const double v[3] = {k.k11, k.k22, k.k23};
  const char* names[3] = {"k11", "k22", "k23"};
  for (int i = 0; i < 3; ++i)
    if (!(v[i] > 0.0 && v[i] <= 1.5)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%g", v[i]);
      throw InputError(where + ": " + names[i] + " expected a number in (0, 1.5] (got " + buf + ")");
    }
}

ReductionFactors parse_reduction(std::string_view text, const std::string& where) {
  std::string t(text);
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.erase(t.begin());
  for (const auto& p : reduction_presets())
    if (t == p.name) return p.k;
  ReductionFactors k;
  if (t.find(',') == std::string::npos) {
    double v = 0;
    if (!parse_double(t, v))
      throw InputError(where + ": unknown reduction '" + t + "' (expected " + allowed_text() + ")");
    k = {v, v, v};
  } else {
    std::vector<double> vals;
    std::stringstream ss(t);
    std::string item;
    while (std::getline(ss, item, ',')) {
      double v = 0;
      if (!parse_double(item, v))
        throw InputError(where + ": cannot read '" + item + "' in reduction '" + t + "' (expected " +
                         allowed_text() + ")");
      vals.push_back(v);
    }
    if (vals.size() != 3)
      throw InputError(where + ": reduction '" + t + "' has " + std::to_string(vals.size()) +
                       " factors (expected three: k11,k22,k23)");
    k = {vals[0], vals[1], vals[2]};
  }
  check_reduction(k, where);
  return k;
}

std::string describe_reduction(const ReductionFactors& k) {
  for (const auto& p : reduction_presets())
    if (p.k.k11 == k.k11 && p.k.k22 == k.k22 && p.k.k23 == k.k23) return p.name;
  char buf[96];
  if (k.k11 == k.k22 && k.k22 == k.k23)
    std::snprintf(buf, sizeof buf, "uniform %g", k.k11);
  else
    std::snprintf(buf, sizeof buf, "%g,%g,%g", k.k11, k.k22, k.k23);
  return buf;
}

}  // namespace railsim::contact
