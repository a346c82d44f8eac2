// Certificates of claim kind "local-optimum" (superpack best --certificate FILE when the critical
// lattice is locally optimal, NOTES.md 8.9): best's certificates at p = 0.6 (D14) and p = 2 (C1)
// verify with best's phi; the checker's hand-written KKT Jacobian agrees with the producer's
// automatic differentiation; and every tampering (a bound, a multiplier below 0, rho, the
// Krawczyk box, a contact triple, p) and a box on which the norm's Hessian is unbounded are
// rejected at a named step. On the command line, best writes the kind where it applies and the
// family's certificate at p = 1.
#include <gmpxx.h>
#include <stdlib.h>

#include <filesystem>

#include "checker/core/render.hpp"
#include "checker/formulas/equations_kkt.hpp"
#include "checker/verifier.hpp"
#include "superpack/cert/local_optimum_certificate.hpp"
#include "superpack/problems/best/best.hpp"
#include "support.hpp"
#include "tamper.hpp"

namespace {

using superpack::Rational;
using superpack_checker::Verdict;
using superpack_checker::verify_document;
using superpack::test::collect_bounds;
using superpack::test::rejected_at;
using superpack::test::check_tampered_bound_rejected;
using superpack::test::replay_tampered;
using Document = nlohmann::json;

// best at p (binary64, two random starts), whose critical lattice must be locally optimal.
const superpack::BestLattice<superpack::DInterval>& best_at(const std::string& p) {
    static std::map<std::string, superpack::BestLattice<superpack::DInterval>> cache;
    auto found = cache.find(p);
    if (found != cache.end()) return found->second;
    superpack::BestOptions options;
    options.search.random_starts = 2;
    auto best = superpack::find_best_lattice(superpack::parse_rational(p), superpack::DoubleField{}, options);
    REQUIRE(best.local);
    INFO(best.local->reason);
    REQUIRE(best.local->verdict == superpack::Outcome::proved);
    return cache.emplace(p, std::move(best)).first->second;
}

// Its local-optimum certificate.
const Document& certificate_at(const std::string& p) {
    static std::map<std::string, Document> cache;
    auto found = cache.find(p);
    if (found != cache.end()) return found->second;
    const superpack::Json text = superpack::local_optimum_certificate(*best_at(p).local, superpack::parse_rational(p),
                                                           superpack::DoubleField{}, 15);
    return cache.emplace(p, Document::parse(text.dump())).first->second;
}

// "m*2^e" and its value.
mpq_class dyadic_value(const std::string& text) {
    const std::size_t star = text.find('*');
    mpq_class value(mpz_class(text.substr(0, star), 10));
    if (star == std::string::npos) return value;
    const long e = std::stol(text.substr(star + 3));
    mpq_class power(1);
    if (e > 0) mpz_mul_2exp(power.get_num_mpz_t(), power.get_num_mpz_t(), e);
    else mpz_mul_2exp(power.get_den_mpz_t(), power.get_den_mpz_t(), -e);
    return value * power;
}

// A dyadic rational as "m*2^e".
std::string dyadic_text(const mpq_class& q) {
    mpz_class den = q.get_den();
    long e = 0;
    while (den > 1) {
        REQUIRE(mpz_even_p(den.get_mpz_t()));
        den /= 2;
        --e;
    }
    return q == 0 ? "0" : q.get_num().get_str() + "*2^" + std::to_string(e);
}

// The exact interval [lo, hi] with its decimal rendered by the checker's rule.
Document exact_interval(const mpq_class& lo, const mpq_class& hi) {
    Document interval{{"lo", dyadic_text(lo)}, {"hi", dyadic_text(hi)}};
    const Document copy = interval;
    superpack_checker::Context context(copy, 4096);
    interval["decimal"] = superpack_checker::decimal_field(context.interval(copy, "x"));
    return interval;
}

Document negated(const Document& interval) {
    return exact_interval(-dyadic_value(interval["hi"]), -dyadic_value(interval["lo"]));
}

Document triple(long a, long b, long c) { return Document::array({a, b, c}); }

// p at both places of the claim and the inputs.
void set_p(Document& document, const std::string& p) {
    document["claim"]["data"]["p"] = p;
    document["inputs"]["p"] = p;
    document["inputs"]["p_decimal"] = p;
}

}  // namespace

