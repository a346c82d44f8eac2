#include "superpack/problems/best/best.hpp"

#include <cmath>

#include "superpack/problems/families/family_registry.hpp"

namespace superpack {

namespace {

// Extra starts besides the families: FCC (the sphere's optimum) and the cubic lattice of the
// cube, each scaled by the search.
std::vector<SearchStart> classical_starts() {
    return {{"FCC", DoubleBasis{{{1, 1, 0}, {1, 0, 1}, {0, 1, 1}}}}, {"cubic", DoubleBasis{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}};
}

template <class I>
DoubleBasis midpoint_basis(const Basis<I>& basis) {
    DoubleBasis b{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) b[i][j] = mid_double(basis[i][j]);
    return b;
}

// The guess's double entries are dyadic rationals, so the exact basis is the guess itself,
// scaled up by 1 + 2^-k: with k = 40, near-contacts of norm 2 (to rounding) clear 2 by about
// 2^-39, far above the enclosure widths, and the density drops by a relative 3 * 2^-40.
Basis<Rational> exact_scaled(const DoubleBasis& guess, int k) {
    const Rational factor = Rational(1) + Rational(1, mpz_class(1) << k);
    Basis<Rational> exact{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) exact[i][j] = Rational(guess[i][j]) * factor;
    return exact;
}

// The fraction with denominator at most 1000 nearest x by continued fractions, if it is within
// 1e-9 of x. Lattices at p = 1/2 (where norms are rational) have rational critical bases.
std::optional<Rational> small_fraction(double x) {
    const double whole = std::floor(x);
    long p0 = 1, q0 = 0, p1 = static_cast<long>(whole), q1 = 1;
    double rest = x - whole;
    for (int step = 0; step < 20 && std::fabs(x - static_cast<double>(p1) / q1) > 1e-12 && rest > 1e-12; ++step) {
        const double inverse = 1 / rest;
        const long a = static_cast<long>(std::floor(inverse));
        rest = inverse - a;
        const long p2 = a * p1 + p0, q2 = a * q1 + q0;
        if (q2 > 1000) break;
        p0 = p1, q0 = q1, p1 = p2, q1 = q2;
    }
    if (std::fabs(x - static_cast<double>(p1) / q1) > 1e-9) return std::nullopt;
    return Rational(p1, q1);
}

// The guess with every entry replaced by its small fraction, when each has one: the exact
// critical lattice itself where it is rational (then its contacts are decided exactly).
std::optional<Basis<Rational>> snapped(const DoubleBasis& guess) {
    Basis<Rational> exact{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const std::optional<Rational> fraction = small_fraction(guess[i][j]);
            if (!fraction) return std::nullopt;
            exact[i][j] = *fraction;
        }
    if (determinant(exact) == 0) return std::nullopt;
    return exact;
}

template <class Field, class I = typename Field::Interval>
SearchLattice<I> check_candidate(const SearchCandidate& candidate, const Rational& p, const Field& field) {
    // A rational critical lattice is checked as it is; any other guess scaled up.
    int scale_exponent = 40;
    Basis<Rational> exact = exact_scaled(candidate.basis, scale_exponent);
    LatticeCheck<I> check;
    const std::optional<Basis<Rational>> fraction = snapped(candidate.basis);
    if (fraction) check = check_exact_lattice(*fraction, p, field);
    if (fraction && check.verdict == Outcome::proved) {
        exact = *fraction;
        scale_exponent = 0;
    } else {
        // Below p = 1/2 too: the closed form of the star test (NOTES.md 13.5) resolves a
        // clearance of 2^-39 at a near contact, where the box cover needed up to 2^-10.
        check = check_exact_lattice(exact, p, field);
    }
    const I phi = enclose_ball_volume(field.rational(p), 3) / abs(determinant(enclose_basis(exact, field)));
    return {candidate, exact, scale_exponent, std::move(check), phi};
}

// The families at p, each certified and checked (those outside their domain only named), and
// the search's starts: their lattices and the classical ones. Below 1/2 the convex families are
// outside their domains and the insertion is the published lattice; at 1/2 it is Minkowski's
// octahedron packing, as O1 is.
template <class Field, class I = typename Field::Interval>
std::vector<SearchStart> certify_families(const Rational& p, const Field& field, BestLattice<I>& best) {
    std::vector<SearchStart> starts;
    for (Family family : convex_families_and_insertion()) {
        if (!family_domain(family, p).inside()) {
            best.outside_domain.push_back(to_string(family));
            continue;
        }
        FamilyLattice<I> lattice = enclose_family(family, p, field);
        LatticeCheck<I> check = check_family_lattice(lattice, p);
        if (lattice.basis) starts.push_back({to_string(family), midpoint_basis(*lattice.basis)});
        best.families.push_back({std::move(lattice), std::move(check)});
    }
    for (const SearchStart& start : classical_starts()) starts.push_back(start);
    return starts;
}

// The densest family proved a packing: the bar a search lattice must pass.
template <class I>
std::optional<std::size_t> densest_family(const BestLattice<I>& best) {
    std::optional<std::size_t> leader;
    for (std::size_t k = 0; k < best.families.size(); ++k) {
        const FamilyEntry<I>& entry = best.families[k];
        if (entry.check.verdict != Outcome::proved || !entry.lattice.phi) continue;
        if (!leader || mid_double(*entry.lattice.phi) > mid_double(*best.families[*leader].lattice.phi)) leader = k;
    }
    return leader;
}

// The search's candidates above the bar, at most four and none repeated, certified or rejected.
template <class Field, class I = typename Field::Interval>
void check_candidates(const Rational& p, const Field& field, double bar, BestLattice<I>& best) {
    constexpr std::size_t most_checked = 4;
    for (const SearchCandidate& candidate : best.search.candidates) {
        bool repeated = false;
        for (const SearchLattice<I>& done : best.checked)
            repeated = repeated || std::fabs(done.guess.density - candidate.density) <= 1e-9 * candidate.density;
        if (!(candidate.density > bar * (1 + 1e-10)) || repeated || best.checked.size() >= most_checked) {
            ++best.rejected;
            continue;
        }
        best.checked.push_back(check_candidate(candidate, p, field));
    }
}

template <class Field, class I = typename Field::Interval>
BestLattice<I> find_best(const Rational& p, const Field& field, const BestOptions& options) {
    require_best_domain(p);
    BestLattice<I> best;
    const I p_interval = field.rational(p);
    const std::vector<SearchStart> starts = certify_families(p, field, best);
    const I volume = enclose_ball_volume(p_interval, 3);
    best.search = search_dense_lattices(mid_double(p_interval), mid_double(volume), starts, options.search);
    const std::optional<std::size_t> leader = densest_family(best);
    check_candidates(p, field, leader ? mid_double(*best.families[*leader].lattice.phi) : 0, best);

    // A search lattice replaces the lattice named so far only when its certified phi is certainly
    // larger: one that coincides with a family (S6 on (p*_o, 1): the search lattice is S6's basis
    // scaled by 1 + 2^-40) or cannot be separated from it leaves the family named, whose lattice
    // is certified by its own definition.
    const I* top = nullptr;
    if (leader) {
        best.source = BestSource::family;
        best.index = *leader;
        top = &*best.families[*leader].lattice.phi;
    }
    for (std::size_t k = 0; k < best.checked.size(); ++k) {
        const SearchLattice<I>& lattice = best.checked[k];
        if (lattice.check.verdict != Outcome::proved) continue;
        if (top == nullptr || certainly_less(*top, lattice.phi)) {
            best.source = BestSource::search;
            best.index = k;
            top = &lattice.phi;
        }
    }
    if (top == nullptr) {
        best.status = Outcome::undecided;
        best.message = "no lattice was certified a packing at this p";
        return best;
    }
    best.status = Outcome::proved;
    // Local optimality is proved on the KKT system of the 2p-norm constraints, which for a star
    // body are not the packing constraints.
    auto local_optimum = [&](const DoubleBasis& basis, const std::vector<Coefficients>& contacts) {
        if (p >= Rational(1, 2)) return certify_local_optimum(basis, contacts, p_interval);
        LocalOptimum<I> none;
        none.reason = "not available below p = 1/2: the packing constraints are the gauge of K - K, not the 2p-norm";
        return none;
    };
    if (best.source == BestSource::family) {
        const FamilyEntry<I>& entry = best.families[best.index];
        best.local = local_optimum(midpoint_basis(*entry.lattice.basis), entry.check.contact_vectors);
        best.configuration = match_configuration(best.families[best.index].check.contact_vectors);
        best.message = "the densest certified lattice is the family " + best_name(best) +
                       "; the search found nothing denser";
    } else {
        const SearchCandidate& guess = best.checked[best.index].guess;
        best.local = local_optimum(guess.basis, guess.near_contacts);
        best.configuration = match_configuration(guess.near_contacts);
        best.message = leader ? "a search lattice, certified admissible, is denser than every certified family"
                              : "a search lattice, certified admissible; no published family is certified a packing here";
    }
    return best;
}

}  // namespace

void require_best_domain(const Rational& p) {
    if (p < Rational(1, 10))
        throw InputError("best: p = " + decimal_or_fraction_text(p) + " is below the supported p >= 1/10 of the search");
    if (p > Rational(1000000))
        throw InputError("best: p = " + decimal_or_fraction_text(p) + " is beyond the supported p <= 10^6 of the search");
}

SearchLattice<DInterval> check_search_lattice(const SearchCandidate& candidate, const Rational& p, const DoubleField& field) {
    return check_candidate(candidate, p, field);
}
SearchLattice<Ball> check_search_lattice(const SearchCandidate& candidate, const Rational& p, const BallField& field) {
    return check_candidate(candidate, p, field);
}

BestLattice<DInterval> find_best_lattice(const Rational& p, const DoubleField& field, const BestOptions& options) {
    return find_best(p, field, options);
}
BestLattice<Ball> find_best_lattice(const Rational& p, const BallField& field, const BestOptions& options) {
    return find_best(p, field, options);
}

template <class I>
const I& best_phi(const BestLattice<I>& best) {
    return best.source == BestSource::family ? *best.families[best.index].lattice.phi : best.checked[best.index].phi;
}

template <class I>
Basis<I> best_basis(const BestLattice<I>& best) {
    if (best.source == BestSource::family) return *best.families[best.index].lattice.basis;
    return enclose_basis(best.checked[best.index].basis, field_of(best.checked[best.index].phi));
}

template <class I>
std::string best_name(const BestLattice<I>& best) {
    if (best.source == BestSource::family) return to_string(best.families[best.index].lattice.family);
    return "search lattice (from " + best.checked[best.index].guess.start + ")";
}

template <class I>
BestCertificate best_certificate(const BestLattice<I>& best) {
    if (best.local && best.local->verdict == Outcome::proved) return BestCertificate::local_optimum;
    if (best.source == BestSource::search) return BestCertificate::search_lattice;
    if (family_definition(best.families[best.index].lattice.family).exact_basis) return BestCertificate::insertion_lattice;
    return BestCertificate::family_lattice;
}

template <class I>
const FamilyEntry<I>* family_entry(const BestLattice<I>& best, Family family) {
    for (const FamilyEntry<I>& entry : best.families)
        if (entry.lattice.family == family) return &entry;
    return nullptr;
}

template <class I>
std::vector<FamilyComparison<I>> compare_families(const BestLattice<I>& best) {
    std::vector<FamilyComparison<I>> comparisons;
    const I& phi = best_phi(best);
    for (std::size_t k = 0; k < best.families.size(); ++k) {
        const FamilyEntry<I>& entry = best.families[k];
        if (entry.check.verdict != Outcome::proved || !entry.lattice.phi) continue;
        const I gap = phi - *entry.lattice.phi;
        if (best.source == BestSource::family && best.index == k)
            comparisons.push_back({&entry, gap, FamilyRelation::ties, "it is the best lattice"});
        else if (certainly_positive(gap))
            comparisons.push_back({&entry, gap, FamilyRelation::beats, ""});
        else
            comparisons.push_back({&entry, gap, FamilyRelation::ties, "phi not separated from the best lattice's at this precision"});
    }
    return comparisons;
}

template const DInterval& best_phi(const BestLattice<DInterval>&);
template const Ball& best_phi(const BestLattice<Ball>&);
template Basis<DInterval> best_basis(const BestLattice<DInterval>&);
template Basis<Ball> best_basis(const BestLattice<Ball>&);
template std::string best_name(const BestLattice<DInterval>&);
template std::string best_name(const BestLattice<Ball>&);
template BestCertificate best_certificate(const BestLattice<DInterval>&);
template BestCertificate best_certificate(const BestLattice<Ball>&);
template const FamilyEntry<DInterval>* family_entry(const BestLattice<DInterval>&, Family);
template const FamilyEntry<Ball>* family_entry(const BestLattice<Ball>&, Family);
template std::vector<FamilyComparison<DInterval>> compare_families(const BestLattice<DInterval>&);
template std::vector<FamilyComparison<Ball>> compare_families(const BestLattice<Ball>&);

}  // namespace superpack
