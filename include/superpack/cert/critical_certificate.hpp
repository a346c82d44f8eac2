// The certificate of claim kind "critical-lattice" (written by `superpack critical --certificate`;
// NOTES.md 12.8): at an exact p, every lattice packing of the superball whose chart basis lies in
// one of the stated chart boxes and satisfies its Minkowski configuration has |det| >= T, so its
// density is at most V(K) / T. It carries the closing regions (the KKT point's Krawczyk leaf,
// rho, the region box and its images in the chart) and, for each start box, its bisection tree
// with every contraction's cuts and every leaf's reason (the tree grammar of 12.8), which the
// checker replays box by box in its own arithmetic.
#pragma once
#include "superpack/cert/certificate.hpp"
#include "superpack/problems/critical.hpp"

namespace superpack {

// The checker's file limit, which a certificate may not exceed (checker/limits.hpp).
constexpr std::size_t critical_certificate_bytes = std::size_t{16} << 20;

// Throws std::runtime_error unless the result is proved and carries its trees
// (CriticalOptions::record_trees), and InputError when the trees exceed the checker's limit.
Json critical_certificate(const CriticalResult<DInterval>& result, const CriticalOptions& options);

}  // namespace superpack
