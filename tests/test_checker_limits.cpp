// The checker on hostile or unusual input (NOTES.md 8.8): its precision follows the certificate's
// (a 700-digit certificate verifies) and "bits" must match the backend; every limit of
// checker/core/limits.hpp is enforced with a one-line rejection that names it, before the heavy work;
// duplicate keys, directories and missing files are unreadable, not internal errors.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "checker/core/json_reader.hpp"
#include "checker/core/limits.hpp"
#include "checker/verifier.hpp"
#include "crossover_reference.hpp"
#include "superpack/cert/crossover_certificate.hpp"
#include "superpack/arith/exact.hpp"
#include "support.hpp"
#include "tamper.hpp"

namespace {

using superpack_checker::Verdict;
using superpack_checker::verify_document;
using superpack_checker::verify_file;
using Document = nlohmann::json;
namespace fs = std::filesystem;

const fs::path proofs = fs::path(SUPERPACK_TEST_DATA) / ".." / ".." / "proofs";
const auto proof = superpack::test::committed_proof;

// A file in the temporary folder, removed at the end of the test.
struct TemporaryFile {
    fs::path path;
    explicit TemporaryFile(const std::string& text, const std::string& name = "certificate.json")
        : path(fs::temp_directory_path() / ("superpack-limits-" + std::to_string(std::rand()) + "-" + name)) {
        std::ofstream(path, std::ios::binary) << text;
    }
    ~TemporaryFile() { fs::remove(path); }
};

superpack_checker::VerifyReport verify_text_file(const std::string& text) { return verify_file(TemporaryFile(text).path); }

bool mentions(const superpack_checker::VerifyReport& report, const std::string& word) {
    return report.message.find(word) != std::string::npos;
}

// "m*2^e" exactly.
mpq_class dyadic_value(const std::string& text) {
    const std::size_t star = text.find("*2^");
    mpq_class value{mpz_class(text.substr(0, star), 10)};
    if (star != std::string::npos) {
        const long exponent = std::stol(text.substr(star + 3));
        if (exponent >= 0) mpq_mul_2exp(value.get_mpq_t(), value.get_mpq_t(), exponent);
        else mpq_div_2exp(value.get_mpq_t(), value.get_mpq_t(), -exponent);
    }
    return value;
}

// The exact interval holds the mpmath decimal (given to 50 digits: a 1e-48 margin).
bool holds(const Document& interval, const std::string& decimal) {
    const mpq_class value = superpack::parse_rational(decimal);
    const mpq_class margin(1, mpz_class("1" + std::string(48, '0')));
    return dyadic_value(interval["lo"]) <= value + margin && value - margin <= dyadic_value(interval["hi"]);
}

// A split node over `box` whose first case is `inner` and whose second is a leaf.
Document split(const Document& box, Document inner) {
    return Document{{"kind", "split"}, {"box", box}, {"dimension", 0u},
                    {"cases", Document::array({std::move(inner), Document{{"kind", "excluded"}, {"box", box}}})}};
}

}  // namespace

TEST_CASE("a 700-digit cubic crossover certificate verifies (the checker's boxes shrink below 2^-1074)") {
    // The checker's Newton iterations stopped when a width, as a double, stopped shrinking; every
    // width below 2^-1074 rounds up to the same subnormal, so p*_c stayed near 1e-650 wide while the
    // certificate's box is 1e-706 wide (NOTES.md 8.8). 600 digits passed by luck.
    const long digits = 700;
    const superpack::BallField field{superpack::bits_for_digits(digits)};
    const auto start = std::chrono::steady_clock::now();
    const Document certificate =
        superpack::cubic_crossover_certificate(superpack::certify_cubic_crossover(field, digits), field, digits);
    const auto report = verify_document(Document::parse(certificate.dump()));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "700-digit cubic crossover: written and verified in " << seconds << " s\n";
    INFO(report.path << ": " << report.message);
    CHECK(report.verdict == Verdict::valid);
    CHECK(report.precision == superpack::bits_for_digits(digits) + 64);
    // The claimed p*_c is the mpmath value (to its 50 digits).
    CHECK(holds(certificate["claim"]["data"]["p"], superpack::test::reference_text("p_c")));
}

