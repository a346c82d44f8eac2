// Certificates of claim kind "superdisk-optimum" (superpack superdisk --p P --certificate FILE):
// the files in proofs/ are valid and agree with the independent mpmath minimum; tampering with
// a bound, a piece, a verdict, p, the argmin or the attaining lattice is rejected naming the
// step; the CLI writes atomically and writes nothing when undecided or outside p > 1/2.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "checker/verifier.hpp"
#include "superpack/cert/superdisk_certificate.hpp"
#include "support.hpp"
#include "tamper.hpp"

namespace {

using superpack_checker::Verdict;
using superpack_checker::verify_document;
using Document = nlohmann::json;
using superpack::test::collect_bounds;
using superpack::test::rejected_at;
using superpack::test::proof_step;
using superpack::test::tamper_bound;

// A certificate built in the process. A loose stopping rule keeps it small (a few dozen
// pieces), so that the tamper loops replay it hundreds of times within seconds; the proof
// has the same structure as the ones in proofs/.
Document certificate(const std::string& p, double relative_tolerance = 1e-2) {
    const superpack::Rational exact = superpack::parse_rational(p);
    superpack::SuperdiskOptions options;
    options.relative_tolerance = relative_tolerance;
    const auto report = superpack::analyse_superdisk(exact, superpack::DoubleField{}, options);
    REQUIRE(report.status == superpack::OptimumStatus::certified);
    return Document::parse(superpack::superdisk_certificate(report, exact, superpack::DoubleField{}, 15).dump());
}

std::vector<std::string> superdisk_proof_files() {
    std::vector<std::string> files;
    const std::filesystem::path folder = std::filesystem::path(SUPERPACK_TEST_DATA) / ".." / ".." / "proofs";
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().filename().string().rfind("superdisk-", 0) == 0) files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

// The enclosure at `pointer` of the document as an MPFI interval at 256 bits.
superpack_checker::Real read_interval(const Document& document, const std::string& pointer) {
    superpack_checker::Context context(document, 256);
    return context.interval(document[Document::json_pointer(pointer)], pointer);
}

// The mpmath value (tests/data/superdisk.json, 45 digits) as a ball of radius 1e-40.
superpack_checker::Real reference(const std::string& decimal) {
    superpack_checker::Real value(256), radius(256);
    REQUIRE(mpfr_set_str(value.lower_end(), decimal.c_str(), 10, MPFR_RNDD) == 0);
    REQUIRE(mpfr_set_str(value.upper_end(), decimal.c_str(), 10, MPFR_RNDU) == 0);
    REQUIRE(mpfr_set_str(radius.lower_end(), "1e-40", 10, MPFR_RNDD) == 0);
    REQUIRE(mpfr_set_str(radius.upper_end(), "1e-40", 10, MPFR_RNDU) == 0);
    return superpack_checker::hull(value - radius, value + radius);
}

bool meet(const superpack_checker::Real& a, const superpack_checker::Real& b) {
    superpack_checker::Real common(256);
    return superpack_checker::intersect(common, a, b);
}

int exit_status(const std::string& arguments) {
    const int raw = std::system((std::string(SUPERPACK_BINARY) + " " + arguments + " >/dev/null 2>&1").c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

}  // namespace

TEST_CASE("superdisk-optimum: the certificates of proofs/ are valid and agree with mpmath") {
    const std::vector<std::string> files = superdisk_proof_files();
    REQUIRE(files.size() >= 4);
    std::ifstream data_file(std::string(SUPERPACK_TEST_DATA) + "/superdisk.json");
    const Document mpmath = Document::parse(data_file);
    int compared = 0;
    for (const std::string& file : files) {
        INFO(file);
        CHECK(std::filesystem::file_size(file) < 2'000'000);
        const auto report = superpack_checker::verify_file(file);
        CHECK(report.verdict == Verdict::valid);
        CHECK(report.claim_kind == "superdisk-optimum");
        std::ifstream in(file);
        const Document document = Document::parse(in);
        const std::string p = document["inputs"]["p_decimal"];
        const auto phi = read_interval(document, "/claim/data/optimal_phi");
        CHECK(superpack_checker::width(phi) < 1e-5);
        if (mpmath.contains(p)) {
            CHECK(meet(phi, reference(mpmath[p]["optimal_phi"])));
            CHECK(meet(read_interval(document, "/claim/data/area"), reference(mpmath[p]["area"])));
            ++compared;
        }
        // The attaining family (mpmath's larger phi) is the one the certificate names.
        const Document& attained = document["claim"]["data"]["attained_by"];
        REQUIRE(attained.size() >= 1);
        if (p == "1") {
            // The circle: both families are the hexagonal lattice, phi = pi / (2 sqrt 3).
            CHECK(attained.size() == 2);
            const superpack_checker::Real root3 = superpack_checker::sqrt(superpack_checker::integer(3, 256));
            CHECK(superpack_checker::subset(superpack_checker::pi(256) / (2 * root3), phi));
        } else if (mpmath.contains(p)) {
            const bool lambda0 = std::stod(mpmath[p]["phi_Lambda0"].get<std::string>()) >
                                 std::stod(mpmath[p]["phi_Lambda1"].get<std::string>());
            CHECK(attained == Document::array({lambda0 ? "Lambda0" : "Lambda1"}));
        }
    }
    CHECK(compared >= 4);
}

TEST_CASE("superdisk-optimum: argmin_t holds every hexagon vertex of the optimal family, none of the other") {
    // The vertices' t from mpmath (scripts/make_superdisk_vertices.py): if a family is optimal,
    // each of its three hexagon vertices (folded into the first octant) is a minimiser of D.
    std::ifstream data_file(std::string(SUPERPACK_TEST_DATA) + "/superdisk_vertices.json");
    const Document vertices = Document::parse(data_file);
    int checked = 0;
    for (const std::string& file : superdisk_proof_files()) {
        INFO(file);
        std::ifstream in(file);
        const Document document = Document::parse(in);
        const std::string p = document["inputs"]["p_decimal"];
        if (!vertices.contains(p)) continue;
        const Document& argmin = document["claim"]["data"]["argmin_t"];
        auto in_argmin = [&](const std::string& t) {
            for (std::size_t k = 0; k < argmin.size(); ++k)
                if (meet(read_interval(document, "/claim/data/argmin_t/" + std::to_string(k)), reference(t))) return true;
            return false;
        };
        const Document& attained = document["claim"]["data"]["attained_by"];
        for (const std::string family : {"Lambda0", "Lambda1"}) {
            const bool optimal = std::find(attained.begin(), attained.end(), family) != attained.end();
            for (const auto& t : vertices[p][family]) {
                INFO(family << " vertex t = " << t.get<std::string>());
                // Lambda0 has t = 1 and Lambda1 t = 0 as a vertex; when only one family is optimal,
                // each vertex of the other is a certified non-minimiser (its gap is > 1e-4).
                if (optimal) CHECK(in_argmin(t));
                else if (attained.size() == 1) CHECK(!in_argmin(t));
                ++checked;
            }
        }
    }
    CHECK(checked >= 16);
}

TEST_CASE("superdisk-optimum: changing a digit of a bound is rejected, naming a step") {
    long tampered = 0, rejected = 0, boxes = 0, boxes_valid = 0;
    for (const char* p : {"1.25", "2"}) {
        const Document original = certificate(p);
        REQUIRE(verify_document(original).verdict == Verdict::valid);
        // Every bound of the claim, the witness and the two lattices; of the pieces, every bound
        // of every tenth piece (each replay takes ~0.05 s, all of them would take minutes).
        std::vector<std::string> bounds;
        collect_bounds(original["claim"], "/claim", bounds);
        collect_bounds(original["proof"]["witness"], "/proof/witness", bounds);
        collect_bounds(original["proof"]["lattices"], "/proof/lattices", bounds);
        const Document& pieces = original["proof"]["pieces"];
        std::set<std::string> methods;
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            // Every tenth piece, and the first piece of each lower-bound method.
            const bool first_of_method = methods.insert(pieces[k]["method"].get<std::string>()).second;
            if (k % 10 == 0 || first_of_method)
                collect_bounds(pieces[k], "/proof/pieces/" + std::to_string(k), bounds);
        }
        REQUIRE(bounds.size() > 50);
        std::cout << "superdisk tamper at p = " << p << ": " << pieces.size() << " pieces, " << bounds.size()
                  << " bounds, methods sampled:";
        for (const std::string& method : methods) std::cout << " " << method;
        std::cout << "\n";
        for (const std::string& bound : bounds) {
            Document copy = original;
            const Document::json_pointer pointer(bound);
            const std::string before = copy[pointer].get<std::string>();
            const std::string after = tamper_bound(copy, bound);
            const auto report = verify_document(copy);
            INFO(p << " " << bound << ": " << before << " -> " << after << " (" << report.path << ": " << report.message << ")");
            if (bound.find("/search_box/") != std::string::npos) {
                // A search box is a hint, not a claimed bound: a smaller box that still holds v(t)
                // and on which K(X) still maps into int X is a valid proof too. Either outcome is
                // sound; a rejection must name the step.
                ++boxes;
                boxes_valid += report.verdict == Verdict::valid;
                CHECK(report.verdict != Verdict::malformed);
                if (report.verdict == Verdict::invalid) CHECK(proof_step(report.path));
                continue;
            }
            CHECK(report.verdict == Verdict::invalid);
            CHECK(proof_step(report.path));
            ++tampered;
            rejected += report.verdict == Verdict::invalid;
        }
    }
    std::cout << "superdisk tamper: " << rejected << " of " << tampered << " single-digit changes of bounds rejected; "
              << boxes << " search-box changes: " << boxes - boxes_valid << " rejected, " << boxes_valid
              << " still valid proofs\n";
}

TEST_CASE("superdisk-optimum: a deleted piece, a changed verdict, p, argmin or attaining lattice is rejected") {
    const Document original = certificate("1.25");
    REQUIRE(verify_document(original).verdict == Verdict::valid);
    const Document& pieces = original["proof"]["pieces"];
    REQUIRE(pieces.size() > 3);

    // A deleted piece leaves a gap in [0, 1], named at the piece after it.
    Document without_piece = original;
    without_piece["proof"]["pieces"].erase(2);
    CHECK(rejected_at(without_piece) == "proof.pieces[2].t");
    Document without_last = original;
    without_last["proof"]["pieces"].erase(pieces.size() - 1);
    CHECK(rejected_at(without_last) == "proof.pieces");
    Document without_first = original;
    without_first["proof"]["pieces"].erase(0);
    CHECK(rejected_at(without_first) == "proof.pieces[0].t");

    // A piece that may hold a minimiser relabelled as discarded.
    std::size_t kept = pieces.size();
    for (std::size_t k = 0; k < pieces.size() && kept == pieces.size(); ++k)
        if (pieces[k]["verdict"] != "discarded") kept = k;
    REQUIRE(kept < pieces.size());
    Document relabelled = original;
    relabelled["proof"]["pieces"][kept]["verdict"] = "discarded";
    auto report = verify_document(relabelled);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path == "proof.pieces[" + std::to_string(kept) + "].verdict");

