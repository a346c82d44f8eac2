// The images of a certified local minimiser in the chart of critical_chart.hpp: every basis
// (b1, b2, b3) of its lattice, times a signed permutation, that has the configuration's form with
// b1 in the chart. Found in floating point (a guess: an image missed leaves boxes undecided, an
// image wrongly included is only a region tested in vain); what each image proves is proved by
// the region and the exact W^-1.
#include <algorithm>
#include <cmath>

#include "superpack/problems/critical/critical.hpp"
#include "superpack/solve/dense3.hpp"

namespace superpack {

namespace {

constexpr double tolerance = 1e-7;

struct SignedPermutation {
    std::array<int, 3> perm;
    std::array<int, 3> sign;
};

std::vector<SignedPermutation> signed_permutations() {
    std::vector<SignedPermutation> all;
    std::array<int, 3> perm{0, 1, 2};
    do {
        for (int signs = 0; signs < 8; ++signs)
            all.push_back({perm, {signs & 1 ? -1 : 1, signs & 2 ? -1 : 1, signs & 4 ? -1 : 1}});
    } while (std::next_permutation(perm.begin(), perm.end()));
    return all;
}

using dense::max_norm;
using dense::Vector3;

Vector3 permuted(const Vector3& u, const SignedPermutation& s) {
    return {s.sign[0] * u[s.perm[0]], s.sign[1] * u[s.perm[1]], s.sign[2] * u[s.perm[2]]};
}

bool close(const Vector3& a, const Vector3& b) {
    return std::fabs(a[0] - b[0]) < tolerance && std::fabs(a[1] - b[1]) < tolerance && std::fabs(a[2] - b[2]) < tolerance;
}

long integer_determinant(const std::array<Coefficients, 3>& w) {
    return w[0][0] * (w[1][1] * w[2][2] - w[1][2] * w[2][1]) - w[0][1] * (w[1][0] * w[2][2] - w[1][2] * w[2][0]) +
           w[0][2] * (w[1][0] * w[2][1] - w[1][1] * w[2][0]);
}

// W^-1 = adj(W) / det W for det W = +-1.
std::array<Coefficients, 3> unimodular_inverse(const std::array<Coefficients, 3>& w, long det) {
    std::array<Coefficients, 3> inverse{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3, i1 = (i + 1) % 3, i2 = (i + 2) % 3;
            inverse[i][j] = (w[j1][i1] * w[j2][i2] - w[j1][i2] * w[j2][i1]) * det;
        }
    return inverse;
}

// The region's contact vectors +-c B* (B* the midpoint of its centre basis), each with its
// coefficients c (a step of its own: the candidates b1, b2, b3 are drawn from them).
void contact_vectors(const ClosingRegion<DInterval>& region, std::vector<Vector3>& vectors, std::vector<Coefficients>& coefficients) {
    DoubleBasis reference{};
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) reference[k][j] = mid_double(region.center[k][j]);
    for (const Coefficients& c : region.contacts)
        for (const int sign : {1, -1}) {
            Vector3 v{};
            for (int j = 0; j < 3; ++j) v[j] = sign * (c[0] * reference[0][j] + c[1] * reference[1][j] + c[2] * reference[2][j]);
            vectors.push_back(v);
            coefficients.push_back({sign * c[0], sign * c[1], sign * c[2]});
        }
}

// Whether b1 is the longest in the max norm among its orbit (every vector for A3, b1..b3 for
// W): the chart's normalisation, one test of a candidate.
bool longest_first(MinkowskiCase configuration, const Vector3& b1, const Vector3& b2, const Vector3& b3,
                   const std::array<Vector3, 3>& others) {
    double longest = std::max(max_norm(b2), max_norm(b3));
    if (configuration == MinkowskiCase::a3)
        for (const Vector3& v : others) longest = std::max(longest, max_norm(v));
    return !(longest > max_norm(b1) + tolerance);
}

// The configuration's six triples must be the region's contacts exactly: the region's lemma
// needs every one of its constraints, and a chart point satisfies only the configuration's six
// (a seven-pair optimum such as D14 gets no image). One test of a candidate W.
bool triples_are_contacts(const ClosingRegion<DInterval>& region, MinkowskiCase configuration, const std::array<Coefficients, 3>& w) {
    bool same = region.contacts.size() == 6;
    for (const Coefficients& d : configuration_triples(configuration)) {
        Coefficients image{};
        for (int k = 0; k < 3; ++k) image[k] = d[0] * w[0][k] + d[1] * w[1][k] + d[2] * w[2][k];
        const Coefficients r = representative(image);
        same = same && std::find(region.contacts.begin(), region.contacts.end(), r) != region.contacts.end();
    }
    return same;
}

// Whether `images` already holds this configuration's chart basis: one image per chart basis
// (the lattice's own symmetries give the others).
bool already_found(const std::vector<ChartImage>& images, MinkowskiCase configuration, const Vector3& b1, const Vector3& b2,
                   const Vector3& b3) {
    return std::any_of(images.begin(), images.end(), [&](const ChartImage& known) {
        return known.configuration == configuration && close(known.chart_basis[0], b1) && close(known.chart_basis[1], b2) &&
               close(known.chart_basis[2], b3);
    });
}

}  // namespace

