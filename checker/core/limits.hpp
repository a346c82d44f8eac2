// How much of a certificate the checker reads: every limit is a named constant here, stated in
// NOTES.md 8.8 and enforced with a one-line rejection that names it (an unreadable file, exit 2).
// The limits keep `superpack verify` safe on hostile input: its stack depth, memory and running
// time follow the size of the file and the precision the file asks for, both bounded here.
#pragma once
#include <cstddef>
#include <cstdint>
#include <limits>

namespace superpack_checker {

// The largest certificate file read, in bytes. A critical-lattice certificate is one long string
// per start box: about 77 bytes per box near a closing region at p = 3, where one shard takes
// 22.9 MB and one box of the domain at --split 8 (the finest) still holds 2.7e5 of its 3.0e5
// boxes; 150 to 210 bytes per box at p = 3/5, gap 9e-5, where the boxes near D14's images, far
// smaller than a start box, put 169 MB in one shard at --split 6 (NOTES.md 12.9). Memory follows
// the values of the document more than its bytes: the text, its strings (at most the file again)
// and at most max_json_values values of about 103 bytes each, so at most about 1 GB per file
// read, and one file per thread of `verify --threads N`.
constexpr std::uintmax_t max_file_bytes = std::uintmax_t{256} << 20;
// The values of one document (numbers, strings, booleans, nulls, arrays and objects; a key is
// not one), counted while parsing and refused before the next is built. Certificates in proofs/
// have at most 35221; a critical-lattice certificate has about 30 per start box, so
// max_chart_boxes of them take 1.3e6.
constexpr std::size_t max_json_values = std::size_t{1} << 22;

// Nesting of JSON arrays and objects (the document itself is level 1). Certificates in proofs/
// reach 22; the producer's partition trees are at most 201 splits deep (certificate_partition.hpp),
// two levels each. Checked while parsing, before a deeper value is built.
constexpr std::size_t max_json_depth = 1024;
// Nesting of "split" nodes in a proof tree (check_partition), with the same margin.
constexpr int max_proof_depth = 256;

// --digits of the producer: 1 to 100000 (the documented limit of the command line).
constexpr long max_digits = 100000;
// binary64 intervals: 53 bits, written as 15 digits.
constexpr long binary64_bits = 53;
constexpr long binary64_digits = 15;
// Arb balls: the producer's bits_for_digits, floor(digits * 3.3220) + 33 (log2 10 < 3.3220, and
// 32 guard bits), computed exactly in integers.
constexpr long arb_bits_for_digits(long digits) { return digits * 33220 / 10000 + 33; }
constexpr long max_bits = arb_bits_for_digits(max_digits);
// The checker works this far above the producer, and never below min_precision.
constexpr long guard_bits = 64;
constexpr long min_precision = 128;
constexpr long max_precision = max_bits + guard_bits;

// How wide a stated enclosure may be (check_encloses): at most enclosure_width_factor times the
// checker's own enclosure of the same value, plus 2^-(bits - enclosure_slack_bits) max(1, |x|) for
// the producer's rounding at its own bits. Measured over the 1003 enclosures the checker replays in
// proofs/ (NOTES.md 8.8): where the checker's own enclosure is as wide as the producer's (witness
// norms over a piece of p, the superdisk optimum) the stated one is at most 1.73 times wider, hence
// 4; elsewhere the checker's is about 2^64 narrower and the stated one at most 2^15.3 of the
// producer's units wide (the cubic crossover's phi*_c), hence 2^20, 27 times that, which still
// leaves a widened binary64 enclosure no more than 2^-33 of its value.
constexpr double enclosure_width_factor = 4;
constexpr long enclosure_slack_bits = 20;

// Exact numbers. A mantissa is exact at the checker's precision, so it has at most
// max_precision bits, that is max_precision * log10(2) < max_precision * 0.30103 decimal
// digits (plus one for rounding); an exponent |e| < 10^8 keeps every value within MPFR's
// exponent range (2^30) with room for the arithmetic; rationals are the short inputs (p, a basis).
constexpr std::size_t max_mantissa_digits = static_cast<std::size_t>(max_precision) * 30103 / 100000 + 1;
constexpr std::size_t max_exponent_digits = 8;
constexpr std::size_t max_rational_characters = 10000;

// Contact pairs of a local-optimum certificate (its KKT system has 9 + pairs unknowns): a lattice
// packing of a superball with 1/2 < p < oo has at most 7 (NOTES.md 11.2.2, item 2); 13 allows the
// cube's 13 pairs as well.
constexpr std::size_t max_contact_pairs = 13;

// An integer coefficient of a lattice vector (a contact, a witness, a shift, a candidate) or of a
// basis change: any 64-bit value but -2^63, so that -c is defined (negating -2^63 is undefined
// behaviour) and every coefficient read is the file's own value, never one wrapped into range.
constexpr long max_coefficient = std::numeric_limits<long>::max();

// The critical-lattice claim (claim_critical_lattice.cpp, NOTES.md 12.8). Start boxes: the whole
// domain has 168, split 8 times (max_domain_split) 168 * 2^8, --around a few. Closing regions:
// one per certified optimum near T (one so far, with 4 images in the chart at p = 2); the images
// are counted over all regions. A tree string is at most the file. Splits nest at most
// max_tree_depth deep (the
// replay keeps its own stack, never recursion): the producer stops at widths of 1e-10, about
// 33 halvings of each of the 6 coordinates, 200 levels. The entries of an image's W^-1 are
// small integers (adjugates of contact coefficients); the bound keeps their products exact.
constexpr std::size_t max_chart_boxes = std::size_t{168} << 8;
constexpr std::size_t max_closing_regions = 16;
constexpr std::size_t max_chart_images = 4096;
constexpr std::size_t max_tree_characters = std::size_t{256} << 20;
constexpr std::size_t max_tree_depth = 1024;
constexpr long max_image_coefficient = 1000;
// The files a critical-lattice-cover names: at most one per start box of the domain split
// max_domain_split times (168 * 2^8); each is read under max_file_bytes, one per thread at a time.
constexpr std::size_t max_cover_files = std::size_t{168} << 8;

// The periodic-packing claim (claim_periodic_packing.cpp): at most 256 particles in the cell
// (the producer's limit, periodic_packing.hpp: molecular dynamics jams a few hundred), and the
// lattice shifts whose boxes the checker enumerates for its list of close pairs, summed over the
// N (N + 1) / 2 pairs of particles and counted before any is enumerated (about 0.1 us each). A
// cube cell of side 12.4 holding 256 superballs at p = 2 and phi = 0.87 needs about 125 per
// pair, 4.1e6 in all; the producer refuses more than 10^6 for one pair.
constexpr std::size_t max_periodic_particles = 256;
constexpr long max_periodic_shifts = 1L << 24;

}  // namespace superpack_checker
