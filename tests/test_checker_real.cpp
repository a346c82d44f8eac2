// The checker's interval arithmetic (checker/core/real.cpp), written on MPFR with the ends stored
// inside each Real, compared with MPFI's functions (another implementation of the same operations)
// on random intervals: every end must be the same number. Both round each end of the exact range
// outward to the same precision, so there is no slack to allow. Precisions 128 (the checker's
// least), 192 and 256 (the last with the ends stored inline) and 320 (ends on the heap); ends from
// 1e-300 to 1e300, both signs, zeros, points, infinite ends and ends that need all the bits.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <mpfi.h>
#include <random>
#include <string>
#include <vector>

#include "checker/core/real.hpp"

namespace {

using superpack_checker::Real;

// MPFI's own interval, for the reference values.
class Reference {
public:
    explicit Reference(mpfr_prec_t precision) { mpfi_init2(value_, precision); }
    explicit Reference(const Real& x) : Reference(x.precision()) { mpfi_interv_fr(value_, x.lo(), x.hi()); }
    Reference(const Reference&) = delete;
    Reference& operator=(const Reference&) = delete;
    ~Reference() { mpfi_clear(value_); }
    mpfi_ptr get() { return value_; }

private:
    mpfi_t value_;
};

// Whether x has the ends of the reference: the same numbers, or both NaN.
bool same_ends(const Real& x, Reference& reference) {
    auto same = [](mpfr_srcptr a, mpfr_srcptr b) { return (mpfr_nan_p(a) && mpfr_nan_p(b)) || mpfr_equal_p(a, b); };
    return same(x.lo(), &reference.get()->left) && same(x.hi(), &reference.get()->right);
}

std::string ends_text(Reference& reference) {
    char lo[96], hi[96];
    mpfr_snprintf(lo, sizeof lo, "%.25Rg", &reference.get()->left);
    mpfr_snprintf(hi, sizeof hi, "%.25Rg", &reference.get()->right);
    return std::string("[") + lo + ", " + hi + "]";
}

class Intervals {
public:
    explicit Intervals(mpfr_prec_t precision) : precision_(precision) {}

    // A random interval: ends of any sign and magnitude, sometimes 0, a point, or infinite, and
    // sometimes with every bit of the precision used.
    Real next() {
        mpfr_t a, b;
        mpfr_inits2(precision_, a, b, static_cast<mpfr_ptr>(nullptr));
        end(a);
        end(b);
        if (pick(8) == 0) mpfr_set(b, a, MPFR_RNDN);
        if (mpfr_greater_p(a, b)) mpfr_swap(a, b);
        const Real x = superpack_checker::outward(a, b, precision_);
        mpfr_clears(a, b, static_cast<mpfr_ptr>(nullptr));
        return x;
    }

private:
    unsigned pick(unsigned n) { return std::uniform_int_distribution<unsigned>(0, n - 1)(random_); }

    void end(mpfr_ptr x) {
        switch (pick(12)) {
            case 0: mpfr_set_zero(x, pick(2) ? 1 : -1); return;
            case 1: mpfr_set_inf(x, pick(2) ? 1 : -1); return;
            case 2: mpfr_set_si(x, static_cast<long>(pick(7)) - 3, MPFR_RNDN); return;
            default: break;
        }
        const double mantissa = std::uniform_real_distribution<double>(0.5, 1)(random_);
        const int exponent = pick(3) == 0 ? static_cast<int>(pick(1990)) - 995 : static_cast<int>(pick(40)) - 20;
        mpfr_set_d(x, pick(2) ? mantissa : -mantissa, MPFR_RNDN);
        if (pick(2)) {  // every bit used: add a tail far below the leading bit
            mpfr_t tail;
            mpfr_init2(tail, precision_);
            mpfr_set_d(tail, std::uniform_real_distribution<double>(0, 1)(random_), MPFR_RNDN);
            mpfr_mul_2si(tail, tail, -static_cast<long>(precision_) + 60, MPFR_RNDN);
            mpfr_add(x, x, tail, MPFR_RNDN);
            mpfr_clear(tail);
        }
        mpfr_mul_2si(x, x, exponent, MPFR_RNDN);
    }

