// Reduction factors on Kalker's creep coefficients (C11, C22, C23).
//
// Measured creep curves are often 30-50 % below Kalker's theory
// (contamination, third-body layers, plasticity). Presets:
//   none             (1, 1, 1)            Kalker's theory
//   elastic_fe       (0.72, 0.56, 0.56)   Toumi 2016, FE elastic (k23 = k22)
//   elastoplastic_fe (0.63, 0.46, 0.46)   Toumi 2016, FE elasto-plastic R900A
//   third_body       (0.5, 0.5, 0.5)      Toumi 2016, layer h=125 um, G3=820 MPa
// (physics-reference.md section 11.)
//
// One text syntax is shared by every command-line option and YAML key:
//   a preset name, one number (uniform k), "k11,k22,k23", or a third-body
//   layer "layer:h=125e-6,G3=820e6[,tau_c=300e6]" (h in m, G3 and tau_c in Pa)
//   whose factors the exact solver computes for the scenario's own contact
//   patch (contact/mim/third_body.hpp); a layer cannot be used before that.
// Every factor must lie in (0, 1.5]; values above 1 are allowed for
// sensitivity studies but flagged by callers as non-physical if they wish.
//
// Naming rule for reports: a preset name is shown only when the user chose
// the preset (ReductionSpec keeps the form the user gave); factors alone are
// always described by their numbers (describe_reduction), so a uniform 0.5
// is "uniform 0.5", never "third_body".
//
// Lists (`critical-speed --reductions`): entries separated by ';', or by ','
// when the list has no ';'. In a comma list a triple is written in brackets
// "(0.72,0.56,0.56)" and a layer's parameters stay with the layer (every
// "name=value" item after "layer:" belongs to it), e.g.
//   1,0.9,0.5,elastic_fe,(0.72,0.5,0.5),layer:h=125e-6,G3=820e6
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "contact/mim/third_body.hpp"
#include "contact/types.hpp"

namespace railsim::contact {

struct ReductionPreset {
  const char* name;
  ReductionFactors k;
  const char* source;
};

// The named presets (excluding "uniform", which needs a number).
const std::vector<ReductionPreset>& reduction_presets();

// How the user gave the factors.
enum class ReductionForm {
  unset,    // nothing given: Kalker's theory (k = 1)
  preset,   // a preset name
  uniform,  // one number
  factors,  // k11,k22,k23
  layer,    // a third-body layer: factors computed by the exact solver
};

struct ReductionSpec {
  ReductionForm form = ReductionForm::unset;
  std::string text;            // as given (trimmed); empty when unset
  std::string preset;          // preset name (form preset)
  ReductionFactors k;          // the factors; for a layer once resolved
  mim::ThirdBodyLayer layer;   // form layer: h [m], G3 [Pa], tau_limit [Pa] (0: none)
  bool resolved = true;        // false for a layer until its factors are computed
};

// Parse one entry (see the syntax above). Throws InputError with `where`
// (e.g. "--reduction" or "file:line: key 'reduction'") prefixed when the text
// is not understood or a value is out of range.
ReductionSpec parse_reduction_spec(std::string_view text, const std::string& where);

// Parse a list of entries (see "Lists" above); at least one entry.
std::vector<ReductionSpec> parse_reduction_list(std::string_view text, const std::string& where);

// Parse factors only: a preset, one number or "k11,k22,k23" (a layer throws
// InputError: its factors need a contact patch).
ReductionFactors parse_reduction(std::string_view text, const std::string& where);

// Validate factors given one by one; throws InputError naming `where`.
void check_reduction(const ReductionFactors& k, const std::string& where);

// Factors by their numbers: "uniform 0.5" when all three are equal, else
// "0.72,0.56,0.56" (never a preset name).
std::string describe_reduction(const ReductionFactors& k);

// Label of an entry for reports and legends: the preset name when the user
// chose one ("elastic_fe"), "uniform 0.5", "0.72,0.56,0.56", or for a layer
// "layer h=125 um, G3=820 MPa[, tau_c=...]"; unset: describe_reduction(k).
std::string reduction_label(const ReductionSpec& s);

// Short text of a layer's parameters ("h=125 um, G3=820 MPa, tau_c=300 MPa").
std::string describe_layer(const mim::ThirdBodyLayer& layer);

// The form's name ("preset", "uniform", "factors", "layer", "unset").
const char* reduction_form_name(ReductionForm f);

}  // namespace railsim::contact
