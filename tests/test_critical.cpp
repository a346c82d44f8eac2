// superpack critical (NOTES.md section 12): the chart, the relabelling reduction, closing
// regions, and small branch and bound runs that prove, alone and in shards.
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "support.hpp"
#include "superpack/problems/critical/critical.hpp"
#include "superpack/problems/critical/critical_contraction.hpp"

using namespace superpack;

namespace {

const CriticalReference<DInterval>& reference_at_2() {
    static const CriticalReference<DInterval> reference = critical_reference(Rational(2), DoubleField{});
    return reference;
}

const ClosingRegion<DInterval>& region_at_2() {
    static const ClosingRegion<DInterval> region =
        certify_closing_region(*reference_at_2().optimum, DoubleField{}.rational(Rational(2)), 1e-2, 6);
    return region;
}

}  // namespace

TEST_CASE("critical chart: (s, t) in [0, 1]^2 covers the triangle x >= y >= z >= 0 of bd(2K), and b_i lie on bd(2K)") {
    const DoubleField field;
    const DInterval two_p = field.integer(4);  // p = 2
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (int trial = 0; trial < 200; ++trial) {
        std::array<double, 3> u{uniform(random), uniform(random), uniform(random)};
        // The signed permutation that sorts |u| decreasing takes u into the cone.
        for (double& x : u) x = std::fabs(x);
        std::sort(u.begin(), u.end(), std::greater<double>());
        const double s = u[1] / u[0], t = u[2] / u[1];
        REQUIRE(s >= 0);
        REQUIRE(s <= 1);
        REQUIRE(t >= 0);
        REQUIRE(t <= 1);
        const std::array<DInterval, chart_dimension> x{DInterval(s), DInterval(t), DInterval(0.0),
                                                       DInterval(0.0), DInterval(0.0), DInterval(0.0)};
        const Basis<DInterval> b = chart_basis(x, 0, 2, two_p);
        const double norm = std::pow(std::pow(u[0], 4) + std::pow(u[1], 4) + std::pow(u[2], 4), 0.25);
        for (int j = 0; j < 3; ++j) CHECK(std::fabs(mid_double(b[0][j]) - 2 * u[j] / norm) < 1e-12);
        for (int k = 0; k < 3; ++k) {
            const DInterval power = half_norm_power(b[k], two_p);
            CHECK(contains(power + DInterval(-1e-12, 1e-12), DInterval(1.0)));
        }
    }
    // Each face point has its face coordinate +-1 and the two free ones in place.
    for (int face = 0; face < cube_faces; ++face) {
        const std::array<DInterval, 3> v = face_point(face, DInterval(0.25), DInterval(-0.5));
        CHECK(mid_double(v[face / 2]) == (face % 2 == 0 ? 1.0 : -1.0));
        CHECK(mid_double(v[face / 2 == 0 ? 1 : 0]) == 0.25);
        CHECK(mid_double(v[face / 2 == 2 ? 1 : 2]) == -0.5);
    }
    CHECK(top_level_domain().size() == static_cast<std::size_t>(top_level_boxes));
    CHECK(top_level_boxes == 168);
    for (const ChartBox<DInterval>& box : top_level_domain()) CHECK(box.face2 <= box.face3);
}