    mpfr_prec_t precision_;
    std::mt19937_64 random_{20261208};
};

using Unary = std::function<Real(const Real&)>;
using UnaryReference = std::function<void(mpfi_ptr, mpfi_ptr)>;
using Binary = std::function<Real(const Real&, const Real&)>;
using BinaryReference = std::function<void(mpfi_ptr, mpfi_ptr, mpfi_ptr)>;

// Compares `own` with `reference` on `count` random intervals where `admits` holds; returns how
// many were compared (the caller requires most of them to be).
long compare_unary(const std::string& name, mpfr_prec_t precision, const Unary& own, const UnaryReference& reference,
                   const std::function<bool(const Real&)>& admits, int count) {
    Intervals intervals(precision);
    long compared = 0;
    for (int k = 0; k < count; ++k) {
        const Real x = intervals.next();
        if (!admits(x)) continue;
        Reference in(x), out(precision);
        reference(out.get(), in.get());
        const Real result = own(x);
        INFO(name << " at " << precision << " bits of " << superpack_checker::text(x) << ": own "
                  << superpack_checker::text(result) << ", MPFI " << ends_text(out));
        CHECK(same_ends(result, out));
        ++compared;
    }
    return compared;
}

long compare_binary(const std::string& name, mpfr_prec_t precision, const Binary& own, const BinaryReference& reference,
                    const std::function<bool(const Real&, const Real&)>& admits, int count) {
    Intervals intervals(precision);
    long compared = 0;
    for (int k = 0; k < count; ++k) {
        const Real a = intervals.next(), b = intervals.next();
        if (!admits(a, b)) continue;
        Reference in_a(a), in_b(b), out(precision);
        reference(out.get(), in_a.get(), in_b.get());
        const Real result = own(a, b);
        INFO(name << " at " << precision << " bits of " << superpack_checker::text(a) << " and " << superpack_checker::text(b)
                  << ": own " << superpack_checker::text(result) << ", MPFI " << ends_text(out));
        CHECK(same_ends(result, out));
        ++compared;
    }
    return compared;
}

bool finite(const Real& x) { return mpfr_number_p(x.lo()) && mpfr_number_p(x.hi()); }

}  // namespace

