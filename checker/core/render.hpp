// How the checker writes numbers: the "decimal" beside every exact interval of a certificate
// (which the checker re-renders and compares, document_check.hpp), and the numbers of the claim
// sentences it renders (claim_*.cpp). Every rendering comes from exact values: the endpoints of
// an interval read exactly from the file, or an exact rational; a lower end is rounded down and
// an upper end up, so the printed interval contains the exact one.
#pragma once
#include <gmpxx.h>

#include <string>

#include "checker/verifier.hpp"

namespace superpack_checker {

// "[lo, hi]" with 17 significant digits in exponent form ("[7.6567517828374320e-01, ...]"):
// the producer's rule for the "decimal" field (MPFR's directed conversion of the exact ends).
std::string decimal_field(const Real& x);
// "[lo, hi]" with 17 significant digits in the shortest form ("[0.76567517828374320, ...]"),
// for a sentence.
std::string enclosure_words(const Real& x);
// One end alone with 17 significant digits, rounded outward: the lower end down, the upper up
// ("a bound >= T" and "at most phi" stay true when printed).
std::string lower_end_words(const Real& x);
std::string upper_end_words(const Real& x);
// A rational exactly: a terminating decimal ("0.85", "-3.9") when it is one, else "a/b". The
// rule of the inputs' "p_decimal".
std::string exact_text(const mpq_class& q);
// exact_text, and for a fraction its first 12 decimals, truncated: "1216766151/2392000000
// (0.508681501254...)".
std::string rational_words(const mpq_class& q);

// check_encloses (replay.hpp), returning the stated enclosure it proved to contain the
// checker's value `own` and to be hardly wider. Sentences show these stated enclosures, not the
// checker's own: they are a function of the file alone, so the rendering does not move with the
// checker's precision or arithmetic, and each is proved to hold the true value about as tightly
// as the checker can.
Real proved_enclosure(Context& context, const Json& stated, const std::string& path, const Real& own);
// An enclosure whose claim is a bound ("2p-norm in [...] < 2", "g(x) in [...] < 1"): it must
// hold the checker's value and lie certainly below `bound` itself, so that what the file states
// shows the claim (a witness norm widened to [1.97, 3.95] held the checker's and showed no "< 2").
Real proved_below(Context& context, const Json& stated, const std::string& path, const Real& own, long bound);

// The inputs' "p_decimal" (the user's p as an exact decimal, or a/b) must be exact_text(p).
void check_p_decimal(Context& context, const Json& inputs, const mpq_class& p);

}  // namespace superpack_checker
