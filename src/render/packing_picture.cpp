#include "superpack/render/packing_picture.hpp"

#include <algorithm>
#include <cmath>

#include "gnuplot.hpp"
#include "superpack/arith/decimal.hpp"
#include "superpack/render/packing_mesh.hpp"

namespace superpack {

namespace {

constexpr int picture_pixels = 1100;
// The grid of each drawn particle: as fine as keeps the whole picture within this many grid
// squares (gnuplot sorts and draws 50000 in about two seconds), between these bounds.
constexpr double square_budget = 50000;
constexpr int finest_grid = 24, coarsest_grid = 4;
// gnuplot's `set view`: the tilt of the z axis away from the eye and the turn about it, degrees.
constexpr double view_tilt = 58, view_turn = 32;
// Colours by index in the cell (cycled beyond 16): distinct, light enough to show shading.
constexpr unsigned colours[] = {0xe0603f, 0x3f86e0, 0xf0c030, 0x4cb56e, 0xa066d0, 0x2fc0bb, 0xe884b8, 0x9a7a50,
                                0xaad04a, 0x6478e0, 0xf7922a, 0x35a898, 0xd05a86, 0x8895a2, 0xc0b04a, 0x78c0f0};

using dense::cross;
using dense::dot;
using dense::operator+;
using dense::operator-;
using dense::operator*;

// The fractional coordinates f of x = f . rows.
Point3 fraction_of(const dense::Matrix3& rows, const Point3& x) { return dense::apply(dense::inverse(dense::transpose(rows)), x); }

// Which fundamental domain is drawn is a choice: the cell is translated so that the centres'
// circular mean (per fractional coordinate) sits at its middle, so the particles of a cell lie
// inside it rather than across its corners. Returns the fractional origin of the drawn cell.
Point3 drawn_origin(const std::vector<Point3>& fractions) {
    const double turn = 2 * std::acos(-1.0);
    Point3 origin;
    for (int c = 0; c < 3; ++c) {
        double x = 0, y = 0;
        for (const Point3& f : fractions) {
            x += std::cos(turn * f[c]);
            y += std::sin(turn * f[c]);
        }
        origin[c] = std::atan2(y, x) / turn - 0.5;
    }
    return origin;
}

// gnuplot's view as directions in space: towards the eye, the screen's right and up.
struct View {
    Point3 eye, right, up;
};

View view() {
    const double degree = std::acos(-1.0) / 180, tilt = view_tilt * degree, turn = view_turn * degree;
    View v;
    v.eye = {std::sin(tilt) * std::sin(turn), -std::sin(tilt) * std::cos(turn), std::cos(tilt)};
    v.right = {std::cos(turn), std::sin(turn), 0};
    v.up = cross(v.eye, v.right);
    return v;
}

Point3 unit(const Point3& x) { return (1 / dense::norm(x)) * x; }

// Our own lighting (gnuplot 5.4's pm3d lighting picks each facet's side by itself and shades
// rounded edges in patches): a light above and left of the eye, Lambert's law over an ambient
// floor and a Blinn-Phong highlight, as a shade in [0, 1) of the particle's colour ramp.
struct Lighting {
    Point3 light, halfway;
    explicit Lighting(const View& v) {
        light = unit(v.eye + 0.75 * v.up - 0.5 * v.right);
        halfway = unit(light + v.eye);
    }
    double shade(const Point3& normal) const {
        constexpr double ambient = 0.22, highlight = 0.24, shininess = 50;
        const double diffuse = ambient + (1 - ambient) * std::max(0.0, dot(normal, light));
        const double specular = std::pow(std::max(0.0, dot(normal, halfway)), shininess);
        return std::min(0.99, (1 - highlight) * diffuse + highlight * specular);
    }
};

// x to 6 digits: a picture needs no more.
std::string point_text(const Point3& x, const std::string& separator) {
    return gnuplot::number(x[0], 6) + separator + gnuplot::number(x[1], 6) + separator + gnuplot::number(x[2], 6);
}

// The box of all that is drawn. gnuplot's `set view equal xyz` scales all axes alike; every
// axis gets a range of the same length, the largest, about the box's middle, so that the
// scene's middle is the plot's and fitting_scale knows the scale.
struct Bounds {
    Point3 low{HUGE_VAL, HUGE_VAL, HUGE_VAL}, high{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    std::vector<Point3> points;
    void add(const Point3& x) {
        points.push_back(x);
        for (int c = 0; c < 3; ++c) {
            low[c] = std::min(low[c], x[c]);
            high[c] = std::max(high[c], x[c]);
        }
    }
    Point3 middle() const { return 0.5 * (low + high); }
    double range() const { return std::max({high[0] - low[0], high[1] - low[1], high[2] - low[2]}); }
    std::string ranges() const {
        std::string text;
        for (int c = 0; c < 3; ++c)
            text += std::string("set ") + "xyz"[c] + "range [" + gnuplot::number(middle()[c] - range() / 2, 6) + ":" +
                    gnuplot::number(middle()[c] + range() / 2, 6) + "]\n";
        return text;
    }
};

// The `set view` scale at which the points fill the plot's width and height up to a margin.
// gnuplot (graph3d.c) maps x to the screen as <x - middle, right> (2 / L) (scale / 2) (4 / 7)
// times the plot's size, L = range().
double fitting_scale(const Bounds& bounds, const View& v) {
    constexpr double filled = 0.43;  // of the plot's size, either side of its middle
    const Point3 middle = bounds.middle();
    double reach = 0;
    for (const Point3& x : bounds.points) {
        const Point3 d = x - middle;
        reach = std::max({reach, std::fabs(dot(d, v.right)), std::fabs(dot(d, v.up))});
    }
    return filled * 7 * bounds.range() / (4 * reach);
}

// The 12 edges of the parallelepiped of fractional coordinates origin + [0, size]^3 as line
// segments: two points, then two blank lines (one blank line would make them a grid, whose
// cross lines splot draws too).
std::string box_edges(const dense::Matrix3& rows, const Point3& origin, double size, Bounds& bounds) {
    std::string text;
    for (int axis = 0; axis < 3; ++axis)
        for (int a : {0, 1})
            for (int b : {0, 1}) {
                Point3 from = origin;
                from[(axis + 1) % 3] += a * size;
                from[(axis + 2) % 3] += b * size;
                Point3 to = from;
                to[axis] += size;
                for (const Point3& f : {from, to}) {
                    const Point3 x = dense::row_combination(rows, f);
                    bounds.add(x);
                    text += point_text(x, " ") + "\n";
                }
                text += "\n\n";
            }
    return text;
}

// "#rrggbb" of colour `rgb` scaled by `factor` and mixed with white by `white`.
std::string colour_text(unsigned rgb, double factor, double white) {
    static const char digits[] = "0123456789abcdef";
    std::string text = "#";
    for (int shift = 16; shift >= 0; shift -= 8) {
        const double channel = (rgb >> shift & 255) * factor;
        const int value = static_cast<int>(std::lround(channel + (255 - channel) * white));
        text += digits[value >> 4 & 15];
        text += digits[value & 15];
    }
    return text;
}

// Colour i's ramp on [i, i + 1]: dark, the colour itself at the shade 1 - highlight, near white
// at the top, with a jump to the next colour's ramp.
std::string palette(std::size_t n) {
    std::string text = "set palette defined (";
    for (std::size_t i = 0; i < n; ++i) {
        const unsigned rgb = colours[i % std::size(colours)];
        const std::string at = std::to_string(i);
        text += (i ? ", " : "") + at + " '" + colour_text(rgb, 0.12, 0) + "', " + at + ".78 '" + colour_text(rgb, 1, 0) + "', " +
                at + ".99 '" + colour_text(rgb, 1, 0.75) + "'";
    }
    return text + ")\nset cbrange [0:" + std::to_string(n) + "]\n";
}

std::string script(const std::string& output, const PeriodicPacking& packing, const DInterval& phi) {
    dense::Matrix3 rows;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) rows[r][c] = packing.cell[r][c].get_d();
    const std::size_t n = packing.centers.size();
    std::vector<PlacedParticle> particles;
    std::vector<Point3> fractions;
    for (std::size_t i = 0; i < n; ++i) {
        particles.push_back(placed_particle(packing, i));
        fractions.push_back(fraction_of(rows, particles.back().center));
    }
    const Point3 origin = drawn_origin(fractions);
    const double drawn = 8.0 * static_cast<double>(n);
    const int grid = std::clamp(static_cast<int>(std::sqrt(square_budget / (6 * drawn))), coarsest_grid, finest_grid);
    const SurfaceMesh surface = superball_surface(packing.p.get_d(), grid);
    const View v = view();
    const Lighting lighting(v);
    std::vector<Point3> normals;
    for (const Point3& x : surface.vertices) normals.push_back(superball_normal(packing.p.get_d(), x));

