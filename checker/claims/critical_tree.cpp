#include "checker/claims/critical_tree.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <vector>

#include "checker/core/limits.hpp"
#include "checker/core/tree_walk.hpp"

namespace superpack_checker {

namespace {

// The configuration vectors whose max norm may not exceed b1's (NOTES.md 12.2): the other five
// for A3, b2 and b3 for W.
std::vector<Triple> max_norm_orbit(Configuration configuration) {
    const std::array<Triple, 6> triples = configuration_triples(configuration);
    if (configuration == Configuration::a3) return {triples.begin() + 1, triples.end()};
    return {triples[1], triples[2]};
}

Real with_end(const Real& x, mpfr_srcptr end, bool lower) {
    return outward(lower ? end : x.lo(), lower ? x.hi() : end, x.precision());
}

// e misses [a, b].
bool misses(const Real& e, const Real& a, const Real& b) { return less(e, a) || less(b, e); }

struct Pending {
    ChartPoint x;
    std::size_t depth;
};

// One round's forms, the combinations built when a step first asks for them.
struct Round {
    ChartForms forms;
    std::optional<std::array<int, 3>> pivots;
    std::optional<std::array<ChartForm, 3>> combined;
    std::optional<ChartForm> lagrange;
    std::optional<std::pair<Triple, ChartForm>> short_vector;  // the last h_c a step asked for
};

class TreeReplay {
public:
    TreeReplay(Context& context, const std::string& tree, const ChartBox& start, const TreeSetting& setting,
               const std::string& path, TreeCounts& counts)
        : context_(context), tree_(tree), start_(start), setting_(setting), path_(path), counts_(counts) {}

    void run() {
        walk_tree(Pending{start_.x, 0}, [&](Pending& node, std::vector<Pending>& stack) {
            node_at_ = at_;
            if (counts_.nodes % 1024 == 0) report_progress();
            try {
                decide(node, stack);
            } catch (const std::domain_error& error) {
                reject(std::string("evaluation outside its domain: ") + error.what());
            }
        });
        if (at_ != tree_.size()) malformed("characters after the last leaf of the tree");
    }

private:
    void report_progress() {
        const auto now = std::chrono::steady_clock::now();
        if (now - counts_.reported < std::chrono::seconds(2)) return;
        counts_.reported = now;
        std::cerr << "superpack-verify: critical-lattice: " << counts_.nodes << " boxes replayed, now in " << path_ << "\n";
    }

    Context& context_;
    const std::string& tree_;
    const ChartBox& start_;
    const TreeSetting& setting_;
    const std::string& path_;
    TreeCounts& counts_;
    std::size_t at_ = 0, node_at_ = 0;
    ChartPoint round_box_ = chart_zeros(53);  // the box of the round being replayed (its forms' box)

    std::string where(std::size_t offset) const { return "at character " + std::to_string(offset) + ": "; }
    [[noreturn]] void malformed(const std::string& message) const { context_.malformed(path_, where(at_) + message); }
    [[noreturn]] void reject(const std::string& message) const { context_.reject(path_, where(node_at_) + message); }
    void require(bool condition, std::size_t offset, const std::string& what) {
        context_.count_step();
        if (!condition) context_.reject(path_, where(offset) + what);
    }

    char next(const char* expected) {
        if (at_ >= tree_.size()) malformed(std::string("the tree ends where ") + expected + " should follow");
        return tree_[at_++];
    }
    int digit(const char* expected, char highest) {
        const char c = next(expected);
        if (c < '0' || c > highest) {
            --at_;
            malformed(std::string("expected ") + expected + ", found '" + std::string(1, c) + "'");
        }
        return c - '0';
    }

    ChartBox box(const ChartPoint& x) const {
        ChartBox b{start_.configuration, start_.face2, start_.face3, x};
        return b;
    }

