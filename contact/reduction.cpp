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
  return s + "one number k (uniform), k11,k22,k23, or layer:h=<m>,G3=<Pa>[,tau_c=<Pa>]";
}

std::string trim(std::string_view v) {
  std::string t(v);
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.pop_back();
  std::size_t i = 0;
  while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i]))) ++i;
  return t.substr(i);
}

bool parse_double(std::string_view s, double& out) {
  std::string str = trim(s);
  if (str.empty()) return false;
  std::size_t used = 0;
  try {
    out = std::stod(str, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == str.size() && std::isfinite(out);
}

std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::vector<std::string> split(const std::string& t, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(t);
  for (std::string item; std::getline(ss, item, sep);) out.push_back(trim(item));
  if (!t.empty() && t.back() == sep) out.emplace_back();
  return out;
}

// "layer:h=125e-6,G3=820e6[,tau_c=...]"
ReductionSpec parse_layer(const std::string& t, const std::string& where) {
  ReductionSpec s;
  s.form = ReductionForm::layer;
  s.text = t;
  s.resolved = false;
  const std::string body = trim(t.substr(t.find(':') + 1));
  const std::string help = " (expected layer:h=<thickness m>,G3=<shear modulus Pa>[,tau_c=<limiting shear stress Pa>], "
                           "e.g. layer:h=125e-6,G3=820e6)";
  bool have_h = false, have_g = false, have_tau = false;
  for (const std::string& item : split(body, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw InputError(where + ": layer parameter '" + item + "' has no value" + help);
    const std::string key = trim(item.substr(0, eq));
    // Each once, as every key of the input files (h=1e-5,G3=1e9,h=2e-5 took the last h without a word).
    if ((key == "h" && have_h) || (key == "G3" && have_g) || (key == "tau_c" && have_tau))
      throw InputError(where + ": layer parameter '" + key + "' given twice; give each once" + help);
    double v = 0.0;
    if (!parse_double(item.substr(eq + 1), v))
      throw InputError(where + ": layer parameter '" + key + "': cannot read '" + trim(item.substr(eq + 1)) + "'" +
                       help);
    if (key == "h") {
      if (!(v > 0.0 && v <= 0.1))
        throw InputError(where + ": layer thickness h expected in (0, 0.1] m (got " + number_text(v) + ")");
      s.layer.h = v;
      have_h = true;
    } else if (key == "G3") {
      if (!(v > 0.0 && v <= 1e12))
        throw InputError(where + ": layer shear modulus G3 expected in (0, 1e12] Pa (got " + number_text(v) + ")");
      s.layer.G3 = v;
      have_g = true;
    } else if (key == "tau_c") {
      if (!(v > 0.0 && v <= 1e11))
        throw InputError(where + ": layer limiting shear stress tau_c expected in (0, 1e11] Pa (got " +
                         number_text(v) + ")");
      s.layer.tau_limit = v;
      have_tau = true;
    } else {
      throw InputError(where + ": unknown layer parameter '" + key + "'" + help);
    }
  }
  if (!have_h || !have_g) throw InputError(where + ": layer needs both h and G3" + help);
  return s;
}

}  // namespace

const char* reduction_form_name(ReductionForm f) {
  switch (f) {
    case ReductionForm::unset: return "unset";
    case ReductionForm::preset: return "preset";
    case ReductionForm::uniform: return "uniform";
    case ReductionForm::factors: return "factors";
    case ReductionForm::layer: return "layer";
  }
  return "unset";
}

void check_reduction(const ReductionFactors& k, const std::string& where) {
  const double v[3] = {k.k11, k.k22, k.k23};
  const char* names[3] = {"k11", "k22", "k23"};
  for (int i = 0; i < 3; ++i)
    if (!(v[i] > 0.0 && v[i] <= 1.5))
      throw InputError(where + ": " + names[i] + " expected a number in (0, 1.5] (got " + number_text(v[i]) + ")");
}

ReductionSpec parse_reduction_spec(std::string_view text, const std::string& where) {
  const std::string t = trim(text);
  if (t.empty()) throw InputError(where + ": empty reduction (expected " + allowed_text() + ")");
  if (t.rfind("layer:", 0) == 0) return parse_layer(t, where);
  ReductionSpec s;
  s.text = t;
  for (const auto& p : reduction_presets())
    if (t == p.name) {
      s.form = ReductionForm::preset;
      s.preset = p.name;
      s.k = p.k;
      return s;
    }
  std::string body = t;
  if (body.size() >= 2 && ((body.front() == '(' && body.back() == ')') || (body.front() == '[' && body.back() == ']')))
    body = trim(body.substr(1, body.size() - 2));
  if (body.find(',') == std::string::npos) {
    double v = 0;
    if (!parse_double(body, v))
      throw InputError(where + ": unknown reduction '" + t + "' (expected " + allowed_text() + ")");
    s.form = ReductionForm::uniform;
    s.k = {v, v, v};
  } else {
    std::vector<double> vals;
    for (const std::string& item : split(body, ',')) {
      double v = 0;
      if (!parse_double(item, v))
        throw InputError(where + ": cannot read '" + item + "' in reduction '" + t + "' (expected " +
                         allowed_text() + ")");
      vals.push_back(v);
    }
    if (vals.size() != 3)
      throw InputError(where + ": reduction '" + t + "' has " + std::to_string(vals.size()) +
                       " factors (expected three: k11,k22,k23)");
    s.form = ReductionForm::factors;
    s.k = {vals[0], vals[1], vals[2]};
  }
  check_reduction(s.k, where);
  return s;
}

std::vector<ReductionSpec> parse_reduction_list(std::string_view text, const std::string& where) {
  const std::string t = trim(text);
  std::vector<std::string> entries;
  if (t.find(';') != std::string::npos) {
    entries = split(t, ';');
  } else {
    // Comma list: brackets group a triple; "name=value" items after a layer belong to it.
    int depth = 0;
    std::string cur;
    std::vector<std::string> raw;
    for (char c : t) {
      if (c == '(' || c == '[') ++depth;
      if (c == ')' || c == ']') --depth;
      if (c == ',' && depth == 0) {
        raw.push_back(trim(cur));
        cur.clear();
      } else {
        cur += c;
      }
    }
    raw.push_back(trim(cur));
    for (const std::string& item : raw) {
      const bool parameter = item.find('=') != std::string::npos && item.rfind("layer:", 0) != 0;
      if (parameter && !entries.empty() && entries.back().rfind("layer:", 0) == 0)
        entries.back() += "," + item;
      else
        entries.push_back(item);
    }
  }
  std::vector<ReductionSpec> out;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (entries[i].empty())
      throw InputError(where + ": entry " + std::to_string(i + 1) + " of '" + t + "' is empty");
    out.push_back(parse_reduction_spec(entries[i], where + " entry " + std::to_string(i + 1)));
  }
  if (out.empty()) throw InputError(where + ": no entries (expected a list such as 1,0.8,0.6,elastic_fe)");
  // An entry twice would run twice (into one folder): the same factors, or the same text.
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const bool same_factors = out[i].resolved && out[j].resolved && out[i].form == out[j].form &&
                                out[i].form != ReductionForm::layer && out[i].k.k11 == out[j].k.k11 &&
                                out[i].k.k22 == out[j].k.k22 && out[i].k.k23 == out[j].k.k23;
      if (same_factors || out[i].text == out[j].text)
        throw InputError(where + ": entry " + std::to_string(i + 1) + " ('" + out[i].text + "') repeats entry " +
                         std::to_string(j + 1) + " ('" + out[j].text + "')");
    }
  return out;
}

