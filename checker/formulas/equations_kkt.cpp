#include "checker/formulas/equations_kkt.hpp"

#include "checker/formulas/equations.hpp"

namespace superpack_checker {

namespace {

// |u|^e for an exponent interval e of any sign: endpoint-wise where e >= 0 (pow_abs); where e may
// be < 0 only for u away from 0, as exp(e log |u|). Otherwise the power is unbounded near u = 0.
Real power(const Real& u, const Real& e) {
    if (mpfr_sgn(e.lo()) >= 0) return pow_abs(u, e);
    if (!excludes_zero(u))
        throw UnboundedPower("|u|^(2p-2) with u in " + text(u) + " (which may be 0) and 2p - 2 in " + text(e) +
                             " (which may be < 0) is unbounded");
    return exp(e * log(abs(u)));
}

// The second derivative of det B in b_kj and b_lm: zero in one row or one column, else
// +-b_rc for the remaining row r and column c, with the sign of the permutation (k, l, r) ->
// (j, m, c) (det B = sum over permutations s of sgn(s) b_0s(0) b_1s(1) b_2s(2)).
Real second_derivative_of_det(const Box& x, int k, int j, int l, int m) {
    if (k == l || j == m) return Real(x[0].precision());
    const int r = 3 - k - l, c = 3 - j - m;
    // (a, b, 3 - a - b) is an even permutation of (0, 1, 2) exactly when b = a + 1 mod 3.
    const bool even_rows = l == (k + 1) % 3, even_columns = m == (j + 1) % 3;
    const Real& entry = x[3 * r + c];
    return even_rows == even_columns ? entry : -entry;
}

// One contact triple at x: v = c B, n = ||v||_(2p), u = v / n, g = grad n (v), and the Hessian
// of n at v when asked.
struct ContactTerms {
    std::array<Real, 3> v, u, g;
    Real n;
    std::array<std::array<Real, 3>, 3> hessian;
};

ContactTerms contact_terms(const Box& x, const Triple& c, const Real& p, bool with_hessian) {
    const mpfr_prec_t precision = p.precision();
    const Real one = integer(1, precision), two_p = integer(2, precision) * p;
    const std::array<Real, 3> zeros{Real(precision), Real(precision), Real(precision)};
    ContactTerms t{zeros, zeros, zeros, Real(precision), {zeros, zeros, zeros}};
    for (int j = 0; j < 3; ++j) t.v[j] = c[0] * x[j] + c[1] * x[3 + j] + c[2] * x[6 + j];
    t.n = lattice_norm(t.v, two_p);
    for (int j = 0; j < 3; ++j) {
        t.u[j] = t.v[j] / t.n;
        t.g[j] = pow_signed(t.u[j], two_p - one);  // sign(u) |u|^(2p-1)
    }
    if (!with_hessian) return t;
    const Real scale = (two_p - one) / t.n;
    for (int j = 0; j < 3; ++j)
        for (int l = 0; l < 3; ++l) {
            Real entry = -(t.g[j] * t.g[l]);
            if (j == l) entry = entry + power(t.u[j], two_p - integer(2, precision));
            t.hessian[j][l] = scale * entry;
        }
    return t;
}

Real cofactor(const Box& x, int k, int j) {
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    return x[3 * k1 + j1] * x[3 * k2 + j2] - x[3 * k1 + j2] * x[3 * k2 + j1];
}

}  // namespace

std::vector<Real> KktEquations::value(const Box& x) const {
    std::vector<Real> f;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) f.push_back(cofactor(x, k, j));
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const Triple& c = contacts[i];
        const ContactTerms t = contact_terms(x, c, p, false);
        const Real& mu = x[9 + i];
        for (int k = 0; k < 3; ++k)
            if (c[k] != 0)
                for (int j = 0; j < 3; ++j) f[3 * k + j] = f[3 * k + j] - c[k] * (mu * t.g[j]);
        f.push_back(t.n - integer(2, p.precision()));
    }
    return f;
}

