// A triangle mesh of a periodic packing, for people to open (Wavefront OBJ: Blender, MeshLab,
// ParaView, OVITO) and for the 3-D picture (packing_picture.hpp). Floating point throughout:
// this is a picture of the certified configuration, not a part of its proof.
//
// The surface of K = {x : |x1|^2p + |x2|^2p + |x3|^2p <= 1} is a cube-sphere grid: each of the
// 6 faces of the cube [-1, 1]^3 cut into m x m squares, 2 triangles each, every grid point u
// mapped radially onto the boundary, x = u / ||u||_2p. Points on the cube's edges are shared by
// the faces that meet there, so the surface is closed: 6 m^2 + 2 vertices, 12 m^2 triangles,
// each oriented counterclockwise seen from outside (its normal points out of the body).
#pragma once
#include <array>
#include <string>
#include <vector>

#include "superpack/problems/periodic/periodic_packing.hpp"
#include "superpack/solve/dense3.hpp"

namespace superpack {

using Point3 = dense::Vector3;

// The OBJ's grid: m = 24 (3458 vertices, 6912 triangles a particle).
constexpr int default_mesh_resolution = 24;

struct SurfaceMesh {
    int m = 0;
    std::vector<Point3> vertices;
    // faces[2 a + s][(m + 1) i + j]: the vertex at grid point (i, j) of the cube face x_a = -1
    // (s = 0) or +1 (s = 1), i along the axis a + 1 and j along a + 2 (mod 3), 0 to m.
    std::array<std::vector<int>, 6> faces;
    // Indices into vertices, from 0: each grid square (i, j) - (i + 1, j + 1) as the triangles
    // (i, j), (i + 1, j), (i + 1, j + 1) and (i, j), (i + 1, j + 1), (i, j + 1), reversed on the
    // faces s = 0, so that every one is counterclockwise seen from outside.
    std::vector<std::array<int, 3>> triangles() const;
};

// The boundary of K on the m x m cube-sphere grid (m >= 1), for 1/2 <= p <= 10^6: the 2p-norm
// is taken of u / max|u_i|, so no power overflows or underflows to a wrong norm.
SurfaceMesh superball_surface(double p, int m);

// The outward unit normal of K at its boundary point x (the gradient of the gauge, scaled like
// the norm); at p = 1/2 on an edge of the octahedron, the mean of the faces' normals.
Point3 superball_normal(double p, const Point3& x);

// Particle i of the packing as a map of body points to space: centers[i] + R(q_i) x.
struct PlacedParticle {
    Point3 center;
    dense::Matrix3 rotation;  // R(q_i), body to space
    Point3 operator()(const Point3& body) const;  // centre + R body
    Point3 turned(const Point3& body) const;      // R body
};
PlacedParticle placed_particle(const PeriodicPacking& packing, std::size_t i);

// The OBJ: comment lines (`comment`, p, the cell's rows, the grid), then per particle i of the
// cell an object "particle_<i>" with its 6 m^2 + 2 vertices and its 12 m^2 faces.
std::string packing_obj(const PeriodicPacking& packing, const std::string& comment, int m = default_mesh_resolution);

}  // namespace superpack