TEST_CASE("local-optimum: best's certificates at p = 0.6 and p = 2 verify, with best's phi in the sentence") {
    for (const std::string p : {"0.6", "2"}) {
        INFO("p = " << p);
        const auto& best = best_at(p);
        const Document& document = certificate_at(p);
        const auto report = verify_document(document);
        INFO(report.path << ": " << report.message);
        REQUIRE(report.verdict == Verdict::valid);
        CHECK(report.claim_kind == "local-optimum");
        CHECK(document["proof"]["kkt"]["box"].size() == 9 + best.local->contacts.size());
        // The claim's phi is best's critical phi, exactly, and the sentence shows it.
        const Document& phi = document["claim"]["data"]["phi"];
        CHECK(phi == Document::parse(superpack::exact_interval_json(*best.local->phi).dump()));
        superpack_checker::Context context(document, 128);
        const std::string words = superpack_checker::enclosure_words(context.interval(phi, "phi"));
        CHECK(report.rendered_claim.find("packing density phi = V_sb(p) / |det B| in " + words) != std::string::npos);
        CHECK(report.rendered_claim.find("strict local minimiser of |det|") != std::string::npos);
        CHECK(report.rendered_claim.find("a locally densest lattice packing") != std::string::npos);
        // The critical lattice is the best one (a family's KKT point): the two phi overlap.
        CHECK(superpack::test::overlaps(*best.local->phi, superpack::best_phi(best)));
    }
    CHECK(best_at("0.6").local->contacts.size() == 7);
    CHECK(best_at("2").local->contacts.size() == 6);
}

