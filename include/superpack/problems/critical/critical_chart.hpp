// The parameter domain of `superpack critical` (NOTES.md 12.2): Minkowski's two configurations
// of a critical lattice of 2K (K the superball, 1/2 < p), and a chart that covers every
// lattice having one of them by a compact box domain in R^6.
//
// A basis b1, b2, b3 with each b_i on bd(2K) is b_i = 2 v_i / ||v_i||_(2p) for a direction v_i on
// the surface of the cube [-1, 1]^3 (the radial map from the cube surface to bd(2K) is a
// homeomorphism). b1 is reduced by the 48 signed permutations of coordinates and by the
// relabellings of the basis that keep the configuration (12.2), to v1 = (1, s, s t) with
// s, t in [0, 1] (the spherical triangle x >= y >= z >= 0) and ||b1||_inf the largest max norm
// in its orbit of configuration vectors; v2 and v3 lie on any face (a face index and two
// coordinates in [-1, 1]). The remaining three conditions of the configuration are equations
// g_i = sum_j |w_ij / 2|^(2p) - 1 = 0 on the three other configuration vectors w_i.
//
// Every formula is one template over the scalar T (an interval, or a Jet for derivatives).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "superpack/arith/jet.hpp"
#include "superpack/geometry/lattice.hpp"
#include "superpack/geometry/lattice_basis.hpp"

namespace superpack {

// Case 1 ("A3", Minkowski's first case): b1, b2, b3, b1 - b2, b2 - b3, b3 - b1 on bd(2K).
// Case 2 ("W"): b1, b2, b3, b1 + b2, b2 + b3, b3 + b1 on bd(2K). (Case 3, W with b1 + b2 + b3,
// lies on case 2's manifold and is covered by it.)
enum class MinkowskiCase { a3, w };

const char* configuration_name(MinkowskiCase configuration);

// The six coefficient triples of the configuration, one per +- pair: b1, b2, b3 first, then
// the three the chart must solve for (in the order of chart_equations).
std::array<Coefficients, 6> configuration_triples(MinkowskiCase configuration);

// The chart coordinates x = (s, t, a2, c2, a3, c3) and the faces of v2 and v3: face f is
// the cube face {x_(f/2) = +1} for even f and {x_(f/2) = -1} for odd f; its free coordinates,
// in increasing index order, are (a, c).
constexpr int chart_dimension = 6;
constexpr int cube_faces = 6;

template <class T>
std::array<T, 3> face_point(int face, const T& a, const T& c) {
    const int axis = face / 2;
    std::array<T, 3> v{a, a, a};
    v[axis] = constant_like(a, face % 2 == 0 ? 1 : -1);
    v[axis == 0 ? 1 : 0] = a;
    v[axis == 2 ? 1 : 2] = c;
    return v;
}

// sum_j |v_j / 2|^(2p): the 2p-th power of ||v||_(2p) / 2. Its base is a coordinate, which may
// be 0, with the exponent 2p > 1: within the contract of pow_abs.
template <class T, class P>
T half_norm_power(const std::array<T, 3>& v, const P& two_p) {
    const P half = field_of(two_p).rational(Rational(1, 2));
    return pow_abs(v[0] * half, two_p) + pow_abs(v[1] * half, two_p) + pow_abs(v[2] * half, two_p);
}

// The point 2 v / ||v||_(2p) of bd(2K) in direction v. On the cube surface one coordinate of v
// is +-1, so sum |v_j|^(2p) lies in [1, 3]: the power 1/(2p) has a base away from 0.
template <class T, class P>
std::array<T, 3> boundary_point(const std::array<T, 3>& v, const P& two_p) {
    const auto field = field_of(two_p);
    const T sum = pow_abs(v[0], two_p) + pow_abs(v[1], two_p) + pow_abs(v[2], two_p);
    const T norm = pow_nonneg(sum, field.integer(1) / two_p);
    const P two = field.integer(2);
    return {two * v[0] / norm, two * v[1] / norm, two * v[2] / norm};
}

// The basis rows b1, b2, b3 at chart coordinates x (T an interval box or Jets).
template <class T, class P>
Basis<T> chart_basis(const std::array<T, chart_dimension>& x, int face2, int face3, const P& two_p) {
    const T one = constant_like(x[0], 1);
    const std::array<T, 3> v1{one, x[0], x[0] * x[1]};
    return {boundary_point(v1, two_p), boundary_point(face_point(face2, x[2], x[3]), two_p),
            boundary_point(face_point(face3, x[4], x[5]), two_p)};
}

// c1 b1 + c2 b2 + c3 b3, with no multiplication by a zero or unit coefficient (so a box
// keeps its width).
template <class T>
std::array<T, 3> combination(const Basis<T>& b, const Coefficients& c) {
    std::array<T, 3> v;
    for (int j = 0; j < 3; ++j) {
        T sum = constant_like(b[0][j], 0);
        for (int k = 0; k < 3; ++k) {
            if (c[k] == 1) sum = sum + b[k][j];
            else if (c[k] == -1) sum = sum - b[k][j];
            else if (c[k] != 0) sum = sum + constant_like(b[k][j], c[k]) * b[k][j];
        }
        v[j] = sum;
    }
    return v;
}

// The three equations of the configuration beyond b_i on bd(2K): g_i = ||w_i / 2||^(2p) - 1.
template <class T, class P>
std::array<T, 3> chart_equations(const Basis<T>& b, MinkowskiCase configuration, const P& two_p) {
    const std::array<Coefficients, 6> triples = configuration_triples(configuration);
    std::array<T, 3> g;
    for (int i = 0; i < 3; ++i) g[i] = half_norm_power(combination(b, triples[3 + i]), two_p) - constant_like(b[0][0], 1);
    return g;
}

}  // namespace superpack
