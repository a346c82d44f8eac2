#include "checker/claims/critical_region.hpp"

#include <algorithm>

#include "checker/core/limits.hpp"
#include "checker/formulas/kkt_point.hpp"
#include "checker/formulas/positive_definite.hpp"

namespace superpack_checker {

namespace {

// Step 3: the Hessian of the augmented Lagrangian over the whole region R.
void check_convexity(Context& context, const std::vector<Triple>& contacts, const KktPoint& point, const Box& region,
                     const mpq_class& rho, const Real& p, const std::string& path) {
    context.current_step = path + ".rho";
    const mpfr_prec_t precision = p.precision();
    const Real weight = rational(rho, precision), two = integer(2, precision), two_p = two * p;
    // x = (R, mu* - rho (n(R) - 2)): the multipliers of grad L(B) = grad det - sum (mu*_i - rho
    // (n_i - 2)) grad n_i, whose Jacobian in B is the KKT block plus rho sum grad n_i grad n_i^T.
    Box x = region;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
        const Triple& c = contacts[i];
        std::array<Real, 3> v{Real(precision), Real(precision), Real(precision)};
        for (int j = 0; j < 3; ++j) v[j] = c[0] * region[j] + c[1] * region[3 + j] + c[2] * region[6 + j];
        x.push_back(point.multipliers[i] - weight * (lattice_norm(v, two_p) - two));
    }
    const KktEquations equations{contacts, p};
    std::vector<std::vector<Real>> jacobian;
    try {
        jacobian = equations.jacobian(x);
    } catch (const UnboundedPower& error) {
        context.reject(path + ".box", std::string("the Hessian of the norm has no bound on the region: ") + error.what());
    }
    std::vector<std::vector<Real>> m(9, std::vector<Real>(9, Real(precision)));
    for (std::size_t a = 0; a < 9; ++a)
        for (std::size_t b = 0; b <= a; ++b) {
            Real constraints(precision);
            for (std::size_t i = 9; i < jacobian.size(); ++i) constraints = constraints + jacobian[i][a] * jacobian[i][b];
            m[a][b] = jacobian[a][b] + weight * constraints;
        }
    // Cholesky, as the producer's certainly_positive_definite: LDL^T's updates l l d take the
    // region's widths three times and leave the last pivot of C1's region (radius 3.9e-5, rho =
    // 10 at p = 2) unproved, where Cholesky's l^2 proves it.
    const std::size_t pivot = first_unproved_cholesky_pivot(m);
    context.require(pivot == 9, path + ".rho",
                    "the Hessian of the augmented Lagrangian with rho = " + rho.get_str() +
                        " is not certainly positive definite on the region (pivot " + std::to_string(pivot) +
                        " of its Cholesky factorization may be <= 0): det >= det B* on the region is not proved");
}

Triple read_coefficients(Context& context, const Json& node, const std::string& path, long bound) {
    if (!node.is_array() || node.size() != 3) context.malformed(path, "expected three integers");
    Triple t{};
    for (int k = 0; k < 3; ++k) t[k] = read_integer(context, node[k], path + "[" + std::to_string(k) + "]", -bound, bound);
    return t;
}

long integer_determinant(const std::array<Triple, 3>& w) {
    return w[0][0] * (w[1][1] * w[2][2] - w[1][2] * w[2][1]) - w[0][1] * (w[1][0] * w[2][2] - w[1][2] * w[2][0]) +
           w[0][2] * (w[1][0] * w[2][1] - w[1][1] * w[2][0]);
}

// Step 4 for one image.
ChartImage read_image(Context& context, const Json& node, const std::string& path, const std::vector<Triple>& contacts,
                      std::size_t region) {
    ChartImage image;
    image.region = region;
    image.configuration = read_configuration(context, node, path);
    const Json& inverse = context.member(node, "inverse", path);
    if (!inverse.is_array() || inverse.size() != 3) context.malformed(path + ".inverse", "expected three rows");
    for (int r = 0; r < 3; ++r)
        image.inverse[r] =
            read_coefficients(context, inverse[r], path + ".inverse[" + std::to_string(r) + "]", max_image_coefficient);
    const Triple perm = read_coefficients(context, context.member(node, "perm", path), path + ".perm", 2);
    const Triple sign = read_coefficients(context, context.member(node, "sign", path), path + ".sign", 1);
    for (int j = 0; j < 3; ++j) {
        image.perm[j] = static_cast<int>(perm[j]);
        image.sign[j] = static_cast<int>(sign[j]);
        context.require(image.sign[j] != 0, path + ".sign", "a sign is 0, not +-1");
    }
    Triple sorted = perm;
    std::sort(sorted.begin(), sorted.end());
    context.require(sorted == Triple{0, 1, 2}, path + ".perm", "not a permutation of 0, 1, 2");
    const long det = integer_determinant(image.inverse);
    context.require(det == 1 || det == -1, path + ".inverse",
                    "W^-1 has determinant " + std::to_string(det) + ", not +-1: W is not an integral basis change");
    // W = adj(W^-1) det(W^-1), exact in integers.
    std::array<Triple, 3> w{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const auto& m = image.inverse;
            w[i][j] = (m[j1][i1] * m[j2][i2] - m[j1][i2] * m[j2][i1]) * det;
        }
    context.require(contacts.size() == 6, path,
                    "the region has " + std::to_string(contacts.size()) +
                        " contact pairs: a configuration's six vectors cannot give every one of its constraints");
    std::vector<bool> hit(contacts.size(), false);
    for (const Triple& t : configuration_triples(image.configuration)) {
        Triple mapped{};
        for (int k = 0; k < 3; ++k) mapped[k] = t[0] * w[0][k] + t[1] * w[1][k] + t[2] * w[2][k];
        const auto found = std::find(contacts.begin(), contacts.end(), representative(mapped));
        context.require(found != contacts.end(), path + ".inverse",
                        "the configuration's vector " + triple_text(t) + " maps to " + triple_text(mapped) +
                            ", which is no contact of the region");
        const std::size_t index = static_cast<std::size_t>(found - contacts.begin());
        context.require(!hit[index], path + ".inverse",
                        "two of the configuration's vectors map to the contact " + triple_text(contacts[index]));
        hit[index] = true;
    }
    return image;
}

}  // namespace

