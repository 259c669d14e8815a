// Measured irregularities from CSV; see measured_irregularity.hpp.
#include "track/measured_irregularity.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/errors.hpp"
#include "core/input_file.hpp"

namespace railsim::track {

namespace {

constexpr double kMaxIrregularity = 0.2;  // [m], the range of a cosine defect's amplitude (defects.cpp)
constexpr double kMinRowSpacing = 1e-3;   // [m] between consecutive rows
constexpr double kWarnOffTrack = 0.1;     // a record more than this fraction of the track off it is said
constexpr double kWarnOffTrackMin = 1.0;  // [m], and at least this much
constexpr double kMmRowSpacing = 10.0;    // [m] median row spacing of a record whose s is in mm (0.1-1 m -> 100-1000)
constexpr double kMmReach = 10.0;         // track lengths past the end of such a record

std::string trim(const std::string& t) {
  const auto b = t.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = t.find_last_not_of(" \t\r");
  return t.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

void smooth_step(double t, double& f, double& df) {
  t = std::clamp(t, 0.0, 1.0);
  f = t * t * t * (10.0 + t * (-15.0 + 6.0 * t));
  df = 30.0 * t * t * (1.0 - t) * (1.0 - t);
}

// A record that reaches beyond the track: the part off the track is never
// used. More than kWarnOffTrack of the track's length off it is said (file,
// both ranges, what is unused); a record whose distances are clearly
// millimetres (rows kMmRowSpacing or more apart, reaching more than
// kMmReach track lengths past the end) is refused.
void check_record_reach(const MeasuredTable& table, double offset, const IrregularityContext& context,
                        const std::string& file, const config::InputNode& fnode) {
  const double length = context.track_length;
  if (!(length > 0.0)) return;
  using config::format_number;
  const double s0 = table.s.front() + offset, s1 = table.s.back() + offset;
  const double before = std::max(0.0, -s0), after = std::max(0.0, s1 - length);
  std::vector<double> spacing(table.s.size() - 1);
  for (std::size_t i = 1; i < table.s.size(); ++i) spacing[i - 1] = table.s[i] - table.s[i - 1];
  std::nth_element(spacing.begin(), spacing.begin() + std::ptrdiff_t(spacing.size() / 2), spacing.end());
  const double median_spacing = spacing[spacing.size() / 2];
  std::size_t on_track = 0;
  for (double s : table.s) on_track += (s + offset >= 0.0 && s + offset <= length) ? 1 : 0;
  const std::string ranges = file + " covers s = " + format_number(s0) + " .. " + format_number(s1) + " m" +
                             (offset != 0.0 ? " (offset " + format_number(offset) + " m)" : "") + ", the track 0 .. " +
                             format_number(length) + " m";
  char times[32];
  std::snprintf(times, sizeof times, "%.3g", s1 / length);
  if (median_spacing >= kMmRowSpacing && after > kMmReach * length)
    fnode.fail(ranges + ": the record reaches " + times + " times the track's length, with rows " +
               format_number(median_spacing) + " m apart (records are sampled every 0.1-1 m): is column 's' in mm? "
               "s is the distance in metres ('units' applies to the channels only)");
  if (context.warnings && before + after > std::max(kWarnOffTrackMin, kWarnOffTrack * length)) {
    std::string unused;
    if (after > 0.0) unused = format_number(after) + " m beyond its end";
    if (before > 0.0) unused += (unused.empty() ? "" : " and ") + format_number(before) + " m before its start";
    context.warnings->push_back(fnode.where() + ": key 'file': " + ranges + ": " + unused + " are not used (" +
                                std::to_string(on_track) + " of " + std::to_string(table.s.size()) +
                                " rows lie on the track); check the record's distances and the offset");
  }
}

}  // namespace

MeasuredTable read_measured_irregularity(const std::string& path, double unit) {
  check_input_file(path, "measured irregularity file");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open measured irregularity file for reading");
  MeasuredTable t;
  t.file = path;
  auto fail = [&](int line, const std::string& what) {
    throw InputError(path + ":" + std::to_string(line) + ": " + what);
  };
  std::vector<std::string> header;
  std::vector<int> column_channel;  // -1 for s, else channel index
  std::string line;
  int lineno = 0, header_line = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string tl = trim(line);
    if (tl.empty() || tl[0] == '#') continue;
    auto cells = split(tl);
    if (header.empty()) {
      header = cells;
      header_line = lineno;
      bool has_s = false;
      for (const auto& h : header) {
        if (h == "s") {
          if (has_s) fail(lineno, "column 's' appears twice");
          has_s = true;
          column_channel.push_back(-1);
          continue;
        }
        const auto c = channel_from_name(h);
        if (!c) fail(lineno, "unknown column '" + h + "' (allowed: s, lateral, vertical, cross_level, gauge)");
        if (t.channels[static_cast<std::size_t>(index(*c))]) fail(lineno, "column '" + h + "' appears twice");
        t.channels[static_cast<std::size_t>(index(*c))].emplace();
        column_channel.push_back(index(*c));
      }
      if (!has_s) fail(lineno, "missing column 's' (distance along the track, m)");
      if (header.size() < 2) fail(lineno, "no channel column (expected one or more of: lateral, vertical, cross_level, gauge)");
      continue;
    }
    if (cells.size() != header.size())
      fail(lineno, "expected " + std::to_string(header.size()) + " cells (" + std::to_string(header.size()) +
                       " columns in the header), found " + std::to_string(cells.size()));
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::string& c = cells[i];
      double v = 0.0;
      const auto res = std::from_chars(c.data(), c.data() + c.size(), v);
      if (c.empty() || res.ec != std::errc() || res.ptr != c.data() + c.size() || !std::isfinite(v))
        fail(lineno, "column '" + header[i] + "': expected a finite number (got '" + c + "')");
      const int ch = column_channel[i];
      if (ch < 0) {
        if (!t.s.empty() && !(v > t.s.back()))
          fail(lineno, "distance s = " + config::format_number(v) + " m is not greater than the previous row's (" +
                           config::format_number(t.s.back()) + " m): rows must be sorted by increasing distance");
        // A spike over a picometre was lost without a word (the track is
        // sampled in millimetres at the finest): rows at least 1 mm apart.
        if (!t.s.empty() && v - t.s.back() < kMinRowSpacing)
          fail(lineno, "distance s = " + config::format_number(v) + " m is only " +
                           config::format_number(v - t.s.back()) + " m after the previous row's: rows must be at "
                           "least 1 mm apart (records are sampled every 0.1-1 m)");
        t.s.push_back(v);
      } else {
        // As a cosine defect's amplitude: a track irregularity within +-200 mm.
        if (!(std::abs(v * unit) <= kMaxIrregularity))
          fail(lineno, "column '" + header[i] + "': " + config::format_number(v) + (unit == 1.0 ? " m" : " mm") +
                           " outside [-200, 200] mm, the range of a track irregularity");
        t.channels[static_cast<std::size_t>(ch)]->push_back(v * unit);
      }
    }
  }
  if (header.empty()) throw InputError(path + ": empty file (expected a header line: s,lateral,...)");
  if (t.s.size() < 4)
    fail(header_line, "expected at least 4 data rows, found " + std::to_string(t.s.size()));
  return t;
}