std::vector<std::vector<Real>> KktEquations::jacobian(const Box& x) const {
    const mpfr_prec_t precision = p.precision();
    const std::size_t n = 9 + contacts.size();
    std::vector<std::vector<Real>> jac(n, std::vector<Real>(n, Real(precision)));
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int l = 0; l < 3; ++l)
                for (int m = 0; m < 3; ++m) jac[3 * k + j][3 * l + m] = second_derivative_of_det(x, k, j, l, m);
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const Triple& c = contacts[i];
        const ContactTerms t = contact_terms(x, c, p, true);
        const Real& mu = x[9 + i];
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) {
                // dF_(3k+j)/dmu_i and dF_(9+i)/db_kj = dn_i/db_kj = c_ik g_ij.
                jac[3 * k + j][9 + i] = -(c[k] * t.g[j]);
                jac[9 + i][3 * k + j] = c[k] * t.g[j];
                if (c[k] == 0) continue;
                // -mu_i d(c_ik g_ij)/db_lm = -mu_i c_ik c_il d^2n/dv_j dv_m.
                for (int l = 0; l < 3; ++l)
                    if (c[l] != 0)
                        for (int m = 0; m < 3; ++m)
                            jac[3 * k + j][3 * l + m] = jac[3 * k + j][3 * l + m] - (c[k] * c[l]) * (mu * t.hessian[j][m]);
            }
    }
    return jac;
}

std::vector<Real> KktEquations::p_derivative(const Box& x) const {
    const mpfr_prec_t precision = p.precision();
    const Real one = integer(1, precision), two = integer(2, precision), two_p = two * p;
    std::vector<Real> df(9 + contacts.size(), Real(precision));
    for (Real& entry : df) entry = integer(0, precision);
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const Triple& c = contacts[i];
        const ContactTerms t = contact_terms(x, c, p, false);
        std::array<Real, 3> logs{Real(precision), Real(precision), Real(precision)};
        Real l = integer(0, precision);
        for (int j = 0; j < 3; ++j) {
            if (!excludes_zero(t.u[j]))
                throw UnboundedPower("ln|u| with u in " + text(t.u[j]) + ", which may be 0, in the derivative in p");
            logs[j] = log(abs(t.u[j]));
            l = l + pow_abs(t.u[j], two_p) * logs[j];
        }
        const Real& mu = x[9 + i];
        for (int k = 0; k < 3; ++k)
            if (c[k] != 0)
                for (int j = 0; j < 3; ++j) {
                    const Real dg = t.g[j] * (two * logs[j] - (two_p - one) * l / p);
                    df[3 * k + j] = df[3 * k + j] - c[k] * (mu * dg);
                }
        df[9 + i] = t.n * l / p;
    }
    return df;
}

System kkt_system(const KktEquations& equations) {
    return {[equations](const Box& x) { return equations.value(x); },
            [equations](const Box& x) { return equations.jacobian(x); }};
}

std::vector<std::string> kkt_symbols() {
    std::vector<std::string> names;
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) names.push_back("b" + std::to_string(k) + std::to_string(j));
    return names;
}

FamilyForms kkt_forms(const std::vector<Triple>& contacts) {
    FamilyForms forms;
    forms.symbols = kkt_symbols();
    // Symbol 1 + 3k + j is b_kj (index 0 of a form is its constant).
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) {
            LinearForm f(10, 0);
            f[1 + 3 * k + j] = 1;
            forms.basis[k][j] = f;
        }
    for (const Triple& c : contacts) {
        const FormVector v = combination(forms, c);
        UnitEquation equation{"the KKT equation ||c B||_(2p) = 2 for c = " + triple_text(c), {}};
        for (const LinearForm& coordinate : v) {
            LinearForm half = coordinate;
            for (mpq_class& a : half) a /= 2;
            equation.terms.push_back(half);
        }
        forms.equations.push_back(equation);
    }
    return forms;
}

}  // namespace superpack_checker
