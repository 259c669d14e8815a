// PNG charts through matplotlib (python3-matplotlib, Debian).
//
// A Chart is a plain description (title, axes, series, reference lines); draw()
// writes it as JSON next to the PNG (so the figure can be re-made or inspected)
// and runs results/plots/render_chart.py with the system python3. Rendering
// problems (python3 or matplotlib missing) are reported, never fatal: the
// numbers are already in the CSV files.
//
// Spans shade x ranges (behind the series); bands fill between two curves.
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
  // "line", "dashed", "dotted", "faint" (thin, light line), "markers", "crosses", "line+markers", "step", or an
  // explicit style from custom_style(). A series without points but with a label only adds a legend entry.
  std::string style = "line";
  std::string color;           // matplotlib colour; empty = automatic
  int panel = 0;               // sub-plot index when Chart::panels is used
};

// A filled band between two curves (e.g. an envelope).
struct ChartBand {
  std::string label;
  std::vector<double> x, y_low, y_high;
  std::string color = "0.6";
  double alpha = 0.35;
  int panel = 0;
};

// A shaded range of x (e.g. a curve or a defect along the track).
struct ChartSpan {
  double x0 = 0.0, x1 = 0.0;
  std::string label;           // legend entry (the first span of each label only)
  std::string color = "0.8";
  double alpha = 0.2;
  std::string hatch;           // matplotlib hatch ("//", "xx"); empty = none
};

// Explicit style: matplotlib marker ("o", "v", "^", "x", "s", "*", ...; empty =
// none), line style ("-", "--", ":"; empty = no line), hollow markers, marker
// size in points (0 = default). Written "custom:marker=o;line=-;open;size=5".
std::string custom_style(const std::string& marker, const std::string& line, bool open = false,
                         double size = 0.0);

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
  std::vector<ChartSpan> spans;
  std::vector<ChartBand> bands;
  std::string legend = "best";  // legend placement: "best" (inside) or "outside" (right of the plot)
  // Optional annotated points (e.g. model names on a Pareto chart).
  std::vector<std::pair<std::string, std::pair<double, double>>> annotations;
  // Panel of each annotation (same order; missing entries = panel 0).
  std::vector<int> annotation_panels;
  // Small multiples: one sub-plot per title (empty = a single plot).
  std::vector<std::string> panels;
  int panel_columns = 0;  // columns of the panel grid; 0 = about square
  // A text box in the plot (e.g. the rule a result was read with); empty = none.
  std::string note;
  bool y_from_zero = false;  // start the y axis at 0
  std::string legend_location;  // matplotlib location of an inside legend ("best" when empty)
  double width = 0.0, height = 0.0;  // figure size [inch] of a single plot; 0 = 8 x 5 (11 x 5 with the legend outside)
};

// Render `chart` to `png_path` (also writes png_path + ".json"). Returns true
// when the PNG was produced; otherwise logs a warning and returns false (no
// python3-matplotlib, no plotting script: the data stay in the .json). A PNG
// or description that cannot be written (disk full, no permission) throws
// InputError naming the file.
bool draw(const Chart& chart, const std::string& png_path);

// Render several charts with one python3 process (saves its start-up, about a
// second per chart). Returns true when every PNG was produced.
bool draw_all(const std::vector<std::pair<const Chart*, std::string>>& charts);

}  // namespace railsim::results
