// `railsim compare-yq SCENARIO.yaml RUN_DIR... --out DIR [--labels L1,L2,...]`:
// Y/Q of the leading wheels of runs written by `railsim run` (e.g. the same
// scenario with k = 1 and k = 0.5) against Nadal's limit on one chart
// (engine/analysis/yq_comparison.hpp). Writes DIR/yq_comparison.png,
// DIR/yq_comparison.csv (one row per run and wheel: peak, place, time, whether
// and over how many metres / seconds the limit is exceeded) and
// DIR/summary.json, and prints the table.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "cli/commands.hpp"
#include "core/errors.hpp"
#include "core/output_lock.hpp"
#include "engine/analysis/yq_comparison.hpp"
#include "results/chart.hpp"
#include "results/csv_writer.hpp"

namespace railsim::cli {

namespace {

struct CompareYqArgs {
  std::string scenario;
  std::vector<std::string> runs;
  std::string labels;
  std::string wheelset;
  std::string out = "yq_comparison";
};

int run_compare_yq(const CompareYqArgs& a) {
  // The comparison's summary.json would replace a run's own (its verdict).
  const auto folder = [](const std::string& p, std::error_code& ec) {
    std::filesystem::path c = std::filesystem::weakly_canonical(p, ec);
    return c.has_filename() ? c : c.parent_path();  // "run/" and "run" are one folder
  };
  for (const auto& run : a.runs) {
    std::error_code e1, e2;
    const auto o = folder(a.out, e1), r = folder(run, e2);
    if (!e1 && !e2 && o == r)
      throw InputError("--out " + a.out + ": is the run folder " + run +
                       " being compared; writing there would replace the run's summary.json: give another folder");
  }
  std::error_code ec;
  std::filesystem::create_directories(a.out, ec);
  if (ec) throw InputError("--out " + a.out + ": cannot create the folder (" + ec.message() + ")");
  const OutputLock lock(a.out, "compare-yq");  // one writer per output folder
  const engine::Scenario sc = engine::load_scenario(a.scenario);
  std::vector<std::string> labels;
  if (!a.labels.empty()) {
    // Every comma separates two labels ("a," is two, the second empty).
    std::size_t from = 0;
    for (std::size_t at; (at = a.labels.find(',', from)) != std::string::npos; from = at + 1)
      labels.push_back(a.labels.substr(from, at - from));
    labels.push_back(a.labels.substr(from));
  }
  const engine::YqComparison c = engine::compare_yq(sc, a.runs, labels, a.wheelset);
  {
    results::CsvWriter csv(a.out + "/yq_comparison.csv",
                           {"run", "wheel", "max_abs_yq", "yq_at_max", "distance_m", "time_s", "nadal_limit",
                            "exceeds_nadal", "exceed_length_m", "exceed_time_s", "first_exceed_m", "last_exceed_m"},
                           false, 1000);
    for (const auto& r : c.runs)
      for (int s = 0; s < 2; ++s) {
        const auto& w = r.wheel[s];
        csv.cell(r.label).cell(s == 0 ? "left" : "right").cell(w.peak).cell(w.peak_signed).cell(w.peak_distance);
        csv.cell(w.peak_time).cell(c.nadal).cell(w.exceeded).cell(w.exceed_length).cell(w.exceed_time);
        csv.cell(w.exceeded ? w.first_exceed : NAN).cell(w.exceeded ? w.last_exceed : NAN);
        csv.end_row();
      }
  }
  engine::yq_comparison_summary(c).write_file(a.out + "/summary.json");
  results::draw(engine::yq_comparison_chart(c), a.out + "/yq_comparison.png");
  std::printf("\nrailsim compare-yq: %s, leading wheelset %s, Nadal limit %.3g (flange angle %.1f deg, mu %.2g)\n\n",
              c.scenario.c_str(), c.wheelset.c_str(), c.nadal, c.flange_angle * 180.0 / M_PI, c.mu);
  // The run column as wide as the longest label (cut at 24 characters, "k1/out" rows could not be told apart).
  int width = 24;
  for (const auto& r : c.runs) width = std::max(width, int(r.label.size()));
  std::printf("  %-*s %-6s %9s %10s %9s %s\n", width, "run", "wheel", "max|Y/Q|", "at [m]", "at [s]", "Nadal exceeded");
  for (const auto& r : c.runs)
    for (int s = 0; s < 2; ++s) {
      const auto& w = r.wheel[s];
      char ex[96] = "no";
      if (w.exceeded)
        std::snprintf(ex, sizeof ex, "yes, over %.2f m (%.3f s), %.1f..%.1f m", w.exceed_length, w.exceed_time,
                      w.first_exceed, w.last_exceed);
      std::printf("  %-*s %-6s %9.3f %10.1f %9.2f %s\n", width, r.label.c_str(), s == 0 ? "left" : "right",
                  w.peak, w.peak_distance, w.peak_time, ex);
    }
  for (const auto& r : c.runs)
    if (!r.warning.empty()) std::printf("  warning: %s: %s\n", r.label.c_str(), r.warning.c_str());
    else if (r.status == "derailed") std::printf("  note: %s: the run ended in a derailment\n", r.label.c_str());
  std::printf("\n  results %s/yq_comparison.csv, summary.json, yq_comparison.png\n\n", a.out.c_str());
  return kExitSuccess;
}

}  // namespace

void register_compare_yq(CLI::App& app, CommandRunner& run) {
  auto a = std::make_shared<CompareYqArgs>();
  auto* cmd = app.add_subcommand(
      "compare-yq", "Y/Q of the leading wheels of several `railsim run` outputs against Nadal's limit, on one chart");
  cmd->add_option("scenario", a->scenario, "Scenario YAML file the runs were made with (wheelsets, flange angle, mu)")
      ->required();
  cmd->add_option("runs", a->runs, "Output folders of `railsim run` (each with channels.csv)")->required();
  cmd->add_option("--labels", a->labels,
                  "Comma-separated labels of the runs (default: the folder names, with their parent folders where "
                  "names repeat)");
  cmd->add_option("--wheelset", a->wheelset, "Wheelset to compare (default: the leading one)");
  cmd->add_option("--out", a->out, "Output folder")->capture_default_str();
  cmd->callback([a, &run] { run = [a] { return run_compare_yq(*a); }; });
}

}  // namespace railsim::cli
