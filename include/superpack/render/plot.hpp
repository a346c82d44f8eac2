// Drawing named series on one pair of axes into a PNG file with gnuplot (pngcairo), run
// without a shell: the script, data included as datablocks, goes to gnuplot's stdin. The PNG
// is written like every result file (cert/atomic_file.hpp): into an exclusive temporary file
// beside the target, checked, then renamed over it.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace superpack {

// A point of a curve; a point without y breaks the curve there.
struct PlotPoint {
    double x;
    std::optional<double> y;
};

// reference: a wide grey curve under the others; solid and dotted: a thin line in the series'
// color, dotted with a dot at each point (so that a lone point shows).
enum class Stroke { reference, solid, dotted };

struct PlotSeries {
    std::string title;
    Stroke stroke;
    int color;  // series with the same color index share a color (not used by reference)
    std::vector<PlotPoint> points;
};

struct PlotAxes {
    std::string title, x_label, y_label;
    std::optional<std::pair<double, double>> y_range;
    bool log_y = false;  // a logarithmic y axis, for values spanning decades
};

// Before the slow work that makes the data: throws FileError unless `path` can be written
// (require_writable_target; a name with a line break is refused too, gnuplot could not be
// given it), and RenderError unless gnuplot runs here with the pngcairo terminal.
void require_plottable(const std::string& path);

// Draws the series that have a point (at least one must) into the PNG `path`; throws
// RenderError naming the problem when gnuplot fails or writes no PNG, and leaves no file then.
void plot_png(const std::string& path, const PlotAxes& axes, const std::vector<PlotSeries>& series);

}  // namespace superpack
