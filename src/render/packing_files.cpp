#include "superpack/render/packing_files.hpp"

#include <cmath>
#include <sstream>

namespace superpack {

std::string extended_xyz(const PeriodicPacking& packing, const std::string& comment) {
    std::ostringstream out;
    out.precision(17);
    out << packing.centers.size() << "\nLattice=\"";
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 3; ++c) out << (row || c ? " " : "") << packing.cell[row][c].get_d();
    const double roundness = 1 / packing.p.get_d();
    out << "\" Properties=species:S:1:pos:R:3:orientation:R:4:aspherical_shape:R:3:roundness:R:2 pbc=\"T T T\" p="
        << decimal_or_fraction_text(packing.p) << " comment=\"" << comment << "\"\n";
    for (std::size_t i = 0; i < packing.centers.size(); ++i) {
        const auto& q = packing.quaternions[i];
        const double length = std::sqrt(Rational(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).get_d());
        out << "Sb";
        for (const Rational& x : packing.centers[i]) out << " " << x.get_d();
        for (int c : {1, 2, 3, 0}) out << " " << q[c].get_d() / length;
        out << " 1 1 1 " << roundness << " " << roundness << "\n";
    }
    return out.str();
}

}  // namespace superpack
