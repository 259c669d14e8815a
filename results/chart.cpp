// PNG charts through matplotlib; see chart.hpp.
#include "results/chart.hpp"

#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <sys/wait.h>

#include "core/errors.hpp"

#include "core/data_dir.hpp"
#include "results/json_writer.hpp"

namespace railsim::results {

namespace {

Json numbers(const std::vector<double>& v) {
  Json a = Json::array();
  for (double d : v) a.push(d);
  return a;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Write the chart description next to the PNG; returns its path.
std::string write_spec(const Chart& chart, const std::string& png_path) {
  Json spec = Json::object();
  spec.set("title", chart.title);
  spec.set("xlabel", chart.xlabel);
  spec.set("ylabel", chart.ylabel);
  spec.set("logx", chart.logx);
  spec.set("logy", chart.logy);
  // The PNG's file name only: the description does not depend on the folder it
  // is in (the renderer puts the PNG next to it), so equal charts have equal files.
  spec.set("output", std::filesystem::path(png_path).filename().string());
  Json series = Json::array();
  for (const auto& s : chart.series) {
    Json js = Json::object();
    js.set("label", s.label);
    js.set("style", s.style);
    js.set("color", s.color);
    js.set("x", numbers(s.x));
    js.set("y", numbers(s.y));
    js.set("panel", s.panel);
    series.push(js);
  }
  spec.set("series", series);
  Json lines = Json::array();
  for (const auto& l : chart.lines) {
    Json jl = Json::object();
    jl.set("value", l.value);
    jl.set("label", l.label);
    jl.set("color", l.color);
    jl.set("vertical", l.vertical);
    lines.push(jl);
  }
  spec.set("lines", lines);
  Json spans = Json::array();
  for (const auto& sp : chart.spans) {
    Json js = Json::object();
    js.set("x0", sp.x0);
    js.set("x1", sp.x1);
    js.set("label", sp.label);
    js.set("color", sp.color);
    js.set("alpha", sp.alpha);
    js.set("hatch", sp.hatch);
    spans.push(js);
  }
  spec.set("spans", spans);
  Json bands = Json::array();
  for (const auto& b : chart.bands) {
    Json jb = Json::object();
    jb.set("label", b.label);
    jb.set("x", numbers(b.x));
    jb.set("y_low", numbers(b.y_low));
    jb.set("y_high", numbers(b.y_high));
    jb.set("color", b.color);
    jb.set("alpha", b.alpha);
    jb.set("panel", b.panel);
    bands.push(jb);
  }
  spec.set("bands", bands);
  spec.set("legend", chart.legend);
  Json ann = Json::array();
  for (std::size_t i = 0; i < chart.annotations.size(); ++i) {
    const auto& a = chart.annotations[i];
    Json ja = Json::object();
    ja.set("text", a.first);
    ja.set("x", a.second.first);
    ja.set("y", a.second.second);
    ja.set("panel", i < chart.annotation_panels.size() ? chart.annotation_panels[i] : 0);
    ann.push(ja);
  }
  spec.set("annotations", ann);
  Json panels = Json::array();
  for (const auto& p : chart.panels) panels.push(p);
  spec.set("panels", panels);
  spec.set("panel_columns", chart.panel_columns);
  if (!chart.note.empty()) spec.set("note", chart.note);
  if (chart.y_from_zero) spec.set("y_from_zero", true);
  if (chart.width > 0 && chart.height > 0) spec.set("size", Json::array().push(chart.width).push(chart.height));
  if (!chart.legend_location.empty()) spec.set("legend_location", chart.legend_location);
  const std::string spec_path = png_path + ".json";
  spec.write_file(spec_path);
  return spec_path;
}

}  // namespace

std::string custom_style(const std::string& marker, const std::string& line, bool open, double size) {
  std::string s = "custom:marker=" + marker + ";line=" + line;
  if (open) s += ";open";
  if (size > 0) {
    char buf[32];
    std::snprintf(buf, sizeof buf, ";size=%g", size);
    s += buf;
  }
  return s;
}

bool draw_all(const std::vector<std::pair<const Chart*, std::string>>& charts) {
  if (charts.empty()) return true;
  std::string args;
  for (const auto& [chart, png] : charts) {
    std::error_code ec;
    // A stale PNG must not pass for a new one (a device such as /dev/full stays).
    if (std::filesystem::is_regular_file(png, ec)) std::filesystem::remove(png, ec);
    args += " " + shell_quote(write_spec(*chart, png));
  }
  // The chart script ships in the data folder (plots/render_chart.py).
  const std::string data = find_data_dir();
  const std::string script = data + "/plots/render_chart.py";
  if (data.empty() || !std::filesystem::exists(script)) {
    spdlog::warn("charts: plotting script {} not found (set RAILSIM_DATA_DIR to railsim's data folder); data kept "
                 "in the .png.json files",
                 data.empty() ? std::string("plots/render_chart.py") : script);
    return false;
  }
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd = python + " " + shell_quote(script) + args + " 2>&1";
  // The script's messages are passed on; exit status 3 means a PNG could not
  // be written (each named on a line "PATH: write failed (reason)"): an error.
  std::string output;
  int status = -1;
  if (std::FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) output.append(buf, n);
    status = ::pclose(p);
  }
  if (!output.empty()) std::fwrite(output.data(), 1, output.size(), stdout);
  const int code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 3) {
    std::string failed;
    for (std::size_t at = 0, end; at < output.size(); at = end + 1) {
      end = output.find('\n', at);
      if (end == std::string::npos) end = output.size();
      const std::string line = output.substr(at, end - at);
      if (line.find(": write failed") != std::string::npos)
        failed += (failed.empty() ? "" : "; ") + line.substr(line.rfind("render_chart.py: ", 0) == 0 ? 17 : 0);
    }
    throw InputError(failed.empty() ? std::string("charts: a PNG could not be written") : failed);
  }
  const bool ran = code == 0;
  bool ok = true;
  for (const auto& [chart, png] : charts) {
    if (ran && std::filesystem::exists(png)) continue;
    spdlog::warn("chart {}: rendering failed (is python3-matplotlib installed?); data kept in {}.json", png, png);
    ok = false;
  }
  return ok;
}

bool draw(const Chart& chart, const std::string& png_path) { return draw_all({{&chart, png_path}}); }

}  // namespace railsim::results
