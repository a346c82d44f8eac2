// Near-neighbour lists for md's fast event loop (sim/event_md.hpp), after Donev, Torquato &
// Stillinger's bounding neighbourhoods (J. Comput. Phys. 202, 737 (2005)): each particle owns a
// region, a sphere that contains its bounding sphere with a skin to spare, and its neighbours
// are the particles (with the lattice image) whose regions meet its own. While two bodies stay
// inside their regions they can touch only if the regions meet, so a prediction need look at
// the neighbours alone; a particle about to leave its region gets a new one (`move`), which
// changes its own list and its entries in the others' lists, and nothing else.
//
// The regions are found through cells: the region centres (wrapped into the cell) are binned
// by their fractional coordinates into m_1 x m_2 x m_3 cells at least as thick as two region
// radii, so that meeting regions lie in the same or adjacent cells (mod m); every lattice image
// of a candidate within reach is then listed. Floating point only.
#pragma once
#include <array>
#include <vector>

#include "superpack/sim/vector3.hpp"

namespace superpack::sim {

struct Neighbour {
    int partner = 0;
    // Added to the partner's position: the image whose region meets this particle's.
    Vector3 offset{0, 0, 0};
    // The last separating direction found for the pair (from this particle towards the image;
    // zero: none yet): where GJK starts its next search (sim/overlap.hpp's SeparationHint).
    Vector3 normal{0, 0, 0};
};

class NeighbourRegions {
public:
    // Regions centred at `centres` (Cartesian, wrapped into the cell with rows `cell`), all of
    // radius `radius`.
    void build(const Matrix3& cell, const std::vector<Vector3>& centres, double radius);
    // Particle i's region becomes the sphere of `radius` about `centre` (wrapped into the cell
    // by the caller): its list is found anew and its entries in the others' lists follow.
    void move(int i, const Vector3& centre, double radius);

    const Vector3& centre(int i) const { return centres_[i]; }
    double radius(int i) const { return radii_[i]; }
    std::vector<Neighbour>& neighbours(int i) { return lists_[i]; }
    const std::vector<Neighbour>& neighbours(int i) const { return lists_[i]; }

private:
    // The cells for regions of radius up to design_radius_.
    void bin_all();
    int cell_of(const Vector3& centre) const;
    // Every image of every candidate partner whose region meets i's, i excluded.
    std::vector<Neighbour> find(int i) const;

    Matrix3 cell_{}, inverse_{};
    Vector3 column_norm_{};  // |column m of B^-1|: fractional coordinate m changes at most this much per unit length
    std::vector<Vector3> centres_;
    std::vector<double> radii_;
    std::vector<std::vector<Neighbour>> lists_;
    double design_radius_ = 0;
    std::array<int, 3> counts_{1, 1, 1};
    std::vector<std::vector<int>> members_;  // per cell, the particles whose centre lies in it
    std::vector<int> home_;                  // per particle, its cell
};

}  // namespace superpack::sim