    void decide(Pending& node, std::vector<Pending>& stack) {
        ++counts_.nodes;
        ChartPoint& x = node.x;
        std::optional<Matrix3> round_basis;  // the basis over the last round's box
        int emptied_by = -1;  // the form of an 'x' step, which empties the box
        while (at_ < tree_.size() && tree_[at_] == 'C') {
            if (emptied_by >= 0) malformed("a round after a cut that left nothing of the box");
            ++at_;
            round_box_ = x;
            Round round{chart_forms(box(x), setting_.chart), std::nullopt, std::nullopt, std::nullopt, std::nullopt};
            round_basis = round.forms.basis;
            read_pivots(round);
            ChartPoint cut = x;
            while (next("a step or ';'") != ';') {
                --at_;
                emptied_by = step(round, cut);
                if (emptied_by >= 0) {
                    if (next("';'") != ';') malformed("a cut that empties the box must end its round");
                    break;
                }
            }
            x = cut;
            ++counts_.rounds;
        }
        node_at_ = at_;
        const char terminal = next("a leaf or 'S'");
        if (terminal == 'E') {
            if (emptied_by < 0) reject("'E' with no cut that emptied the box");
            ++counts_.leaves[static_cast<int>(emptied_by == 3   ? LeafReason::determinant
                                              : emptied_by == 4 ? LeafReason::short_vector
                                                                : LeafReason::no_configuration)];
            return;
        }
        if (emptied_by >= 0) malformed("after a cut that emptied the box the leaf must be 'E'");
        switch (terminal) {
            case 'S': split(node, stack, digit("a split coordinate 0..5", '5')); return;
            case 'n': leaf_no_configuration(x); return;
            case 'r': leaf_relabelled(x); return;
            case 'm': leaf_symmetric(x); return;
            case 'v': leaf_volume(x); return;
            case 'd': leaf_determinant(x); return;
            case 's':
                if (!round_basis) reject("a short-vector leaf needs a round (its basis is the round's)");
                leaf_short_vector(*round_basis);
                return;
            case 'c':
                if (!round_basis) reject("a closing-region leaf needs a round (its basis is the round's)");
                leaf_closing_region(*round_basis);
                return;
            default:
                --at_;
                malformed("expected a leaf (S, E, n, r, v, d, m, s, c) or a round (C), found '" + std::string(1, terminal) + "'");
        }
    }

    void read_pivots(Round& round) {
        if (at_ + 3 <= tree_.size() && tree_.compare(at_, 3, "---") == 0) {
            at_ += 3;
            return;
        }
        std::array<int, 3> pivots{};
        for (int& p : pivots) p = digit("a pivot column 0..5 or \"---\"", '5');
        round.pivots = pivots;
    }

    const ChartForm& form(Round& round, int index, std::size_t offset) {
        if (index == 3) {
            if (!round.lagrange) round.lagrange = lagrangian(round.forms);
            return *round.lagrange;
        }
        if (!round.pivots) reject_at(offset, "a cut of F_" + std::to_string(index) + " in a round without pivots (\"---\")");
        if (!round.combined) round.combined = preconditioned(round.forms, *round.pivots);
        return (*round.combined)[index];
    }
    [[noreturn]] void reject_at(std::size_t offset, const std::string& message) const {
        context_.reject(path_, where(offset) + message);
    }

    // The enclosure of the form over the slab misses its target: 0 for F_0..F_2, [V_lo, T] and
    // [-T, -V_lo] for the Lagrangian, [0, inf) for a short vector's h_c (c B inside 2K).
    bool outside_target(int index, const Real& e) const {
        if (index < 3) return excludes_zero(e);
        if (index == 4) return less(e, Real(e.precision()));
        return misses(e, setting_.volume_lo, setting_.threshold) && misses(e, -setting_.threshold, -setting_.volume_lo);
    }

