#include "checker/claims/family_verdict.hpp"

#include <set>

#include "checker/core/limits.hpp"
#include "checker/core/render.hpp"

namespace superpack_checker {

namespace {

using Coordinates = std::array<Real, 3>;

Coordinates coordinates(const FormVector& v, const std::vector<Real>& values, mpfr_prec_t precision) {
    return {evaluate(v[0], values, precision), evaluate(v[1], values, precision), evaluate(v[2], values, precision)};
}

Real norm(const Coordinates& v, const Real& p) { return lattice_norm(v, 2 * p); }

Coordinates cross(const Coordinates& u, const Coordinates& w) {
    return {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
}

// floor of the upper end of x, or -1 when it exceeds 1000 (too large a box to enumerate).
long floor_of_upper(const Real& x) {
    mpfr_t upper;
    mpfr_init2(upper, x.precision());
    mpfr_floor(upper, x.hi());
    const long result = mpfr_cmp_si(upper, 1000) > 0 || !mpfr_number_p(upper) ? -1 : mpfr_get_si(upper, MPFR_RNDD);
    mpfr_clear(upper);
    return result;
}

// The values of the forms' symbols, in the forms' order, from the replayed parameters.
std::vector<Real> symbol_values(Context& context, const FamilyForms& forms, const NamedReals& symbols,
                                const std::string& enumeration_path) {
    std::vector<Real> values;
    for (const std::string& name : forms.symbols) {
        bool found = false;
        for (const auto& [symbol, value] : symbols)
            if (symbol == name) {
                values.push_back(value);
                found = true;
            }
        if (!found) context.malformed(enumeration_path, "no value for the symbol " + name);
    }
    return values;
}

// An overlap: proved by its witness alone (no enumeration), a nonzero lattice vector whose norm
// is certainly below 2.
FamilyVerdict check_overlap_witness(Context& context, const FamilyForms& forms, const std::vector<Real>& values,
                                    const Real& p, const Json& stated, const std::string& stated_path,
                                    const Json& enumeration, const std::string& enumeration_path) {
    const mpfr_prec_t precision = p.precision();
    FamilyVerdict result;
    if (!enumeration.is_null()) context.malformed(enumeration_path, "an overlap is proved by its witness: expected null");
    const std::string path = stated_path + ".witness";
    const Json& witness = context.member(stated, "witness", stated_path);
    const Triple t = read_triple(context, context.member(witness, "coefficients", path), path + ".coefficients");
    context.require(t != Triple{0, 0, 0}, path, "the zero vector is no witness");
    const Real own = norm(coordinates(combination(forms, t), values, precision), p);
    result.witness = t;
    result.witness_norm = proved_below(context, context.member(witness, "norm", path), path + ".norm", own, 2);
    return result;
}

// The coefficient box from the checker's own basis: |a_i| <= 2 ||e_j x e_k||_1 / |det|; the
// stated box must hold it.
Triple coefficient_bound(Context& context, const FamilyForms& forms, const std::vector<Real>& values, mpfr_prec_t precision,
                         const Json& enumeration, const std::string& enumeration_path) {
    std::array<Coordinates, 3> rows{coordinates(forms.basis[0], values, precision),
                                    coordinates(forms.basis[1], values, precision),
                                    coordinates(forms.basis[2], values, precision)};
    const Real det = rows[0][0] * (rows[1][1] * rows[2][2] - rows[1][2] * rows[2][1]) -
                     rows[0][1] * (rows[1][0] * rows[2][2] - rows[1][2] * rows[2][0]) +
                     rows[0][2] * (rows[1][0] * rows[2][1] - rows[1][1] * rows[2][0]);
    context.require(excludes_zero(det), enumeration_path, "the basis may be singular: determinant " + text(det));
    const Triple stated_bound =
        read_triple(context, context.member(enumeration, "coefficient_bound", enumeration_path), enumeration_path + ".coefficient_bound");
    Triple bound;
    for (int i = 0; i < 3; ++i) {
        const Coordinates normal = cross(rows[(i + 1) % 3], rows[(i + 2) % 3]);
        const long n = floor_of_upper(integer(2, precision) * (abs(normal[0]) + abs(normal[1]) + abs(normal[2])) / abs(det));
        context.require(n >= 0, enumeration_path + ".coefficient_bound", "the coefficient box is too large to enumerate");
        bound[i] = n;
        context.require(stated_bound[i] >= n, enumeration_path + ".coefficient_bound",
                        "the stated bound " + std::to_string(stated_bound[i]) + " on coefficient " + std::to_string(i) +
                            " is below the checker's " + std::to_string(n));
    }
    return bound;
}

// Every canonical triple of the box decided: a contact by one of the family's identities, or
// norm certainly above 2 (certainly below 2 refutes the packing). Returns the contacts.
std::set<Triple> enumerate_contacts(Context& context, const FamilyForms& forms, const std::vector<Real>& values,
                                    const Real& p, const Triple& bound, const std::string& stated_path,
                                    const std::string& enumeration_path) {
    const mpfr_prec_t precision = p.precision();
    const Real two = integer(2, precision);
    std::set<Triple> contacts;
    for (long a = 0; a <= bound[0]; ++a)
        for (long b = (a == 0 ? 0 : -bound[1]); b <= bound[1]; ++b)
            for (long c = (a == 0 && b == 0 ? 1 : -bound[2]); c <= bound[2]; ++c) {
                const Triple t{a, b, c};
                context.count_step();
                const FormVector forms_of_v = combination(forms, t);
                const Coordinates v = coordinates(forms_of_v, values, precision);
                // ||v||_(2p) >= |v_j|: a coordinate certainly beyond 2 settles the triple.
                if (less(two, abs(v[0])) || less(two, abs(v[1])) || less(two, abs(v[2]))) continue;
                if (!contact_identity(forms, forms_of_v).empty()) {
                    contacts.insert(t);
                    continue;
                }
                const Real own = norm(v, p);
                context.require(!less(own, two), stated_path,
                                "the vector " + triple_text(t) + " has norm " + text(own) + " < 2: not a packing");
                context.require(less(two, own), enumeration_path,
                                "the norm enclosure " + text(own) + " of " + triple_text(t) +
                                    " holds 2 and no contact identity of the family decides it");
            }
    return contacts;
}

// The stated contact count and vectors, and the enumeration's listed contacts, must all be the
// checker's contacts. Returns the count.
long check_stated_contacts(Context& context, const std::set<Triple>& contacts, const Json& stated,
                           const std::string& stated_path, const Json& enumeration, const std::string& enumeration_path) {
    const long count = read_integer(context, context.member(stated, "contacts", stated_path), stated_path + ".contacts", 0,
                                    2 * static_cast<long>(max_contact_pairs), "max_contact_pairs");
    context.require(count == 2 * static_cast<long>(contacts.size()), stated_path + ".contacts",
                    "the checker finds " + std::to_string(2 * contacts.size()) + " contacts");
    const Json& vectors = context.member(stated, "contact_vectors", stated_path);
    if (!vectors.is_array()) context.malformed(stated_path + ".contact_vectors", "expected an array");
    std::set<Triple> stated_contacts, distinct;  // distinct: no vector listed twice in place of another
    for (std::size_t k = 0; k < vectors.size(); ++k) {
        Triple t = read_triple(context, vectors[k], stated_path + ".contact_vectors[" + std::to_string(k) + "]");
        distinct.insert(t);
        if (!canonical(t)) t = {-t[0], -t[1], -t[2]};
        stated_contacts.insert(t);
    }
    context.require(stated_contacts == contacts && distinct.size() == 2 * contacts.size() && vectors.size() == distinct.size(),
                    stated_path + ".contact_vectors",
                    "the stated contact vectors differ from the checker's");
    const Json& listed = context.member(enumeration, "contacts", enumeration_path);
    if (!listed.is_array()) context.malformed(enumeration_path + ".contacts", "expected an array");
    std::set<Triple> listed_contacts;
    for (std::size_t k = 0; k < listed.size(); ++k) {
        const std::string path = enumeration_path + ".contacts[" + std::to_string(k) + "]";
        listed_contacts.insert(read_triple(context, context.member(listed[k], "coefficients", path), path + ".coefficients"));
    }
    context.require(listed_contacts == contacts, enumeration_path + ".contacts",
                    "the listed contacts differ from the checker's (each must be one of the family's identities)");
    return count;
}

}  // namespace

FamilyVerdict check_family_verdict(Context& context, const FamilyForms& forms, const NamedReals& symbols, const Real& p,
                                   const std::string& verdict, const Json& stated, const std::string& stated_path,
                                   const Json& enumeration, const std::string& enumeration_path) {
    const std::vector<Real> values = symbol_values(context, forms, symbols, enumeration_path);
    context.current_step = stated_path;
    if (verdict == "overlapping")
        return check_overlap_witness(context, forms, values, p, stated, stated_path, enumeration, enumeration_path);
    if (verdict != "packing") context.malformed(stated_path + ".verdict", "expected packing or overlapping");
    if (!enumeration.is_object() || context.string_at(enumeration, "kind", enumeration_path) != "enumeration")
        context.malformed(enumeration_path, "a packing needs its enumeration");
    const Triple bound = coefficient_bound(context, forms, values, p.precision(), enumeration, enumeration_path);
    const std::set<Triple> contacts = enumerate_contacts(context, forms, values, p, bound, stated_path, enumeration_path);
    FamilyVerdict result;
    result.packing = true;
    result.contacts = check_stated_contacts(context, contacts, stated, stated_path, enumeration, enumeration_path);
    return result;
}

std::string verdict_words(const FamilyVerdict& verdict) {
    if (verdict.packing)
        return "is a packing of the superball |x|^(2p) + |y|^(2p) + |z|^(2p) <= 1 with " + std::to_string(verdict.contacts) +
               " contacts (every nonzero lattice vector has 2p-norm >= 2, with equality exactly for the contact vectors)";
    return "is not a packing: the lattice vector " + triple_text(verdict.witness) + " has 2p-norm in " +
           enclosure_words(*verdict.witness_norm) + " < 2";
}

}  // namespace superpack_checker
