// Certificates of claim kind "critical-lattice" (superpack critical --certificate FILE, NOTES.md
// 12.8): the boxes around C1's images at p = 2 and gap 0 certify, and the checker rejects, each at
// a named tree, a changed leaf reason (a symmetric leaf among them), a removed leaf, a cut moved to
// the other side, a split at another coordinate (and one without a coordinate, malformed), a
// closing region leaf pointed at another image, a removed start box and a raised T; and a start
// box of a symmetric ('m') tree replaced by hand-made boxes on each side of each of the leaf's
// conditions (NOTES.md 12.2's fundamental domain, 12.3's reason 7).
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "checker/verifier.hpp"
#include "critical_certificates.hpp"
#include "superpack/cert/certificate.hpp"
#include "support.hpp"
#include "tamper.hpp"

namespace {

using superpack::Rational;
using superpack_checker::Verdict;
using superpack_checker::verify_document;
using superpack::test::rejected_at;
using Document = nlohmann::json;

// critical at p = 2, gap 0, on the boxes of half-width 3e-5 around C1's images, with its trees
// (at 1e-5 two boxes are symmetric leaves and the two others close at once).
const Document& certificate_around_c1() {
    static const Document document =
        superpack::test::critical_certificate_at_p2([](superpack::CriticalOptions& options) { options.around = 3e-5; });
    return document;
}

// The leaves of a tree string (NOTES.md 12.8's grammar): the offset and length of each.
struct Token {
    std::size_t offset, length;
    char letter;
};

// A step: the form ('4' with three coefficient digits for a short vector), the coordinate, then
// 'x' or a side and 16 hex digits.
std::size_t step_length(const std::string& tree, std::size_t at) {
    const std::size_t form = tree[at] == '4' ? 4 : 1;
    return form + (tree[at + form + 1] == 'x' ? 2 : 18);
}

// Where a step's 'l', 'h' or 'x' is.
std::size_t side_of(const std::string& tree, std::size_t step) { return step + (tree[step] == '4' ? 5 : 2); }

void skip_round(const std::string& tree, std::size_t& at) {
    at += 4;  // 'C' and the three pivots
    while (tree[at] != ';') at += step_length(tree, at);
    ++at;
}

void collect_leaves(const std::string& tree, std::size_t& at, std::vector<Token>& leaves) {
    while (tree[at] == 'C') skip_round(tree, at);
    const char letter = tree[at];
    if (letter == 'S') {
        at += 2;  // 'S' and the split coordinate
        collect_leaves(tree, at, leaves);
        collect_leaves(tree, at, leaves);
        return;
    }
    std::size_t length = 1;
    if (letter == 's') length = 4;
    if (letter == 'c') length = tree.find('.', at) + 1 - at;
    leaves.push_back({at, length, letter});
    at += length;
}

std::vector<Token> leaves_of(const std::string& tree) {
    std::vector<Token> leaves;
    std::size_t at = 0;
    collect_leaves(tree, at, leaves);
    REQUIRE(at == tree.size());
    return leaves;
}

// The first tree with a leaf of `letter`: its index and the leaf.
std::pair<std::size_t, Token> first_leaf(const Document& document, char letter) {
    const Document& trees = document["proof"]["trees"];
    for (std::size_t k = 0; k < trees.size(); ++k)
        for (const Token& token : leaves_of(trees[k].get<std::string>()))
            if (token.letter == letter) return {k, token};
    FAIL("no leaf '" << letter << "'");
    return {0, {0, 0, letter}};
}

std::string tree_path(std::size_t k) { return "proof.trees[" + std::to_string(k) + "]"; }

// The first tree with a split (the trees of start boxes outside the fundamental domain are one 'm').
std::size_t first_split_tree(const Document& document) {
    const Document& trees = document["proof"]["trees"];
    for (std::size_t k = 0; k < trees.size(); ++k)
        if (trees[k].get<std::string>().find('S') != std::string::npos) return k;
    FAIL("no tree with a split");
    return 0;
}

// The first leaf of `letter` replaced by change(leaf) must be rejected at its tree.
void check_leaf_change_rejected(const Document& original, char letter,
                                const std::function<std::string(const std::string&)>& change) {
    Document copy = original;
    const auto [k, leaf] = first_leaf(copy, letter);
    std::string tree = copy["proof"]["trees"][k];
    tree.replace(leaf.offset, leaf.length, change(tree.substr(leaf.offset, leaf.length)));
    copy["proof"]["trees"][k] = tree;
    CHECK(rejected_at(copy).rfind(tree_path(k), 0) == 0);
}

// A start box {configuration, face2, face3, x}: x_k in centre_k +- 1/64, except a2 = x[2] in
// [-1, -15/16] when `a2_at_minus_one` (every end a binary64 number, all in the chart's domain).
Document chart_box_json(const char* configuration, int face2, int face3, const std::array<double, 6>& centre,
                        bool a2_at_minus_one = false) {
    Document x = Document::array();
    for (int k = 0; k < 6; ++k) {
        const bool edge = a2_at_minus_one && k == 2;
        const superpack::DInterval xk(edge ? -1.0 : centre[k] - 1.0 / 64, edge ? -15.0 / 16 : centre[k] + 1.0 / 64);
        x.push_back(Document::parse(superpack::exact_interval_json(xk).dump()));
    }
    return {{"configuration", configuration}, {"face2", face2}, {"face3", face3}, {"x", x}};
}

}  // namespace

