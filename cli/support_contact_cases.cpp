// Contact case files and result rows; see support_contact_cases.hpp.
#include "cli/support_contact_cases.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <set>

#include "contact/hertz.hpp"
#include "contact/reduction.hpp"
#include "core/errors.hpp"

namespace railsim::cli {

namespace {

constexpr double kMaxSpin = 1000.0;  // |phi| [1/m] of a case

contact::ReductionFactors read_reduction(const config::InputNode& node) {
  const std::string where = node.where() + ": key '" + node.path() + "'";
  if (node.is_map()) {
    node.allow_only({"k11", "k22", "k23"});
    contact::ReductionFactors k{node.in_range("k11", 0.0, 1.5, true), node.in_range("k22", 0.0, 1.5, true),
                                node.in_range("k23", 0.0, 1.5, true)};
    contact::check_reduction(k, where);
    return k;
  }
  if (!node.is_scalar())
    node.fail("expected a preset name, one number or k11,k22,k23 (or a map {k11, k22, k23})");
  return contact::parse_reduction(node.as_string(), where);
}

ContactCase read_case(const config::InputNode& n, const contact::Material& material,
                      const contact::ReductionFactors& k) {
  n.allow_only({"id", "A", "B", "a", "b", "Fz", "xi", "eta", "phi", "V"});
  ContactCase c;
  c.id = n.string("id");
  const bool curv = n.has("A") || n.has("B");
  const bool axes = n.has("a") || n.has("b");
  if (curv && axes) n.fail("give either the curvatures A, B [1/m] or the semi-axes a, b [m], not both");
  if (!curv && !axes) n.fail("missing the contact shape: give A, B [1/m] or a, b [m]");
  // A normal load from 1 N to 10 MN (a wheel carries 50-150 kN, a flange-root patch some 500 N; 1e-300 N was
  // taken, as in wheelset-contact's floor of 1 N); semi-axes from 1 um to 1 m.
  const double Fz = n.in_range("Fz", 1.0, 1e7);
  try {
    c.input.patch = curv ? contact::hertz_from_load(n.positive("A"), n.positive("B"), Fz, material)
                         : contact::hertz_from_semi_axes(n.in_range("a", 1e-6, 1.0), n.in_range("b", 1e-6, 1.0), Fz,
                                                         material);
  } catch (const InputError& e) {
    if (std::string(e.what()).find(n.file()) == 0) throw;  // already located
    n.fail(e.what());
  }
  if (curv && !(c.input.patch.a >= 1e-6 && c.input.patch.a <= 1.0 && c.input.patch.b >= 1e-6 && c.input.patch.b <= 1.0)) {
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "the Hertz patch of these curvatures at Fz = %g N has semi-axes a = %.4g m, b = %.4g m, outside "
                  "[1e-06, 1] m",
                  Fz, c.input.patch.a, c.input.patch.b);
    n.at("Fz").fail(buf);
  }
  // Wheel-rail patches lie within a/b 0.05-20; past [0.01, 100] the solvers'
  // grids (elements across the minor axis) grow with the ratio into minutes and gigabytes.
  const double ratio = c.input.patch.a / c.input.patch.b;
  if (!(ratio >= 0.01 && ratio <= 100.0)) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "patch aspect ratio a/b = %.4g outside [0.01, 100] (wheel-rail patches lie within 0.05-20)", ratio);
    n.at(curv ? "A" : "a").fail(buf);
  }
  // Spin [1/m] within +-1000: on a wheel-rail patch sin(contact angle) / rolling radius stays below 4 1/m
  // (flange, 0.28 m wheel) and the yaw-rate term psi'/V is of the same order; 1000 1/m turns the patch
  // through a radian per mm rolled. 1e300 was taken (FASTSIM gave forces, flagged valid).
  c.input.creep = {n.number("xi"), n.number("eta"), n.in_range("phi", -kMaxSpin, kMaxSpin)};
  c.input.material = material;
  c.input.reduction = k;
  if (n.has("V")) c.input.rolling_speed = n.in_range("V", 0.0, 200.0);  // [m/s], as a scenario's speed
  return c;
}

}  // namespace

ContactCaseSet read_contact_cases(const config::InputNode& root) {
  root.allow_only({"material", "reduction", "cases"});
  ContactCaseSet set;
  set.file = root.file();
  const auto m = root.at("material");
  m.allow_only({"E", "nu", "mu"});
  set.material.E = m.in_range("E", 1e9, 1e13);  // [Pa], as wheelset-contact (steel 2.1e11)
  set.material.nu = m.in_range("nu", 0.0, 0.5, true, false);
  // mu > 2 is beyond any dry contact of metals; above 1 it is legal but implausible for wheel on rail.
  set.material.mu = m.in_range("mu", 0.0, 2.0, true);
  if (set.material.mu > 1.0) {
    set.warnings.push_back(m.at("mu").where() + ": key 'material.mu': " + config::format_number(set.material.mu) +
                           " is legal but implausible for wheel on rail (usual range 0.05-0.6; above 1 is beyond "
                           "measured wheel-rail friction)");
    spdlog::warn("{}", set.warnings.back());
  }
  if (const auto r = root.find("reduction")) set.reduction = read_reduction(*r);
  const auto cases = root.at("cases");
  if (!cases.is_sequence() || cases.elements().empty()) cases.fail("expected a non-empty list of cases");
  std::set<std::string> ids;
  for (const auto& n : cases.elements()) {
    ContactCase c = read_case(n, set.material, set.reduction);
    if (!ids.insert(c.id).second) n.at("id").fail("duplicate case id '" + c.id + "'");
    set.cases.push_back(std::move(c));
  }
  return set;
}

ContactCaseSet load_contact_cases(const std::string& path) {
  return read_contact_cases(config::InputNode::load_file(path));
}

void set_reduction(ContactCaseSet& set, const contact::ReductionFactors& k) {
  set.reduction = k;
  for (auto& c : set.cases) c.input.reduction = k;
}

std::vector<std::string> contact_csv_columns() {
  return {"id", "model", "reduction", "A", "B", "a", "b", "p0", "Fz", "xi", "eta", "phi",
          "Fx", "Fy", "Mz", "valid", "reason", "iterations", "time_ns"};
}

void write_contact_row(results::CsvWriter& csv, const ContactCase& c, std::string_view model,
                       const TimedForces& r) {
  const auto& p = c.input.patch;
  const auto& k = c.input.creep;
  csv.cell(c.id).cell(model).cell(contact::describe_reduction(c.input.reduction));
  csv.cell(p.A).cell(p.B).cell(p.a).cell(p.b).cell(p.p0).cell(p.Fz);
  csv.cell(k.xi).cell(k.eta).cell(k.phi);
  csv.cell(r.forces.Fx).cell(r.forces.Fy).cell(r.forces.Mz);
  csv.cell(r.forces.valid).cell(r.forces.reason).cell(r.forces.iterations).cell(r.time_ns);
  csv.end_row();
}

}  // namespace railsim::cli
