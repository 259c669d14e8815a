// Loading a Track from YAML; see track_file.hpp for the format.
#include "track/track_file.hpp"

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "core/errors.hpp"
#include "track/circular_curve.hpp"
#include "track/clothoid.hpp"
#include "track/irregularity_registry.hpp"
#include "track/straight.hpp"

namespace railsim::track {

namespace {

constexpr double kPi = 3.14159265358979323846;
using config::format_number;
using config::InputNode;

// Re-throw an InputError raised while reading one list item with the item
// named after "file:line: ", e.g. "f.yaml:7: segments[2] (clothoid): key 'length': ...".
// "file:line: what" -> "file:line: label: what" (else "label: what").
std::string with_label(const std::string& msg, const std::string& file, const std::string& label) {
  const std::string head = file + ":";
  if (msg.rfind(head, 0) == 0) {
    std::size_t p = head.size();
    while (p < msg.size() && std::isdigit(static_cast<unsigned char>(msg[p]))) ++p;
    if (msg.compare(p, 2, ": ") == 0) {
      p += 2;
      return msg.substr(0, p) + label + ": " + msg.substr(p);
    }
  }
  return label + ": " + msg;
}

[[noreturn]] void rethrow_with_label(const InputError& e, const std::string& file, const std::string& label) {
  throw InputError(with_label(e.what(), file, label));
}

// A segment as written in the file; clothoid ends are resolved afterwards.
struct SegmentSpec {
  std::string kind;
  double length = 0.0;
  double kappa = 0.0;  // straight, circular
  double cant = 0.0;   // E [m], straight, circular
  TransitionShape shape = TransitionShape::linear;
  int line = 0;
  std::string label;
};

SegmentSpec parse_segment(const InputNode& n, const std::string& label) {
  SegmentSpec s;
  s.line = n.line();
  s.label = label;
  if (!n.is_map()) n.fail("expected a mapping with a 'type' key (got " + n.text() + ")");
  const std::string type = n.at("type").as_string();
  if (type == "straight") {
    n.allow_only({"type", "length"});
    s.kind = type;
    s.length = n.positive("length");
  } else if (type == "circular") {
    n.allow_only({"type", "length", "radius", "direction", "cant_mm"});
    s.kind = type;
    s.length = n.positive("length");
    const InputNode r = n.at("radius");
    const double radius = r.as_positive();
    if (radius < 10.0) r.fail("radius must be at least 10 m (got " + r.text() + ")");
    const InputNode d = n.at("direction");
    const std::string dir = d.as_string();
    double sign = 1.0;
    if (dir == "left") sign = 1.0;
    else if (dir == "right") sign = -1.0;
    else d.fail("expected one of: left, right (got '" + dir + "')");
    s.kappa = sign / radius;
    // The outer rail is raised: E = z_right - z_left has the sign of kappa.
    const double cant_mm = n.has("cant_mm") ? n.at("cant_mm").as_in_range(0.0, 250.0) : 0.0;
    s.cant = sign * cant_mm * 1e-3;
  } else if (type == "clothoid") {
    n.allow_only({"type", "length", "shape"});
    s.kind = type;
    s.length = n.positive("length");
    if (auto sh = n.find("shape")) {
      const std::string v = sh->as_string();
      if (v == "linear") s.shape = TransitionShape::linear;
      else if (v == "bloss") s.shape = TransitionShape::bloss;
      else if (v == "cosine") s.shape = TransitionShape::cosine;
      else sh->fail("expected one of: linear, bloss, cosine (got '" + v + "')");
    }
  } else {
    n.at("type").fail("unknown segment type '" + type + "' (allowed: straight, clothoid, circular)");
  }
  return s;
}

// Largest |x|, |y| of the track's start pose [m] (10,000 km).
constexpr double kMaxStartCoordinate = 1e7;

// Steepest cant ramp accepted along a clothoid [m/m].
constexpr double kMaxCantGradient = 0.02;

std::vector<std::unique_ptr<Segment>> build_segments(const InputNode& list, const std::string& file) {
  std::vector<SegmentSpec> specs;
  const auto items = list.elements();
  if (items.empty()) list.fail("expected at least one segment");
  for (std::size_t i = 0; i < items.size(); ++i) {
    // A fresh node with an empty key path so that messages read "key 'length'".
    const InputNode n(items[i].raw(), file, "");
    std::string label = items[i].path();  // "segments[2]", or "track.segments[2]" when embedded
    try {
      if (n.is_map() && n.has("type") && n.raw()["type"].IsScalar())
        label += " (" + n.raw()["type"].Scalar() + ")";
      specs.push_back(parse_segment(n, label));
    } catch (const InputError& e) {
      rethrow_with_label(e, file, label);
    }
  }
  auto fail_at = [&](const SegmentSpec& s, const std::string& what) -> void {
    throw InputError(file + ":" + std::to_string(s.line) + ": " + s.label + ": " + what);
  };
  std::vector<std::unique_ptr<Segment>> out;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const SegmentSpec& s = specs[i];
    if (s.kind == "clothoid") {
      const SegmentSpec* prev = i > 0 ? &specs[i - 1] : nullptr;
      const SegmentSpec* next = i + 1 < specs.size() ? &specs[i + 1] : nullptr;
      if ((prev && prev->kind == "clothoid") || (next && next->kind == "clothoid"))
        fail_at(s, "a clothoid takes its end curvature and cant from its neighbours, so two clothoids cannot be "
                   "adjacent; put a straight or circular segment between them");
      const double k0 = prev ? prev->kappa : 0.0, E0 = prev ? prev->cant : 0.0;
      const double k1 = next ? next->kappa : 0.0, E1 = next ? next->cant : 0.0;
      // A transition shorter than a wheelbase, or a cant ramp far steeper
      // than track standards allow, was a step in disguise (0.5 m from 0 to
      // 150 mm: the run failed with a wheel load of 1e10 N).
      if (s.length < 1.0)
        fail_at(s, "key 'length': a clothoid of " + format_number(s.length) + " m: at least 1 m (transitions are "
                   "tens of metres long)");
      const double gradient = std::abs(E1 - E0) / s.length;  // [m/m]
      if (gradient > kMaxCantGradient)
        fail_at(s, "key 'length': the cant changes by " + format_number(std::abs(E1 - E0) * 1e3) + " mm over " +
                       format_number(s.length) + " m (" + format_number(gradient * 1e3) + " mm/m): at most " +
                       format_number(kMaxCantGradient * 1e3) + " mm/m, about ten times what line standards allow "
                       "(EN 13803: 2.25-2.5 mm/m); give a clothoid of at least " +
                       format_number(std::abs(E1 - E0) / kMaxCantGradient) + " m");
      out.push_back(std::make_unique<Clothoid>(s.length, k0, k1, E0, E1, s.shape));
      continue;
    }
    if (i > 0 && specs[i - 1].kind != "clothoid") {
      const SegmentSpec& p = specs[i - 1];
      if (std::abs(p.kappa - s.kappa) > 1e-12 || std::abs(p.cant - s.cant) > 1e-9)
        fail_at(s, "starts with curvature " + format_number(s.kappa) + " 1/m and cant " +
                       format_number(std::abs(s.cant) * 1e3) + " mm but " + p.label + " ends with " +
                       format_number(p.kappa) + " 1/m and " + format_number(std::abs(p.cant) * 1e3) +
                       " mm; insert a clothoid between them");
    }
    if (s.kind == "straight")
      out.push_back(std::make_unique<Straight>(s.length));
    else
      out.push_back(std::make_unique<CircularCurve>(s.length, s.kappa, s.cant));
  }
  return out;
}

}  // namespace

