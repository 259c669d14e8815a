// `railsim track TRACK.yaml --out track.csv [--step 0.25] [--from s0 --to s1] [--speed-kmh V]`:
// load a track file and sample its alignment and irregularities for plotting
// (engine/analysis/track_sampling.hpp); this file writes the rows and prints.
// Columns (SI unless the name says mm): s, x, y, heading, curvature,
// dcurvature, cant_mm, cant_angle, dcant_angle, the four irregularity channels
// and the left/right rail positions in mm, their slopes (d/ds, dimensionless),
// and with --speed-kmh the cant deficiency in mm. Signs: track/track.hpp.
#include <spdlog/spdlog.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.hpp"
#include "cli/support_option_checks.hpp"
#include "config/yaml_input.hpp"
#include "core/errors.hpp"
#include "engine/analysis/track_sampling.hpp"
#include "results/csv_writer.hpp"
#include "track/track_file.hpp"

namespace railsim::cli {

namespace {

struct TrackOptions {
  std::string track_file;
  std::string out;
  double step = 0.25;
  std::optional<double> from, to;
  std::optional<double> speed_kmh;
};

int run_track(const TrackOptions& o) {
  using config::format_number;
  check_out_is_not_input(o.out, o.track_file);
  const track::Track track = track::load_track(o.track_file);
  // The measured-irregularity files the track file names are inputs too:
  // read already, but --out naming one would overwrite it.
  for (const auto& c : track.irregularities().components()) check_out_against_inputs(o.out, c->input_files());
  const double s0 = o.from.value_or(0.0);
  const double s1 = o.to.value_or(track.length());
  if (!(o.step > 0.0) || !std::isfinite(o.step))
    throw InputError("--step: expected a positive number (got " + format_number(o.step) + ")");
  if (o.speed_kmh && !(*o.speed_kmh > 0.0 && *o.speed_kmh <= 720.0))
    throw InputError("--speed-kmh: expected a speed in (0, 720] km/h (got " + format_number(*o.speed_kmh) + ")");
  for (const auto& [name, v] : {std::pair<const char*, double>{"--from", s0}, {"--to", s1}})
    if (!(v >= 0.0 && v <= track.length()))
      throw InputError(std::string(name) + ": expected a distance in [0, " + format_number(track.length()) +
                       "] m (the track's defined length; got " + format_number(v) + ")");
  if (!(s1 > s0)) throw InputError("--from/--to: need from < to (got " + format_number(s0) + ", " + format_number(s1) + ")");
  const double count = engine::track_sample_count(s0, s1, o.step);
  if (count > 2e7) throw InputError("--step " + format_number(o.step) + " gives " + format_number(count) +
                                    " rows (limit 2e7); use a larger step or a shorter range");

  spdlog::info("track '{}': {:.3f} m, {} segments, rail spacing {} m, gauge {} m", track.name(), track.length(),
               track.alignment().segment_count(), track.rail_spacing(), track.gauge());
  for (int i = 0; i < track.alignment().segment_count(); ++i) {
    const auto& seg = track.alignment().segment(i);
    spdlog::info("  segments[{}] {:9s} s = {:9.3f} .. {:9.3f} m, curvature {:.6g} -> {:.6g} 1/m, cant {:.4g} -> {:.4g} mm",
                 i, seg.kind(), track.alignment().segment_start(i), track.alignment().segment_start(i + 1),
                 seg.curvature_start(), seg.curvature_end(), seg.cant_start() * 1e3, seg.cant_end() * 1e3);
  }
  for (const auto& c : track.irregularities().components()) spdlog::info("  {}", c->describe());
  for (const std::string& w : track.warnings()) spdlog::warn("{}", w);

  std::vector<std::string> cols = {"s",           "x",           "y",           "heading",        "curvature",
                                   "dcurvature",  "cant_mm",     "cant_angle",  "dcant_angle",    "lateral_mm",
                                   "vertical_mm", "cross_level_mm", "gauge_mm", "left_lateral_mm", "right_lateral_mm",
                                   "left_vertical_mm", "right_vertical_mm", "lateral_slope", "vertical_slope",
                                   "cross_level_slope", "gauge_slope"};
  if (o.speed_kmh) cols.push_back("cant_deficiency_mm");
  results::CsvWriter csv(o.out, cols, false, 100000);
  std::vector<double> row(cols.size());
  const std::optional<double> speed = o.speed_kmh ? std::optional<double>(*o.speed_kmh / 3.6) : std::nullopt;
  const auto write_row = [&](const engine::TrackSample& smp) {
    const double s = smp.s;
    const track::TrackState& t = smp.state;
    const auto& irr = t.irregularity;
    std::size_t k = 0;
    for (double v : {s, t.x, t.y, t.heading, t.curvature, t.dcurvature, t.cant * 1e3, t.cant_angle, t.dcant_angle,
                     irr.value[0] * 1e3, irr.value[1] * 1e3, irr.value[2] * 1e3, irr.value[3] * 1e3,
                     irr.left_lateral() * 1e3, irr.right_lateral() * 1e3, irr.left_vertical() * 1e3,
                     irr.right_vertical() * 1e3, irr.slope[0], irr.slope[1], irr.slope[2], irr.slope[3]})
      row[k++] = v;
    if (o.speed_kmh) row[k++] = smp.cant_deficiency * 1e3;
    csv.row(row);
  };
  const engine::TrackSamplingStats st = engine::sample_track(track, s0, s1, o.step, speed, write_row);
  const long n = st.rows;
  csv.close();
  std::printf("track %s: %.3f m, %d segments, %zu irregularity components\n", track.name().c_str(), track.length(),
              track.alignment().segment_count(), track.irregularities().components().size());
  std::printf("sampled s = %.6g .. %.6g m every %.6g m: %ld rows -> %s\n", s0, s1, o.step, n, o.out.c_str());
  for (track::Channel c : track::kAllChannels) {
    const auto i = static_cast<std::size_t>(track::index(c));
    std::printf("  %-12s max |r| = %8.3f mm   rms = %8.3f mm\n", track::channel_name(c), st.max_abs[i] * 1e3,
                st.rms[i] * 1e3);
  }
  return kExitSuccess;
}

}  // namespace

void register_track(CLI::App& app, CommandRunner& run) {
  auto opts = std::make_shared<TrackOptions>();
  auto* cmd = app.add_subcommand("track", "Sample a track file's alignment and irregularities into a CSV file");
  cmd->add_option("track", opts->track_file, "Track definition (YAML, e.g. tracks/curve_R300.yaml)")->required();
  cmd->add_option("--out,-o", opts->out, "Output CSV file")->required();
  cmd->add_option("--step", opts->step, "Sampling step [m]")->capture_default_str();
  cmd->add_option("--from", opts->from, "First distance [m] (default 0)");
  cmd->add_option("--to", opts->to, "Last distance [m] (default: track length)");
  cmd->add_option("--speed-kmh", opts->speed_kmh, "Add a cant deficiency column for this speed [km/h]");
  cmd->callback([opts, &run] { run = [opts] { return run_track(*opts); }; });
}

}  // namespace railsim::cli
