// Test helpers: golden data, reference balls, the field types every test body runs with.
#pragma once
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "superpack/arith/arb_access.hpp"
#include "superpack/problems/families/families.hpp"

namespace superpack::test {

// The backends each TEMPLATE_TEST_CASE runs with: binary64 intervals and Arb at two precisions.
struct Binary64 : DoubleField {};
struct Arb128 : BallField {
    Arb128() : BallField{128} {}
};
struct Arb400 : BallField {
    Arb400() : BallField{400} {}
};

inline const nlohmann::json& golden() {
    static const nlohmann::json data = [] {
        std::ifstream file(std::string(SUPERPACK_TEST_DATA) + "/golden.json");
        REQUIRE(file.good());
        return nlohmann::json::parse(file);
    }();
    return data;
}

// D14's x, y, z and phi at seven p (scripts/make_d14_golden.py, mpmath at 60 digits).
inline const nlohmann::json& d14_golden() {
    static const nlohmann::json data = [] {
        std::ifstream file(std::string(SUPERPACK_TEST_DATA) + "/d14.json");
        REQUIRE(file.good());
        return nlohmann::json::parse(file);
    }();
    return data["d14"];
}

// S6's basis, multipliers and phi at five p (scripts/make_s6_golden.py, mpmath at 60 digits).
inline const nlohmann::json& s6_golden() {
    static const nlohmann::json data = [] {
        std::ifstream file(std::string(SUPERPACK_TEST_DATA) + "/s6.json");
        REQUIRE(file.good());
        return nlohmann::json::parse(file);
    }();
    return data["s6"];
}

// The reference value from mpmath (50 digits) as a ball of radius 1e-48: the generator is
// not rigorous, so a test asks for overlap with this ball, never for equality.
inline Ball reference(const std::string& decimal) {
    Ball result(256);
    const std::string text = decimal + " +/- 1e-48";
    REQUIRE(arb_set_str(arb_of(result), text.c_str(), 256) == 0);
    return result;
}

inline Ball as_ball(const Ball& x) { return x; }
inline Ball as_ball(const DInterval& x) { return from_doubles(Ball(64), x.lower(), x.upper()); }

// Does the enclosure x meet the reference ball?
template <class I>
bool meets(const I& x, const std::string& decimal) {
    Ball meet(256);
    return intersect(meet, as_ball(x), reference(decimal));
}

template <class I>
bool overlaps(const I& a, const I& b) {
    I meet = a;
    return intersect(meet, a, b);
}

// A generous width bound for the backend: binary64 loses a few hundred ulps, Arb a few bits.
template <class Field>
double width_budget(const Field& field) {
    return std::ldexp(1.0, -static_cast<int>(field.bits()) + 16);
}

}  // namespace superpack::test