std::vector<ChartImage> chart_images(const ClosingRegion<DInterval>& region, std::size_t index) {
    std::vector<ChartImage> images;
    if (region.verdict != Outcome::proved) return images;
    std::vector<Vector3> vectors;
    std::vector<Coefficients> coefficients;
    contact_vectors(region, vectors, coefficients);
    auto is_contact = [&](const Vector3& v) {
        return std::any_of(vectors.begin(), vectors.end(), [&](const Vector3& u) { return close(u, v); });
    };
    for (const SignedPermutation& s : signed_permutations())
        for (std::size_t i1 = 0; i1 < vectors.size(); ++i1) {
            const Vector3 b1 = permuted(vectors[i1], s);
            // b1 in the chart's cone x >= y >= z >= 0.
            if (b1[0] < b1[1] - tolerance || b1[1] < b1[2] - tolerance || b1[2] < -tolerance) continue;
            for (std::size_t i2 = 0; i2 < vectors.size(); ++i2)
                for (std::size_t i3 = 0; i3 < vectors.size(); ++i3) {
                    const Vector3 b2 = permuted(vectors[i2], s), b3 = permuted(vectors[i3], s);
                    const Vector3 &u1 = vectors[i1], &u2 = vectors[i2], &u3 = vectors[i3];
                    for (const MinkowskiCase configuration : {MinkowskiCase::a3, MinkowskiCase::w}) {
                        // The contacts are those of B*, before the permutation (which keeps max norms).
                        const int sigma = configuration == MinkowskiCase::a3 ? -1 : 1;
                        const std::array<Vector3, 3> others{
                            Vector3{u1[0] + sigma * u2[0], u1[1] + sigma * u2[1], u1[2] + sigma * u2[2]},
                            Vector3{u2[0] + sigma * u3[0], u2[1] + sigma * u3[1], u2[2] + sigma * u3[2]},
                            Vector3{u3[0] + sigma * u1[0], u3[1] + sigma * u1[1], u3[2] + sigma * u1[2]}};
                        if (!std::all_of(others.begin(), others.end(), is_contact)) continue;
                        if (!longest_first(configuration, b1, b2, b3, others)) continue;
                        const std::array<Coefficients, 3> w{coefficients[i1], coefficients[i2], coefficients[i3]};
                        const long det = integer_determinant(w);
                        if (det != 1 && det != -1) continue;
                        if (!triples_are_contacts(region, configuration, w)) continue;
                        if (already_found(images, configuration, b1, b2, b3)) continue;
                        const DoubleBasis chart{b1, b2, b3};
                        ChartImage image;
                        image.configuration = configuration;
                        image.inverse = unimodular_inverse(w, det);
                        image.perm = s.perm;
                        image.sign = s.sign;
                        image.chart_basis = chart;
                        image.region = index;
                        images.push_back(image);
                    }
                }
        }
    return images;
}

}  // namespace superpack
