#include "superpack/geometry/contact_configuration.hpp"

#include <algorithm>
#include <set>

namespace superpack {

namespace {

long det3(const Transform& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// x with x M = c for a unimodular M (rows b1, b2, b3): x = c adj(M) / det M, exact.
Coefficients coordinates(const Coefficients& c, const Transform& m, long det) {
    Transform adjugate{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
            adjugate[i][j] = m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1];
        }
    Coefficients x{};
    for (int j = 0; j < 3; ++j) x[j] = (c[0] * adjugate[0][j] + c[1] * adjugate[1][j] + c[2] * adjugate[2][j]) * det;
    return x;
}

const std::set<Coefficients>& six_pair_set() {
    static const std::set<Coefficients> set{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, -1}, {1, 0, -1}, {1, -1, 0}};
    return set;
}
const std::set<Coefficients>& seven_pair_set() {
    static const std::set<Coefficients> set{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}};
    return set;
}

}  // namespace

ConfigurationMatch match_configuration(const std::vector<Coefficients>& contacts) {
    std::vector<Coefficients> pairs;
    for (const Coefficients& c : contacts) {
        const Coefficients r = representative(c);
        if (std::find(pairs.begin(), pairs.end(), r) == pairs.end()) pairs.push_back(r);
    }
    ConfigurationMatch match;
    match.pairs = pairs.size();
    if (pairs.size() != 6 && pairs.size() != 7) return match;
    const std::set<Coefficients>& target = pairs.size() == 6 ? six_pair_set() : seven_pair_set();
    // Every basis of three contacts, with signs (the first sign is free: -M gives -x).
    for (std::size_t i = 0; i < pairs.size(); ++i)
        for (std::size_t j = 0; j < pairs.size(); ++j)
            for (std::size_t k = 0; k < pairs.size(); ++k) {
                if (i == j || j == k || i == k) continue;
                for (int signs = 0; signs < 4; ++signs) {
                    Transform m{pairs[i], pairs[j], pairs[k]};
                    if (signs & 1) for (long& x : m[1]) x = -x;
                    if (signs & 2) for (long& x : m[2]) x = -x;
                    const long det = det3(m);
                    if (det != 1 && det != -1) continue;
                    std::set<Coefficients> image;
                    for (const Coefficients& c : pairs) image.insert(representative(coordinates(c, m, det)));
                    if (image == target) {
                        match.configuration = pairs.size() == 6 ? Configuration::six_pairs : Configuration::seven_pairs;
                        match.basis = m;
                        return match;
                    }
                }
            }
    return match;
}

std::string configuration_text(const ConfigurationMatch& match) {
    switch (match.configuration) {
        case Configuration::six_pairs: return "six pairs: Minkowski's {b1, b2, b3, b2-b3, b3-b1, b1-b2}";
        case Configuration::seven_pairs: return "seven pairs: Minkowski's {b1, b2, b3, b1+b2, b2+b3, b3+b1, b1+b2+b3}";
        case Configuration::other: break;
    }
    return std::to_string(match.pairs) + " pairs, not one of Minkowski's two configurations";
}

}  // namespace superpack
