// Proof trees for branch-and-bound results: the partition behind isolate_roots (solve/root_partition.hpp)
// as a certificate tree of {"kind": "split", "box", "dimension", "cases": [a, b]} nodes with
// "excluded" and "krawczyk" leaves (NOTES.md section 8). Any claim kind whose proof is a
// root search uses partition_json; the checker walks it with check_partition (checker/core/replay.hpp).
#pragma once
#include <stdexcept>
#include <vector>

#include "superpack/cert/certificate.hpp"
#include "superpack/solve/bisection.hpp"
#include "superpack/solve/root_partition.hpp"

namespace superpack {

// A JSON array of exact intervals.
template <class I>
Json box_json(const std::vector<I>& box) {
    Json result = Json::array();
    for (const I& x : box) result.push_back(exact_interval_json(x));
    return result;
}

namespace certificate_detail {

// Rebuilds the bisection tree behind a flat list of RootLeaf pieces (isolate_roots returns
// them in depth-first order, left before right) by replaying its split rule, the widest
// component cut at its midpoint (solve/bisection.hpp). The operations are deterministic, so each piece matches
// a node exactly; a mismatch means the rule changed, and no certificate is written.
template <class I, class F>
class PartitionWriter {
public:
    PartitionWriter(const F& f, const std::vector<RootLeaf<I>>& leaves) : f_(f), leaves_(leaves) {}

    Json node(const std::vector<I>& box, int depth) {
        if (next_ < leaves_.size() && same_box(leaves_[next_].piece, box)) return leaf(leaves_[next_++]);
        if (depth > 200 || next_ >= leaves_.size())
            throw std::runtime_error("certificate: the search pieces do not form the bisection tree");
        const std::size_t widest = widest_component(box);
        const auto halves = bisect_widest(box);
        Json cases = Json::array();
        cases.push_back(node(halves.first, depth + 1));
        cases.push_back(node(halves.second, depth + 1));
        return Json{{"kind", "split"}, {"box", box_json(box)}, {"dimension", widest}, {"cases", cases}};
    }

    bool complete() const { return next_ == leaves_.size(); }

private:
    static bool same_box(const std::vector<I>& a, const std::vector<I>& b) {
        for (std::size_t k = 0; k < a.size(); ++k)
            if (!same_interval(a[k], b[k])) return false;
        return true;
    }

    Json leaf(const RootLeaf<I>& leaf) const {
        if (leaf.status == RootStatus::undecided) throw std::runtime_error("certificate: an undecided piece");
        const std::vector<I> values = f_(leaf.piece);
        if (leaf.status == RootStatus::none) {
            for (std::size_t i = 0; i < values.size(); ++i)
                if (!contains_zero(values[i]))
                    return Json{{"kind", "excluded"}, {"box", box_json(leaf.piece)}, {"values", box_json(values)}};
            return Json{{"kind", "krawczyk"}, {"status", "none"}, {"box", box_json(leaf.piece)}};
        }
        return Json{{"kind", "krawczyk"}, {"status", "unique"}, {"box", box_json(leaf.piece)}, {"root", box_json(leaf.root)}};
    }

    const F& f_;
    const std::vector<RootLeaf<I>>& leaves_;
    std::size_t next_ = 0;
};

}  // namespace certificate_detail

// `leaves` as returned by isolate_roots(f, box, ...); f maps a std::vector<I> to the values.
// Throws std::runtime_error (no certificate) if a piece is undecided or the pieces do not
// form the bisection tree of `box`.
template <class I, class F>
Json partition_json(const F& f, const std::vector<I>& box, const std::vector<RootLeaf<I>>& leaves) {
    certificate_detail::PartitionWriter<I, F> writer(f, leaves);
    Json tree = writer.node(box, 0);
    if (!writer.complete()) throw std::runtime_error("certificate: search pieces left over after the tree");
    return tree;
}

}  // namespace superpack
