#include "superpack/problems/families/s6_definition.hpp"

#include <cmath>

namespace superpack {

namespace {

// S6 at p = 9/10 to 17 digits: its basis in the canonical basis (det > 0; rows near O0's
// (2, 0, 0), (1, 1, 2c), (1, -1, 2c), whose contacts are the same six triples) and its
// multipliers in the order of the triples. Written as decimal strings and read exactly: it is only
// the start of Newton's method, so its digits need not be right (scripts/make_s6_golden.py starts
// from the same rows and finds the point at 60 digits).
const char* const seed_basis[3][3] = {{"1.90805548445494916", "0.47475880023923244", "-0.11762932418028790"},
                                      {"0.80513865790399241", "1.13517568504265190", "1.27516095776406723"},
                                      {"1.27493589363672022", "-0.77456511029171860", "1.15811080256286860"}};
const char* const seed_multipliers[6] = {"0.95036130676301218", "1.39984719699950400", "1.42116093853598366",
                                         "0.94906469532231531", "1.38097796027931676", "1.34724881166778884"};

KktPoint seed_point() {
    KktPoint point;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) point.basis[i][j] = parse_rational(seed_basis[i][j]).get_d();
    for (const char* mu : seed_multipliers) point.multipliers.push_back(parse_rational(mu).get_d());
    return point;
}

}  // namespace

const std::vector<Coefficients>& s6_contact_triples() {
    static const std::vector<Coefficients> triples{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, -1}, {1, 0, -1}, {1, -1, 0}};
    return triples;
}

Rational s6_seed_p() { return Rational(9, 10); }

std::optional<KktPoint> s6_guess(double p, std::string& failure) {
    const double start = s6_seed_p().get_d();
    double at = start, step = 1.0 / 400;
    // The seed itself is polished at 9/10 first, so that a step never starts from the rounded seed.
    std::optional<KktPoint> next = kkt_point(seed_point(), start, s6_contact_triples());
    if (!next) {
        failure = "Newton's method found no KKT point with positive multipliers near the stored seed at p = 9/10";
        return std::nullopt;
    }
    KktPoint point = *next;
    while (at != p) {
        const double target = std::fabs(p - at) <= step ? p : at + std::copysign(step, p - at);
        next = kkt_point(point, target, s6_contact_triples());
        if (next) {
            point = *next;
            at = target;
            continue;
        }
        step /= 2;
        if (step < std::ldexp(1.0, -24)) {
            failure = "the floating-point continuation of the KKT point from p = 9/10 stalled at p = " + std::to_string(at) +
                      " (Newton found no KKT point with positive multipliers in the next step)";
            return std::nullopt;
        }
    }
    return point;
}

}  // namespace superpack