TEST_CASE("\"bits\" must be what \"backend\" and \"digits\" give, checked before any work") {
    const Document binary64 = proof("density-O0-p0.85"), arb = proof("density-C0-p1.5-30digits");
    REQUIRE(verify_document(binary64).verdict == Verdict::valid);
    REQUIRE(verify_document(arb).verdict == Verdict::valid);
    auto rejected = [](Document document, const std::string& key, const Document& value) {
        document[key] = value;
        const auto report = verify_document(document);
        INFO(key << " = " << value.dump() << ": " << report.path << ": " << report.message);
        CHECK(report.verdict == Verdict::malformed);
        return report.path;
    };
    // A 3 KB binary64 certificate that asks for 100000 bits (the old checker ran it for minutes).
    CHECK(rejected(binary64, "bits", 100000) == "bits");
    CHECK(rejected(binary64, "bits", 64) == "bits");
    CHECK(rejected(binary64, "bits", "53") == "bits");
    CHECK(rejected(binary64, "digits", 30) == "digits");
    CHECK(rejected(arb, "bits", 133) == "bits");
    CHECK(rejected(arb, "bits", 53) == "bits");
    CHECK(rejected(arb, "digits", 31) == "bits");
    CHECK(rejected(arb, "digits", 0) == "digits");
    CHECK(rejected(arb, "digits", superpack_checker::max_digits + 1) == "digits");
    CHECK(rejected(arb, "digits", Document::number_unsigned_t{1} << 63) == "digits");
    CHECK(rejected(arb, "backend", "mpfr") == "backend");
    // The checker's rule is the producer's bits_for_digits at every --digits the command line takes.
    long disagreements = 0;
    for (long digits = 1; digits <= superpack_checker::max_digits; ++digits)
        disagreements += superpack_checker::arb_bits_for_digits(digits) != superpack::bits_for_digits(digits);
    CHECK(disagreements == 0);
}

TEST_CASE("nesting beyond max_json_depth or max_proof_depth is refused with the limit named") {
    // 100000 nested arrays: refused while parsing, before the deeper values are built.
    const auto arrays = verify_text_file(std::string(100000, '[') + std::string(100000, ']'));
    CHECK(arrays.verdict == Verdict::malformed);
    CHECK(mentions(arrays, "max_json_depth"));
    // A proof tree 20000 splits deep (the old checker: 20 s and 4.5 GB; 100000 crashed it).
    Document certificate = proof("density-O1-p0.6");
    Document& cases = certificate["proof"]["parameters"]["cases"];
    const Document box = cases[0]["box"];
    const std::string marker = "\"deep-tree\"";
    cases[0] = "deep-tree";
    const std::string text = certificate.dump(), node = split(box, Document()).dump();
    const std::size_t hole = node.find("null");
    std::string deep = text.substr(0, text.find(marker));
    for (int level = 0; level < 20000; ++level) deep += node.substr(0, hole);
    deep += Document{{"kind", "excluded"}, {"box", box}}.dump();
    for (int level = 0; level < 20000; ++level) deep += node.substr(hole + 4);
    deep += text.substr(text.find(marker) + marker.size());
    const auto tree = verify_text_file(deep);
    CHECK(tree.verdict == Verdict::malformed);
    CHECK(mentions(tree, "max_json_depth"));
    CHECK(tree.path.rfind("proof.parameters.cases[0].cases[0].cases[0]", 0) == 0);
    // A tree within the JSON limit but deeper than max_proof_depth splits.
    Document inner{{"kind", "excluded"}, {"box", box}};
    for (int level = 0; level <= superpack_checker::max_proof_depth; ++level) inner = split(box, inner);
    cases[0] = inner;
    const auto splits = verify_document(certificate);
    CHECK(splits.verdict == Verdict::malformed);
    INFO(splits.path << ": " << splits.message);
    CHECK(mentions(splits, "max_proof_depth"));
    // A document built in memory (not through the parser) is held to the JSON limit too.
    Document nested = Document::array();
    for (std::size_t level = 0; level < superpack_checker::max_json_depth + 10; ++level) nested = Document::array({nested});
    cases[0]["box"] = nested;
    const auto in_memory = verify_document(certificate);
    CHECK(in_memory.verdict == Verdict::malformed);
    CHECK(mentions(in_memory, "max_json_depth"));
    CHECK(in_memory.path.rfind("proof.parameters.cases[0].box[0][0]", 0) == 0);
}