TEST_CASE("critical relabelling: Stab(A3) moves b1 to each of its 12 vectors, Stab(W) only to +-b1, +-b2, +-b3") {
    for (const MinkowskiCase configuration : {MinkowskiCase::a3, MinkowskiCase::w}) {
        std::vector<Coefficients> set;
        for (const Coefficients& c : configuration_triples(configuration)) {
            set.push_back(c);
            set.push_back({-c[0], -c[1], -c[2]});
        }
        auto in_set = [&](const Coefficients& c) { return std::find(set.begin(), set.end(), c) != set.end(); };
        std::set<Coefficients> first_rows;
        std::size_t order = 0;
        for (const Coefficients& r0 : set)
            for (const Coefficients& r1 : set)
                for (const Coefficients& r2 : set) {
                    const std::array<Coefficients, 3> w{r0, r1, r2};
                    const long det = r0[0] * (r1[1] * r2[2] - r1[2] * r2[1]) - r0[1] * (r1[0] * r2[2] - r1[2] * r2[0]) +
                                     r0[2] * (r1[0] * r2[1] - r1[1] * r2[0]);
                    if (det != 1 && det != -1) continue;
                    // B -> W B keeps the configuration iff d^T W is in +-C for every d in C.
                    bool keeps = true;
                    for (const Coefficients& d : set) {
                        Coefficients image{};
                        for (int k = 0; k < 3; ++k) image[k] = d[0] * w[0][k] + d[1] * w[1][k] + d[2] * w[2][k];
                        keeps = keeps && in_set(image);
                    }
                    if (!keeps) continue;
                    ++order;
                    first_rows.insert(r0);
                }
        INFO(configuration_name(configuration));
        // Swapping b2 and b3 keeps b1 and the configuration: the chart may take face2 <= face3.
        const std::array<Coefficients, 3> swap{{{1, 0, 0}, {0, 0, 1}, {0, 1, 0}}};
        for (const Coefficients& d : set) {
            Coefficients image{};
            for (int k = 0; k < 3; ++k) image[k] = d[0] * swap[0][k] + d[1] * swap[1][k] + d[2] * swap[2][k];
            CHECK(in_set(image));
        }
        if (configuration == MinkowskiCase::a3) {
            CHECK(order == 48);
            CHECK(first_rows.size() == 12);
        } else {
            CHECK(order == 12);
            CHECK(first_rows.size() == 6);
            for (const Coefficients& c : first_rows) CHECK(std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) == 1);
        }
    }
}

TEST_CASE("critical at p = 2: C1's images lie in the chart on the configuration, with |det| = det*") {
    const ClosingRegion<DInterval>& region = region_at_2();
    REQUIRE(region.verdict == Outcome::proved);
    const std::vector<ChartImage> images = chart_images(region, 0);
    REQUIRE(!images.empty());
    const DoubleField field;
    const DInterval two_p = field.integer(4);
    const double det_star = mid_double(region.determinant);
    for (const ChartImage& image : images) {
        CHECK(image.configuration == MinkowskiCase::a3);  // C1's contacts are an A3 set, no W set
        const ChartBox<DInterval> box = chart_box_around(image.chart_basis, image.configuration, 0);
        std::array<DInterval, chart_dimension> x = box.x;
        const Basis<DInterval> b = chart_basis(x, box.face2, box.face3, two_p);
        for (const DInterval& g : chart_equations(b, image.configuration, two_p)) CHECK(std::fabs(mid_double(g)) < 1e-9);
        CHECK(std::fabs(std::fabs(mid_double(determinant(b))) - det_star) < 1e-9);
    }
}

TEST_CASE("closing region at C1, p = 2: proved with the KKT multipliers, refused with wrong ones or too wide") {
    const ClosingRegion<DInterval>& region = region_at_2();
    REQUIRE(region.verdict == Outcome::proved);
    CHECK(region.radius > 0);
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) CHECK(contains(region.region[k][j], region.center[k][j]));
    const DInterval p = DoubleField{}.rational(Rational(2));
    // Wrong multipliers: the first one 1% too large. Krawczyk finds no KKT point in that box.
    LocalOptimum<DInterval> wrong = *reference_at_2().optimum;
    wrong.multipliers[0] = wrong.multipliers[0] * DInterval(1.01);
    const ClosingRegion<DInterval> refused = certify_closing_region(wrong, p, 1e-2, 6);
    CHECK(refused.verdict != Outcome::proved);
    CHECK(refused.reason.find("Krawczyk") != std::string::npos);
    // A region far too wide: the Hessian is not positive definite on all of it.
    const ClosingRegion<DInterval> wide = certify_closing_region(*reference_at_2().optimum, p, 0.5, 1);
    CHECK(wide.verdict != Outcome::proved);
}

