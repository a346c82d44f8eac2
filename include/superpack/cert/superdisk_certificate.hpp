// The certificate of claim kind "superdisk-optimum" (written by `superpack superdisk --p P
// --certificate FILE`): the densest lattice packing of the superdisk at an exact p > 1/2 has
// its density in an enclosure, attained (within it) by the named PRL lattices, and every
// minimiser of D(t) lies in the listed t-intervals. The proof is the branch and bound of
// analyse_superdisk: every piece of [0, 1] with its verdict and its Krawczyk box of v(t),
// and the witness lattice giving the upper bound. NOTES.md sections 7 and 8.6.
#pragma once
#include "superpack/cert/certificate.hpp"
#include "superpack/problems/superdisk/superdisk.hpp"

namespace superpack {

// Throws std::runtime_error unless report.status is certified by the branch and bound
// (p > 1/2: the tiling case p = 1/2 and the concave p < 1/2 have no certificate).
template <class Field>
Json superdisk_certificate(const SuperdiskReport<typename Field::Interval>& report, const Rational& p,
                           const Field& field, long digits);

}  // namespace superpack
