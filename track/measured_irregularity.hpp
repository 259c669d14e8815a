// Measured track irregularities read from a CSV file.
//
// File format: optional '#' comment lines, a header line, then one row per
// measuring point:
//   s,lateral,vertical,cross_level,gauge
//   0.00,0.12,-0.40,0.05,0.30
// `s` (distance along the track [m]) is required and must strictly increase;
// the other columns are any of the four channels (irregularity.hpp, signs
// there), in mm (units: mm, the default) or m (units: m). Unknown columns,
// missing columns, ragged rows, non-numbers and unsorted distances are errors
// naming the file and line (InputError). At least 4 rows.
// Between points each channel is interpolated by a monotone piecewise cubic
// Hermite interpolant (PCHIP, Fritsch-Carlson 1980; Boost.Math), which does
// not overshoot the measured values and gives a continuous slope. Outside the
// measured range the component is zero; an optional taper (quintic smooth-step
// over `taper` metres at each end) removes the jump there.
// Placed on a track (offset), a record wholly off the track is refused; one
// reaching beyond it by more than 10 % of the track's length (and 1 m) is
// accepted with a warning naming the file and both ranges (Track::warnings);
// one whose distances are clearly in mm (rows 10 m or more apart, reaching
// more than 10 track lengths past the end) is refused.
#pragma once

// Boost 1.74 pchip.hpp calls an unqualified isnan(): <math.h> puts it in the global namespace.
#include <math.h>  // NOLINT(modernize-deprecated-headers)

#include <boost/math/interpolators/pchip.hpp>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/yaml_input.hpp"
#include "track/irregularity.hpp"
#include "track/irregularity_registry.hpp"

namespace railsim::track {

// Raw table of a measured file (SI: metres).
struct MeasuredTable {
  std::string file;
  std::vector<double> s;
  std::array<std::optional<std::vector<double>>, kChannelCount> channels;  // present channels only
};

// Read and check a measured-irregularity CSV. `unit` converts the channel
// columns to metres (1e-3 for mm). Throws InputError "file:line: ...".
MeasuredTable read_measured_irregularity(const std::string& path, double unit = 1e-3);

class MeasuredIrregularity final : public IrregularityComponent {
 public:
  // `offset` shifts the file's distances onto the track (s_track = s_file + offset).
  MeasuredIrregularity(MeasuredTable table, double offset = 0.0, double taper = 0.0, double scale = 1.0);
  void add_to(double s, IrregularityState& out) const override;
  double s_begin() const override { return s_begin_; }
  double s_end() const override { return s_end_; }
  std::string describe() const override;
  // The file read (as resolved against the track file's folder).
  std::vector<std::string> input_files() const override { return {file_}; }

 private:
  using Spline = boost::math::interpolators::pchip<std::vector<double>>;
  std::string file_;
  std::array<std::optional<Spline>, kChannelCount> splines_;
  double offset_, taper_, scale_;
  double s_begin_ = 0.0, s_end_ = 0.0;
  std::size_t rows_ = 0;
};

// Registry parser ("measured").
std::unique_ptr<IrregularityComponent> parse_measured_irregularity(const config::InputNode& node,
                                                                   const IrregularityContext& context);

}  // namespace railsim::track