    // Particle i and its images in the 2 x 2 x 2 block: each face of each a pm3d grid of m + 1
    // scans of m + 1 points "x y z colour" (scans apart by a blank line, grids by two), the
    // colour i + its shade; gnuplot sorts the grid squares of all by depth.
    Bounds bounds;
    std::string text = "$particles << EOD\n";
    for (std::size_t i = 0; i < n; ++i) {
        PlacedParticle placed = particles[i];
        Point3 fraction = fractions[i];
        for (int c = 0; c < 3; ++c) fraction[c] -= std::floor(fraction[c] - origin[c]);
        std::vector<std::string> colour;
        for (const Point3& normal : normals)
            colour.push_back(" " + gnuplot::number(static_cast<double>(i) + lighting.shade(placed.turned(normal)), 6));
        for (int shift = 0; shift < 8; ++shift) {
            const Point3 image{fraction[0] + (shift & 1), fraction[1] + (shift >> 1 & 1), fraction[2] + (shift >> 2 & 1)};
            placed.center = dense::row_combination(rows, image);
            for (const std::vector<int>& face : surface.faces) {
                for (std::size_t k = 0; k < face.size(); ++k) {
                    const Point3 x = placed(surface.vertices[face[k]]);
                    bounds.add(x);
                    text += point_text(x, " ") + colour[face[k]] + "\n";
                    if ((k + 1) % (grid + 1) == 0) text += "\n";
                }
                text += "\n";
            }
        }
    }
    text += "EOD\n";

