// `superpack critical` at p = 2 (binary64): the branch and bound over boxes of half-width 5e-5
// (in the chart) around C1's images, on 1 and then 2 threads in the same run; the goal is a
// speedup of 1.8 (issue 13), reported as the ratio of the two wall times. The leaves must be
// the same on both (the order of the queue does not change a box's reason).
#include <chrono>
#include <cstdio>

#include "superpack/problems/critical.hpp"

using namespace superpack;

int main() {
    const DoubleField field;
    const Rational p(2);
    const CriticalReference<DInterval> reference = critical_reference(p, field);
    if (!reference.optimum) return 1;
    const ClosingRegion<DInterval> region = certify_closing_region(*reference.optimum, field.rational(p), 1e-2, 6);
    CriticalOptions options;
    options.p = p;
    for (const ChartImage& image : chart_images(region, 0))
        options.start_boxes.push_back(chart_box_around(image.chart_basis, image.configuration, 5e-5));
    CriticalResult<DInterval> results[2];
    double seconds[2];
    for (int threads = 1; threads <= 2; ++threads) {
        options.threads = threads;
        const auto start = std::chrono::steady_clock::now();
        results[threads - 1] = critical_bound(reference, options);
        seconds[threads - 1] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    const bool proved = results[0].status == Outcome::proved && results[1].status == Outcome::proved &&
                        results[0].counts == results[1].counts;
    const double speedup = seconds[0] / seconds[1];
    std::printf("critical --p 2 around C1's images (%ld boxes, %s): 1 thread %.2f s, 2 threads %.2f s, speedup %.2fx "
                "goal 1.8x %s\n",
                results[0].processed, proved ? "proved, same leaves" : "NOT PROVED OR LEAVES DIFFER", seconds[0], seconds[1],
                speedup, speedup >= 1.8 ? "PASS" : "FAIL");
    return proved ? 0 : 1;  // a missed speedup is reported, not an error
}