TEST_CASE("critical-lattice certificate at p = 2 around C1's images (gap 0): it verifies, with the leaf kinds near C1") {
    const Document& document = certificate_around_c1();
    const auto report = verify_document(document);
    INFO(report.path << ": " << report.message);
    REQUIRE(report.verdict == Verdict::valid);
    CHECK(document["claim"]["data"]["domain"] == "boxes");
    CHECK(document["proof"]["regions"].size() == 1);
    CHECK(document["proof"]["regions"][0]["images"].size() == 4);
    first_leaf(document, 'c');
    first_leaf(document, 'd');
    first_leaf(document, 'm');
}

TEST_CASE("critical-lattice tampering: a leaf's reason (symmetric too), a removed leaf, a cut, a split, an image, a start box, T") {
    const Document& original = certificate_around_c1();

    SECTION("a determinant leaf said to have no configuration point") {
        check_leaf_change_rejected(original, 'd', [](const std::string&) { return std::string("n"); });
    }
    SECTION("a closing-region leaf said to be a determinant leaf") {
        check_leaf_change_rejected(original, 'c', [](const std::string&) { return std::string("d"); });
    }
    SECTION("a symmetric leaf said to be a determinant leaf") {
        check_leaf_change_rejected(original, 'm', [](const std::string&) { return std::string("d"); });
    }
    SECTION("a determinant leaf said to be symmetric (it lies in the fundamental domain)") {
        check_leaf_change_rejected(original, 'd', [](const std::string&) { return std::string("m"); });
    }
    SECTION("a closing-region leaf said to be symmetric") {
        check_leaf_change_rejected(original, 'c', [](const std::string&) { return std::string("m"); });
    }
    SECTION("a closing-region leaf pointed at another image") {
        check_leaf_change_rejected(original, 'c', [](const std::string& leaf) {
            const int image = std::stoi(leaf.substr(1, leaf.size() - 2));
            return "c" + std::to_string((image + 1) % 4) + ".";
        });
    }
    SECTION("the last leaf of a tree removed (a box left uncovered)") {
        Document copy = original;
        const std::size_t k = first_split_tree(copy);
        std::string tree = copy["proof"]["trees"][k];
        const std::vector<Token> leaves = leaves_of(tree);
        REQUIRE(leaves.size() > 1);
        tree.erase(leaves.back().offset, leaves.back().length);
        copy["proof"]["trees"][k] = tree;
        const auto report = verify_document(copy);
        CHECK(report.verdict != Verdict::valid);
        CHECK(report.path.rfind(tree_path(k), 0) == 0);
    }
    SECTION("a cut moved to the other side of the coordinate") {
        Document copy = original;
        const std::size_t k = first_split_tree(copy);
        std::string tree = copy["proof"]["trees"][k];
        // The first cut: a step with side 'l' or 'h' in some round (a round may have none).
        std::size_t at = 0, cut = std::string::npos;
        while (cut == std::string::npos && (at = tree.find('C', at)) != std::string::npos) {
            std::size_t step = at + 4;
            while (tree[step] != ';' && tree[side_of(tree, step)] == 'x') step += step_length(tree, step);
            if (tree[step] != ';') cut = step;
            at = step;
        }
        REQUIRE(cut != std::string::npos);
        const std::size_t side = side_of(tree, cut);
        tree[side] = tree[side] == 'l' ? 'h' : 'l';
        copy["proof"]["trees"][k] = tree;
        CHECK(rejected_at(copy).rfind(tree_path(k), 0) == 0);
    }
    SECTION("a split at another coordinate than the producer's (the cuts below refer to its halves)") {
        Document copy = original;
        const std::size_t k = first_split_tree(copy);
        std::string tree = copy["proof"]["trees"][k];
        const std::size_t split = tree.find('S');
        REQUIRE(split != std::string::npos);
        tree[split + 1] = static_cast<char>('0' + (tree[split + 1] - '0' + 1) % 6);
        copy["proof"]["trees"][k] = tree;
        CHECK(rejected_at(copy).rfind(tree_path(k), 0) == 0);
    }
    SECTION("a split with no coordinate, or coordinate 6, is malformed") {
        for (const char* replacement : {"S", "S6"}) {
            Document copy = original;
            const std::size_t k = first_split_tree(copy);
            std::string tree = copy["proof"]["trees"][k];
            const std::size_t split = tree.find('S');
            REQUIRE(split != std::string::npos);
            tree.replace(split, 2, replacement);
            copy["proof"]["trees"][k] = tree;
            const auto report = verify_document(copy);
            CHECK(report.verdict == Verdict::malformed);
            CHECK(report.path.rfind(tree_path(k), 0) == 0);
        }
    }
    SECTION("a start box removed with its tree: the claim is another one") {
        Document copy = original;
        copy["proof"]["boxes"].erase(0);
        copy["proof"]["trees"].erase(0);
        CHECK(rejected_at(copy) == "claim.text");
    }
    SECTION("T raised above C1's det") {
        Document copy = original;
        Document& threshold = copy["claim"]["data"]["threshold"];
        superpack::test::tamper_bound(copy, "/claim/data/threshold/lo");
        threshold["hi"] = threshold["lo"];
        const std::string path = rejected_at(copy);
        CHECK(superpack::test::proof_step(path));
    }
}