TEST_CASE("checker Real: arithmetic equals MPFI's end for end, at inline and heap precisions") {
    constexpr int count = 4000;
    for (const mpfr_prec_t precision : {128, 192, 256, 320}) {
        auto any = [](const Real&, const Real&) { return true; };
        CHECK(compare_binary("a + b", precision, [](const Real& a, const Real& b) { return a + b; }, mpfi_add,
                             [](const Real& a, const Real& b) {
                                 // -oo + oo has no value; both sides then give NaN, but say so apart.
                                 return !(mpfr_inf_p(a.lo()) && mpfr_inf_p(b.hi()) && mpfr_sgn(a.lo()) != mpfr_sgn(b.hi()));
                             },
                             count) > count / 2);
        CHECK(compare_binary("a - b", precision, [](const Real& a, const Real& b) { return a - b; }, mpfi_sub, any, count) >
              count / 2);
        CHECK(compare_binary("a b", precision, [](const Real& a, const Real& b) { return a * b; }, mpfi_mul, any, count) ==
              count);
        CHECK(compare_binary("a / b", precision, [](const Real& a, const Real& b) { return a / b; }, mpfi_div,
                             [](const Real& a, const Real& b) { return superpack_checker::excludes_zero(b) && finite(a) && finite(b); },
                             count) > count / 4);
        CHECK(compare_binary("hull", precision, [](const Real& a, const Real& b) { return superpack_checker::hull(a, b); },
                             mpfi_union, any, count) == count);
        CHECK(compare_unary("-x", precision, [](const Real& x) { return -x; }, mpfi_neg,
                            [](const Real&) { return true; }, count) == count);
        CHECK(compare_unary("|x|", precision, [](const Real& x) { return superpack_checker::abs(x); }, mpfi_abs,
                            [](const Real&) { return true; }, count) == count);
        CHECK(compare_unary("x^2", precision, [](const Real& x) { return superpack_checker::square(x); }, mpfi_sqr,
                            [](const Real&) { return true; }, count) == count);
        CHECK(compare_unary("exp", precision, [](const Real& x) { return superpack_checker::exp(x); }, mpfi_exp,
                            [](const Real&) { return true; }, count) == count);
        CHECK(compare_unary("expm1", precision, [](const Real& x) { return superpack_checker::expm1(x); }, mpfi_expm1,
                            [](const Real&) { return true; }, count) == count);
        CHECK(compare_unary("log", precision, [](const Real& x) { return superpack_checker::log(x); }, mpfi_log,
                            [](const Real& x) { return superpack_checker::positive(x); }, count) > count / 8);
        CHECK(compare_unary("log1p", precision, [](const Real& x) { return superpack_checker::log1p(x); }, mpfi_log1p,
                            [](const Real& x) { return mpfr_cmp_si(x.lo(), -1) > 0; }, count) > count / 8);
        CHECK(compare_unary("sqrt", precision, [](const Real& x) { return superpack_checker::sqrt(x); }, mpfi_sqrt,
                            [](const Real& x) { return mpfr_sgn(x.lo()) >= 0; }, count) > count / 8);
    }
}

TEST_CASE("checker Real: constants, conversions and copies across precisions") {
    for (const mpfr_prec_t precision : {128, 256, 320, 1000}) {
        Reference pi(precision), integer(precision), fraction(precision), doubles(precision);
        mpfi_const_pi(pi.get());
        CHECK(same_ends(superpack_checker::pi(precision), pi));
        mpfi_set_si(integer.get(), -123456789);
        CHECK(same_ends(superpack_checker::integer(-123456789, precision), integer));
        const mpq_class third(-1, 3);
        mpfi_set_q(fraction.get(), third.get_mpq_t());
        CHECK(same_ends(superpack_checker::rational(third, precision), fraction));
        mpfi_interv_d(doubles.get(), -0.1, 4.9e-324);
        CHECK(same_ends(superpack_checker::doubles(-0.1, 4.9e-324, precision), doubles));

        // A copy, an assignment to another precision and back, and a vector that grows keep the ends.
        const Real x = superpack_checker::rational(third, precision);
        Real y(precision == 128 ? 320 : 128);
        y = x;
        CHECK(y.precision() == precision);
        CHECK(same_ends(y, fraction));
        std::vector<Real> grown;
        for (int k = 0; k < 100; ++k) grown.push_back(k % 2 ? x : Real(precision));
        CHECK(same_ends(grown[99], fraction));
        CHECK(mpfr_zero_p(grown[98].lo()));
        CHECK(mpfr_zero_p(grown[98].hi()));
    }
}

TEST_CASE("checker Real: a NaN end stays NaN through hull and products, where MPFR's min and max would drop it") {
    Real undefined = superpack_checker::log(superpack_checker::integer(1, 128)) * superpack_checker::integer(1, 128);
    mpfr_set_nan(undefined.lower_end());
    const Real one = superpack_checker::integer(1, 128);
    for (const Real& result : {superpack_checker::hull(undefined, one), superpack_checker::hull(one, undefined), undefined * one,
                               superpack_checker::integer(0, 128) * undefined, undefined * superpack_checker::integer(0, 128)}) {
        CHECK(mpfr_nan_p(result.lo()));
        CHECK_FALSE(superpack_checker::positive(result));
        CHECK_FALSE(superpack_checker::negative(result));
    }
}

