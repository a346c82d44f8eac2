#include "checker/formulas/equations_audit.hpp"

#include <algorithm>
#include <stdexcept>

namespace superpack_checker {

namespace {

// A form over n symbols from its coefficients (constant first).
LinearForm form(std::initializer_list<mpq_class> coefficients) { return LinearForm(coefficients); }

bool is_zero(const LinearForm& f) {
    return std::all_of(f.begin(), f.end(), [](const mpq_class& x) { return x == 0; });
}

// f and -f are the same term of a gauge sum: fix the sign so that the first nonzero
// coefficient is positive.
LinearForm up_to_sign(LinearForm f) {
    for (const mpq_class& x : f)
        if (x != 0) {
            if (x < 0)
                for (mpq_class& y : f) y = -y;
            break;
        }
    return f;
}

std::vector<LinearForm> canonical_terms(std::vector<LinearForm> terms) {
    std::vector<LinearForm> result;
    for (LinearForm& f : terms)
        if (!is_zero(f)) result.push_back(up_to_sign(std::move(f)));
    std::sort(result.begin(), result.end());
    return result;
}

}  // namespace

FamilyForms family_forms(const std::string& family) {
    const mpq_class half(1, 2);
    if (family == "C0") {
        // symbols t, s. Eq. 1: e1 = 2t(1, 1, 0), e2 = (0, 0, 2), e3 = (-2s, 2(s + t), 1).
        return {{"t", "s"},
                {{{form({0, 2, 0}), form({0, 2, 0}), form({0, 0, 0})},
                  {form({0, 0, 0}), form({0, 0, 0}), form({2, 0, 0})},
                  {form({0, 0, -2}), form({0, 2, 2}), form({1, 0, 0})}}},
                {{"1^(2p) = 1", {form({1, 0, 0})}},
                 {"t^(2p) = 1/2 (t = 2^(-1/(2p)))", {form({0, 1, 0}), form({0, 1, 0})}},
                 {"Eq. 2: (s + t)^(2p) + s^(2p) + (1/2)^(2p) = 1", {form({0, 1, 1}), form({0, 0, 1}), form({half, 0, 0})}}}};
    }
    if (family == "C1") {
        // Eq. 8: e1 = 2t(1, 1, 0), e2 = 2t(1, 0, 1), e3 = (2(s + t), -2s, -2s).
        return {{"t", "s"},
                {{{form({0, 2, 0}), form({0, 2, 0}), form({0, 0, 0})},
                  {form({0, 2, 0}), form({0, 0, 0}), form({0, 2, 0})},
                  {form({0, 2, 2}), form({0, 0, -2}), form({0, 0, -2})}}},
                {{"1^(2p) = 1", {form({1, 0, 0})}},
                 {"t^(2p) = 1/2 (t = 2^(-1/(2p)))", {form({0, 1, 0}), form({0, 1, 0})}},
                 {"Eq. 9: (s + t)^(2p) + 2 s^(2p) = 1", {form({0, 1, 1}), form({0, 0, 1}), form({0, 0, 1})}}}};
    }
    if (family == "O0") {
        // symbol c. Eq. 5: e1 = (2, 0, 0), e2 = (0, 2, 0), e3 = (1, 1, 2c).
        return {{"c"},
                {{{form({2, 0}), form({0, 0}), form({0, 0})},
                  {form({0, 0}), form({2, 0}), form({0, 0})},
                  {form({1, 0}), form({1, 0}), form({0, 2})}}},
                {{"1^(2p) = 1", {form({1, 0})}},
                 {"Eq. 5: c^(2p) = 1 - 2^(1-2p), i.e. 2 (1/2)^(2p) + c^(2p) = 1", {form({half, 0}), form({half, 0}), form({0, 1})}}}};
    }
    if (family == "O1") {
        // symbols l, q, s. Eq. 11: e1 = 2l(1, 1, -1), e2 = 2(-q, s, -q), e3 = 2(q, -q, -s).
        return {{"l", "q", "s"},
                {{{form({0, 2, 0, 0}), form({0, 2, 0, 0}), form({0, -2, 0, 0})},
                  {form({0, 0, -2, 0}), form({0, 0, 0, 2}), form({0, 0, -2, 0})},
                  {form({0, 0, 2, 0}), form({0, 0, -2, 0}), form({0, 0, 0, -2})}}},
                {{"1^(2p) = 1", {form({1, 0, 0, 0})}},
                 {"3 l^(2p) = 1 (l = 3^(-1/(2p)))", {form({0, 1, 0, 0}), form({0, 1, 0, 0}), form({0, 1, 0, 0})}},
                 {"Eq. 12, first line: 2|q|^(2p) + |s|^(2p) = 1", {form({0, 0, 1, 0}), form({0, 0, 1, 0}), form({0, 0, 0, 1})}},
                 {"Eq. 12, second line: |l+q|^(2p) + |s-l|^(2p) + |l-q|^(2p) = 1",
                  {form({0, 1, 1, 0}), form({0, -1, 0, 1}), form({0, 1, -1, 0})}}}};
    }
    if (family == "D14") {
        // symbols x, y, z (Dostert and Vallentin 2020, Theorem 4.2): rows 2(-x, y, z), 2(z, -x, y),
        // 2(y, z, -x); b1 + b2 = 2(z-x, y-x, y+z) and its cyclic images, b1 + b2 + b3 = 2(s, s, s).
        return {{"x", "y", "z"},
                {{{form({0, -2, 0, 0}), form({0, 0, 2, 0}), form({0, 0, 0, 2})},
                  {form({0, 0, 0, 2}), form({0, -2, 0, 0}), form({0, 0, 2, 0})},
                  {form({0, 0, 2, 0}), form({0, 0, 0, 2}), form({0, -2, 0, 0})}}},
                {{"1^(2p) = 1", {form({1, 0, 0, 0})}},
                 {"D14, first equation: |x|^(2p) + |y|^(2p) + |z|^(2p) = 1", {form({0, 1, 0, 0}), form({0, 0, 1, 0}), form({0, 0, 0, 1})}},
                 {"D14, second equation: |x-y|^(2p) + |z-x|^(2p) + |y+z|^(2p) = 1",
                  {form({0, 1, -1, 0}), form({0, -1, 0, 1}), form({0, 0, 1, 1})}},
                 {"D14, third equation: 3|-x+y+z|^(2p) = 1", {form({0, -1, 1, 1}), form({0, -1, 1, 1}), form({0, -1, 1, 1})}}}};
    }
    throw std::invalid_argument("unknown family \"" + family + "\"");
}

FormVector combination(const FamilyForms& forms, const Triple& coefficients) {
    const std::size_t n = forms.symbols.size() + 1;
    FormVector v{LinearForm(n, 0), LinearForm(n, 0), LinearForm(n, 0)};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (std::size_t k = 0; k < n; ++k) v[j][k] += coefficients[i] * forms.basis[i][j][k];
    return v;
}

std::string contact_identity(const FamilyForms& forms, const FormVector& v) {
    std::vector<LinearForm> halves;
    for (const LinearForm& coordinate : v) {
        LinearForm half = coordinate;
        for (mpq_class& x : half) x /= 2;
        halves.push_back(half);
    }
    const std::vector<LinearForm> terms = canonical_terms(halves);
    for (const UnitEquation& equation : forms.equations)
        if (canonical_terms(equation.terms) == terms) return equation.name;
    return "";
}

Real evaluate(const LinearForm& form, const std::vector<Real>& values, mpfr_prec_t precision) {
    Real result = rational(form[0], precision);
    for (std::size_t k = 0; k < values.size(); ++k)
        if (form[k + 1] != 0) result = result + rational(form[k + 1], precision) * values[k];
    return result;
}

}  // namespace superpack_checker
