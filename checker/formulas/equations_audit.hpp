// The families' bases as exact linear forms in their symbols, and the contact identities
// written again from the paper (Jiao, Stillinger, Torquato 2009, Eqs. 1-13), for the claim
// kinds family-lattice-check and audit.
//
// A "unit equation" is a multiset of linear forms f_1..f_k with sum |f_i|^(2p) = 1 at the
// family's parameters: the definitions t^(2p) = 1/2 (t = 2^(-1/(2p))), 3 l^(2p) = 1
// (l = 3^(-1/(2p))), the trivial 1^(2p) = 1, and the contact equations Eq. 2 (C0), Eq. 9 (C1),
// Eq. 5 (O0, c^(2p) = 1 - 2^(1-2p)), both lines of Eq. 12 (O1) and the three equations of D14. A lattice vector v whose
// nonzero coordinates, halved, are those forms up to sign and order (compared as exact linear
// forms, so identically in p and the parameters) has sum |v_i|^(2p) = 2^(2p) exactly: norm 2.
// This decides the contacts that interval evaluation cannot (their norm is exactly 2).
#pragma once
#include <gmpxx.h>

#include <array>
#include <string>
#include <vector>

#include "checker/core/real.hpp"
#include "checker/formulas/triple.hpp"

namespace superpack_checker {

// c_0 + c_1 x_1 + ... + c_n x_n over the family's symbols x_1..x_n (index 0: the constant 1).
using LinearForm = std::vector<mpq_class>;
using FormVector = std::array<LinearForm, 3>;

struct UnitEquation {
    std::string name;  // where it comes from, e.g. "Eq. 2"
    std::vector<LinearForm> terms;
};

struct FamilyForms {
    std::vector<std::string> symbols;     // x_1..x_n, e.g. {"t", "s"}
    std::array<FormVector, 3> basis;      // rows e1, e2, e3 (Eqs. 1, 8, 5, 11; D14 2b1, 2b2, 2b3)
    std::vector<UnitEquation> equations;
};

// The forms of "C0", "C1", "O0", "O1" or "D14"; throws std::invalid_argument for another name.
FamilyForms family_forms(const std::string& family);

FormVector combination(const FamilyForms& forms, const Triple& coefficients);

// The name of the unit equation that makes ||v||_(2p) = 2 identically, or "" when none does.
std::string contact_identity(const FamilyForms& forms, const FormVector& v);

// The value of a form, given the values of the symbols in the order of forms.symbols.
Real evaluate(const LinearForm& form, const std::vector<Real>& values, mpfr_prec_t precision);

}  // namespace superpack_checker