TEST_CASE("closing region at p = 3/5: D14 has seven contact pairs, so its region has no image in a six-pair chart") {
    const DoubleField field;
    const CriticalReference<DInterval> reference = critical_reference(Rational(3, 5), field);
    REQUIRE(reference.optimum);
    REQUIRE(reference.optimum->verdict == Outcome::proved);
    CHECK(reference.optimum->contacts.size() == 7);
    const ClosingRegion<DInterval> region = certify_closing_region(*reference.optimum, field.rational(Rational(3, 5)), 1e-2, 6);
    INFO(region.reason);
    REQUIRE(region.verdict == Outcome::proved);
    // A chart point satisfies only six of the region's seven constraints: no image.
    CHECK(chart_images(region, 0).empty());
}

TEST_CASE("critical at p = 2 around C1's images: every box closes (det bound or closing region), one run and two shards") {
    const ClosingRegion<DInterval>& region = region_at_2();
    REQUIRE(region.verdict == Outcome::proved);
    CriticalOptions options;
    options.p = Rational(2);
    for (const ChartImage& image : chart_images(region, 0))
        options.start_boxes.push_back(chart_box_around(image.chart_basis, image.configuration, 3e-5));
    const CriticalResult<DInterval> whole = critical_bound(reference_at_2(), options);
    INFO(whole.message);
    REQUIRE(whole.status == Outcome::proved);
    CHECK(whole.partial_domain);
    CHECK(whole.counts[static_cast<int>(BoxReason::closing_region)] > 0);
    CHECK(whole.counts[static_cast<int>(BoxReason::determinant)] > 0);
    // Two of the four images lie outside the fundamental domain of the relabellings that keep b1
    // (a2 > a3 on a shared face, or b1 . (b2 + b3) < |b1|^2): their boxes are symmetric leaves.
    CHECK(whole.counts[static_cast<int>(BoxReason::symmetric)] == 2);
    // The bound is det* itself (gap 0): T is the certified lower end of det of C1.
    CHECK(certainly_less(whole.threshold, DInterval(mid_double(region.determinant)) + DInterval(1e-12)));
    CHECK(mid_double(whole.relative_gap) < 1e-12);

    // Two shards, two threads each: the same leaves between them.
    std::array<long, box_reasons> sum{};
    for (int shard = 0; shard < 2; ++shard) {
        CriticalOptions part = options;
        part.shard = shard;
        part.shards = 2;
        part.threads = 2;
        const CriticalResult<DInterval> result = critical_bound(reference_at_2(), part);
        CHECK(result.status == Outcome::proved);
        for (int r = 0; r < box_reasons; ++r) sum[r] += result.counts[r];
    }
    CHECK(sum == whole.counts);

    // With a closing region too small to hold any box (radius 1e-12), the boxes at C1 cannot
    // close (T is det* itself): undecided at the width floor, never proved.
    CriticalOptions floor = options;
    floor.min_width = 5e-6;
    floor.region_radius = 1e-12;
    const CriticalResult<DInterval> undecided = critical_bound(reference_at_2(), floor);
    CHECK(undecided.status == Outcome::undecided);
    CHECK(undecided.counts[static_cast<int>(BoxReason::undecided_width)] > 0);
    // A budget reached leaves the rest undecided, counted.
    CriticalOptions budget = options;
    budget.max_boxes = 10;
    const CriticalResult<DInterval> stopped = critical_bound(reference_at_2(), budget);
    CHECK(stopped.status == Outcome::undecided);
    CHECK(stopped.counts[static_cast<int>(BoxReason::undecided_budget)] > 0);
}