    // One step; returns the form index when it is an 'x' (the whole box cut), else -1.
    int step(Round& round, ChartPoint& cut) {
        const std::size_t offset = at_;
        const int index = digit("a form 0..4", '4');
        Triple c{};
        if (index == 4) {
            for (long& coefficient : c) coefficient = digit("a coefficient digit 0..4 (-2..2)", '4') - 2;
            if (c == Triple{0, 0, 0}) reject_at(offset, "a short-vector cut with coefficients all 0");
        }
        const int k = digit("a coordinate 0..5", '5');
        const char side = next("'l', 'h' or 'x'");
        ++counts_.cuts;
        if (index == 4 && !(round.short_vector && round.short_vector->first == c))
            round.short_vector.emplace(c, short_vector_form(box(round_box_), round.forms, c, setting_.chart));
        const ChartForm& f = index == 4 ? round.short_vector->second : form(round, index, offset);
        const std::string name = index == 3   ? std::string("the Lagrangian")
                                 : index == 4 ? "h_c for c = " + triple_text(c)
                                              : "F_" + std::to_string(index);
        if (side == 'x') {
            const Real e = enclose(f, cut, round.forms.center);
            require(outside_target(index, e), offset,
                    name + " over the whole box is " + text(e) + ", which meets its target: the box is not empty");
            return index;
        }
        if (side != 'l' && side != 'h') {
            --at_;
            malformed("expected 'l', 'h' or 'x'");
        }
        const double end = hex_end();
        mpfr_t b;
        mpfr_init2(b, 53);
        mpfr_set_d(b, end, MPFR_RNDN);  // exact
        const Real& old = cut[k];
        const bool lower = side == 'l';
        const bool inside = lower ? mpfr_less_p(old.lo(), b) && mpfr_lessequal_p(b, old.hi())
                                  : mpfr_lessequal_p(old.lo(), b) && mpfr_less_p(b, old.hi());
        if (!inside) {
            mpfr_clear(b);
            reject_at(offset, std::string("the new ") + (lower ? "lower" : "upper") + " end of coordinate " + std::to_string(k) +
                                  " is not strictly inside " + text(old));
        }
        ChartPoint slab = cut;
        slab[k] = with_end(old, b, !lower);  // [lo, b] cut off below, [b, hi] above
        const Real narrowed = with_end(old, b, lower);
        mpfr_clear(b);
        const Real e = enclose(f, slab, round.forms.center);
        require(outside_target(index, e), offset,
                name + " over the slab cut off " + (lower ? "below" : "above") + " coordinate " + std::to_string(k) + " is " +
                    text(e) + ", which meets its target: the cut is not proved");
        cut[k] = narrowed;
        return -1;
    }

    double hex_end() {
        if (at_ + 16 > tree_.size()) malformed("the tree ends inside a cut's 16 hex digits");
        std::uint64_t bits = 0;
        for (int i = 0; i < 16; ++i) {
            const char c = tree_[at_];
            const int value = c >= '0' && c <= '9' ? c - '0' : (c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1);
            if (value < 0) malformed("expected 16 lowercase hex digits of a binary64 end");
            bits = (bits << 4) | static_cast<std::uint64_t>(value);
            ++at_;
        }
        double end;
        std::memcpy(&end, &bits, sizeof end);
        mpfr_t value;
        mpfr_init2(value, 53);
        mpfr_set_d(value, end, MPFR_RNDN);  // exact (NaN and infinities stay what they are)
        const bool accepted = binary64_box_end(value);
        mpfr_clear(value);
        if (!accepted) {
            at_ -= 16;
            malformed("a cut's end is not finite, or nonzero and below 2^-1000 in size");
        }
        return end;
    }

    // Any coordinate is sound: the two halves cover the box, and each is replayed.
    void split(Pending& node, std::vector<Pending>& stack, int k) {
        if (node.depth + 1 > max_tree_depth)
            malformed("splits nested deeper than " + std::to_string(max_tree_depth) + " (max_tree_depth)");
        const Real middle = median(node.x[k]);
        if (!binary64_box_end(middle.lo())) reject("the median of a split is nonzero and below 2^-1000 in size");
        Pending lower{node.x, node.depth + 1}, upper{node.x, node.depth + 1};
        lower.x[k] = with_end(node.x[k], middle.lo(), false);
        upper.x[k] = with_end(node.x[k], middle.lo(), true);
        stack.push_back(std::move(upper));  // the lower half's node comes first in pre-order
        stack.push_back(std::move(lower));
    }

