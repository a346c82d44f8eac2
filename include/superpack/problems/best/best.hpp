// superpack best: the densest lattice packing of the superball at p that superpack can certify
// (NOTES.md, "Densest lattice search"). The published families (every one whose domain holds p)
// are certified as usual; a floating-point search (problems/guess/lattice_search.hpp) looks for denser
// lattices; a search lattice counts only once made exact and proved admissible by the lattice
// check, and only if it is denser than every certified family. Made exact means: its entries
// replaced by fractions of denominator <= 1000 when each is within 1e-9 of one and that lattice
// is admissible (a rational critical lattice, as at p = 1/2, with its contacts decided exactly);
// otherwise its double entries scaled up by 1 + 2^-40, so that its near-contacts clear 2. The search only guesses: what is reported
// is what was proved, whatever the search found.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "superpack/geometry/contact_configuration.hpp"
#include "superpack/problems/families/family_lattice_check.hpp"
#include "superpack/problems/guess/lattice_search.hpp"
#include "superpack/problems/optimality/local_optimality.hpp"

namespace superpack {

template <class I>
struct FamilyEntry {
    FamilyLattice<I> lattice;
    LatticeCheck<I> check;  // proved: the family lattice is a packing at p
};

// A search candidate made exact and checked.
template <class I>
struct SearchLattice {
    SearchCandidate guess;
    Basis<Rational> basis;  // the guess snapped to small fractions, or its entries times 1 + 2^-k
    int scale_exponent = 0; // that k, or 0 for the snapped fractions
    LatticeCheck<I> check;
    I phi;                  // V(p) / |det basis|, a packing density when check.verdict is proved
};

enum class BestSource { family, search };

template <class I>
struct BestLattice {
    Outcome status = Outcome::undecided;  // proved: a certified packing was found
    std::string message;
    std::vector<FamilyEntry<I>> families;        // every family whose domain holds p
    std::vector<std::string> outside_domain;     // the others, by name
    SearchResult search;
    std::vector<SearchLattice<I>> checked;       // distinct candidates denser than the best family, checked
    long rejected = 0;  // candidates not denser (in floating point) than the best certified family
    BestSource source = BestSource::family;
    std::size_t index = 0;  // into families or checked
    ConfigurationMatch configuration;  // of the best lattice's contacts (search: near contacts, numerically)
    // Whether the critical lattice at the best one (its KKT point for its contacts) is a
    // certified strict local minimiser of |det| (problems/optimality/local_optimality.hpp).
    std::optional<LocalOptimum<I>> local;
};

struct BestOptions {
    SearchOptions search;
};

// The search's domain, 1/10 <= p <= 10^6: throws InputError outside it. At p = 1/20 the search
// did not end within 38 minutes and its finds were undecided by the star test (NOTES.md 13.4).
void require_best_domain(const Rational& p);
// Requires the domain above.
BestLattice<DInterval> find_best_lattice(const Rational& p, const DoubleField& field, const BestOptions& options);
BestLattice<Ball> find_best_lattice(const Rational& p, const BallField& field, const BestOptions& options);

// One search candidate made exact (snapped to small fractions, else scaled by 1 + 2^-40) and
// checked by the lattice check.
SearchLattice<DInterval> check_search_lattice(const SearchCandidate& candidate, const Rational& p, const DoubleField& field);
SearchLattice<Ball> check_search_lattice(const SearchCandidate& candidate, const Rational& p, const BallField& field);

// The best lattice's phi and basis.
template <class I>
const I& best_phi(const BestLattice<I>& best);
template <class I>
Basis<I> best_basis(const BestLattice<I>& best);
template <class I>
std::string best_name(const BestLattice<I>& best);

// The claim of the certificate of a certified best lattice. A certified local optimum proves
// admissibility and phi of the critical lattice as well, so it subsumes the lattice check;
// otherwise the best lattice's own check: a search lattice's exact basis, Minkowski's exact
// basis for the insertion, or the family's lattice claim.
enum class BestCertificate { local_optimum, search_lattice, insertion_lattice, family_lattice };
template <class I>
BestCertificate best_certificate(const BestLattice<I>& best);

// The entry of `family` among the families certified at p, or null when p is outside its domain.
template <class I>
const FamilyEntry<I>* family_entry(const BestLattice<I>& best, Family family);

// Each family proved a packing at p (with its phi) against the best lattice: it "beats" the
// family when the gap phi_best - phi_family is certainly positive, and "ties" otherwise, with the
// reason (the family is the best lattice itself, or the two phi are not separated).
enum class FamilyRelation { beats, ties };
template <class I>
struct FamilyComparison {
    const FamilyEntry<I>* entry;
    I gap;
    FamilyRelation relation;
    std::string reason;  // empty when it beats
};
template <class I>
std::vector<FamilyComparison<I>> compare_families(const BestLattice<I>& best);

}  // namespace superpack
