// What `simulate` and `md` do with a simulation's end state: hand it to problems/ to be rounded
// to exact rationals and proved a packing (problems/periodic/end_state.hpp, with sim's separating
// planes as guesses), compare it with the best lattice superpack certifies at p, and write it to
// the files people open (render/).
// Floating point guesses, intervals prove: a bad guess costs density, never soundness.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "common.hpp"
#include "superpack/problems/best/best.hpp"
#include "superpack/problems/periodic/end_state.hpp"
#include "superpack/sim/periodic_configuration.hpp"

namespace superpack::cli {

// The files of a proved packing; an empty path is not written.
struct PackingFiles {
    std::string xyz, mesh, png, certificate;
};

// --xyz, --mesh, --png and --certificate, with their help texts.
void add_packing_file_options(CLI::App& command, PackingFiles& files);
// Before the long work: every target writable, and gnuplot there for --png (Failure otherwise).
void require_packing_files(const PackingFiles& files);

// The best lattice at p (throws Failure, exit 4, when none is certified), said on stderr.
BestLattice<DInterval> reference_lattice(const Rational& p, const std::string& command);
// The lattice with basis `basis` (a certified enclosure, its midpoints taken) as a start of
// `particles` bodies: the supercell of sim::lattice_configuration, every length times `expansion`.
sim::PeriodicConfiguration lattice_start(const Basis<DInterval>& basis, int particles, double expansion);

// The end state as the plain numbers prove_end_state takes.
SimulationEndState simulation_end_state(const sim::PeriodicConfiguration& end);
// sim's separating planes (GJK) as the guesses of the end state's proof; it refers to `shape` and
// `end`, which must outlive it.
NormalGuess separation_guess(const sim::SuperballShape& shape, const sim::PeriodicConfiguration& end);

// The proof's keys of the JSON document: certified, reason, best_lattice, and when certified phi,
// ratio_to_best_lattice, scale, pairs_separated and the exact configuration.
void add_proof_json(Json& document, const PeriodicCertificate<DInterval>& proof, const BestLattice<DInterval>& best);
// The proof's lines of the table.
void print_proof(std::ostream& out, const PeriodicCertificate<DInterval>& proof, const BestLattice<DInterval>& best);
// Writes the files of a certified packing (nothing when it is not certified).
void write_packing_files(const PackingFiles& files, const PeriodicCertificate<DInterval>& proof, const std::string& command);

}  // namespace superpack::cli