ReductionFactors parse_reduction(std::string_view text, const std::string& where) {
  const ReductionSpec s = parse_reduction_spec(text, where);
  if (s.form == ReductionForm::layer)
    throw InputError(where + ": a third-body layer ('" + s.text +
                     "') needs the contact patch of a scenario; it is accepted by scenarios and critical-speed only");
  return s.k;
}

std::string describe_reduction(const ReductionFactors& k) {
  char buf[96];
  if (k.k11 == k.k22 && k.k22 == k.k23)
    std::snprintf(buf, sizeof buf, "uniform %g", k.k11);
  else
    std::snprintf(buf, sizeof buf, "%g,%g,%g", k.k11, k.k22, k.k23);
  return buf;
}

std::string describe_layer(const mim::ThirdBodyLayer& l) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "h=%g um, G3=%g MPa", l.h * 1e6, l.G3 * 1e-6);
  std::string s = buf;
  if (l.tau_limit > 0.0) {
    std::snprintf(buf, sizeof buf, ", tau_c=%g MPa", l.tau_limit * 1e-6);
    s += buf;
  }
  return s;
}

std::string reduction_label(const ReductionSpec& s) {
  switch (s.form) {
    case ReductionForm::preset: return s.preset;
    case ReductionForm::layer: return "layer " + describe_layer(s.layer);
    default: return describe_reduction(s.k);
  }
}

}  // namespace railsim::contact
