// Certificates of the crossover and slope claims (NOTES.md 8.5), replayed by the checker's
// claim kinds "cubic-crossover", "octahedral-crossover" and "sphere-slopes":
//   cubic:      phi_C1 - phi_C0 has exactly one zero p*_c in (1, 10], with the sign on each
//               side and phi*_c: the producer's partition of [1, 10] (each piece with its sign
//               and the Newton boxes of s for C0 and C1 over it) and the exact lemma at p = 1;
//   octahedral: p*_o = ln3/ln4 is the root of Eq. (6), O0 and the q -> 0 limit of O1 are one
//               lattice with |det| = 4 there, phi*_o = V_sb(p*_o) / 4;
//   slopes:     dphi/dp at p = 1 for C0, C1, O0, a_minus, a_plus and the paper's closed forms.
// Each function throws std::runtime_error for an uncertified result: no certificate without
// a proof.
#pragma once
#include "superpack/cert/certificate.hpp"
#include "superpack/problems/crossover/crossover.hpp"

namespace superpack {

template <class Field>
Json cubic_crossover_certificate(const CubicCrossover<typename Field::Interval>& crossover, const Field& field,
                                 long digits);
template <class Field>
Json octahedral_crossover_certificate(const OctahedralCrossover<typename Field::Interval>& crossover,
                                      const Field& field, long digits);
template <class Field>
Json sphere_slopes_certificate(const SphereSlopes<typename Field::Interval>& slopes, const Field& field, long digits);

}  // namespace superpack
