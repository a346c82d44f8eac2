// The certificate of claim kind "critical-lattice" (written by `superpack critical --certificate`;
// NOTES.md 12.8): at an exact p, every lattice packing of the superball whose chart basis lies in
// one of the stated chart boxes and satisfies its Minkowski configuration has |det| >= T, so its
// density is at most V(K) / T. It carries the closing regions (the KKT point's Krawczyk leaf,
// rho, the region box and its images in the chart) and, for each start box, its bisection tree
// with every contraction's cuts and every leaf's reason (the tree grammar of 12.8), which the
// checker replays box by box in its own arithmetic.
#pragma once
#include "superpack/cert/certificate.hpp"
#include "superpack/problems/critical/critical.hpp"

namespace superpack {

// The checker's file limit, which a certificate may not exceed (checker/core/limits.hpp).
constexpr std::size_t critical_certificate_bytes = std::size_t{256} << 20;

// Throws std::runtime_error unless the result is proved and carries its trees
// (CriticalOptions::record_trees), and InputError when the trees exceed the checker's limit.
Json critical_certificate(const CriticalResult<DInterval>& result, const CriticalOptions& options);

// What a cover certificate repeats of its parts (critical-lattice certificates of the shards of
// one run at --split K), as read from them; `names` are the parts' file names in the cover's
// directory, where the checker opens them.
struct CoverParts {
    Json p, p_decimal, gap, threshold, volume, upper_phi;
    int split = 0;
    std::vector<std::string> names;
};

// The certificate of claim kind "critical-lattice-cover" (NOTES.md 12.9): the bound on the whole
// domain from the parts, which the checker replays in full (on `threads`, from `directory`)
// before the cover is written. Throws CertificateRejected when a part or the tiling fails.
Json critical_cover_certificate(const CoverParts& parts, const std::string& directory, int threads);

}  // namespace superpack
