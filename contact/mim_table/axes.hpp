// The MIM table's axis maps (mim_table.hpp): u(s) = s / (1 + s) for the
// creepages xi', e' >= 0 and v(s) = s / (1 + |s|) for the spin psi', and their
// inverses, shared by the build (nodes -> creepages) and the lookup
// (creepages -> axis coordinates). Internal to contact/.
#pragma once

#include <cmath>

namespace railsim::contact::mim_table_detail {

inline double u_of(double s) { return s / (1.0 + s); }
inline double v_of(double s) { return s / (1.0 + std::abs(s)); }
inline double s_of_u(double u) { return u / (1.0 - u); }
inline double s_of_v(double v) { return v / (1.0 - std::abs(v)); }

}  // namespace railsim::contact::mim_table_detail