TEST_CASE("more than max_json_values values are refused while parsing, with the limit named") {
    // A list of n zeros is n + 1 values: the limit itself is read, one more is refused at the
    // value that exceeds it, before it is built.
    auto zeros = [](std::size_t n) {
        std::string text = "[0";
        for (std::size_t k = 1; k < n; ++k) text += ",0";
        return text + "]";
    };
    const superpack_checker::JsonReading at_limit = superpack_checker::read_json(zeros(superpack_checker::max_json_values - 1));
    CHECK(at_limit.ok);
    CHECK(at_limit.document.size() == superpack_checker::max_json_values - 1);
    const superpack_checker::JsonReading beyond = superpack_checker::read_json(zeros(superpack_checker::max_json_values));
    CHECK_FALSE(beyond.ok);
    CHECK(beyond.message.find("max_json_values") != std::string::npos);
    // In a certificate: a list of empty objects (the largest memory per byte of file) is refused
    // in one line, at its path.
    std::string text = proof("density-O0-p0.85").dump();
    std::string padding = "\"padding\":[{}";
    for (std::size_t k = 0; k < superpack_checker::max_json_values; ++k) padding += ",{}";
    text.insert(1, padding + "],");
    const auto padded = verify_text_file(text);
    CHECK(padded.verdict == Verdict::malformed);
    CHECK(mentions(padded, "max_json_values"));
    CHECK(padded.path.rfind("padding[", 0) == 0);
}

TEST_CASE("a duplicate key is refused with its path (nlohmann would keep one silently)") {
    const std::string text = proof("density-O0-p0.85").dump();
    auto duplicated = [&](const std::string& before, const std::string& inserted) {
        std::string copy = text;
        const std::size_t at = copy.find(before);
        REQUIRE(at != std::string::npos);
        copy.insert(at + before.size(), inserted);
        return verify_text_file(copy);
    };
    const auto kind = duplicated("\"claim\":{", "\"kind\":\"family-lattice\",");
    CHECK(kind.verdict == Verdict::malformed);
    CHECK(kind.path == "claim.kind");
    CHECK(mentions(kind, "duplicate key"));
    const auto bits = duplicated("{", "\"bits\":53,");
    CHECK(bits.verdict == Verdict::malformed);
    CHECK(bits.path == "bits");
    const auto deep = duplicated("\"phi\":{", "\"lo\":\"0\",");
    CHECK(deep.verdict == Verdict::malformed);
    CHECK(deep.path == "claim.data.phi.lo");
}

TEST_CASE("a mantissa, exponent or rational beyond its limit is refused, naming the limit") {
    const Document certificate = proof("density-O0-p0.85");
    auto with_phi_lo = [&](const std::string& lo) {
        Document copy = certificate;
        copy["claim"]["data"]["phi"]["lo"] = lo;
        return verify_document(copy);
    };
    const auto mantissa = with_phi_lo(std::string(superpack_checker::max_mantissa_digits + 1, '7'));
    CHECK(mantissa.verdict == Verdict::malformed);
    CHECK(mantissa.path == "claim.data.phi");
    CHECK(mentions(mantissa, "max_mantissa_digits"));
    const auto exponent = with_phi_lo("1*2^-" + std::string(superpack_checker::max_exponent_digits + 1, '1'));
    CHECK(exponent.verdict == Verdict::malformed);
    CHECK(mentions(exponent, "max_exponent_digits"));
    // Within the digit limit but more bits than the checker's precision: unreadable as before.
    CHECK(with_phi_lo(std::string(100, '7') + "*2^-400").verdict == Verdict::malformed);
    Document rational = certificate;
    rational["inputs"]["p"] = "17/2" + std::string(superpack_checker::max_rational_characters, '0');
    const auto long_rational = verify_document(rational);
    CHECK(long_rational.verdict == Verdict::malformed);
    CHECK(mentions(long_rational, "max_rational_characters"));
}

