#include "superpack/render/packing_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <locale>
#include <map>
#include <sstream>
#include <stdexcept>

namespace superpack {

using dense::operator+;
using dense::operator*;

namespace {

using GridPoint = std::array<int, 3>;

// ||u||_2p, scaled by the largest |u_i| first (it is 1 in the scaled sum, the others at most 1).
double norm_2p(const Point3& u, double p) {
    const double largest = dense::max_abs(u);
    double sum = 0;
    for (double x : u) sum += std::pow(std::fabs(x) / largest, 2 * p);
    return largest * std::pow(sum, 1 / (2 * p));
}

}  // namespace

SurfaceMesh superball_surface(double p, int m) {
    if (m < 1) throw std::invalid_argument("superball_surface: the grid needs m >= 1");
    SurfaceMesh mesh;
    mesh.m = m;
    // Grid points are the integer points of the cube [0, m]^3's surface, each numbered once.
    std::map<GridPoint, int> index;
    for (int axis = 0; axis < 3; ++axis)
        for (int side : {0, 1})
            for (int i = 0; i <= m; ++i)
                for (int j = 0; j <= m; ++j) {
                    GridPoint g;
                    g[axis] = side * m;
                    g[(axis + 1) % 3] = i;
                    g[(axis + 2) % 3] = j;
                    const auto [at, fresh] = index.emplace(g, static_cast<int>(mesh.vertices.size()));
                    if (fresh) {
                        Point3 u;
                        for (int c = 0; c < 3; ++c) u[c] = 2.0 * g[c] / m - 1;
                        mesh.vertices.push_back((1 / norm_2p(u, p)) * u);
                    }
                    mesh.faces[2 * axis + side].push_back(at->second);
                }
    return mesh;
}

std::vector<std::array<int, 3>> SurfaceMesh::triangles() const {
    std::vector<std::array<int, 3>> result;
    result.reserve(12 * static_cast<std::size_t>(m) * m);
    for (int face = 0; face < 6; ++face) {
        auto at = [&](int i, int j) { return faces[face][(m + 1) * i + j]; };
        // (e_{a+1}, e_{a+2}, e_a) is right-handed: counterclockwise in (i, j) faces +e_a.
        const bool outward = face % 2 == 1;
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                std::array<int, 4> corner{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
                if (!outward) std::swap(corner[1], corner[3]);
                result.push_back({corner[0], corner[1], corner[2]});
                result.push_back({corner[0], corner[2], corner[3]});
            }
    }
    return result;
}

Point3 superball_normal(double p, const Point3& x) {
    const double largest = dense::max_abs(x);
    Point3 gradient;
    for (int c = 0; c < 3; ++c) gradient[c] = std::copysign(std::pow(std::fabs(x[c]) / largest, 2 * p - 1), x[c]);
    if (p == 0.5)  // the gradient's sign vector: 0 where x_c = 0, on an edge
        for (int c = 0; c < 3; ++c) gradient[c] = x[c] == 0 ? 0 : gradient[c];
    return (1 / dense::norm(gradient)) * gradient;
}

Point3 PlacedParticle::turned(const Point3& body) const { return dense::apply(rotation, body); }

Point3 PlacedParticle::operator()(const Point3& body) const { return center + dense::apply(rotation, body); }

PlacedParticle placed_particle(const PeriodicPacking& packing, std::size_t i) {
    PlacedParticle placed;
    const Basis<Rational> rotation = rotation_of(packing.quaternions.at(i));
    for (int r = 0; r < 3; ++r) {
        placed.center[r] = packing.centers.at(i)[r].get_d();
        for (int c = 0; c < 3; ++c) placed.rotation[r][c] = rotation[r][c].get_d();
    }
    return placed;
}

std::string packing_obj(const PeriodicPacking& packing, const std::string& comment, int m) {
    const SurfaceMesh surface = superball_surface(packing.p.get_d(), m);
    const std::vector<std::array<int, 3>> triangles = surface.triangles();
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out.precision(12);
    out << "# " << comment << "\n# superballs |x|^2p + |y|^2p + |z|^2p <= 1, p = " << decimal_or_fraction_text(packing.p) << ", "
        << packing.centers.size() << " particles per periodic cell\n# cell rows (period vectors):";
    for (const auto& row : packing.cell) out << "  " << row[0].get_d() << " " << row[1].get_d() << " " << row[2].get_d();
    out << "\n# each particle: a cube-sphere grid of 6 x " << m << " x " << m << " squares, " << surface.vertices.size()
        << " vertices and " << triangles.size() << " triangles, faces counterclockwise seen from outside\n";
    for (std::size_t i = 0; i < packing.centers.size(); ++i) {
        const PlacedParticle placed = placed_particle(packing, i);
        out << "o particle_" << i << "\n";
        for (const Point3& x : surface.vertices) {
            const Point3 y = placed(x);
            out << "v " << y[0] << " " << y[1] << " " << y[2] << "\n";
        }
        const std::size_t first = 1 + i * surface.vertices.size();  // OBJ counts from 1
        for (const auto& t : triangles) out << "f " << first + t[0] << " " << first + t[1] << " " << first + t[2] << "\n";
    }
    return out.str();
}

}  // namespace superpack