    // p changed in both places (the proof no longer fits), in the inputs only, or to 1/2.
    Document both = original;
    both["claim"]["data"]["p"] = both["inputs"]["p"] = "13/10";
    report = verify_document(both);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.", 0) == 0);
    INFO("changed p rejected at " << report.path << ": " << report.message);
    Document inputs_only = original;
    inputs_only["inputs"]["p"] = "13/10";
    CHECK(rejected_at(inputs_only) == "inputs.p");
    Document tiling = original;
    tiling["claim"]["data"]["p"] = tiling["inputs"]["p"] = "1/2";
    CHECK(rejected_at(tiling) == "inputs.p");

    // At p = 5/4 Lambda1 is optimal: claiming Lambda0, or dropping the argmin component of
    // t = 0, is rejected.
    Document wrong_family = original;
    wrong_family["claim"]["data"]["attained_by"] = Document::array({"Lambda0"});
    CHECK(rejected_at(wrong_family) == "claim.data.attained_by");
    Document fewer_components = original;
    REQUIRE(fewer_components["claim"]["data"]["argmin_t"].size() >= 1);
    fewer_components["claim"]["data"]["argmin_t"].erase(0);
    CHECK(rejected_at(fewer_components) == "claim.data.argmin_t");

    // A lower-bound method that does not fit (a bounded piece said to be monotone).
    std::size_t bounded = pieces.size();
    for (std::size_t k = 0; k < pieces.size() && bounded == pieces.size(); ++k)
        if (pieces[k]["method"] == "naive_and_mean_value") bounded = k;
    REQUIRE(bounded < pieces.size());
    Document monotone = original;
    monotone["proof"]["pieces"][bounded]["method"] = "left_end";
    report = verify_document(monotone);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.pieces[" + std::to_string(bounded) + "]", 0) == 0);

