#include "superpack/render/plot.hpp"

#include <algorithm>

#include "gnuplot.hpp"
#include "superpack/cert/atomic_file.hpp"
#include "superpack/render/render_error.hpp"

namespace superpack {

namespace {

constexpr int width_pixels = 1000, height_pixels = 650;

using gnuplot::number;
using gnuplot::output_path;
using gnuplot::quoted;

bool has_point(const PlotSeries& series) {
    return std::any_of(series.points.begin(), series.points.end(), [](const PlotPoint& point) { return point.y.has_value(); });
}

// One datablock: "x y" lines, one blank line where the curve breaks.
std::string datablock(const std::string& name, const PlotSeries& series) {
    std::string text = name + " << EOD\n";
    bool broken = true;
    for (const PlotPoint& point : series.points) {
        if (point.y) {
            text += number(point.x) + " " + number(*point.y) + "\n";
            broken = false;
        } else if (!broken) {
            text += "\n";
            broken = true;
        }
    }
    return text + "EOD\n";
}

std::string style(const PlotSeries& series) {
    const std::string color = " linecolor " + std::to_string(series.color + 1);
    switch (series.stroke) {
        case Stroke::reference: return "with lines linewidth 4 linecolor rgb '#999999'";
        case Stroke::solid: return "with lines linewidth 1.5" + color;
        case Stroke::dotted: return "with linespoints linewidth 1 dashtype 3 pointtype 7 pointsize 0.4" + color;
    }
    return "";
}

std::string script(const std::string& output, const PlotAxes& axes, const std::vector<PlotSeries>& series) {
    std::string text, plots;
    for (std::size_t k = 0; k < series.size(); ++k) {
        if (!has_point(series[k])) continue;
        const std::string name = "$series" + std::to_string(k);
        text += datablock(name, series[k]);
        plots += (plots.empty() ? "plot " : ", ") + name + " using 1:2 " + style(series[k]) + " title " + quoted(series[k].title);
    }
    if (plots.empty()) throw RenderError("cannot plot: no series has a point");
    text += "set terminal pngcairo noenhanced size " + std::to_string(width_pixels) + "," + std::to_string(height_pixels) + "\n";
    text += "set output " + quoted(output_path(output)) + "\n";
    text += "set title " + quoted(axes.title) + "\n";
    text += "set xlabel " + quoted(axes.x_label) + "\n";
    text += "set ylabel " + quoted(axes.y_label) + "\n";
    text += "set key bottom right\nset grid\n";
    if (axes.log_y) text += "set logscale y\nset format y \"%g\"\n";
    if (axes.y_range) text += "set yrange [" + number(axes.y_range->first) + ":" + number(axes.y_range->second) + "]\n";
    return text + plots + "\nunset output\n";
}

}  // namespace

void require_plottable(const std::string& path) {
    require_writable_target(path);
    if (path.find_first_of("\n\r") != std::string::npos)
        throw FileError("cannot plot to '" + path + "': the name holds a line break");
    gnuplot::run("set terminal pngcairo\n");
}

void plot_png(const std::string& path, const PlotAxes& axes, const std::vector<PlotSeries>& series) {
    gnuplot::write_png(path, [&](const std::string& output) { return script(output, axes, series); });
}

}  // namespace superpack
