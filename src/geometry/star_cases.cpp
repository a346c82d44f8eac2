#include "superpack/geometry/star_cases.hpp"

#include <string>

namespace superpack {

namespace {

// (1 - A)^(1/q) for the part of A below 1 (a case with A >= 1 somewhere in the box is not certain
// to hold, so its reach may be taken over A < 1 only): the reach of one body's arm along x_k. Each
// end from a point, so that a ball's radius never puts a base below 0.
template <class I>
I reach(const I& sum, const I& inverse_q) {
    const auto field = field_of(sum);
    const I zero = field.integer(0), one = field.integer(1);
    const I least = lower_point(one - upper_point(sum)), most = upper_point(one - lower_point(sum));
    const I low = certainly_positive(least) ? lower_point(pow_nonneg(least, inverse_q)) : zero;
    const I high = certainly_positive(most) ? upper_point(pow_nonneg(most, inverse_q)) : zero;
    return hull(low, high);
}

}  // namespace

template <class I>
Outcome star_disjoint_by_cases(const Superball& body, const std::vector<I>& v) {
    const int d = body.dimension;
    if (static_cast<int>(v.size()) != d)
        throw InputError("star overlap: a translation of " + std::to_string(v.size()) + " coordinates for a body of dimension " +
                         std::to_string(d));
    if (2 * body.p > 1) throw InputError("the closed-form overlap test needs 2p <= 1 (a star body or the octahedron)");
    const auto field = field_of(v[0]);
    const I q = field.rational(2 * body.p), inverse_q = field.rational(1 / (2 * body.p));
    const I one = field.integer(1);
    std::vector<I> power, size;
    std::vector<bool> reaches_one;  // |v_i| >= 1 for every v in the box, so |v_i|^q >= 1 exactly
    for (const I& x : v) {
        size.push_back(abs(x));
        // K lies in [-1, 1]^d: a coordinate of size >= 2 parts the two cubes, exactly (the case
        // at k would otherwise weigh 1 + 1 against 2 through rounded powers).
        if (certainly_nonnegative(size.back() - field.integer(2))) return Outcome::proved;
        power.push_back(pow_abs(x, q));
        reaches_one.push_back(certainly_nonnegative(size.back() - one));
    }
    bool every_case_fails = true;
    for (int k = 0; k < d; ++k) {
        for (int split = 0; split < (1 << (d - 1)); ++split) {
            I in_s = field.integer(0), in_t = field.integer(0);
            bool fails = false;
            for (int i = 0, bit = 0; i < d; ++i) {
                if (i == k) continue;
                const bool s = (split >> bit++) & 1;
                fails = fails || reaches_one[i];
                (s ? in_s : in_t) = (s ? in_s : in_t) + power[i];
            }
            if (fails || certainly_nonnegative(in_s - one) || certainly_nonnegative(in_t - one)) continue;
            const I margin = reach(in_s, inverse_q) + reach(in_t, inverse_q) - size[k];
            if (certainly_less(in_s, one) && certainly_less(in_t, one) && certainly_positive(margin)) return Outcome::refuted;
            if (!certainly_nonnegative(-margin)) every_case_fails = false;
        }
    }
    return every_case_fails ? Outcome::proved : Outcome::undecided;
}

template Outcome star_disjoint_by_cases(const Superball&, const std::vector<DInterval>&);
template Outcome star_disjoint_by_cases(const Superball&, const std::vector<Ball>&);

}  // namespace superpack