MeasuredIrregularity::MeasuredIrregularity(MeasuredTable table, double offset, double taper, double scale)
    : file_(table.file), offset_(offset), taper_(taper), scale_(scale) {
  s_begin_ = table.s.front() + offset;
  s_end_ = table.s.back() + offset;
  rows_ = table.s.size();
  for (std::size_t c = 0; c < kChannelCount; ++c) {
    if (!table.channels[c]) continue;
    std::vector<double> x = table.s;
    splines_[c].emplace(std::move(x), std::move(*table.channels[c]));
  }
}

void MeasuredIrregularity::add_to(double s, IrregularityState& out) const {
  if (s < s_begin_ || s > s_end_) return;
  const double u = std::clamp(s - offset_, s_begin_ - offset_, s_end_ - offset_);
  double w = scale_, dw = 0.0;
  if (taper_ > 0.0) {
    double f = 1.0, df = 0.0;
    if (s - s_begin_ < taper_) {
      smooth_step((s - s_begin_) / taper_, f, df);
      dw = scale_ * df / taper_;
    } else if (s_end_ - s < taper_) {
      smooth_step((s_end_ - s) / taper_, f, df);
      dw = -scale_ * df / taper_;
    }
    w = scale_ * f;
  }
  for (Channel c : kAllChannels) {
    const auto& sp = splines_[static_cast<std::size_t>(index(c))];
    if (!sp) continue;
    const double v = (*sp)(u);
    out.add(c, w * v, w * sp->prime(u) + dw * v);
  }
}

