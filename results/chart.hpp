// PNG charts through matplotlib (python3-matplotlib, Debian).
//
// A Chart is a plain description (title, axes, series, reference lines); draw()
// writes it as JSON next to the PNG (so the figure can be re-made or inspected)
// and runs results/plots/render_chart.py with the system python3. Rendering
// problems (python3 or matplotlib missing) are reported, never fatal: the
// numbers are already in the CSV files.
//
// Small multiples: when `panels` is not empty the figure is a grid of
// sub-plots with shared axes, one per panel title; each series goes to the
// panel with its index (`ChartSeries::panel`), reference lines and the axis
// scales apply to every panel, annotations to the panel they name.
#pragma once

#include <string>
#include <vector>

namespace railsim::results {

struct ChartSeries {
  std::string label;
  std::vector<double> x, y;
  std::string style = "line";  // "line", "markers", "crosses", "line+markers", "step"
  std::string color;           // matplotlib colour; empty = automatic
  int panel = 0;               // sub-plot index when Chart::panels is used
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
  // Panel of each annotation (same order; missing entries = panel 0).
  std::vector<int> annotation_panels;
  // Small multiples: one sub-plot per title (empty = a single plot).
  std::vector<std::string> panels;
  int panel_columns = 0;  // columns of the panel grid; 0 = about square
};

// Render `chart` to `png_path` (also writes png_path + ".json"). Returns true
// when the PNG was produced; otherwise logs a warning and returns false.
bool draw(const Chart& chart, const std::string& png_path);

}  // namespace railsim::results