// critical at p = 3/5, gap 9e-5, on one start box of the domain split 8 times (box 13802, 415
// boxes, 287 cuts of short vectors' h_c, form '4', 29 of them emptying a box).
TEST_CASE("critical-lattice short-vector cuts at p = 3/5: they verify; a changed coefficient, c = 0, a cut moved, rejected") {
    const Document original = superpack::test::critical_certificate_at(Rational(3, 5), [](superpack::CriticalOptions& options) {
        options.gap = Rational(9, 100000);
        options.split = 8;
        options.shard = 13802;
        options.shards = 43008;
    });
    const auto report = verify_document(original);
    INFO(report.path << ": " << report.message);
    REQUIRE(report.verdict == Verdict::valid);
    const std::string tree = original["proof"]["trees"][0];
    // The first short-vector cut: '4', three coefficient digits, a coordinate, 'l' or 'h'.
    std::size_t cut = std::string::npos;
    for (std::size_t at = 0; (at = tree.find('C', at)) != std::string::npos && cut == std::string::npos; ++at) {
        std::size_t step = at + 4;
        while (tree[step] != ';' && cut == std::string::npos) {
            if (tree[step] == '4' && tree[side_of(tree, step)] != 'x') cut = step;
            step += step_length(tree, step);
        }
    }
    REQUIRE(cut != std::string::npos);
    auto changed = [&](const std::function<void(std::string&)>& change) {
        Document copy = original;
        std::string t = tree;
        change(t);
        copy["proof"]["trees"][0] = t;
        return copy;
    };
    SECTION("another short vector") {
        CHECK(rejected_at(changed([&](std::string& t) { t[cut + 1] = t[cut + 1] == '4' ? '3' : static_cast<char>(t[cut + 1] + 1); }))
                  .rfind(tree_path(0), 0) == 0);
    }
    SECTION("c = 0, whose h_c < 0 everywhere") {
        CHECK(rejected_at(changed([&](std::string& t) { t.replace(cut + 1, 3, "222"); })).rfind(tree_path(0), 0) == 0);
    }
    SECTION("the cut moved to the other side") {
        CHECK(rejected_at(changed([&](std::string& t) { t[side_of(t, cut)] = t[side_of(t, cut)] == 'l' ? 'h' : 'l'; }))
                  .rfind(tree_path(0), 0) == 0);
    }
    SECTION("a form 5 is malformed") {
        CHECK(verify_document(changed([&](std::string& t) { t[cut] = '5'; })).verdict == Verdict::malformed);
    }
}