TEST_CASE("critical contractors: contract_linear keeps each point where the form meets a target and cuts the rest") {
    const DInterval zero(0.0), whole(-1.0, 1.0);
    ChartPoint center, x;
    center.fill(zero);
    x.fill(whole);
    // f = 0.1 + x0 + [-0.01, 0.01] x1 on [-1, 1]^6.
    LinearForm form{DInterval(0.1), {}};
    form.slope.fill(zero);
    form.slope[0] = DInterval(1.0);
    form.slope[1] = DInterval(-0.01, 0.01);
    ChartPoint root = x;
    REQUIRE(contract_linear(form, {zero}, root, center));
    CHECK(contains(root[0], DInterval(-0.11 + 1e-9, -0.09 - 1e-9)));
    CHECK(certainly_less(DInterval(-0.12), root[0]));
    CHECK(certainly_less(root[0], DInterval(-0.08)));
    for (int k = 1; k < chart_dimension; ++k) CHECK(same_interval(root[k], whole));  // slopes with 0: not cut
    // Two targets: the hull of both parts; a target out of reach: nothing left.
    ChartPoint two = x;
    REQUIRE(contract_linear(form, {zero, DInterval(0.5, 0.6)}, two, center));
    CHECK(contains(two[0], DInterval(-0.11 + 1e-9, 0.51 - 1e-9)));
    CHECK(certainly_less(two[0], DInterval(0.52)));
    ChartPoint none = x;
    CHECK(!contract_linear(form, {DInterval(5.0, 6.0)}, none, center));
}

TEST_CASE("critical contractors: at C1's images the configuration contractor keeps the lattice and narrows three coordinates") {
    const ClosingRegion<DInterval>& region = region_at_2();
    REQUIRE(region.verdict == Outcome::proved);
    const DInterval two_p = DoubleField{}.integer(4);
    for (const ChartImage& image : chart_images(region, 0)) {
        const ChartBox<DInterval> point = chart_box_around(image.chart_basis, image.configuration, 0);
        const ChartBox<DInterval> narrow = chart_box_around(image.chart_basis, image.configuration, 1e-4);
        const ChartBox<DInterval> wide = chart_box_around(image.chart_basis, image.configuration, 1e-2);
        // Wide (1e-2) in three coordinates and narrow (1e-4) in the others: where the three
        // wide ones can serve as the manifold's normal coordinates, its shadow over the narrow
        // three is far narrower than 1e-2. Every choice must keep the image.
        int best = 0;
        for (int a = 0; a < chart_dimension; ++a)
            for (int b = a + 1; b < chart_dimension; ++b)
                for (int c = b + 1; c < chart_dimension; ++c) {
                    ChartBox<DInterval> box = narrow;
                    for (const int k : {a, b, c}) box.x[k] = wide.x[k];
                    ChartPoint x = box.x;
                    REQUIRE(contract_to_configuration(chart_forms(box, two_p), x));
                    int narrowed = 0;
                    for (int k = 0; k < chart_dimension; ++k) {
                        // The image is on the manifold (to the guess's 1e-12): it must stay.
                        CHECK(contains(x[k] + DInterval(-1e-12, 1e-12), point.x[k]));
                        if (width_upper(x[k]) < 0.5 * width_upper(box.x[k])) ++narrowed;
                    }
                    best = std::max(best, narrowed);
                }
        CHECK(best >= 3);
        // The narrow box moved off the manifold by 0.05 in a2: no configuration point is left.
        ChartBox<DInterval> moved = narrow;
        moved.x[2] = moved.x[2] + DInterval(0.05);
        ChartPoint y = moved.x;
        CHECK(!contract_to_configuration(chart_forms(moved, two_p), y));
    }
}

TEST_CASE("critical: the domain's limits are refused") {
    CHECK_THROWS_AS(require_critical_domain(Rational(1, 2), Rational(0)), InputError);
    CHECK_THROWS_AS(require_critical_domain(Rational(11), Rational(0)), InputError);
    CHECK_THROWS_AS(require_critical_domain(Rational(1), Rational(0)), InputError);
    CHECK_THROWS_AS(require_critical_domain(Rational(2), Rational(1, 2)), InputError);
    CHECK_THROWS_AS(require_critical_domain(Rational(2), Rational(-1, 100)), InputError);
    CHECK_NOTHROW(require_critical_domain(Rational(1), Rational(1, 1000)));
    CHECK_NOTHROW(require_critical_domain(Rational(2), Rational(0)));
}
