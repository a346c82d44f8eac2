// The checker's chart forms (checker/formulas/chart_forms.cpp, NOTES.md 12.3 and 12.8): at points
// of random chart boxes, every value lies in its form's enclosure f(m) + sum_k slope_k (x_k - m_k)
// (the equations g_i, det, a weighted sum of them as the Lagrangian is, and a short vector's h_c
// with a random c != 0) and in the basis's enclosure (naive ∩ mean-value). The replay of
// critical-lattice certificates proves its cuts and leaves with these enclosures, and the
// certificate tests do not see a slope that is too narrow: with the h_c slopes dropped, or one
// slope of det set to 0, every certificate test still passed. This one fails under both.
//
// Boxes: both configurations, any faces (face2 > face3 too), each coordinate's width from its
// whole range down to 1e-6 (log-uniform), at a fixed seed; points: corners and interior points.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "checker/formulas/chart_forms.hpp"

namespace {

using namespace superpack_checker;

constexpr mpfr_prec_t bits = 128;

struct Misses {
    long checks = 0, misses = 0;
    std::string first;  // the first value outside its enclosure, for the report
    void check(const Real& value, const Real& enclosure, const std::string& what) {
        ++checks;
        if (subset(value, enclosure)) return;
        if (misses++ == 0) first = what + ": " + text(value) + " not in " + text(enclosure);
    }
};

ChartBox random_box(std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(0, 1);
    ChartBox box{unit(random) < 0.5 ? Configuration::a3 : Configuration::w, static_cast<int>(random() % 6),
                 static_cast<int>(random() % 6), chart_zeros(bits)};
    for (int k = 0; k < chart_dimension; ++k) {
        const double lo0 = k < 2 ? 0 : -1, range = k < 2 ? 1 : 2;
        const double width = range * std::pow(10.0, -6 * unit(random));
        const double lo = lo0 + (range - width) * unit(random);
        box.x[k] = doubles(lo, std::min(lo + width, 1.0), bits);
    }
    return box;
}

// Point s of the box: s < 2 the corners with all lower (upper) ends, s < 4 alternating ends,
// s < 8 random corners, then random points.
ChartBox point_of(const ChartBox& box, int s, std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(0, 1);
    ChartBox point = box;
    for (int k = 0; k < chart_dimension; ++k) {
        const double lo = mpfr_get_d(box.x[k].lo(), MPFR_RNDN), hi = mpfr_get_d(box.x[k].hi(), MPFR_RNDN);
        bool upper = s == 1;
        if (s == 2 || s == 3) upper = (k + s) % 2 == 0;
        if (s >= 4 && s < 8) upper = (random() & 1) != 0;
        double v = upper ? hi : lo;
        if (s >= 8) v = std::min(hi, std::max(lo, lo + (hi - lo) * unit(random)));
        point.x[k] = doubles(v, v, bits);
    }
    return point;
}

// `boxes` random boxes at p, `points` points in each.
Misses probe(const mpq_class& p, int boxes, int points, unsigned long seed) {
    const ChartSetting setting = chart_setting(p, bits);
    std::mt19937_64 random(seed);
    Misses misses;
    for (int t = 0; t < boxes; ++t) {
        const ChartBox box = random_box(random);
        const ChartForms forms = chart_forms(box, setting);
        Triple c{static_cast<long>(random() % 5) - 2, static_cast<long>(random() % 5) - 2, static_cast<long>(random() % 5) - 2};
        if (c == Triple{0, 0, 0}) c = Triple{1, 1, 1};
        const ChartForm h = short_vector_form(box, forms, c, setting);
        const std::vector<double> weights{1, -0.75, 0.5, 2};
        const ChartForm sum = combine(weights, {forms.determinant, forms.equations[0], forms.equations[1], forms.equations[2]});
        std::ostringstream name;
        name << "box " << t << " (" << configuration_name(box.configuration) << ", faces " << box.face2 << " " << box.face3
             << ", c = " << c[0] << " " << c[1] << " " << c[2] << ") ";
        for (int s = 0; s < points; ++s) {
            const ChartBox point = point_of(box, s, random);
            const ChartValues at = chart_values(point, setting);
            const std::string where = name.str() + "point " + std::to_string(s) + " ";
            for (int i = 0; i < 3; ++i)
                misses.check(at.equations[i], enclose(forms.equations[i], point.x, forms.center), where + "g" + std::to_string(i));
            misses.check(at.determinant, enclose(forms.determinant, point.x, forms.center), where + "det");
            const Real combined = at.determinant - doubles(0.75, 0.75, bits) * at.equations[0] +
                                  doubles(0.5, 0.5, bits) * at.equations[1] + doubles(2, 2, bits) * at.equations[2];
            misses.check(combined, enclose(sum, point.x, forms.center), where + "det - 0.75 g0 + 0.5 g1 + 2 g2");
            for (int r = 0; r < 3; ++r)
                for (int j = 0; j < 3; ++j)
                    misses.check(at.basis[r][j], forms.basis[r][j], where + "b" + std::to_string(r) + std::to_string(j));
            const Real hc = half_norm_power(combination(at.basis, c), setting) - integer(1, bits);
            misses.check(hc, enclose(h, point.x, forms.center), where + "h_c");
        }
    }
    return misses;
}

}  // namespace

TEST_CASE("chart forms: g_i, det, a sum of them, h_c and the basis enclose their values on random boxes (p = 2, 3/5)") {
    for (const mpq_class& p : {mpq_class(2), mpq_class(3, 5)}) {
        const Misses misses = probe(p, 150, 12, 20240601);
        INFO("p = " << p.get_str() << ": " << misses.misses << " of " << misses.checks << " values outside; first: " << misses.first);
        CHECK(misses.checks == 150L * 12 * 15);
        CHECK(misses.misses == 0);
    }
}
