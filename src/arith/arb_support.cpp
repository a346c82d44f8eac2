#include "arith/arb_support.hpp"

#include <stdexcept>

namespace superpack::detail {

void lower_exact(arf_t lo, const arb_t x) {
    arf_t radius;
    arf_init(radius);
    arf_set_mag(radius, arb_radref(x));
    arf_sub(lo, arb_midref(x), radius, ARF_PREC_EXACT, ARF_RND_DOWN);
    arf_clear(radius);
}

void upper_exact(arf_t hi, const arb_t x) {
    arf_t radius;
    arf_init(radius);
    arf_set_mag(radius, arb_radref(x));
    arf_add(hi, arb_midref(x), radius, ARF_PREC_EXACT, ARF_RND_UP);
    arf_clear(radius);
}

namespace {

using Function = void (*)(arb_t, const arb_t, slong);

// Hull of f at the two endpoints of x.
void endpoint_hull(arb_t result, const arb_t x, slong precision, Function f) {
    arf_t lo, hi;
    arb_t a, b;
    arf_init(lo);
    arf_init(hi);
    arb_init(a);
    arb_init(b);
    lower_exact(lo, x);
    upper_exact(hi, x);
    arb_set_arf(a, lo);
    arb_set_arf(b, hi);
    f(a, a, precision);
    f(b, b, precision);
    arb_union(result, a, b, precision);
    arf_clear(lo);
    arf_clear(hi);
    arb_clear(a);
    arb_clear(b);
}

void require_positive(const arb_t x, const char* what) {
    if (!arb_is_positive(x)) throw std::domain_error(std::string(what) + ": argument not certainly positive");
}

}  // namespace

void enclose_gamma(arb_t result, const arb_t x, slong precision) {
    require_positive(x, "gamma");
    // A narrow ball: Arb's derivative-bounded evaluation is as tight as the endpoint hull and
    // costs one Gamma instead of two Gamma and two digamma evaluations.
    if (arb_is_exact(x) || mag_cmp_2exp_si(arb_radref(x), arf_abs_bound_lt_2exp_si(arb_midref(x)) - 24) < 0) {
        arb_gamma(result, x, precision);
        return;
    }
    arb_t slope;
    arb_init(slope);
    enclose_digamma(slope, x, precision);
    const bool monotone = arb_is_positive(slope) || arb_is_negative(slope);
    arb_clear(slope);
    if (monotone)
        endpoint_hull(result, x, precision, arb_gamma);
    else
        arb_gamma(result, x, precision);
}

void enclose_digamma(arb_t result, const arb_t x, slong precision) {
    require_positive(x, "digamma");
    if (arb_is_exact(x))
        arb_digamma(result, x, precision);
    else
        endpoint_hull(result, x, precision, arb_digamma);
}

}  // namespace superpack::detail
