// Benchmark: the audit of every family over its claimed range (S6: its default range about 9/10) (goal <= 60 s on 2 cores).
// Reference measured in the same run: the unverified double-precision check of the same O1
// lattices (a plain norm loop over the same coefficient boxes, no intervals), so the ratio says
// what rigour costs.
#include <chrono>
#include <cmath>
#include <iostream>

#include "superpack/problems/families/audit.hpp"

using namespace superpack;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Plain doubles: the O1 lattice at p, its short-vector scan in the box |a|,|b|,|c| <= 3.
double unverified_o1_scan(double p) {
    const double two_p = 2 * p, l = std::pow(3.0, -1 / two_p);
    double q = 1.0 / 6, s = 2.0 / 3;
    for (int iteration = 0; iteration < 50; ++iteration) {  // Newton on Eq. (12), guesses only
        const double f1 = 2 * std::pow(q, two_p) + std::pow(s, two_p) - 1;
        const double f2 = std::pow(l + q, two_p) + std::pow(std::fabs(s - l), two_p) + std::pow(l - q, two_p) - 1;
        const double a = 2 * two_p * std::pow(q, two_p - 1), b = two_p * std::pow(s, two_p - 1);
        const double c = two_p * (std::pow(l + q, two_p - 1) - std::pow(l - q, two_p - 1));
        const double d = two_p * std::copysign(std::pow(std::fabs(s - l), two_p - 1), s - l);
        const double det = a * d - b * c;
        q -= (d * f1 - b * f2) / det;
        s -= (a * f2 - c * f1) / det;
    }
    const double basis[3][3] = {{2 * l, 2 * l, -2 * l}, {-2 * q, 2 * s, -2 * q}, {2 * q, -2 * q, -2 * s}};
    double shortest = 1e300;
    for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j)
            for (int k = -3; k <= 3; ++k) {
                if (i == 0 && j == 0 && k == 0) continue;
                double sum = 0;
                for (int m = 0; m < 3; ++m)
                    sum += std::pow(std::fabs(i * basis[0][m] + j * basis[1][m] + k * basis[2][m]), two_p);
                shortest = std::min(shortest, std::pow(sum, 1 / two_p));
            }
    return shortest;
}

}  // namespace

int main() {
    const auto reference_start = std::chrono::steady_clock::now();
    double sink = 0;
    for (int i = 0; i < 300; ++i) sink += unverified_o1_scan(0.5 + 0.29 * (i + 0.5) / 300);
    const double reference = seconds_since(reference_start);

    const auto start = std::chrono::steady_clock::now();
    std::size_t pieces = 0, undecided = 0;
    for (Family family : all_families()) {
        const AuditResult result = audit_family(family, claimed_audit_range(family), default_audit_settings(family));
        pieces += result.pieces.size();
        for (const AuditPiece& piece : result.pieces) undecided += piece.outcome == "undecided";
    }
    const double measured = seconds_since(start);
    std::cout << "pieces " << pieces << ", undecided " << undecided << " (unverified scans: " << (sink > 0) << ")\n";
    std::cout << "audit of C0, C1, O0, O1, D14, S6 (its default range): " << measured << " s (" << measured / reference
              << "x of the unverified double scan of 300 O1 lattices, " << reference << " s) goal 60 s "
              << (measured <= 60 ? "PASS" : "FAIL") << "\n";
    return 0;
}
