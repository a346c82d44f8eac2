#include "final_packing.hpp"

#include "output_paths.hpp"
#include "superpack/cert/atomic_file.hpp"
#include "superpack/cert/periodic_certificate.hpp"
#include "superpack/render/packing_files.hpp"
#include "superpack/render/packing_mesh.hpp"
#include "superpack/render/packing_picture.hpp"
#include "superpack/render/plot.hpp"
#include "superpack/sim/overlap.hpp"

namespace superpack::cli {

namespace {

std::string bracketed(const DInterval& x) {
    const DecimalEnclosure d = to_decimal(x, 17);
    return "[" + d.lo + ", " + d.hi + "]";
}

}  // namespace

void add_packing_file_options(CLI::App& command, PackingFiles& files) {
    add_output_option(command, "--xyz", files.xyz, "write the certified packing as extended XYZ (OVITO reads its superquadric shapes)");
    add_output_option(command, "--mesh", files.mesh,
                      "write the certified packing as a triangle mesh (Wavefront OBJ): each particle of the cell a closed "
                      "surface of " + std::to_string(12 * default_mesh_resolution * default_mesh_resolution) +
                          " triangles (a cube-sphere grid of 6 x " + std::to_string(default_mesh_resolution) + " x " +
                          std::to_string(default_mesh_resolution) + " squares)");
    add_output_option(command, "--png", files.png,
                      "draw the certified packing into a PNG (gnuplot): a 2 x 2 x 2 block of cells, each particle shaded "
                      "in the colour of its index in the cell, the cell's edges drawn");
    add_output_option(command, "--certificate", files.certificate, "write a periodic-packing certificate (replay it with `superpack verify FILE`)");
}

void require_packing_files(const PackingFiles& files) {
    require_output_paths({{"--xyz", files.xyz}, {"--mesh", files.mesh}, {"--png", files.png}, {"--certificate", files.certificate}});
    if (!files.png.empty()) require_plottable(files.png);
}

BestLattice<DInterval> reference_lattice(const Rational& p, const std::string& command) {
    std::cerr << command << ": certifying the best lattice at p = " << decimal_or_fraction_text(p) << " for comparison\n";
    BestLattice<DInterval> best = decided_in_binary64([&] { return find_best_lattice(p, DoubleField{}, BestOptions{}); });
    if (best.status != Outcome::proved)
        throw Failure(exit_undecided, command + ": no certified lattice at p = " + decimal_or_fraction_text(p) + " to compare with");
    return best;
}

sim::PeriodicConfiguration lattice_start(const Basis<DInterval>& basis, int particles, double expansion) {
    sim::Matrix3 rows;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rows[i][j] = mid_double(basis[i][j]);
    return sim::lattice_configuration(rows, particles, expansion);
}

SimulationEndState simulation_end_state(const sim::PeriodicConfiguration& end) {
    SimulationEndState state;
    state.cell = end.cell;
    state.fractional = end.fractional;
    for (const sim::Quaternion& q : end.orientations) state.quaternions.push_back({q.w, q.x, q.y, q.z});
    return state;
}

NormalGuess separation_guess(const sim::SuperballShape& shape, const sim::PeriodicConfiguration& end) {
    return [&shape, &end](std::size_t first, std::size_t second, const std::array<double, 3>& difference) {
        const sim::Placement a{{0, 0, 0}, sim::rotation_matrix(end.orientations[first])};
        const sim::Placement b{difference, sim::rotation_matrix(end.orientations[second])};
        // Also for a pair GJK calls touching: its best plane is near the contact normal.
        return sim::separation(shape, a, b).normal;
    };
}

void add_proof_json(Json& document, const PeriodicCertificate<DInterval>& proof, const BestLattice<DInterval>& best) {
    const bool certified = proof.status == Outcome::proved;
    document["certified"] = certified;
    document["reason"] = proof.reason;
    document["best_lattice"] = Json{{"name", best_name(best)}, {"phi", enclosure_json(best_phi(best))}};
    if (!certified) return;
    document["phi"] = enclosure_json(*proof.phi);
    document["ratio_to_best_lattice"] = enclosure_json(*proof.phi / best_phi(best));
    document["scale"] = rational_text(proof.scale);
    document["pairs_separated"] = proof.pairs.size();
    document["configuration"] = periodic_packing_json(proof.packing);
}

void print_proof(std::ostream& out, const PeriodicCertificate<DInterval>& proof, const BestLattice<DInterval>& best) {
    if (proof.status != Outcome::proved) {
        out << "  not certified: " << proof.reason << "\n";
        return;
    }
    out << "  certified phi  " << bracketed(*proof.phi) << "  (" << proof.reason << "; " << proof.pairs.size() << " pairs)\n"
        << "  best lattice   " << bracketed(best_phi(best)) << "  (" << best_name(best) << ")\n"
        << "  ratio          " << bracketed(*proof.phi / best_phi(best)) << "\n";
}

void write_packing_files(const PackingFiles& files, const PeriodicCertificate<DInterval>& proof, const std::string& command) {
    if (proof.status != Outcome::proved) return;
    if (!files.certificate.empty())
        write_certificate_or_fail(files.certificate, DoubleField{}, 15, 0, [&] { return periodic_certificate(proof, DoubleField{}, 15, command); });
    const DecimalEnclosure phi = to_decimal(*proof.phi, 12);
    const std::string comment = "superpack " + command + ": certified phi in " + phi.lo + " .. " + phi.hi;
    if (!files.xyz.empty()) write_atomically(files.xyz, extended_xyz(proof.packing, comment));
    if (!files.mesh.empty()) write_atomically(files.mesh, packing_obj(proof.packing, comment));
    if (!files.png.empty()) packing_png(files.png, proof.packing, *proof.phi);
}

}  // namespace superpack::cli
