#include "arith/elementary_double.hpp"

#include <arb_poly.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <tuple>

#include "superpack/arith/arb_access.hpp"
#include "superpack/arith/interval.hpp"

namespace superpack::detail {

namespace {

// exp: x = n ln2/256 + r, |r| <= ln2/512 + tiny, exp(x) = 2^(n div 256) 2^((n mod 256)/256) exp(r),
// exp(r) by its Taylor polynomial of degree 5.
constexpr int kExpTable = 256;
constexpr int kExpDegree = 5;
// log: x = 2^e m, m in [3/4, 3/2) (so that no cancellation of e log 2 and log m arises near
// x = 1), c = j/128 the nearest table point, z = (m - c)/(m + c), log m = log c + 2 atanh z
// with |z| <= 1/384, 2 atanh z = 2 (z + z^3/3 + z^5/5 + z^7/7) + R.
constexpr int kLogTable = 128;
constexpr int kAtanhTerms = 4;
// log Gamma on [1, 2]: Taylor polynomials of degree 13 at the centres c = 1 + (2i + 1)/16.
// With |h| <= 1/16 + 2^-20 and c >= 17/16 the remainder is below 2^-60 (NOTES.md 1.4).
constexpr int kGammaCentres = 8;
constexpr int kGammaDegree = 13;
// The split constants: n ln2/256 and e ln2 must be exact products for |n| < 2^18, |e| < 2^11.
constexpr int kStepBits = 33;
constexpr int kLn2Bits = 42;

// Every constant is an enclosure made once, from exact rationals (MPFR) or from Arb.
struct Tables {
    double ln2_high;            // ln2 to 42 bits, exactly
    DInterval ln2_low;          // ln2 - ln2_high
    double step_high;           // ln2/256 to 33 bits, exactly
    DInterval step_low;         // ln2/256 - step_high
    std::array<DInterval, kExpTable> exp2_fraction;    // 2^(j/256)
    std::array<DInterval, 2 * kLogTable + 1> log_centre;  // log(j/128), j >= 1
    std::array<double, kExpDegree + 1> exp_coefficient;     // 1/k!, rounded to nearest
    std::array<double, kAtanhTerms> atanh_coefficient;      // 1/(2k + 1), rounded to nearest
    std::array<std::array<DInterval, kGammaDegree + 1>, kGammaCentres> log_gamma_taylor;
};

constexpr slong kTableBits = 128;

DInterval to_double(const Ball& x) { return from_arb(arb_of(x)); }

double nearest(const Rational& q) {
    mpfr_t x;
    mpfr_init2(x, 53);
    mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
    const double result = mpfr_get_d(x, MPFR_RNDN);
    mpfr_clear(x);
    return result;
}

// A binary64 number with `bits` significant bits near x, and an enclosure of x minus it.
std::pair<double, DInterval> split(const Ball& x, int bits) {
    int exponent = 0;
    const double fraction = std::frexp(mid_double(x), &exponent);
    const double high = std::ldexp(std::nearbyint(std::ldexp(fraction, bits)), exponent - bits);
    return {high, to_double(x - from_doubles(x, high, high))};
}

const Tables& tables() {
    static const Tables made = [] {
        Tables t;
        const BallField b{kTableBits};
        const Ball ln2 = log(b.integer(2));
        std::tie(t.ln2_high, t.ln2_low) = split(ln2, kLn2Bits);
        std::tie(t.step_high, t.step_low) = split(ln2 / b.integer(kExpTable), kStepBits);
        for (int j = 0; j < kExpTable; ++j) t.exp2_fraction[j] = to_double(exp(b.rational(Rational(j, kExpTable)) * ln2));
        for (int j = 1; j <= 2 * kLogTable; ++j) t.log_centre[j] = to_double(log(b.rational(Rational(j, kLogTable))));
        mpz_class factorial = 1;
        for (int k = 0; k <= kExpDegree; ++k) {
            if (k > 0) factorial *= k;
            t.exp_coefficient[k] = nearest(Rational(1) / Rational(factorial));
        }
        for (int k = 0; k < kAtanhTerms; ++k) t.atanh_coefficient[k] = nearest(Rational(1, 2 * k + 1));
        arb_poly_t shifted, series;
        arb_poly_init(shifted);
        arb_poly_init(series);
        for (int i = 0; i < kGammaCentres; ++i) {
            // log Gamma(c + h) as a power series in h, coefficient k = (log Gamma)^(k)(c) / k!.
            const Ball centre = b.rational(Rational(1) + Rational(2 * i + 1, 2 * kGammaCentres));
            arb_poly_set_coeff_arb(shifted, 0, arb_of(centre));
            arb_poly_set_coeff_si(shifted, 1, 1);
            arb_poly_lgamma_series(series, shifted, kGammaDegree + 1, kTableBits);
            for (int k = 0; k <= kGammaDegree; ++k) {
                Ball coefficient = b.integer(0);
                arb_poly_get_coeff_arb(arb_of(coefficient), series, k);
                t.log_gamma_taylor[i][k] = to_double(coefficient);
            }
        }
        arb_poly_clear(shifted);
        arb_poly_clear(series);
        return t;
    }();
    return made;
}

// [-bound, bound] for a remainder bounded by `bound` (an upper bound).
DInterval symmetric(double bound) { return DInterval(-bound, bound); }

double magnitude(const DInterval& x) { return std::max(std::fabs(x.lower()), std::fabs(x.upper())); }

// 2^k as a binary64 number, for -1022 <= k <= 1023 (a normal number, so scaling by it is exact).
double power_of_two(long k) {
    const std::uint64_t bits = static_cast<std::uint64_t>(k + 1023) << 52;
    double result;
    std::memcpy(&result, &bits, sizeof result);
    return result;
}

// Outside these ranges a result or a scale factor leaves the normal binary64 numbers.
constexpr double kExpArgumentLimit = 700;
constexpr int kLogExponentLimit = 1000;
// A narrower argument is evaluated as one interval; a wider one at its two endpoints
// (exp and log are increasing), so that the series sees a small reduced argument.
constexpr double kNarrowWidth = 0x1p-20;

bool narrow(const DInterval& x) { return x.upper() - x.lower() <= kNarrowWidth; }

// The two series below run in plain round-to-nearest binary64 (the start-up self-test checks
// the mode), with an error bound proved once for the whole reduced range (NOTES.md 1.4)
// instead of interval arithmetic at every step: they are the inner loop of every power.

// exp(r) as 1 + r (1 + r (c2 + r (c3 + r (c4 + r c5)))) for |r| <= 2^-9, u = 2^-53: the last
// addition errs by at most 1.002u, everything before it by 0.004u, and the Taylor remainder
// |r|^6/6! e^|r| is below 2^-62 = 0.002u, so 1.25u bounds the total.
double exp_polynomial(double r, const std::array<double, kExpDegree + 1>& c) {
    double h = c[5];
    for (int k = 4; k >= 1; --k) h = h * r + c[k];
    return 1 + h * r;
}

// 2 atanh z = 2z (1 + z^2/3 + z^4/5 + z^6/7) for |z| <= 2^-8: relative rounding error at most
// 3.2u, so with |value| <= 2^-7 (1 + 2^-15) the error is below 2^-58; with the remainder
// 2|z|^9/(9(1 - z^2)) <= 2^-74, 2^-57 bounds both.
double atanh_series(double z, const std::array<double, kAtanhTerms>& c) {
    const double w = z * z;
    double h = c[kAtanhTerms - 1];
    for (int k = kAtanhTerms - 2; k >= 0; --k) h = h * w + c[k];
    return (2 * z) * h;
}

// exp on a narrow x with |x| <= kExpArgumentLimit.
DInterval exp_narrow(const DInterval& x) {
    const Tables& t = tables();
    rounded_arith_outward rounding;
    // n is a guess: any integer keeps the identity exact; the nearest one makes r small.
    const double n = std::nearbyint(x.lower() / t.step_high);
    // n step_high is exact (18 + 33 bits); x - n step_high is exact by Sterbenz's lemma, and
    // the directed subtraction would round it outward if it were not.
    const double shift = n * t.step_high;
    const DInterval correction = DInterval(n) * t.step_low;
    const double r_lo = rounding.sub_down(rounding.sub_down(x.lower(), shift), correction.upper());
    const double r_hi = rounding.sub_up(rounding.sub_up(x.upper(), shift), correction.lower());
    if (!(std::fabs(r_lo) <= power_of_two(-9) && std::fabs(r_hi) <= power_of_two(-9)))
        throw std::logic_error("exp: argument reduction failed");
    const double error = 5 * power_of_two(-55);
    const double p_lo = exp_polynomial(r_lo, t.exp_coefficient);
    const double p_hi = r_hi == r_lo ? p_lo : exp_polynomial(r_hi, t.exp_coefficient);
    const DInterval series(rounding.sub_down(p_lo, error), rounding.add_up(p_hi, error));
    const long index = static_cast<long>(n);
    const long quotient = index >= 0 ? index / kExpTable : -((-index + kExpTable - 1) / kExpTable);
    const int fraction = static_cast<int>(index - quotient * kExpTable);
    const DInterval scaled = t.exp2_fraction[fraction] * series;
    const double scale = power_of_two(quotient);
    return DInterval(scaled.lower() * scale, scaled.upper() * scale);
}

// log on a narrow x > 0 whose ends share one binade: x = m 2^e with m in [3/4, 3/2) at x's
// lower end (frexp's exponent is `exponent`).
DInterval log_narrow(const DInterval& x, int exponent) {
    const Tables& t = tables();
    rounded_arith_outward rounding;
    const int e = x.lower() * power_of_two(-exponent) < 0.75 ? exponent - 1 : exponent;
    const double scale = power_of_two(-e);
    const double m_lo = x.lower() * scale, m_hi = x.upper() * scale;  // exact: a power of two
    const int j = static_cast<int>(std::nearbyint(m_lo * kLogTable));
    const double centre = static_cast<double>(j) / kLogTable;
    // m - centre is exact: both are multiples of 2^-53 and |m - centre| <= 2^-8 + the width.
    // z = (m - c)/(m + c) is increasing in m, and so is atanh.
    const double z_lo = rounding.div_down(m_lo - centre, m_lo - centre < 0 ? rounding.add_down(m_lo, centre)
                                                                          : rounding.add_up(m_lo, centre));
    const double z_hi = rounding.div_up(m_hi - centre, m_hi - centre < 0 ? rounding.add_up(m_hi, centre)
                                                                        : rounding.add_down(m_hi, centre));
    if (!(std::fabs(z_lo) <= power_of_two(-8) && std::fabs(z_hi) <= power_of_two(-8)))
        throw std::logic_error("log: argument reduction failed");
    const double error = power_of_two(-57);
    const double s_lo = z_lo == 0 ? 0.0 : rounding.sub_down(atanh_series(z_lo, t.atanh_coefficient), error);
    const double s_hi = z_hi == 0 ? 0.0 : rounding.add_up(atanh_series(z_hi, t.atanh_coefficient), error);
    // e ln2_high is exact (11 + 42 bits).
    const double power = static_cast<double>(e);
    return (DInterval(power * t.ln2_high) + t.log_centre[j]) + (DInterval(power) * t.ln2_low + DInterval(s_lo, s_hi));
}

// log Gamma on a narrow y in [1, 2].
DInterval log_gamma_narrow(const DInterval& y) {
    const Tables& t = tables();
    const int i = std::min(kGammaCentres - 1, static_cast<int>(std::floor((y.lower() - 1) * kGammaCentres)));
    const double centre = 1 + static_cast<double>(2 * i + 1) / (2 * kGammaCentres);  // exact
    const DInterval h = y - DInterval(centre);
    if (!(magnitude(h) <= power_of_two(-4) + power_of_two(-20))) throw std::logic_error("gamma: argument reduction failed");
    DInterval series = t.log_gamma_taylor[i][kGammaDegree];
    for (int k = kGammaDegree - 1; k >= 0; --k) series = series * h + t.log_gamma_taylor[i][k];
    return series + symmetric(power_of_two(-60));
}

}  // namespace

DInterval enclose_exp(const DInterval& x) {
    if (!(std::fabs(x.lower()) <= kExpArgumentLimit && std::fabs(x.upper()) <= kExpArgumentLimit))
        return through_arb(x, arb_exp);
    if (narrow(x)) return exp_narrow(x);
    return DInterval(exp_narrow(DInterval(x.lower())).lower(), exp_narrow(DInterval(x.upper())).upper());
}

DInterval enclose_log(const DInterval& x) {
    if (!(x.lower() > 0)) throw std::domain_error("log: argument not certainly positive");
    int low_exponent = 0, high_exponent = 0;
    std::frexp(x.lower(), &low_exponent);
    std::frexp(x.upper(), &high_exponent);
    if (std::isinf(x.upper()) || low_exponent < -kLogExponentLimit || high_exponent > kLogExponentLimit)
        return through_arb(x, arb_log);
    if (low_exponent == high_exponent && narrow(DInterval(x.lower(), x.upper()) * DInterval(power_of_two(1 - low_exponent))))
        return log_narrow(x, low_exponent);
    return DInterval(log_narrow(DInterval(x.lower()), low_exponent).lower(),
                     log_narrow(DInterval(x.upper()), high_exponent).upper());
}

// Half the narrow width, so that the reduced argument (x + 1 or x - m, rounded outward) stays
// within 1/16 + 2^-20 of its Taylor centre, as the remainder bound requires.
bool gamma_series_applies(const DInterval& x) {
    return x.upper() - x.lower() <= kNarrowWidth / 2 && x.lower() >= power_of_two(-4) && x.upper() < 8 &&
           std::floor(x.lower()) == std::floor(x.upper());
}

DInterval enclose_gamma_series(const DInterval& x) {
    if (!gamma_series_applies(x)) throw std::logic_error("gamma: argument outside the series' range");
    // Gamma(x) = Gamma(x + 1) / x below 1, and (x - 1) ... (x - m) Gamma(x - m) above 2.
    if (x.upper() < 1) return enclose_exp(log_gamma_narrow(x + DInterval(1))) / x;
    const double shift = std::floor(x.lower()) - 1;
    DInterval product(1);
    for (double i = 1; i <= shift; ++i) product *= x - DInterval(i);
    return enclose_exp(log_gamma_narrow(x - DInterval(shift))) * product;
}

}  // namespace superpack::detail
