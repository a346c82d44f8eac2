// The certificate of claim kind "local-optimum" (written by `superpack best --certificate` when
// the critical lattice is certified locally optimal; NOTES.md 8.9): at an exact p > 1/2 the
// KKT point (B, mu) of min det B subject to ||c_i B||_(2p) = 2 for its contact triples, unique
// in a Krawczyk box, is an admissible lattice (a packing) and a strict local minimiser of |det|
// among the admissible lattices near it, with phi = V_sb(p) / |det B|. It carries the Krawczyk
// leaf of x = (B, mu) (the format of the partition leaves, certificate_partition.hpp), the
// weight rho of the second-order condition, and the lattice check's enumeration on the root box.
#pragma once
#include "superpack/cert/certificate.hpp"
#include "superpack/problems/optimality/local_optimality.hpp"

namespace superpack {

// Throws std::runtime_error unless local.verdict is proved (only proofs are certified).
template <class Field>
Json local_optimum_certificate(const LocalOptimum<typename Field::Interval>& local, const Rational& p, const Field& field,
                               long digits);

}  // namespace superpack
