// PNG charts through matplotlib; see chart.hpp.
#include "results/chart.hpp"

#include <spdlog/spdlog.h>

#include <cstdlib>
#include <filesystem>

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

}  // namespace

bool draw(const Chart& chart, const std::string& png_path) {
  Json spec = Json::object();
  spec.set("title", chart.title);
  spec.set("xlabel", chart.xlabel);
  spec.set("ylabel", chart.ylabel);
  spec.set("logx", chart.logx);
  spec.set("logy", chart.logy);
  spec.set("output", png_path);
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
  const std::string spec_path = png_path + ".json";
  spec.write_file(spec_path);

  // The chart script ships in the data folder (plots/render_chart.py).
  const std::string data = find_data_dir();
  const std::string script = data + "/plots/render_chart.py";
  if (data.empty() || !std::filesystem::exists(script)) {
    spdlog::warn("chart {}: plotting script {} not found (set RAILSIM_DATA_DIR to railsim's data folder); data kept in {}",
                 png_path, data.empty() ? std::string("plots/render_chart.py") : script, spec_path);
    return false;
  }
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd = python + " " + shell_quote(script) + " " + shell_quote(spec_path) + " 2>&1";
  if (std::system(cmd.c_str()) != 0 || !std::filesystem::exists(png_path)) {
    spdlog::warn("chart {}: rendering failed (is python3-matplotlib installed?); data kept in {}", png_path,
                 spec_path);
    return false;
  }
  return true;
}

}  // namespace railsim::results
