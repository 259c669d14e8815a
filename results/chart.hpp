// PNG charts through matplotlib (python3-matplotlib, Debian).
//
// A Chart is a plain description (title, axes, series, reference lines); draw()
// writes it as JSON next to the PNG (so the figure can be re-made or inspected)
// and runs results/plots/render_chart.py with the system python3. Rendering
// problems (python3 or matplotlib missing) are reported, never fatal: the
// numbers are already in the CSV files.
#pragma once

#include <string>
#include <vector>

namespace railsim::results {

struct ChartSeries {
  std::string label;
  std::vector<double> x, y;
  std::string style = "line";  // "line", "markers", "line+markers", "step"
  std::string color;           // matplotlib colour; empty = automatic
};

struct ChartLine {
  double value = 0.0;       // x of a vertical line, or y of a horizontal one
  std::string label;
  std::string color = "k";
  bool vertical = true;
};

struct Chart {
  std::string title, xlabel, ylabel;
  bool logx = false, logy = false;
  std::vector<ChartSeries> series;
  std::vector<ChartLine> lines;
  // Optional annotated points (e.g. model names on a Pareto chart).
  std::vector<std::pair<std::string, std::pair<double, double>>> annotations;
};

// Render `chart` to `png_path` (also writes png_path + ".json"). Returns true
// when the PNG was produced; otherwise logs a warning and returns false.
bool draw(const Chart& chart, const std::string& png_path);

}  // namespace railsim::results