TEST_CASE("local-optimum: the checker's KKT values and Jacobian, derived by hand, agree with the producer's Jets") {
    for (const std::string p_text : {"0.6", "2"}) {
        INFO("p = " << p_text);
        const superpack::LocalOptimum<superpack::DInterval>& local = *best_at(p_text).local;
        const superpack::DoubleField field;
        const superpack::DInterval p = field.rational(superpack::parse_rational(p_text));
        std::vector<superpack::DInterval> x;
        for (const auto& row : *local.basis)
            for (const auto& entry : row) x.push_back(entry);
        x.insert(x.end(), local.multipliers.begin(), local.multipliers.end());
        const std::size_t n = x.size();
        std::vector<superpack_checker::Triple> contacts;
        for (const auto& c : local.contacts) contacts.push_back({c[0], c[1], c[2]});
        const superpack_checker::KktEquations equations{contacts, superpack_checker::rational(superpack::parse_rational(p_text), 128)};
        superpack_checker::Box box;
        for (const auto& xi : x) {
            box.push_back(superpack_checker::doubles(xi.lower(), xi.upper(), 128));
        }
        const auto own = equations.value(box);
        const auto own_jacobian = equations.jacobian(box);
        const auto values = superpack::kkt_equations(x, local.contacts, p);
        REQUIRE(own.size() == n);
        long compared = 0;
        for (std::size_t j = 0; j < n; ++j) {
            std::vector<superpack::Jet<superpack::DInterval>> seeded;
            for (std::size_t k = 0; k < n; ++k) seeded.push_back(k == j ? superpack::variable(x[k]) : superpack::constant(x[k]));
            const auto column = superpack::kkt_equations(seeded, local.contacts, p);
            for (std::size_t i = 0; i < n; ++i) {
                INFO("entry (" << i << ", " << j << "): checker " << superpack_checker::text(own_jacobian[i][j]) << ", producer ["
                               << column[i].derivative.lower() << ", " << column[i].derivative.upper() << "]");
                const superpack_checker::Real producer =
                    superpack_checker::doubles(column[i].derivative.lower(), column[i].derivative.upper(), 128);
                superpack_checker::Real meet(128);
                CHECK(superpack_checker::intersect(meet, own_jacobian[i][j], producer));
                ++compared;
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            const superpack_checker::Real producer = superpack_checker::doubles(values[i].lower(), values[i].upper(), 128);
            superpack_checker::Real meet(128);
            CHECK(superpack_checker::intersect(meet, own[i], producer));
        }
        CHECK(compared == static_cast<long>(n * n));
    }
}

TEST_CASE("local-optimum: changing a digit of any bound is rejected at a proof step") {
    const Document& original = certificate_at("0.6");
    std::vector<std::string> bounds;
    collect_bounds(original["claim"], "/claim", bounds);
    collect_bounds(original["proof"], "/proof", bounds);
    // box and root (16 each), basis (9), multipliers (7), volume, determinant, phi: both ends.
    REQUIRE(bounds.size() == 2 * (16 + 16 + 9 + 7 + 3));
    for (const std::string& bound : bounds) {
        check_tampered_bound_rejected(original, bound);
    }
}

TEST_CASE("local-optimum: multipliers below 0, rho, the box, a contact triple, a basis entry and p are each rejected") {
    const Document& original = certificate_at("0.6");
    const std::size_t m = original["claim"]["data"]["contact_pairs"].size();
    REQUIRE(m == 7);

    // The same lattice with b3 negated: a true KKT point of det B again, but det < 0 and every
    // multiplier negated (the gradient of det changes sign, those of the norms do not).
    Document flipped = original;
    Document& data = flipped["claim"]["data"];
    for (const char* key : {"box", "root"}) {
        Document& box = flipped["proof"]["kkt"][key];
        for (std::size_t k = 6; k < 9; ++k) box[k] = negated(box[k]);
        for (std::size_t k = 9; k < 9 + m; ++k) box[k] = negated(box[k]);
    }
    for (int j = 0; j < 3; ++j) data["basis"][2][j] = negated(data["basis"][2][j]);
    for (std::size_t i = 0; i < m; ++i) data["multipliers"][i] = negated(data["multipliers"][i]);
    // The contact triples (a, b, c) become (a, b, -c), as one triple per pair, first nonzero entry > 0.
    auto flip = [](const Document& c) {
        const long a = c[0], b = c[1], d = -c[2].get<long>();
        return a > 0 || (a == 0 && b > 0) ? triple(a, b, d) : triple(-a, -b, -d);
    };
    for (Document& c : data["contact_pairs"]) c = flip(c);
    for (Document& c : data["contact_vectors"]) c = triple(c[0], c[1], -c[2].get<long>());
    for (Document& c : flipped["proof"]["lattice"]["contacts"]) c["coefficients"] = flip(c["coefficients"]);
    data["determinant"] = negated(data["determinant"]);
    CHECK(rejected_at(flipped) == "claim.data.multipliers[0]");

    // rho: the certificates need rho = 0 or more; a weight that makes H + rho A^T A indefinite.
    Document weight = original;
    const std::string rho = weight["proof"]["second_order"]["rho"];
    weight["proof"]["second_order"]["rho"] = rho == "0" ? "-100000" : "0";
    CHECK(rejected_at(weight) == "proof.second_order.rho");

    // The Krawczyk box shrunk to its upper quarter in b_00, away from the root near its middle.
    Document shrunk = original;
    Document& side = shrunk["proof"]["kkt"]["box"][0];
    const mpq_class lo = dyadic_value(side["lo"]), hi = dyadic_value(side["hi"]);
    side = exact_interval((lo + 3 * hi) / 4, hi);
    CHECK(rejected_at(shrunk) == "proof.kkt");

    // A contact triple dropped: alone (the box no longer fits the system), or with its multiplier
    // everywhere (a KKT system of six pairs, which has no root there).
    Document dropped = original;
    dropped["claim"]["data"]["contact_pairs"].erase(m - 1);
    CHECK(rejected_at(dropped) == "proof.kkt.box");
    for (const char* key : {"box", "root"}) dropped["proof"]["kkt"][key].erase(9 + m - 1);
    dropped["claim"]["data"]["multipliers"].erase(m - 1);
    CHECK(rejected_at(dropped) == "proof.kkt");
    // A triple changed to a lattice vector that is not a contact.
    Document changed = original;
    Document& first = changed["claim"]["data"]["contact_pairs"][0];
    first = triple(2 * first[0].get<long>(), 2 * first[1].get<long>(), 2 * first[2].get<long>());
    CHECK(rejected_at(changed) == "proof.kkt");
    // A triple listed twice, or as its negative (the same pair: the same KKT system).
    Document twice = original;
    twice["claim"]["data"]["contact_pairs"][1] = twice["claim"]["data"]["contact_pairs"][0];
    CHECK(rejected_at(twice) == "claim.data.contact_pairs[1]");
    Document negative = original;
    Document& pair = negative["claim"]["data"]["contact_pairs"][0];
    pair = triple(-pair[0].get<long>(), -pair[1].get<long>(), -pair[2].get<long>());
    CHECK(rejected_at(negative) == "claim.data.contact_pairs[0]");

    // A basis entry nudged (inward by one leading digit; its decimal rendered again).
    CHECK(replay_tampered(original, "/claim/data/basis/1/2/lo").report.path == "claim.data.basis[1][2]");

    // p changed everywhere (the KKT point moves off the box), in the inputs only, or to 1/2.
    Document moved = original;
    set_p(moved, "61/100");
    moved["inputs"]["p_decimal"] = "0.61";
    CHECK(rejected_at(moved) == "proof.kkt");
    Document inputs_only = original;
    inputs_only["inputs"]["p"] = "61/100";
    CHECK(rejected_at(inputs_only) == "inputs.p");
    Document half = original;
    set_p(half, "1/2");
    CHECK(rejected_at(half) == "inputs.p");
}

TEST_CASE("local-optimum: a box on which a contact coordinate may be 0 at p < 1 is rejected, never bounded") {
    // |u|^(2p-2) in the Hessian of the norm is unbounded near u = 0 when p < 1: the KKT
    // Jacobian has no enclosure on such a box, and the replay must say so, not bound it.
    const Document& original = certificate_at("0.6");
    // (1) best's certificate at p = 0.6 with b_00 widened past 0: the contact (1, 0, 0) B has the
    // coordinate b_00.
    const Document& pairs = original["claim"]["data"]["contact_pairs"];
    REQUIRE(std::find(pairs.begin(), pairs.end(), triple(1, 0, 0)) != pairs.end());
    Document wide = original;
    Document& side = wide["proof"]["kkt"]["box"][0];
    REQUIRE(dyadic_value(side["hi"]) < 0);
    side = exact_interval(dyadic_value(side["lo"]), mpq_class(1, 4));
    // (2) O0 at p = 0.85, a KKT point (NOTES.md 11.5.1) whose contacts (2, 0, 0) and (0, 2, 0)
    // have zero coordinates: no lattice there is a local optimum (11.5.2, curvature caveat).
    Document o0 = original;
    set_p(o0, "17/20");
    o0["inputs"]["p_decimal"] = "0.85";
    o0["claim"]["data"]["contact_pairs"] = Document::array(
        {triple(1, 0, 0), triple(0, 1, 0), triple(0, 0, 1), triple(1, 0, -1), triple(0, 1, -1), triple(1, 1, -1)});
    const double height = std::pow(1 - std::pow(2.0, 1 - 1.7), 1 / 1.7);  // c of Eq. 5, a guess
    const mpq_class radius(1, 1 << 20);
    const std::vector<mpq_class> centre{2, 0, 0, 0, 2, 0, 1, 1, mpq_class(2 * height)};
    Document box = Document::array();
    for (const mpq_class& x : centre) box.push_back(exact_interval(x - radius, x + radius));
    for (int i = 0; i < 6; ++i) box.push_back(exact_interval(mpq_class(1, 128), 4));
    o0["proof"]["kkt"]["box"] = box;
    o0["proof"]["kkt"]["root"] = box;
    for (const Document* document : {&wide, &o0}) {
        const auto report = verify_document(*document);
        INFO(report.path << ": " << report.message);
        CHECK(report.verdict == Verdict::invalid);
        CHECK(report.path == "proof.kkt.box");
        CHECK(report.message.find("have no bound there") != std::string::npos);
    }
}

TEST_CASE("best --certificate: local-optimum where the critical lattice is locally optimal, family-lattice at p = 1") {
    std::string pattern = (std::filesystem::temp_directory_path() / "superpack-local-optimum-XXXXXX").string();
    REQUIRE(mkdtemp(pattern.data()) != nullptr);
    const std::filesystem::path folder(pattern);
    // At p = 1 rotations leave no isolated KKT point: today's certificate of the best lattice.
    for (const auto& [p, kind] : {std::pair<std::string, std::string>{"2", "local-optimum"}, {"1", "family-lattice"}}) {
        const std::string file = (folder / ("best-" + p + ".json")).string();
        const std::string command = std::string(SUPERPACK_BINARY) + " best --p " + p + " --starts 2 --certificate '" + file +
                                    "' > /dev/null 2>&1";
        CHECK(std::system(command.c_str()) == 0);
        std::ifstream in(file);
        REQUIRE(in.good());
        const Document document = Document::parse(in);
        CHECK(document["claim"]["kind"] == kind);
        CHECK(verify_document(document).verdict == Verdict::valid);
    }
    std::filesystem::remove_all(folder);
}
