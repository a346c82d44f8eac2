// The mpmath reference values of scripts/make_crossover_reference.py (tests/data/crossover.json).
#pragma once
#include "support.hpp"

namespace superpack::test {

inline const nlohmann::json& crossover_reference() {
    static const nlohmann::json data = [] {
        std::ifstream file(std::string(SUPERPACK_TEST_DATA) + "/crossover.json");
        REQUIRE(file.good());
        return nlohmann::json::parse(file);
    }();
    return data;
}

inline std::string reference_text(const std::string& key) { return crossover_reference()[key].get<std::string>(); }

}  // namespace superpack::test