// The symmetric leaf 'm' (critical_tree.cpp's leaf_symmetric): a2 > a3 certainly where face2 =
// face3, or (A3 only) F = b1 . (b2 + b3 - b1) certainly < 0. The start box of the first tree that
// is one 'm' is replaced (the claim's sentence counts boxes and leaves only, so it stays), and the
// box must be rejected at that tree unless it is outside the fundamental domain. F over each box,
// at p = 2 (by sampling its corners in binary64): a, b, c, d about -8.7..-8.3, 3.0..3.4,
// 4.6..4.8, 4.6..4.8; e about -0.16..0.26. Each section fails under one mutation of the guards:
//   a: `if (start_.configuration == Configuration::a3)` -> `if (true)` (F < 0 used for W);
//   b: `start_.face2 == start_.face3 &&` dropped (a2 > a3 used across different faces);
//   c and d: `less(x[4], x[2])` -> `less(x[2], x[4])` (the face condition reversed);
//   e: `less(sum, 0)` -> `!less(0, sum)` (F <= 0 possible taken for F < 0).
TEST_CASE("critical-lattice symmetric leaf: a start box on each side of its conditions, accepted or rejected") {
    const Document& original = certificate_around_c1();
    const Document& trees = original["proof"]["trees"];
    std::size_t k = 0;
    while (k < trees.size() && trees[k] != "m") ++k;
    REQUIRE(k < trees.size());
    auto with_box = [&](const Document& box) {
        Document copy = original;
        copy["proof"]["boxes"][k] = box;
        return copy;
    };
    // s = t = 1/2 (b1 along (1, 1/2, 1/4)), v2 and v3 near (1, 1/2, 1/4) or (1, 1/4, 1/4) on +x.
    const std::array<double, 6> a2_above{0.5, 0.5, 0.5, 0.25, 0.25, 0.25}, a2_below{0.5, 0.5, 0.25, 0.25, 0.5, 0.25};

    SECTION("W, F < 0 on different faces: F is no reason for W (it has only the swap)") {
        CHECK(rejected_at(with_box(chart_box_json("W", 1, 3, a2_above))).rfind(tree_path(k), 0) == 0);
        // The same box as A3 is symmetric by F < 0.
        CHECK(verify_document(with_box(chart_box_json("A3", 1, 3, a2_above))).verdict == Verdict::valid);
    }
    SECTION("A3, a2 > a3 but on different faces (+x, +y), F > 0") {
        CHECK(rejected_at(with_box(chart_box_json("A3", 0, 2, a2_above))).rfind(tree_path(k), 0) == 0);
    }
    SECTION("A3, one face (+x), a2 < a3, F > 0: inside the fundamental domain") {
        CHECK(rejected_at(with_box(chart_box_json("A3", 0, 0, a2_below))).rfind(tree_path(k), 0) == 0);
    }
    SECTION("one face (+x), a2 > a3, F > 0: symmetric, for A3 and W") {
        for (const char* configuration : {"A3", "W"}) {
            const auto report = verify_document(with_box(chart_box_json(configuration, 0, 0, a2_above)));
            INFO(configuration << " " << report.path << ": " << report.message);
            CHECK(report.verdict == Verdict::valid);
        }
    }
    SECTION("A3, F of both signs on the box (a2 in [-1, -15/16] on +x, v3 on +y), no face condition") {
        CHECK(rejected_at(with_box(chart_box_json("A3", 0, 2, a2_above, true))).rfind(tree_path(k), 0) == 0);
    }
}