namespace {

// An interval with one NaN end: [NaN, end] (nan_lower) or [end, NaN].
Real half_undefined(bool nan_lower, long end, mpfr_prec_t precision) {
    Real x = superpack_checker::integer(end, precision);
    mpfr_set_nan(nan_lower ? x.lower_end() : x.upper_end());
    return x;
}

// MPFI's interval with the same ends as x, as they are (mpfi_interv_fr would make both NaN).
void set_ends(Reference& reference, const Real& x) {
    mpfr_set(&reference.get()->left, x.lo(), MPFR_RNDD);  // exact: the same precision
    mpfr_set(&reference.get()->right, x.hi(), MPFR_RNDU);
}

}  // namespace

TEST_CASE("checker Real: an end NaN undoes the whole interval in quotients, |x| and x^2, as in MPFI") {
    using namespace superpack_checker;
    constexpr mpfr_prec_t precision = 128;
    // Reachable by arithmetic: an overflow [oo, oo] times [-1, 0] is [-oo, NaN] (0 oo has no
    // value), exp of it [0, NaN], and -(1 + exp) is [NaN, -1]: the NaN is a lower end, and mpfr_sgn
    // calls NaN 0, so [NaN, -1] once counted as "at or above 0". Its true range lies in [-2, -1].
    Real overflow(precision);
    mpfr_set_inf(overflow.lower_end(), 1);
    mpfr_set_inf(overflow.upper_end(), 1);
    const Real a = -(integer(1, precision) + exp(hull(integer(-1, precision), integer(0, precision)) * overflow));
    REQUIRE(mpfr_nan_p(a.lo()));
    REQUIRE(mpfr_cmp_si(a.hi(), -1) == 0);
    const Real one_two = hull(integer(1, precision), integer(2, precision));
    // a / [1, 2] reaches -1/2 (a = -1, b = 2); |a| and a^2 are at least 1: none may be bounded as
    // if a were at or above 0 ([NaN, -1], [NaN, -1] and [NaN, 1] before).
    CHECK_FALSE(less(a / one_two, rational(mpq_class(-9, 10), precision)));
    CHECK_FALSE(negative(abs(a)));
    CHECK_FALSE(less(square(a), integer(2, precision)));

    const Real minus_two_minus_one = -one_two;
    for (const bool nan_lower : {true, false}) {
        for (const long end : {-2L, 0L, 2L}) {
            const Real x = half_undefined(nan_lower, end, precision);
            INFO((nan_lower ? "[NaN, " : "[") << end << (nan_lower ? "]" : ", NaN]"));
            Reference in(precision), out(precision);
            set_ends(in, x);
            for (const Real* divisor : {&one_two, &minus_two_minus_one}) {
                Reference by(precision);
                set_ends(by, *divisor);
                mpfi_div(out.get(), in.get(), by.get());
                CHECK(same_ends(x / *divisor, out));
                if (end != 0) {  // a divisor with a NaN end that excludes 0: [NaN, -2] or [2, NaN]
                    mpfi_div(out.get(), by.get(), in.get());
                    if (excludes_zero(x)) CHECK(same_ends(*divisor / x, out));
                }
            }
            mpfi_abs(out.get(), in.get());
            CHECK(same_ends(abs(x), out));
            mpfi_sqr(out.get(), in.get());
            CHECK(same_ends(square(x), out));
            CHECK(mpfr_nan_p(abs(x).hi()));
            CHECK(mpfr_nan_p(square(x).hi()));
        }
    }
}