    void count(LeafReason reason) { ++counts_.leaves[static_cast<int>(reason)]; }

    void leaf_no_configuration(const ChartPoint& x) {
        const ChartValues naive = chart_values(box(x), setting_.chart);
        for (const Real& g : naive.equations)
            if (excludes_zero(g)) return count(LeafReason::no_configuration);
        const ChartForms forms = chart_forms(box(x), setting_.chart);
        for (const ChartForm& g : forms.equations)
            if (excludes_zero(enclose(g, x, forms.center))) return count(LeafReason::no_configuration);
        require(false, node_at_, "no g_i has one sign on the box (naive or mean-value): 'n' is not proved");
    }

    void leaf_relabelled(const ChartPoint& x) {
        const Matrix3 basis = chart_values(box(x), setting_.chart).basis;
        for (const Triple& c : max_norm_orbit(start_.configuration))
            for (const Real& coordinate : combination(basis, c))
                if (less(upper_point(basis[0][0]), abs(coordinate))) return count(LeafReason::relabelled);
        require(false, node_at_, "no orbit vector is certainly longer than b1 in the max norm: 'r' is not proved");
    }

    // NOTES.md 12.2: the swap (b1, b2, b3) -> (b1, b3, b2) (both configurations) and, for A3,
    // (b1, b2, b3) -> (b1, b1 - b2, b1 - b3) keep b1 and the configuration; the chart keeps
    // a2 <= a3 where v2 and v3 share a face, and b1 . (b2 + b3 - b1) >= 0 for A3.
    void leaf_symmetric(const ChartPoint& x) {
        if (start_.face2 == start_.face3 && less(x[4], x[2])) return count(LeafReason::symmetric);
        if (start_.configuration == Configuration::a3) {
            const Matrix3 b = chart_values(box(x), setting_.chart).basis;
            Real sum = b[0][0] * (b[1][0] + b[2][0] - b[0][0]);
            for (int j = 1; j < 3; ++j) sum = sum + b[0][j] * (b[1][j] + b[2][j] - b[0][j]);
            if (less(sum, Real(sum.precision()))) return count(LeafReason::symmetric);
        }
        require(false, node_at_,
                "neither a2 > a3 on a shared face nor (A3) b1 . (b2 + b3 - b1) < 0 on the box: 'm' is not proved");
    }

    void leaf_volume(const ChartPoint& x) {
        const ChartValues naive = chart_values(box(x), setting_.chart);
        if (less(abs(naive.determinant), setting_.volume_lo)) return count(LeafReason::volume);
        const ChartForms forms = chart_forms(box(x), setting_.chart);
        const Real value = enclose(lagrangian(forms), x, forms.center);
        require(less(abs(value), setting_.volume_lo), node_at_,
                "|det| over the box and the Lagrangian " + text(value) +
                    " are not certainly below V(K)'s lower end: 'v' is not proved");
        count(LeafReason::volume);
    }

    void leaf_determinant(const ChartPoint& x) {
        const ChartForms forms = chart_forms(box(x), setting_.chart);
        const Real value = enclose(lagrangian(forms), x, forms.center);
        require(less(setting_.threshold, value) || less(value, -setting_.threshold), node_at_,
                "the Lagrangian over the box is " + text(value) + ", not certainly beyond +-T: 'd' is not proved");
        count(LeafReason::determinant);
    }

    void leaf_short_vector(const Matrix3& basis) {
        Triple c{};
        for (long& coefficient : c) coefficient = digit("a coefficient digit 0..4 (-2..2)", '4') - 2;
        require(c != Triple{0, 0, 0}, node_at_, "the short vector's coefficients are all 0");
        for (const Triple& t : configuration_triples(start_.configuration))
            require(representative(c) != t, node_at_,
                    "the short vector " + triple_text(c) + " is a configuration vector (of norm 2 on the configuration)");
        const Real power = half_norm_power(combination(basis, c), setting_.chart);
        require(less(power, integer(1, power.precision())), node_at_,
                "sum |v_j / 2|^(2p) for v = " + triple_text(c) + " B is " + text(power) +
                    ", not certainly < 1: 's' is not proved");
        count(LeafReason::short_vector);
    }