TEST_CASE("exact numbers are read in base 10: a leading 0 is not octal") {
    // GMP's default base reads "017" as 15 and throws on "089"; the checker read a different
    // number than the text states (found by the fuzz test).
    Document certificate = proof("density-O0-p0.85");
    const std::string lo = certificate["claim"]["data"]["phi"]["lo"];
    certificate["claim"]["data"]["phi"]["lo"] = "0" + lo;
    certificate["inputs"]["p"] = "017/020";
    const auto padded = verify_document(certificate);
    INFO(padded.path << ": " << padded.message);
    CHECK(padded.verdict == Verdict::valid);
    certificate["claim"]["data"]["phi"]["hi"] = "089*2^-52";  // not octal (GMP's base 0 throws): below lo
    const auto below = verify_document(certificate);
    CHECK(below.verdict == Verdict::invalid);
    CHECK(below.path == "claim.data.phi");
}

TEST_CASE("a file beyond max_file_bytes, a directory or a missing file is unreadable in one line") {
    const TemporaryFile large("", "large.json");
    fs::resize_file(large.path, superpack_checker::max_file_bytes + 1);  // sparse: nothing is written
    const auto too_large = verify_file(large.path);
    CHECK(too_large.verdict == Verdict::malformed);
    CHECK(mentions(too_large, "max_file_bytes"));
    const auto directory = verify_file(proofs.string());
    CHECK(directory.verdict == Verdict::malformed);
    CHECK(mentions(directory, "directory"));
    const auto missing = verify_file((proofs / "no-such-certificate.json").string());
    CHECK(missing.verdict == Verdict::malformed);
    CHECK(mentions(missing, "cannot read"));
    // The command line: exit 2 and one line, never "internal error".
    const std::string err = (fs::temp_directory_path() / "superpack-limits-directory.err").string();
    const int status = std::system((std::string(SUPERPACK_BINARY) + " verify '" + proofs.string() + "' >/dev/null 2>" + err).c_str());
    std::ifstream stream(err);
    const std::string message((std::istreambuf_iterator<char>(stream)), {});
    std::remove(err.c_str());
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 2);
    CHECK(std::count(message.begin(), message.end(), '\n') == 1);
    CHECK(message.find("internal error") == std::string::npos);
}

TEST_CASE("checker predicates never hold for an interval with a NaN end; widths compare below 2^-1074") {
    using namespace superpack_checker;
    Real undefined(128);
    mpfr_set_nan(undefined.lower_end());
    mpfr_set_nan(undefined.upper_end());
    const Real wide = hull(integer(-1000, 128), integer(1000, 128));
    CHECK_FALSE(subset(undefined, wide));
    CHECK_FALSE(interior_subset(undefined, wide));
    CHECK_FALSE(less(undefined, wide));
    // Widths 2^-5000 and 2^-4000: a double sees one subnormal for both.
    auto one_plus = [](long exponent) {
        mpfr_t lo, hi;
        mpfr_inits2(6000, lo, hi, static_cast<mpfr_ptr>(nullptr));
        mpfr_set_si(lo, 1, MPFR_RNDN);
        mpfr_set_si_2exp(hi, 1, exponent, MPFR_RNDN);
        mpfr_add(hi, hi, lo, MPFR_RNDN);  // exact in 6000 bits
        Real result(6000);
        REQUIRE(exact_interval(result, lo, hi));
        mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
        return result;
    };
    CHECK(width(one_plus(-5000)) < width(one_plus(-4000)));
    CHECK(width(one_plus(-5000)) > 0.0);
}

TEST_CASE("the octahedral crossover's closed form must be the one the checker proves (found by the fuzz test)") {
    Document certificate = proof("crossover-octahedral");
    REQUIRE(verify_document(certificate).verdict == Verdict::valid);
    certificate["claim"]["data"]["closed_form"] = "1";
    const auto forged = verify_document(certificate);
    CHECK(forged.verdict == Verdict::invalid);
    CHECK(forged.path == "claim.data.closed_form");
    certificate["claim"]["data"].erase("closed_form");
    CHECK(verify_document(certificate).verdict == Verdict::malformed);
}
