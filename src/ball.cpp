#include "superpack/ball.hpp"

#include <algorithm>
#include <utility>

#include "arb_support.hpp"
#include "superpack/interval.hpp"

namespace superpack {

Ball::Ball(slong precision) : precision_(precision) { arb_init(value_); }
Ball::Ball(const Ball& other) : precision_(other.precision_) {
    arb_init(value_);
    arb_set(value_, other.value_);
}
Ball::Ball(Ball&& other) noexcept : precision_(other.precision_) {
    arb_init(value_);
    arb_swap(value_, other.value_);
}
Ball& Ball::operator=(const Ball& other) {
    arb_set(value_, other.value_);
    precision_ = other.precision_;
    return *this;
}
Ball& Ball::operator=(Ball&& other) noexcept {
    arb_swap(value_, other.value_);
    std::swap(precision_, other.precision_);
    return *this;
}
Ball::~Ball() { arb_clear(value_); }

namespace {
slong joint(const Ball& a, const Ball& b) { return std::max(a.precision(), b.precision()); }

template <class Operation>
Ball binary(const Ball& a, const Ball& b, Operation operation) {
    Ball result(joint(a, b));
    operation(result.get(), a.get(), b.get(), result.precision());
    return result;
}

template <class Operation>
Ball with_integer(const Ball& a, long n, Operation operation) {
    Ball result(a.precision());
    operation(result.get(), a.get(), n, result.precision());
    return result;
}

Ball from_arf(const arf_t value, slong precision) {
    Ball result(precision);
    arb_set_arf(result.get(), value);
    return result;
}
}  // namespace

Ball operator+(const Ball& a, const Ball& b) { return binary(a, b, arb_add); }
Ball operator-(const Ball& a, const Ball& b) { return binary(a, b, arb_sub); }
Ball operator*(const Ball& a, const Ball& b) { return binary(a, b, arb_mul); }
Ball operator/(const Ball& a, const Ball& b) { return binary(a, b, arb_div); }
Ball operator-(const Ball& a) {
    Ball result(a.precision());
    arb_neg(result.get(), a.get());
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
    arb_set_fmpq(result.get(), value, precision);
    fmpq_clear(value);
    return result;
}
Ball BallField::integer(long n) const {
    Ball result(precision);
    arb_set_si(result.get(), n);
    return result;
}
Ball BallField::pi() const {
    Ball result(precision);
    arb_const_pi(result.get(), precision);
    return result;
}

namespace {
template <class Operation>
Ball unary(const Ball& x, Operation operation) {
    Ball result(x.precision());
    operation(result.get(), x.get(), result.precision());
    return result;
}
}  // namespace

Ball exp(const Ball& x) { return unary(x, arb_exp); }
Ball log(const Ball& x) {
    if (!arb_is_positive(x.get())) throw std::domain_error("log: argument not certainly positive");
    return unary(x, arb_log);
}
Ball log1p(const Ball& x) {
    if (!arb_is_positive((x + 1).get())) throw std::domain_error("log1p: argument not certainly > -1");
    return unary(x, arb_log1p);
}
Ball expm1(const Ball& x) { return unary(x, arb_expm1); }
Ball sqrt(const Ball& x) { return unary(x, arb_sqrt); }
Ball square(const Ball& x) {
    Ball result(x.precision());
    arb_sqr(result.get(), x.get(), result.precision());
    return result;
}
Ball abs(const Ball& x) {
    Ball result(x.precision());
    if (!arb_contains_zero(x.get())) {
        arb_abs(result.get(), x.get());
        return result;
    }
    // [0, max(|lo|, |hi|)] with lower end exactly 0: arb_abs would keep a radius reaching
    // below zero. arb_nonnegative_part gives [0, b] as a ball whose lower end is 0.
    arb_t magnitude;
    arb_init(magnitude);
    arb_union(magnitude, upper_point(x).get(), (-lower_point(x)).get(), x.precision());
    arb_union(magnitude, magnitude, BallField{x.precision()}.integer(0).get(), x.precision());
    arb_nonnegative_part(result.get(), magnitude);
    arb_clear(magnitude);
    return result;
}
Ball power_of_positive(const Ball& x, const Ball& y) {
    Ball result(std::max(x.precision(), y.precision()));
    arb_log(result.get(), x.get(), result.precision());
    arb_mul(result.get(), result.get(), y.get(), result.precision());
    arb_exp(result.get(), result.get(), result.precision());
    return result;
}
Ball gamma(const Ball& x) { return unary(x, detail::enclose_gamma); }
Ball digamma(const Ball& x) { return unary(x, detail::enclose_digamma); }

Ball lower_point(const Ball& x) {
    arf_t lo;
    arf_init(lo);
    detail::lower_exact(lo, x.get());
    Ball result = from_arf(lo, x.precision());
    arf_clear(lo);
    return result;
}
Ball upper_point(const Ball& x) {
    arf_t hi;
    arf_init(hi);
    detail::upper_exact(hi, x.get());
    Ball result = from_arf(hi, x.precision());
    arf_clear(hi);
    return result;
}
Ball midpoint(const Ball& x) { return from_arf(arb_midref(x.get()), x.precision()); }
Ball hull(const Ball& a, const Ball& b) {
    Ball result = binary(a, b, arb_union);
    // The union's radius is rounded up and may reach below 0 even when a, b >= 0. The hull
    // of nonnegative sets is nonnegative, so cutting at 0 keeps it an enclosure.
    if (arb_is_nonnegative(a.get()) && arb_is_nonnegative(b.get())) arb_nonnegative_part(result.get(), result.get());
    return result;
}
bool intersect(Ball& result, const Ball& a, const Ball& b) {
    Ball value(joint(a, b));
    if (!arb_intersection(value.get(), a.get(), b.get(), value.precision())) return false;
    result = std::move(value);
    return true;
}

bool certainly_positive(const Ball& x) { return arb_is_positive(x.get()); }
bool certainly_negative(const Ball& x) { return arb_is_negative(x.get()); }
bool certainly_nonnegative(const Ball& x) { return arb_is_nonnegative(x.get()); }
bool certainly_less(const Ball& a, const Ball& b) { return arb_lt(a.get(), b.get()); }
bool contains_zero(const Ball& x) { return arb_contains_zero(x.get()); }
bool contains(const Ball& outer, const Ball& inner) { return arb_contains(outer.get(), inner.get()); }
bool interior_contains(const Ball& outer, const Ball& inner) {
    return arb_contains_interior(outer.get(), inner.get());
}

double mid_double(const Ball& x) { return arf_get_d(arb_midref(x.get()), ARF_RND_NEAR); }
double width_upper(const Ball& x) { return 2 * mag_get_d(arb_radref(x.get())); }
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
    arf_add(arb_midref(result.get()), a, b, ARF_PREC_EXACT, ARF_RND_DOWN);
    arf_mul_2exp_si(arb_midref(result.get()), arb_midref(result.get()), -1);
    arf_sub(radius, b, a, ARF_PREC_EXACT, ARF_RND_UP);
    arf_mul_2exp_si(radius, radius, -1);
    arf_get_mag(arb_radref(result.get()), radius);
    arf_clear(a);
    arf_clear(b);
    arf_clear(radius);
    return result;
}

void get_bounds(mpfr_t lo, mpfr_t hi, const Ball& x) { arb_get_interval_mpfr(lo, hi, x.get()); }

}  // namespace superpack
