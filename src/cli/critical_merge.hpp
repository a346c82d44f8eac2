// Reading back the JSON documents of `superpack critical --shard i/n --json` for --merge.
#pragma once
#include <string>

#include "superpack/arith/enclosure_json.hpp"
#include "superpack/problems/critical.hpp"

namespace superpack::cli {

// A shard document's fields that a merge compares and sums. InputError names the file and the
// field when the file is unreadable, too large, not a regular file, or not a critical document.
struct ShardDocument {
    std::string p_exact, gap;
    Json threshold;  // the enclosure of T as printed
    ShardSummary summary;
};
ShardDocument read_shard_document(const std::string& path);

// A shard document is at most this large (its undecided examples are capped at 20 boxes).
constexpr long max_shard_bytes = 1 << 20;

}  // namespace superpack::cli
