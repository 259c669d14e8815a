// Normal-contact models selectable by name: "hertz" (ellipse from the
// curvatures A, B at the touching point; contact/hertz.hpp) and "semi_hertz"
// (STRIPES on the gap profile across the contact plane; semi_hertz.hpp).
// Both return the patch as strips (lateral position q, half-length, peak
// pressure) for strip-wise tangential models, plus an equivalent ellipse
// (a = largest strip half-length, b = area / (pi a), curvatures that give it
// under the same load via hertz_from_semi_axes) for ellipse-based models.
// Units SI. Adding a model: one class and one line in normal_models().
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "contact/geometry/semi_hertz.hpp"
#include "contact/types.hpp"

namespace railsim::contact {

struct NormalProblem {
  double A = 0.0, B = 0.0;  // relative curvatures at the touching point [1/m]
  const GapProfile* gap = nullptr;  // gap across the contact plane (required by semi_hertz)
  double Fn = 0.0;          // normal load [N]
  Material material;
};

struct NormalSolution {
  HertzPatch equivalent;  // equivalent ellipse (A, B, a, b, p0 = p_max, approach, Fz = Fn)
  double area = 0.0;      // [m^2]
  double p_max = 0.0;     // [Pa]
  double approach = 0.0;  // [m]
  int parts = 0;
  std::vector<SemiHertzStrip> strips;
};

class NormalModel {
 public:
  virtual ~NormalModel() = default;
  virtual const char* name() const = 0;
  // Throws InputError for bad input, NumericalError on solver failure.
  virtual void solve(const NormalProblem& problem, NormalSolution& out) = 0;
};

struct NormalModelEntry {
  const char* name;
  const char* description;
  std::unique_ptr<NormalModel> (*make)();
};

const std::vector<NormalModelEntry>& normal_models();
// Unknown names throw InputError listing the known ones.
std::unique_ptr<NormalModel> make_normal_model(std::string_view name);
std::string normal_model_names();

}  // namespace railsim::contact