    const std::string title = "superballs p = " + decimal_or_fraction_text(packing.p) + ", " + std::to_string(n) +
                              " per cell (2 x 2 x 2 cells shown): certified phi >= " + to_fixed(phi, 6).lo;
    text += "$cell << EOD\n" + box_edges(rows, origin, 1, bounds) + "EOD\n";
    text += "$block << EOD\n" + box_edges(rows, origin, 2, bounds) + "EOD\n";
    text += "set terminal pngcairo noenhanced size " + std::to_string(picture_pixels) + "," + std::to_string(picture_pixels) + "\n";
    text += "set output " + gnuplot::quoted(gnuplot::output_path(output)) + "\n";
    text += "unset border\nunset tics\nunset key\nunset colorbox\n" + bounds.ranges();
    text += "set view equal xyz\nset view " + gnuplot::number(view_tilt) + ", " + gnuplot::number(view_turn) + ", " +
            gnuplot::number(fitting_scale(bounds, v), 4) + "\nset xyplane 0\n";
    text += "set pm3d depthorder\nset pm3d corners2color mean\n" + palette(n);
    text += "set style fill solid 1 noborder\n";
    // Two layers: gnuplot draws depth-sorted pm3d after every line of its plot, so the cell's
    // edges are a second plot over the first.
    // Both with the title, so that both get the same margins.
    text += "set multiplot\nset title " + gnuplot::quoted(title) + " font ',15'\n";
    text += "splot $particles using 1:2:3:4 with pm3d\n";
    text += "splot $block with lines linewidth 1 dashtype 2 linecolor rgb '#505050', "
            "$cell with lines linewidth 2 linecolor rgb '#181818'\n";
    text += "unset multiplot\n";
    return text + "unset output\n";
}

}  // namespace

void packing_png(const std::string& path, const PeriodicPacking& packing, const DInterval& phi) {
    gnuplot::write_png(path, [&](const std::string& output) { return script(output, packing, phi); });
}

}  // namespace superpack
