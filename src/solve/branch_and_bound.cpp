#include "superpack/solve/branch_and_bound.hpp"

namespace superpack::search_detail {

// Six digits, so that places sort by start box first (at most a million start boxes).
std::string tree_place(std::size_t index) {
    std::string digits = std::to_string(index);
    return std::string(6 - std::min<std::size_t>(6, digits.size()), '0') + digits;
}

// Sorted by place, the records are each tree in pre-order: a place sorts before its
// extensions, and '0' before '1'.
std::vector<std::string> assemble_trees(std::vector<std::pair<std::string, std::string>>& records, std::size_t count) {
    std::sort(records.begin(), records.end());
    std::vector<std::string> trees(count);
    for (const auto& record : records) trees[std::stoul(record.first.substr(0, 6))] += record.second;
    return trees;
}

}  // namespace superpack::search_detail
