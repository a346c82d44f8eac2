#include "superpack/arith/ball.hpp"

#include <algorithm>
#include <type_traits>
#include <utility>

#include "arith/arb_support.hpp"
#include "superpack/arith/arb_access.hpp"
#include "superpack/arith/interval.hpp"
#include "superpack/arith/mpfr_bounds.hpp"

namespace superpack {

static_assert(sizeof(arb_struct) == Ball::storage_size, "Ball storage must hold exactly one arb_struct");
static_assert(alignof(arb_struct) <= Ball::storage_alignment, "Ball storage is under-aligned for arb_struct");
static_assert(std::is_same<slong, long>::value, "Ball precisions are Arb's slong");

Ball::Ball(long precision) : precision_(precision) { arb_init(arb_of(*this)); }
Ball::Ball(const Ball& other) : precision_(other.precision_) {
    arb_init(arb_of(*this));
    arb_set(arb_of(*this), arb_of(other));
}
Ball::Ball(Ball&& other) noexcept : precision_(other.precision_) {
    arb_init(arb_of(*this));
    arb_swap(arb_of(*this), arb_of(other));
}
Ball& Ball::operator=(const Ball& other) {
    arb_set(arb_of(*this), arb_of(other));
    precision_ = other.precision_;
    return *this;
}
Ball& Ball::operator=(Ball&& other) noexcept {
    arb_swap(arb_of(*this), arb_of(other));
    std::swap(precision_, other.precision_);
    return *this;
}
Ball::~Ball() { arb_clear(arb_of(*this)); }

namespace {
slong joint(const Ball& a, const Ball& b) { return std::max(a.precision(), b.precision()); }

template <class Operation>
Ball binary(const Ball& a, const Ball& b, Operation operation) {
    Ball result(joint(a, b));
    operation(arb_of(result), arb_of(a), arb_of(b), result.precision());
    return result;
}

template <class Operation>
Ball with_integer(const Ball& a, long n, Operation operation) {
    Ball result(a.precision());
    operation(arb_of(result), arb_of(a), n, result.precision());
    return result;
}

Ball from_arf(const arf_t value, slong precision) {
    Ball result(precision);
    arb_set_arf(arb_of(result), value);
    return result;
}
}  // namespace

Ball operator+(const Ball& a, const Ball& b) { return binary(a, b, arb_add); }
Ball operator-(const Ball& a, const Ball& b) { return binary(a, b, arb_sub); }
Ball operator*(const Ball& a, const Ball& b) { return binary(a, b, arb_mul); }
Ball operator/(const Ball& a, const Ball& b) { return binary(a, b, arb_div); }
Ball operator-(const Ball& a) {
    Ball result(a.precision());
    arb_neg(arb_of(result), arb_of(a));
    return result;
}
Ball operator+(const Ball& a, long n) { return with_integer(a, n, arb_add_si); }
Ball operator-(const Ball& a, long n) { return with_integer(a, n, arb_sub_si); }
Ball operator-(long n, const Ball& a) { return -(a - n); }
Ball operator*(const Ball& a, long n) { return with_integer(a, n, arb_mul_si); }
Ball operator*(long n, const Ball& a) { return a * n; }
Ball operator/(const Ball& a, long n) { return with_integer(a, n, arb_div_si); }
Ball operator/(long n, const Ball& a) { return BallField{a.precision()}.integer(n) / a; }
Ball& operator+=(Ball& a, const Ball& b) { return a = a + b; }
Ball& operator-=(Ball& a, const Ball& b) { return a = a - b; }
Ball& operator*=(Ball& a, const Ball& b) { return a = a * b; }

long bits_for_digits(long digits) {
    // log2(10) < 3.3220; 32 guard bits cover the cancellation in f(s) near its root.
    return static_cast<long>(digits * 3.3220) + 1 + 32;
}

Ball BallField::rational(const Rational& q) const {
    Ball result(precision);
    fmpq_t value;
    fmpq_init(value);
    fmpq_set_mpq(value, q.get_mpq_t());
    arb_set_fmpq(arb_of(result), value, precision);
    fmpq_clear(value);
    return result;
}
Ball BallField::integer(long n) const {
    Ball result(precision);
    arb_set_si(arb_of(result), n);
    return result;
}
Ball BallField::pi() const {
    Ball result(precision);
    arb_const_pi(arb_of(result), precision);
    return result;
}

namespace {
template <class Operation>
Ball unary(const Ball& x, Operation operation) {
    Ball result(x.precision());
    operation(arb_of(result), arb_of(x), result.precision());
    return result;
}
}  // namespace

Ball exp(const Ball& x) { return unary(x, arb_exp); }
Ball log(const Ball& x) {
    if (!arb_is_positive(arb_of(x))) throw std::domain_error("log: argument not certainly positive");
    return unary(x, arb_log);
}
Ball log1p(const Ball& x) {
    if (!arb_is_positive(arb_of(x + 1))) throw std::domain_error("log1p: argument not certainly > -1");
    return unary(x, arb_log1p);
}
Ball expm1(const Ball& x) { return unary(x, arb_expm1); }
Ball sqrt(const Ball& x) { return unary(x, arb_sqrt); }
Ball square(const Ball& x) {
    Ball result(x.precision());
    arb_sqr(arb_of(result), arb_of(x), result.precision());
    return result;
}
Ball abs(const Ball& x) {
    Ball result(x.precision());
    if (!arb_contains_zero(arb_of(x))) {
        arb_abs(arb_of(result), arb_of(x));
        return result;
    }
    // [0, max(|lo|, |hi|)] with lower end exactly 0: arb_abs would keep a radius reaching
    // below zero. arb_nonnegative_part gives [0, b] as a ball whose lower end is 0.
    arb_t magnitude;
    arb_init(magnitude);
    arb_union(magnitude, arb_of(upper_point(x)), arb_of(-lower_point(x)), x.precision());
    arb_union(magnitude, magnitude, arb_of(BallField{x.precision()}.integer(0)), x.precision());
    arb_nonnegative_part(arb_of(result), magnitude);
    arb_clear(magnitude);
    return result;
}
Ball power_of_positive(const Ball& x, const Ball& y) {
    Ball result(std::max(x.precision(), y.precision()));
    arb_log(arb_of(result), arb_of(x), result.precision());
    arb_mul(arb_of(result), arb_of(result), arb_of(y), result.precision());
    arb_exp(arb_of(result), arb_of(result), result.precision());
    return result;
}
Ball gamma(const Ball& x) { return unary(x, detail::enclose_gamma); }
Ball digamma(const Ball& x) { return unary(x, detail::enclose_digamma); }

Ball lower_point(const Ball& x) {
    arf_t lo;
    arf_init(lo);
    detail::lower_exact(lo, arb_of(x));
    Ball result = from_arf(lo, x.precision());
    arf_clear(lo);
    return result;
}
Ball upper_point(const Ball& x) {
    arf_t hi;
    arf_init(hi);
    detail::upper_exact(hi, arb_of(x));
    Ball result = from_arf(hi, x.precision());
    arf_clear(hi);
    return result;
}
Ball midpoint(const Ball& x) { return from_arf(arb_midref(arb_of(x)), x.precision()); }
Ball hull(const Ball& a, const Ball& b) {
    Ball result = binary(a, b, arb_union);
    // The union's radius is rounded up and may reach below 0 even when a, b >= 0. The hull
    // of nonnegative sets is nonnegative, so cutting at 0 keeps it an enclosure.
    if (arb_is_nonnegative(arb_of(a)) && arb_is_nonnegative(arb_of(b))) arb_nonnegative_part(arb_of(result), arb_of(result));
    return result;
}
bool intersect(Ball& result, const Ball& a, const Ball& b) {
    Ball value(joint(a, b));
    if (!arb_intersection(arb_of(value), arb_of(a), arb_of(b), value.precision())) return false;
    result = std::move(value);
    return true;
}

bool certainly_positive(const Ball& x) { return arb_is_positive(arb_of(x)); }
bool certainly_negative(const Ball& x) { return arb_is_negative(arb_of(x)); }
bool certainly_nonnegative(const Ball& x) { return arb_is_nonnegative(arb_of(x)); }
bool certainly_less(const Ball& a, const Ball& b) { return arb_lt(arb_of(a), arb_of(b)); }
bool contains_zero(const Ball& x) { return arb_contains_zero(arb_of(x)); }
bool contains(const Ball& outer, const Ball& inner) { return arb_contains(arb_of(outer), arb_of(inner)); }
bool interior_contains(const Ball& outer, const Ball& inner) {
    return arb_contains_interior(arb_of(outer), arb_of(inner));
}

double mid_double(const Ball& x) { return arf_get_d(arb_midref(arb_of(x)), ARF_RND_NEAR); }
double width_upper(const Ball& x) { return 2 * mag_get_d(arb_radref(arb_of(x))); }
Ball from_doubles(const Ball& like, double lo, double hi) {
    // Midpoint (lo + hi) / 2 exactly and radius (hi - lo) / 2 rounded up to the 30 bits of a
    // mag_t: the ball is [lo, hi] exactly whenever hi - lo has at most 30 significant bits,
    // and otherwise exceeds it by less than 2^-29 of its width. (arb_set_interval_arf rounds
    // the midpoint to the working precision as well, which widens even such intervals.)
    Ball result(like.precision());
    arf_t a, b, radius;
    arf_init(a);
    arf_init(b);
    arf_init(radius);
    arf_set_d(a, lo);
    arf_set_d(b, hi);
    arf_add(arb_midref(arb_of(result)), a, b, ARF_PREC_EXACT, ARF_RND_DOWN);
    arf_mul_2exp_si(arb_midref(arb_of(result)), arb_midref(arb_of(result)), -1);
    arf_sub(radius, b, a, ARF_PREC_EXACT, ARF_RND_UP);
    arf_mul_2exp_si(radius, radius, -1);
    arf_get_mag(arb_radref(arb_of(result)), radius);
    arf_clear(a);
    arf_clear(b);
    arf_clear(radius);
    return result;
}

void get_bounds(mpfr_t lo, mpfr_t hi, const Ball& x) { arb_get_interval_mpfr(lo, hi, arb_of(x)); }

Ball unbounded_above(const Ball& lower) {
    Ball result(lower.precision());
    arb_zero_pm_inf(arb_of(result));
    return result;
}
bool bounded(const Ball& x) { return arb_is_finite(arb_of(x)); }
bool same_interval(const Ball& a, const Ball& b) { return arb_equal(arb_of(a), arb_of(b)) != 0; }

}  // namespace superpack