std::string MeasuredIrregularity::describe() const {
  std::string ch;
  for (Channel c : kAllChannels)
    if (splines_[static_cast<std::size_t>(index(c))]) ch += (ch.empty() ? "" : "+") + std::string(channel_name(c));
  char buf[160];
  std::snprintf(buf, sizeof buf, " s = %.6g-%.6g m, %zu points", s_begin_, s_end_, rows_);
  return "measured " + file_ + " (" + ch + ")" + buf;
}

std::unique_ptr<IrregularityComponent> parse_measured_irregularity(const config::InputNode& node,
                                                                   const IrregularityContext& context) {
  node.allow_only({"type", "file", "units", "channels", "offset", "taper", "scale"});
  const config::InputNode fnode = node.at("file");
  std::filesystem::path p(fnode.as_string());
  if (p.is_relative() && !context.base_dir.empty()) p = std::filesystem::path(context.base_dir) / p;
  double unit = 1e-3;
  if (auto u = node.find("units")) {
    const std::string v = u->as_string();
    if (v == "mm") unit = 1e-3;
    else if (v == "m") unit = 1.0;
    else u->fail("expected one of: mm, m (got '" + v + "')");
  }
  MeasuredTable table;
  try {
    table = read_measured_irregularity(p.string(), unit);
  } catch (const InputError& e) {
    fnode.fail(e.what());
  }
  if (auto chs = node.find("channels")) {
    // Keep only the listed channels; each must be in the file.
    std::array<bool, kChannelCount> keep{};
    for (const auto& e : chs->elements()) {
      const auto c = channel_from_name(e.as_string());
      if (!c) e.fail("unknown channel '" + e.as_string() + "' (allowed: lateral, vertical, cross_level, gauge)");
      if (!table.channels[static_cast<std::size_t>(index(*c))])
        e.fail("channel '" + e.as_string() + "' is not a column of " + p.string());
      keep[static_cast<std::size_t>(index(*c))] = true;
    }
    for (std::size_t c = 0; c < kChannelCount; ++c)
      if (!keep[c]) table.channels[c].reset();
  }
  const double offset = node.has("offset") ? node.at("offset").as_in_range(-1e7, 1e7) : 0.0;
  // The record must meet the track (an offset past its end gave a silent zero).
  const double s0 = table.s.front() + offset, s1 = table.s.back() + offset;
  if (context.track_length > 0.0 && (s1 <= 0.0 || s0 >= context.track_length))
    (node.has("offset") ? node.at("offset") : fnode)
        .fail("the record lies at s = " + config::format_number(s0) + " .. " + config::format_number(s1) +
              " m, outside the track (0 .. " + config::format_number(context.track_length) +
              " m): give an offset that places it on the track");
  check_record_reach(table, offset, context, p.string(), fnode);
  const double span = table.s.back() - table.s.front();
  const double taper = node.has("taper") ? node.at("taper").as_in_range(0.0, 0.5 * span) : 0.0;
  const double scale = node.has("scale") ? node.at("scale").as_in_range(0.0, 100.0) : 1.0;
  double largest = 0.0;
  for (const auto& c : table.channels)
    if (c)
      for (double v : *c) largest = std::max(largest, std::abs(v));
  if (largest * scale > kMaxIrregularity)
    node.at("scale").fail("scale " + config::format_number(scale) + " makes the record's largest value " +
                          config::format_number(largest * scale * 1e3) +
                          " mm, outside [-200, 200] mm, the range of a track irregularity");
  return std::make_unique<MeasuredIrregularity>(std::move(table), offset, taper, scale);
}

}  // namespace railsim::track
