// Goal: the certified superdisk optimum to width 1e-9 in at most 1 s per p (best of 3 runs).
// The time is also given as a ratio to a reference measured in the same run: enclosing the
// Lambda1 lattice at one p (its closed form at t = 0 and the disk's area), so a slower machine
// shifts both. The reference is the best of five blocks of 200 calls: a single block, the first
// thing the process does, varied by half between runs.
#include <algorithm>
#include <chrono>
#include <cstdio>

#include "superpack/problems/superdisk/superdisk.hpp"

using namespace superpack;

namespace {

template <class Body>
double seconds(const Body& body) {
    const auto start = std::chrono::steady_clock::now();
    body();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main() {
    const DoubleField field;
    const int repeats = 200;
    double reference = 1e9;
    for (int block = 0; block < 5; ++block)
        reference = std::min(reference, seconds([&] {
                                 for (int k = 0; k < repeats; ++k)
                                     (void)enclose_hexagon_lattice(Rational(0), parse_rational("1.25"), field);
                             }) / repeats);
    bool all = true;
    for (const char* p : {"0.6", "0.75", "1.1", "1.25", "1.5", "2", "3"}) {
        double width = 1;
        std::string attained;
        // Best of three runs: the machine is shared, and the goal is about the method, not the noise.
        double time = 1e9;
        for (int run = 0; run < 3; ++run)
            time = std::min(time, seconds([&] {
                const auto report = analyse_superdisk(parse_rational(p), field);
                width = report.status == OptimumStatus::certified ? width_upper(report.optimal_phi) : 1.0;
                attained = report.attained_by;
            }));
        const bool pass = time <= 1.0 && width <= 1e-9;
        all = all && pass;
        std::printf("superdisk optimum p=%s (width %.2e, %s): %.3f s (%.0fx of one lattice enclosure, %.2e s) goal 1 s "
                    "and width 1e-9 %s\n",
                    p, width, attained.c_str(), time, time / reference, reference, pass ? "PASS" : "FAIL");
    }
    return all ? 0 : 1;
}
