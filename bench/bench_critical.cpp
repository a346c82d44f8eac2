// `superpack critical` (binary64), issue 13's figures measured in one run:
//   1. the whole domain at p = 2 with gap 1e-4 on 1 thread and then on 2: boxes, time, and the
//      speedup (goal 1.8x) as the ratio of the two wall times; the leaves must be the same (a
//      box's reason does not depend on the order of the queue);
//   2. the same run as 4 shards merged (merge_shards): the same status and the same leaves;
//   3. the boxes around C1's images (half-width 5e-5) at gap 0, where the closing region decides;
//   4. the cost of a proof, for issue 45: one shard's certificate at p = 2 (gap 0) and one at
//      p = 3/5 (gap 9e-5), written by `superpack critical --certificate`: the producer's boxes a
//      second on 1 thread, the certificate's bytes a box, and the checker's boxes a second on 1
//      thread (`superpack verify`, the process's wall time, best of two).
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "command_run.hpp"
#include "superpack/problems/critical/critical.hpp"

using namespace superpack;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool same_leaves(const CriticalResult<DInterval>& a, const CriticalResult<DInterval>& b) {
    return a.status == b.status && a.counts == b.counts && a.processed == b.processed;
}

const char* verdict(const CriticalResult<DInterval>& result) {
    return result.status == Outcome::proved ? "proved" : "NOT PROVED";
}

// Section 4: one shard written as a certificate, and replayed by the checker.
bool proof_cost(const std::string& directory, const char* p, const char* gap, int split, const char* shard) {
    const std::string file = directory + "/critical-p" + p + ".json";
    const CommandRun producer = run_json(std::string("critical --threads 1 --p ") + p + " --gap " + gap + " --split " +
                                         std::to_string(split) + " --shard " + shard + " --certificate " + file);
    struct stat status {};
    if (producer.document.is_discarded() || producer.document.value("status", "") != "proved" ||
        stat(file.c_str(), &status) != 0) {
        std::printf("critical --p %s --gap %s, shard %s at --split %d: NOT PROVED\n", p, gap, shard, split);
        return false;
    }
    double checker = 1e9;
    bool valid = true;
    for (int run = 0; run < 2; ++run) {
        const CommandRun replay = run_json("verify " + file);
        valid = valid && replay.document.value("verdict", "") == "valid";
        checker = std::min(checker, replay.seconds);
    }
    const double boxes = producer.document.at("processed").get<double>();
    std::printf("critical --p %s --gap %s, shard %s at --split %d: %.0f boxes; producer %.0f boxes/s (1 thread, %.2f s), "
                "certificate %.1f bytes/box (%.0f kB), checker %.0f boxes/s (1 process, %.2f s)%s\n",
                p, gap, shard, split, boxes, boxes / producer.document.at("seconds").get<double>(),
                producer.document.at("seconds").get<double>(), static_cast<double>(status.st_size) / boxes,
                static_cast<double>(status.st_size) / 1e3, boxes / checker, checker, valid ? "" : " CHECKER REJECTS");
    std::remove(file.c_str());
    return valid;
}

}  // namespace

int main() {
    const DoubleField field;
    const Rational p(2);
    const CriticalReference<DInterval> reference = critical_reference(p, field);
    if (!reference.optimum) return 1;
    CriticalOptions options;
    options.p = p;
    options.gap = Rational(1, 10000);

    CriticalResult<DInterval> whole[2];
    double seconds[2];
    for (int threads = 1; threads <= 2; ++threads) {
        options.threads = threads;
        const auto start = std::chrono::steady_clock::now();
        whole[threads - 1] = critical_bound(reference, options);
        seconds[threads - 1] = seconds_since(start);
    }
    const double speedup = seconds[0] / seconds[1];
    std::printf("critical --p 2 --gap 1e-4, whole domain: %s, %ld boxes, 1 thread %.1f s, 2 threads %.1f s, speedup %.2fx "
                "goal 1.8x %s%s\n",
                verdict(whole[0]), whole[0].processed, seconds[0], seconds[1], speedup, speedup >= 1.8 ? "PASS" : "FAIL",
                same_leaves(whole[0], whole[1]) ? "" : " (LEAVES DIFFER)");

    std::vector<ShardSummary> shards;
    for (int shard = 0; shard < 4; ++shard) {
        options.shard = shard;
        options.shards = 4;
        const CriticalResult<DInterval> part = critical_bound(reference, options);
        shards.push_back({shard, 4, 0, part.status == Outcome::proved, part.counts, part.processed, part.start_boxes, part.seconds});
    }
    const CriticalResult<DInterval> merged = merge_shards(critical_setup(reference, options), shards);
    const bool merge_agrees = same_leaves(merged, whole[0]);
    std::printf("critical --p 2 --gap 1e-4 as 4 shards merged: %s, %ld boxes, %s\n", verdict(merged), merged.processed,
                merge_agrees ? "the same leaves as the whole run" : "LEAVES DIFFER FROM THE WHOLE RUN");

    options = CriticalOptions{};
    options.p = p;
    const ClosingRegion<DInterval> region = certify_closing_region(*reference.optimum, field.rational(p), 1e-2, 6);
    for (const ChartImage& image : chart_images(region, 0))
        options.start_boxes.push_back(chart_box_around(image.chart_basis, image.configuration, 5e-5));
    const auto start = std::chrono::steady_clock::now();
    const CriticalResult<DInterval> near = critical_bound(reference, options);
    std::printf("critical --p 2, gap 0, half-width 5e-5 around C1's images: %s, %ld boxes (%ld closing_region), %.2f s\n",
                verdict(near), near.processed, near.counts[static_cast<int>(BoxReason::closing_region)], seconds_since(start));

    char directory[] = "/tmp/superpack-bench-XXXXXX";
    bool costs = mkdtemp(directory) != nullptr;
    costs = costs && proof_cost(directory, "2", "0", 4, "7/336");
    costs = costs && proof_cost(directory, "0.6", "9e-5", 6, "200/672");
    rmdir(directory);

    const bool proved = whole[0].status == Outcome::proved && same_leaves(whole[0], whole[1]) && merge_agrees &&
                        near.status == Outcome::proved && costs;
    return proved ? 0 : 1;  // a missed speedup is reported, not an error
}
