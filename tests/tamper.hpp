// Tampering with certificates in tests: every exact bound of a document, and a single-digit
// change that moves a bound inward. Shared by the certificate tests of every claim kind.
#pragma once
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "checker/core/render.hpp"
#include "checker/verifier.hpp"

namespace superpack::test {

// Every exact interval {"lo", "hi", "decimal"} under `node`, as JSON pointers to its two ends
// (exact intervals carry a decimal text, NOTES.md 8.1; rational ranges such as a piece's p do not).
inline void collect_bounds(const nlohmann::json& node, const std::string& pointer, std::vector<std::string>& bounds) {
    if (node.is_object()) {
        if (node.contains("lo") && node.contains("hi") && node.contains("decimal") && node["lo"].is_string()) {
            bounds.push_back(pointer + "/lo");
            bounds.push_back(pointer + "/hi");
            return;
        }
        for (const auto& [key, value] : node.items()) collect_bounds(value, pointer + "/" + key, bounds);
    } else if (node.is_array()) {
        for (std::size_t k = 0; k < node.size(); ++k) collect_bounds(node[k], pointer + "/" + std::to_string(k), bounds);
    }
}

// A committed certificate, proofs/<name>.json.
inline nlohmann::json committed_proof(const std::string& name) {
    std::ifstream file(std::filesystem::path(SUPERPACK_TEST_DATA) / ".." / ".." / "proofs" / (name + ".json"));
    REQUIRE(file.good());
    return nlohmann::json::parse(file);
}

// Changes the leading digit of the mantissa so that the bound moves inward (a lower end up,
// an upper end down): "5*2^-3" as a lower end becomes "6*2^-3", as an upper end "4*2^-3".
inline std::string tamper_inward(const std::string& text, bool lower) {
    if (text == "0") return lower ? "1" : "-1";
    const std::size_t star = text.find('*');
    std::string mantissa = text.substr(0, star);
    const std::string rest = star == std::string::npos ? "" : text.substr(star);
    const bool negative = mantissa[0] == '-';
    const std::size_t lead = negative ? 1 : 0;
    const bool grow = lower != negative;  // make |m| larger?
    if (grow) {
        if (mantissa[lead] == '9') mantissa.insert(lead, "1");
        else ++mantissa[lead];
    } else {
        --mantissa[lead];
        while (mantissa.size() > lead + 1 && mantissa[lead] == '0') mantissa.erase(lead, 1);
    }
    return mantissa + rest;
}

// Sets the bound at `pointer` (".../lo" or ".../hi") to `value` and renders the decimal beside it
// again by the checker's rule, as a forger would, so that only the checker's own steps can tell.
inline void set_bound(nlohmann::json& document, const std::string& pointer, const std::string& value) {
    const nlohmann::json::json_pointer at(pointer);
    document[at] = value;
    nlohmann::json& interval = document[at.parent_pointer()];
    try {
        const nlohmann::json copy = interval;
        superpack_checker::Context context(copy, 4096);
        interval["decimal"] = superpack_checker::decimal_field(context.interval(copy, pointer));
    } catch (const superpack_checker::Rejection&) {
        // lo > hi now (an empty interval): the replay rejects it at the bound's step anyway.
    }
}

// Moves the bound at `pointer` (".../lo" or ".../hi") inward with tamper_inward and renders the
// decimal beside it again by the checker's rule, so that only the replay of the proof can tell
// (the generic checks of decimals and of claim.text come after it). Returns the new bound.
inline std::string tamper_bound(nlohmann::json& document, const std::string& pointer) {
    const bool lower = pointer.substr(pointer.size() - 2) == "lo";
    const std::string after = tamper_inward(document[nlohmann::json::json_pointer(pointer)].get<std::string>(), lower);
    set_bound(document, pointer, after);
    return after;
}

// A step of the proof, not the generic checks that follow it (a decimal, claim.text): where a
// tampered bound must be rejected.
inline bool proof_step(const std::string& path) {
    return !path.empty() && path != "claim.text" && (path.size() < 8 || path.substr(path.size() - 8) != ".decimal");
}

// A copy of `original` with the bound at `pointer` moved inward (tamper_bound), replayed by the
// checker: the report, and the bound before and after, for the test's own assertions.
struct TamperedReplay {
    superpack_checker::VerifyReport report;
    std::string before, after;
};
inline TamperedReplay replay_tampered(const nlohmann::json& original, const std::string& pointer) {
    nlohmann::json copy = original;
    const std::string before = copy[nlohmann::json::json_pointer(pointer)].get<std::string>();
    const std::string after = tamper_bound(copy, pointer);
    return {superpack_checker::verify_document(copy), before, after};
}

// Replays `original` with the bound at `pointer` moved inward and checks that the checker rejects
// it at a step of the proof: the assertion every certificate test makes for each bound it tampers.
inline void check_tampered_bound_rejected(const nlohmann::json& original, const std::string& pointer) {
    const TamperedReplay replay = replay_tampered(original, pointer);
    INFO(pointer << ": " << replay.before << " -> " << replay.after << " (" << replay.report.path << ": "
                 << replay.report.message << ")");
    CHECK(replay.report.verdict == superpack_checker::Verdict::invalid);
    CHECK(proof_step(replay.report.path));
}

// The step at which the checker rejects `document`, or "(not rejected: <verdict>)": one
// comparison asserts both that the file is invalid and where.
inline std::string rejected_at(const nlohmann::json& document) {
    const auto report = superpack_checker::verify_document(document);
    if (report.verdict == superpack_checker::Verdict::invalid) return report.path;
    return "(not rejected)";
}

}  // namespace superpack::test