    // A witness at another t (a true lattice, but not the stated determinant).
    Document other_witness = original;
    other_witness["proof"]["witness"]["t"] = Document{{"lo", "1*2^-1"}, {"hi", "1*2^-1"}};
    report = verify_document(other_witness);
    CHECK(report.verdict == Verdict::invalid);
    CHECK(report.path.rfind("proof.witness", 0) == 0);
}

TEST_CASE("superpack superdisk --certificate on the command line") {
    const std::string folder = std::filesystem::temp_directory_path() / "superpack-test-superdisk-certificate";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const std::string good = folder + "/good.json", none = folder + "/none.json";
    // Written atomically: an old file at the path is replaced whole, and no temporary is left.
    std::ofstream(good) << "old";
    REQUIRE(exit_status("superdisk --p 2 --certificate " + good) == 0);
    CHECK(exit_status("verify " + good) == 0);
    int entries = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        (void)entry;
        ++entries;
    }
    CHECK(entries == 1);
    // Undecided (p = 0.501: the contact system near the y-axis cannot be certified): exit 4,
    // the file at the path is untouched.
    std::ofstream(none) << "old";
    CHECK(exit_status("superdisk --p 0.501 --certificate " + none) == 4);
    std::ifstream kept(none);
    const std::string text((std::istreambuf_iterator<char>(kept)), {});
    CHECK(text == "old");
    std::filesystem::remove(none);
    // p = 1/2 (tiling) and p < 1/2: no certificate of this kind (exit 2), nothing written.
    CHECK(exit_status("superdisk --p 1/2 --certificate " + none) == 2);
    CHECK(exit_status("superdisk --p 0.3 --certificate " + none) == 2);
    CHECK(exit_status("superdisk --scan 1:2:1 --csv --certificate " + none) == 2);
    CHECK(!std::filesystem::exists(none));
    std::filesystem::remove_all(folder);
}