    void leaf_closing_region(const Matrix3& basis) {
        const std::size_t digits_at = at_;
        std::size_t index = 0;
        while (at_ < tree_.size() && tree_[at_] >= '0' && tree_[at_] <= '9') {
            if (at_ - digits_at >= 9) malformed("an image index of more than 9 digits");
            index = 10 * index + static_cast<std::size_t>(tree_[at_++] - '0');
        }
        if (at_ == digits_at) malformed("expected the digits of an image index");
        if (tree_[digits_at] == '0' && at_ - digits_at > 1) malformed("an image index with a leading 0");
        if (next("'.'") != '.') {
            --at_;
            malformed("expected '.' after an image index");
        }
        const ClosingRegions& regions = *setting_.regions;
        require(index < regions.images.size(), node_at_,
                "image " + std::to_string(index) + " does not exist (" + std::to_string(regions.images.size()) + " images)");
        const ChartImage& image = regions.images[index];
        require(image.configuration == start_.configuration, node_at_,
                "image " + std::to_string(index) + " is of configuration " + configuration_name(image.configuration) +
                    ", the box of " + configuration_name(start_.configuration));
        require(maps_into_region(image, regions.regions[image.region], basis), node_at_,
                "W^-1 B P^-1 over the box is not inside closing region " + std::to_string(image.region) + " (image " +
                    std::to_string(index) + "): 'c' is not proved");
        count(LeafReason::closing_region);
    }
};

}  // namespace

const char* reason_name(LeafReason reason) {
    switch (reason) {
        case LeafReason::determinant: return "determinant";
        case LeafReason::no_configuration: return "no_configuration";
        case LeafReason::relabelled: return "relabelled";
        case LeafReason::short_vector: return "short_vector";
        case LeafReason::volume: return "volume";
        case LeafReason::closing_region: return "closing_region";
        case LeafReason::symmetric: return "symmetric";
    }
    return "";
}

void replay_tree(Context& context, const std::string& tree, const ChartBox& start, const TreeSetting& setting,
                 const std::string& path, TreeCounts& counts) {
    if (tree.size() > max_tree_characters)
        context.malformed(path, "a tree of " + std::to_string(tree.size()) + " characters exceeds the limit of " +
                                    std::to_string(max_tree_characters) + " (max_tree_characters)");
    TreeReplay(context, tree, start, setting, path, counts).run();
}

ChartBox read_chart_box(Context& context, const Json& node, const std::string& path) {
    if (!node.is_object()) context.malformed(path, "expected a chart box");
    ChartBox box{Configuration::a3, 0, 0, chart_zeros(context.precision())};
    box.configuration = read_configuration(context, node, path);
    box.face2 = static_cast<int>(read_integer(context, context.member(node, "face2", path), path + ".face2", 0, 5));
    box.face3 = static_cast<int>(read_integer(context, context.member(node, "face3", path), path + ".face3", 0, 5));
    const Box x = context.box(context.member(node, "x", path), path + ".x");
    if (x.size() != chart_dimension) context.malformed(path + ".x", "expected the six chart coordinates (s, t, a2, c2, a3, c3)");
    const mpfr_prec_t precision = context.precision();
    const Real unit = hull(integer(0, precision), integer(1, precision)), side = hull(integer(-1, precision), integer(1, precision));
    for (int k = 0; k < chart_dimension; ++k) {
        const std::string at = path + ".x[" + std::to_string(k) + "]";
        if (!binary64_box_end(x[k].lo()) || !binary64_box_end(x[k].hi()))
            context.malformed(at, "a chart box's ends must be binary64 numbers, 0 or at least 2^-1000 in size");
        // The chart's domain: s, t in [0, 1], a face's coordinates in [-1, 1].
        context.require(subset(x[k], k < 2 ? unit : side), at, "outside the chart's domain");
        box.x[k] = x[k];
    }
    return box;
}

}  // namespace superpack_checker
