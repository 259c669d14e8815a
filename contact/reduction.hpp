// Reduction factors on Kalker's creep coefficients (C11, C22, C23).
//
// Measured creep curves are often 30-50 % below Kalker's theory
// (contamination, third-body layers, plasticity). Presets:
//   none             (1, 1, 1)            Kalker's theory
//   uniform          (k, k, k)            one factor, given as a number
//   elastic_fe       (0.72, 0.56, 0.56)   Toumi 2016, FE elastic (k23 = k22)
//   elastoplastic_fe (0.63, 0.46, 0.46)   Toumi 2016, FE elasto-plastic R900A
//   third_body       (0.5, 0.5, 0.5)      Toumi 2016, layer h=125 um, G3=820 MPa
// (physics-reference.md section 11.)
//
// One text syntax is shared by every command-line option and YAML key:
//   a preset name, one number (uniform k), or "k11,k22,k23".
// Every factor must lie in (0, 1.5]; values above 1 are allowed for
// sensitivity studies but flagged by callers as non-physical if they wish.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "contact/types.hpp"

namespace railsim::contact {

struct ReductionPreset {
  const char* name;
  ReductionFactors k;
  const char* source;
};

// The named presets (excluding "uniform", which needs a number).
const std::vector<ReductionPreset>& reduction_presets();

// Parse "none" | "elastic_fe" | ... | "0.6" | "0.72,0.56,0.56".
// Throws InputError with `where` (e.g. "--reduction" or "file:line: key 'reduction'")
// prefixed when the text is not understood or a factor is out of (0, 1.5].
ReductionFactors parse_reduction(std::string_view text, const std::string& where);

// Validate factors given one by one; throws InputError naming `where`.
void check_reduction(const ReductionFactors& k, const std::string& where);

// Short text for reports: the preset name when it matches one, else "k11,k22,k23".
std::string describe_reduction(const ReductionFactors& k);

}  // namespace railsim::contact
