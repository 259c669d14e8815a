// Running-safety limit values; see safety_limits.hpp for the sources.
#include "engine/analysis/safety_limits.hpp"

#include <algorithm>
#include <cmath>

namespace railsim::engine {

double nadal_limit(double flange_angle, double mu) {
  const double t = std::tan(flange_angle);
  return (t - mu) / (1.0 + mu * t);
}

double weinstock_limit(double flange_angle, double mu) { return nadal_limit(flange_angle, mu) + mu; }

double prudhomme_limit(double axle_load, double k1) {
  const double P0_kN = axle_load / 1000.0;
  return k1 * (10.0 + P0_kN / 3.0) * 1000.0;
}

const char* vehicle_category_name(VehicleCategory c) {
  switch (c) {
    case VehicleCategory::passenger: return "passenger";
    case VehicleCategory::locomotive: return "locomotive";
    case VehicleCategory::multiple_unit: return "multiple_unit";
    case VehicleCategory::freight: return "freight";
  }
  return "unknown";
}

double track_shift_factor(VehicleCategory c) { return c == VehicleCategory::freight ? 0.85 : 1.0; }

double yq_2m_limit(double radius) { return radius >= 250.0 ? 0.8 : 1.2; }

double qmax_limit(double static_wheel_load, double max_speed) {
  const double v = max_speed * 3.6;  // km/h
  double cap = 160e3;
  if (v <= 160.0) cap = 200e3;
  else if (v <= 200.0) cap = 190e3;
  else if (v <= 250.0) cap = 180e3;
  else if (v <= 300.0) cap = 170e3;
  return std::min(90e3 + static_wheel_load, cap);
}

double instability_sum_y_limit(double axle_load, double k1) { return 0.5 * prudhomme_limit(axle_load, k1); }

double bogie_frame_acceleration_limit(double bogie_mass) { return 0.5 * (12.0 - bogie_mass / 1000.0 / 5.0); }

}  // namespace railsim::engine
