// Randomized cross-check of the two arithmetics a certificate passes through: superpack's
// producer backends (binary64 intervals and Arb balls) against the checker's MPFI. On the
// same random input intervals, x^(2p), V_sb(p) and Gamma(x) must overlap (each is a rigorous
// enclosure of the same set), and point inputs must give narrow results (so that overlap
// is not won by width).
#include <iostream>
#include <random>

#include "checker/formulas/equations.hpp"
#include "support.hpp"
#include "superpack/arith/mpfr_bounds.hpp"

namespace {

using superpack_checker::Real;

constexpr int evaluations = 10000;  // per function and per producer backend
constexpr mpfr_prec_t checker_bits = 128;

Real checker_interval(double lo, double hi) {
    return superpack_checker::doubles(lo, hi, checker_bits);  // exact: both ends are doubles
}

template <class I>
bool overlap(const I& producer, const Real& checker) {
    mpfr_t lo, hi;
    mpfr_inits2(300, lo, hi, static_cast<mpfr_ptr>(nullptr));
    superpack::get_bounds(lo, hi, producer);
    const bool met = mpfr_cmp(lo, checker.hi()) <= 0 && mpfr_cmp(checker.lo(), hi) <= 0;
    mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
    return met;
}

bool narrow(const Real& x, double relative) {
    return superpack_checker::width(x) <= relative * std::max(1.0, std::fabs(superpack_checker::middle(x)));
}

// A random interval [lo, lo + w]: a point a third of the time, else of width 2^-k, k in [2, 50].
std::pair<double, double> random_interval(std::mt19937_64& random, double from, double to) {
    const double lo = std::uniform_real_distribution<double>(from, to)(random);
    if (random() % 3 == 0) return {lo, lo};
    const int k = 2 + static_cast<int>(random() % 49);
    return {lo, lo + std::ldexp(1.0, -k)};
}

struct Counts {
    long evaluations = 0, overlapping = 0, narrow_points = 0, points = 0;
};

template <class Field>
void cross_check(const Field& field, const char* name) {
    std::mt19937_64 random(20261125);
    using I = typename Field::Interval;
    auto make = [&](std::pair<double, double> ends) { return superpack::from_doubles(field.integer(0), ends.first, ends.second); };
    Counts power, volume, gamma;
    for (int n = 0; n < evaluations; ++n) {
        // x^(2p), x of either sign (|x|^(2p)), p in [1/2, 4].
        const auto x = random_interval(random, -2.0, 3.0), p = random_interval(random, 0.5, 4.0);
        const I mine = superpack::pow_abs(make(x), field.integer(2) * make(p));
        const Real theirs = superpack_checker::pow_abs(checker_interval(x.first, x.second),
                                                       superpack_checker::integer(2, checker_bits) * checker_interval(p.first, p.second));
        ++power.evaluations;
        power.overlapping += overlap(mine, theirs);
        if (x.first == x.second && p.first == p.second) {
            ++power.points;
            power.narrow_points += narrow(theirs, 1e-30);
        }
        // V_sb(p), p in [0.3, 8].
        const auto q = random_interval(random, 0.3, 8.0);
        const I my_volume = superpack::enclose_ball_volume(make(q), 3);
        const Real their_volume = superpack_checker::superball_volume(checker_interval(q.first, q.second));
        ++volume.evaluations;
        volume.overlapping += overlap(my_volume, their_volume);
        if (q.first == q.second) {
            ++volume.points;
            volume.narrow_points += narrow(their_volume, 1e-30);
        }
        // Gamma(x), x in [0.05, 12], and a tenth of the time near its minimum x0 = 1.46163...
        const auto g = n % 10 == 0 ? random_interval(random, 1.4615, 1.4618) : random_interval(random, 0.05, 12.0);
        const I my_gamma = superpack::gamma(make(g));
        const Real their_gamma = superpack_checker::gamma(checker_interval(g.first, g.second));
        ++gamma.evaluations;
        gamma.overlapping += overlap(my_gamma, their_gamma);
        if (g.first == g.second) {
            ++gamma.points;
            gamma.narrow_points += narrow(their_gamma, 1e-30);
        }
    }
    for (const auto& [what, counts] : {std::pair{"x^(2p)", power}, {"V_sb", volume}, {"Gamma", gamma}}) {
        std::cout << "cross-check " << name << " vs MPFI, " << what << ": " << counts.overlapping << " of "
                  << counts.evaluations << " overlap; " << counts.narrow_points << " of " << counts.points
                  << " point inputs narrower than 1e-30 (relative) in MPFI\n";
        INFO(name << " " << what);
        CHECK(counts.overlapping == counts.evaluations);
        CHECK(counts.narrow_points == counts.points);
        CHECK(counts.points > evaluations / 20);
    }
}

}  // namespace

TEST_CASE("producer backends and the checker's MPFI agree on 10^4 random x^(2p), V_sb, Gamma") {
    cross_check(superpack::DoubleField{}, "binary64");
    cross_check(superpack::BallField{128}, "Arb-128");
}
