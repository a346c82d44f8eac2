// The critical-lattice certificate of a run of `critical_bound` at p = 2, gap 0, with its trees
// recorded: what the certificate tests of critical-lattice and critical-lattice-cover tamper with.
#pragma once
#include <catch2/catch.hpp>
#include <functional>
#include <nlohmann/json.hpp>

#include "superpack/cert/critical_certificate.hpp"

namespace superpack::test {

// `place` sets where the run starts (--around, --split and --shard) and the gap; the run must be
// proved.
inline nlohmann::json critical_certificate_at(const Rational& p, const std::function<void(CriticalOptions&)>& place) {
    const CriticalReference<DInterval> reference = critical_reference(p, DoubleField{});
    CriticalOptions options;
    options.p = p;
    options.record_trees = true;
    place(options);
    const CriticalResult<DInterval> result = critical_bound(reference, options);
    REQUIRE(result.status == Outcome::proved);
    return nlohmann::json::parse(critical_certificate(result, options).dump());
}

inline nlohmann::json critical_certificate_at_p2(const std::function<void(CriticalOptions&)>& place) {
    return critical_certificate_at(Rational(2), place);
}

}  // namespace superpack::test