Track load_track(const std::string& path) {
  const InputNode root = InputNode::load_file(path);
  const std::filesystem::path p(path);
  return load_track(root, p.parent_path().string(), p.stem().string());
}

Track load_track(const InputNode& root, const std::string& base_dir, const std::string& default_name) {
  root.allow_only({"name", "description", "rail_spacing", "gauge", "start", "segments", "irregularities"});
  const std::string name = root.string_or("name", default_name);
  const double rail_spacing = root.has("rail_spacing") ? root.at("rail_spacing").as_in_range(0.5, 2.5) : 1.5;
  const double gauge = root.has("gauge") ? root.at("gauge").as_in_range(0.5, 2.0) : 1.435;
  // The gauge (between the rails' running edges) lies inside the distance of
  // the rail centres, by about a rail head's width (1.435 / 1.5 m standard).
  if (!(gauge < rail_spacing)) {
    const InputNode& at = root.has("gauge") ? root.at("gauge") : root.at("rail_spacing");
    at.fail("gauge " + format_number(gauge) + " m is not smaller than rail_spacing " + format_number(rail_spacing) +
            " m" + (root.has("rail_spacing") ? "" : " (the default)") +
            ": rail_spacing is the distance of the rail centres, about the gauge plus a rail head's width "
            "(1.5 m for the standard gauge 1.435 m); give both");
  }
  Pose start;
  if (auto st = root.find("start")) {
    st->allow_only({"x", "y", "heading_deg"});
    // Within 10,000 km and one turn either way: x = 1e300 m wrote x = 1e300 on every row (the
    // track's metres lost in the rounding) and heading_deg = 1e20 an arbitrary direction, exit 0.
    start.x = st->has("x") ? st->in_range("x", -kMaxStartCoordinate, kMaxStartCoordinate) : 0.0;
    start.y = st->has("y") ? st->in_range("y", -kMaxStartCoordinate, kMaxStartCoordinate) : 0.0;
    start.heading = (st->has("heading_deg") ? st->in_range("heading_deg", -360.0, 360.0) : 0.0) * kPi / 180.0;
  }
  Alignment alignment(build_segments(root.at("segments"), root.file()), rail_spacing, start);

  IrregularitySet irregularities;
  std::vector<std::string> warnings;
  if (auto irr = root.find("irregularities")) {
    std::vector<std::string> item_warnings;
    IrregularityContext ctx;
    ctx.track_length = alignment.length();
    ctx.rail_spacing = rail_spacing;
    ctx.base_dir = base_dir;
    ctx.warnings = &item_warnings;
    const auto items = irr->elements();
    for (std::size_t i = 0; i < items.size(); ++i) {
      const InputNode n(items[i].raw(), root.file(), "");
      std::string label = items[i].path();
      try {
        if (!n.is_map()) n.fail("expected a mapping with a 'type' key (got " + n.text() + ")");
        const InputNode type = n.at("type");
        const std::string t = type.as_string();
        label += " (" + t + ")";
        const IrregularityGeneratorEntry* gen = find_irregularity_generator(t);
        if (!gen)
          type.fail("unknown irregularity type '" + t + "' (known: " + irregularity_generator_names() + ")");
        irregularities.add(gen->parse(n, ctx));
      } catch (const InputError& e) {
        rethrow_with_label(e, root.file(), label);
      }
      for (const std::string& w : item_warnings) warnings.push_back(with_label(w, root.file(), label));
      item_warnings.clear();
    }
  }
  return Track(name, std::move(alignment), std::move(irregularities), gauge, root.has("gauge"), std::move(warnings));
}

}  // namespace railsim::track
