// Normal-model registry: hertz and semi_hertz (see normal_model.hpp).
#include "contact/geometry/normal_model.hpp"

#include <algorithm>
#include <cmath>

#include "contact/hertz.hpp"
#include "core/errors.hpp"

namespace railsim::contact {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kHertzStrips = 41;

class HertzNormal final : public NormalModel {
 public:
  const char* name() const override { return "hertz"; }
  void solve(const NormalProblem& p, NormalSolution& out) override {
    const HertzPatch h = hertz_from_load(p.A, p.B, p.Fn, p.material);
    out.equivalent = h;
    out.area = kPi * h.a * h.b;
    out.p_max = h.p0;
    out.approach = h.approach;
    out.parts = 1;
    out.strips.resize(kHertzStrips);
    for (int j = 0; j < kHertzStrips; ++j) {
      const double q = h.b * (-1.0 + (2.0 * j + 1.0) / kHertzStrips);
      const double f = std::sqrt(std::max(0.0, 1.0 - q * q / (h.b * h.b)));
      out.strips[static_cast<std::size_t>(j)] = {q, h.a * f, h.p0 * f};
    }
  }
};

class SemiHertzNormal final : public NormalModel {
 public:
  const char* name() const override { return "semi_hertz"; }
  void solve(const NormalProblem& p, NormalSolution& out) override {
    if (p.gap == nullptr) throw InputError("normal model 'semi_hertz' needs the gap profile across the contact");
    SemiHertzResult r = semi_hertz_from_load(*p.gap, p.Fn, p.material, ws_);
    out.area = r.area;
    out.p_max = r.p_max;
    out.approach = r.approach;
    out.parts = r.parts;
    out.strips = std::move(r.strips);
    const double a = 0.5 * r.length;
    const double b = r.area / (kPi * a);
    out.equivalent = hertz_from_semi_axes(a, b, p.Fn, p.material);
    out.equivalent.p0 = r.p_max;
    out.equivalent.approach = r.approach;
  }

 private:
  SemiHertzWorkspace ws_;
};
}  // namespace

const std::vector<NormalModelEntry>& normal_models() {
  static const std::vector<NormalModelEntry> list = {
      {"hertz", "Hertz ellipse from the curvatures at the contact point",
       [] { return std::unique_ptr<NormalModel>(new HertzNormal); }},
      {"semi_hertz", "STRIPES semi-Hertzian patch (Ayasse & Chollet 2005) from the profile gap",
       [] { return std::unique_ptr<NormalModel>(new SemiHertzNormal); }},
  };
  return list;
}

std::string normal_model_names() {
  std::string s;
  for (const auto& e : normal_models()) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

std::unique_ptr<NormalModel> make_normal_model(std::string_view name) {
  for (const auto& e : normal_models())
    if (name == e.name) return e.make();
  throw InputError("unknown normal contact model '" + std::string(name) + "' (known: " + normal_model_names() + ")");
}

}  // namespace railsim::contact