ClosingRegions replay_closing_regions(Context& context, const Json& list, const std::string& path, const mpq_class& p,
                                      const Real& threshold) {
    if (!list.is_array()) context.malformed(path, "expected an array of closing regions");
    if (list.size() > max_closing_regions)
        context.malformed(path, std::to_string(list.size()) + " closing regions exceed the limit of " +
                                    std::to_string(max_closing_regions) + " (max_closing_regions)");
    const mpfr_prec_t precision = context.precision();
    const Real p_interval = rational(p, precision);
    ClosingRegions result;
    for (std::size_t r = 0; r < list.size(); ++r) {
        const std::string at = path + "[" + std::to_string(r) + "]";
        const Json& node = list[r];
        if (!node.is_object()) context.malformed(at, "expected a closing region");
        ClosingRegion region;
        // A region of the chart's configurations has six pairs; one with more (a seven-pair
        // optimum) is replayed as well and gets no image, since its lemma needs every one of
        // its constraints and a configuration has six (step 4).
        region.contacts = read_contact_pairs(context, node, "contact_pairs", at);
        // 1. The KKT point.
        const KktPoint point = replay_kkt_point(context, region.contacts, context.member(node, "kkt", at), at + ".kkt", p_interval);
        context.current_step = at;
        const mpq_class rho = context.rational_at(node, "rho", at);
        context.require(rho >= 0, at + ".rho", "rho is negative");
        region.box = context.box(context.member(node, "box", at), at + ".box");
        if (region.box.size() != 9) context.malformed(at + ".box", "expected the nine entries of a basis");
        // 2. B* in R, and det B* >= T.
        for (std::size_t k = 0; k < 9; ++k)
            context.require(subset(point.root[k], region.box[k]), at + ".box[" + std::to_string(k) + "]",
                            "the critical lattice's entry " + text(point.root[k]) + " is not inside the region");
        const Real det = determinant(point.basis);
        context.require(positive(det), at + ".kkt", "det B* is not certainly positive: " + text(det));
        context.require(mpfr_lessequal_p(threshold.hi(), det.lo()) != 0, at,
                        "T = " + text(threshold) + " is above the lower end of det B* in " + text(det) +
                            ": the region does not prove |det| >= T");
        // 3. Convexity.
        check_convexity(context, region.contacts, point, region.box, rho, p_interval, at);
        // 4. The images.
        const Json& images = context.member(node, "images", at);
        if (!images.is_array()) context.malformed(at + ".images", "expected an array of images");
        for (std::size_t g = 0; g < images.size(); ++g) {
            if (result.images.size() >= max_chart_images)
                context.malformed(at + ".images", "more than " + std::to_string(max_chart_images) +
                                                      " images in all exceed the limit (max_chart_images)");
            const std::string image_path = at + ".images[" + std::to_string(g) + "]";
            if (!images[g].is_object()) context.malformed(image_path, "expected an image");
            result.images.push_back(read_image(context, images[g], image_path, region.contacts, r));
        }
        result.regions.push_back(region);
    }
    return result;
}

bool maps_into_region(const ChartImage& image, const ClosingRegion& region, const Matrix3& basis) {
    for (int r = 0; r < 3; ++r) {
        const std::array<Real, 3> row = combination(basis, image.inverse[r]);
        for (int j = 0; j < 3; ++j) {
            const Real entry = image.sign[j] > 0 ? row[j] : -row[j];
            if (!subset(entry, region.box[3 * r + image.perm[j]])) return false;
        }
    }
    return true;
}

}  // namespace superpack_checker
