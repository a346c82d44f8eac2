// Reading back what shards of `superpack critical` wrote: their JSON documents (--shard i/n
// --json) for --merge, and their critical-lattice certificates for --cover. In cert, beside the
// writers of those certificates, so that the command only parses and prints.
#pragma once
#include <string>
#include <vector>

#include "superpack/arith/enclosure_json.hpp"
#include "superpack/cert/critical_certificate.hpp"
#include "superpack/problems/critical/critical.hpp"

namespace superpack {

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

// The parts of a cover certificate at `cover` (the --certificate path): critical-lattice
// certificates of shards, all in the cover's directory, at one p, gap and T, holding at least the
// 168 * 2^K start boxes of the domain at --split K (more where a start box was replaced by its
// halves: box k at --split K is boxes 2k and 2k + 1 at K + 1). InputError names the file
// otherwise; whether the boxes tile the domain is the checker's to prove.
CoverParts read_cover_parts(const std::vector<std::string>& paths, const std::string& cover, int split);

}  // namespace superpack
