#include "checker/formulas/star_cases.hpp"

#include "checker/core/real.hpp"

namespace superpack_checker {

namespace {

// An upper bound of the reach (1 - A)^(1/q) of one arm, 0 where A may reach 1.
Real reach_upper(const Real& sum, const Real& inverse_q) {
    const Real room = upper_point(integer(1, sum.precision()) - sum);
    return positive(room) ? upper_point(pow_abs(room, inverse_q)) : integer(0, sum.precision());
}

}  // namespace

StarVerdict star_cases(const RationalVector& v, const mpq_class& q, mpfr_prec_t precision) {
    const Real exponent = rational(q, precision), inverse_q = rational(1 / q, precision);
    const Real one = integer(1, precision);
    bool every_case_fails = true;
    for (int k = 0; k < 3; ++k) {
        for (int split = 0; split < 4; ++split) {
            Real in_s = integer(0, precision), in_t = integer(0, precision);
            bool fails = false;
            for (int i = 0, bit = 0; i < 3; ++i) {
                if (i == k) continue;
                const bool s = (split >> bit++) & 1;
                fails = fails || abs(v[i]) >= 1;
                (s ? in_s : in_t) = (s ? in_s : in_t) + pow_abs(rational(v[i], precision), exponent);
            }
            // A_S >= 1 for certain (its lower end is not below 1): the case fails.
            if (fails || !less(lower_point(in_s), one) || !less(lower_point(in_t), one)) continue;
            const Real size = rational(abs(v[k]), precision);
            if (less(in_s, one) && less(in_t, one)) {
                const Real lower_margin = pow_abs(one - in_s, inverse_q) + pow_abs(one - in_t, inverse_q) - size;
                if (positive(lower_margin)) return StarVerdict::overlapping;
            }
            // The case fails only where the reach cannot exceed |v_k|: a margin whose enclosure
            // meets 0 (a contact within the rounding) leaves the answer undecided.
            if (!negative(reach_upper(in_s, inverse_q) + reach_upper(in_t, inverse_q) - size)) every_case_fails = false;
        }
    }
    return every_case_fails ? StarVerdict::disjoint : StarVerdict::undecided;
}

}  // namespace superpack_checker