TEST_CASE("checker Real: building intervals from ends, points of them, intersections, mixed precisions") {
    using namespace superpack_checker;
    // outward and doubles take their ends in either order; a NaN end makes both NaN (mpfi_interv_fr
    // and mpfi_interv_d do the same; std::min(1.0, NaN) would have dropped it).
    mpfr_t three, third, nan;
    mpfr_inits2(320, three, third, nan, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_si(three, 3, MPFR_RNDN);
    mpfr_set_si(third, 1, MPFR_RNDN);
    mpfr_div_si(third, third, 3, MPFR_RNDN);  // not exact in 128 bits
    mpfr_set_nan(nan);
    const Real reversed = outward(three, third, 128);
    CHECK(mpfr_cmp(reversed.lo(), third) < 0);
    CHECK(mpfr_cmp_si(reversed.hi(), 3) == 0);
    const Real ordered = outward(third, three, 128);
    CHECK(mpfr_equal_p(ordered.lo(), reversed.lo()));
    CHECK(mpfr_nan_p(outward(nan, three, 128).hi()));
    CHECK(mpfr_nan_p(outward(three, nan, 128).lo()));
    const Real doubled = doubles(2.5, -0.1, 128);
    CHECK(mpfr_cmp_d(doubled.lo(), -0.1) == 0);
    CHECK(mpfr_cmp_d(doubled.hi(), 2.5) == 0);
    CHECK(mpfr_nan_p(doubles(1.0, std::nan(""), 128).lo()));
    CHECK(mpfr_nan_p(doubles(std::nan(""), 1.0, 128).hi()));
    // exact_interval refuses an end that needs more bits, and then leaves the result alone.
    Real exact = integer(7, 128);
    CHECK_FALSE(exact_interval(exact, three, third));
    CHECK_FALSE(exact_interval(exact, third, three));
    mpfr_neg(three, three, MPFR_RNDN);
    CHECK_FALSE(exact_interval(exact, three, third));  // the upper end alone inexact
    CHECK_FALSE(exact_interval(exact, third, three));
    mpfr_neg(three, three, MPFR_RNDN);
    CHECK(mpfr_cmp_si(exact.lo(), 7) == 0);
    CHECK(mpfr_cmp_si(exact.hi(), 7) == 0);
    CHECK(exact_interval(exact, three, three));
    CHECK(mpfr_cmp_si(exact.lo(), 3) == 0);
    mpfr_clears(three, third, nan, static_cast<mpfr_ptr>(nullptr));

    // Points, intersections and the four operations between two precisions, against MPFI.
    Intervals narrow(128), wide(320);
    for (int k = 0; k < 2000; ++k) {
        const Real a = narrow.next(), b = wide.next();
        INFO(text(a) << " and " << text(b));
        Reference in_a(a), in_b(b), point(128), out(320);
        mpfi_interv_fr(point.get(), a.lo(), a.lo());
        CHECK(same_ends(lower_point(a), point));
        mpfi_interv_fr(point.get(), a.hi(), a.hi());
        CHECK(same_ends(upper_point(a), point));
        Real meet(128);
        if (intersect(meet, a, b)) {
            mpfi_intersect(out.get(), in_a.get(), in_b.get());
            CHECK(same_ends(meet, out));
        } else {
            CHECK((mpfr_less_p(a.hi(), b.lo()) || mpfr_less_p(b.hi(), a.lo())));
        }
        mpfi_add(out.get(), in_a.get(), in_b.get());
        if (!mpfr_nan_p(&out.get()->left) && !mpfr_nan_p(&out.get()->right)) CHECK(same_ends(a + b, out));
        mpfi_sub(out.get(), in_b.get(), in_a.get());
        if (!mpfr_nan_p(&out.get()->left) && !mpfr_nan_p(&out.get()->right)) CHECK(same_ends(b - a, out));
        mpfi_mul(out.get(), in_a.get(), in_b.get());
        CHECK(same_ends(a * b, out));
        if (excludes_zero(a) && finite(a) && finite(b)) {
            mpfi_div(out.get(), in_b.get(), in_a.get());
            CHECK(same_ends(b / a, out));
        }
    }
}
