// superpack md --p P --n N --growth G [--seed K] [--init random|fcc|FAMILY] [--cell fixed|deforming]
//              [--max-collisions C] [--pressure-limit L] [--json] [--xyz FILE] [--mesh FILE.obj]
//              [--png FILE.png] [--certificate FILE]
// Event-driven molecular dynamics of growing superballs (Donev, Torquato & Stillinger;
// sim/event_md.hpp) until jammed, and the proof of the packing it ends with
// (problems/periodic/end_state.hpp):
// floating point guesses, intervals prove.
#include <chrono>
#include <memory>
#include <sstream>

#include "common.hpp"
#include "final_packing.hpp"
#include "superpack/sim/event_md.hpp"

namespace superpack::cli {

namespace {

struct MdOptions {
    std::string p, init = "random", cell = "fixed";
    int particles = 100;
    double growth = 0.01;
    std::uint32_t seed = 1;
    long max_collisions = 20000000;
    double pressure_limit = 1e6;
    bool json = false;
    PackingFiles files;
};

// Limits, stated in --help: the proof takes up to max_periodic_particles, and a collision costs
// a few predictions against the particles nearby, so the collisions bound the run's time.
constexpr int min_particles = 2, max_particles = 256;
constexpr double min_growth = 1e-7, max_growth = 1;
constexpr long max_collisions_limit = 1000000000;
// Above about 10^9 the gaps near jamming reach the collisions' contact tolerance (1e-10 a R_c).
constexpr double min_pressure_limit = 10, max_pressure_limit = 1e9;
// A random start's density (insertion fails far above it), and the unsaturated lattice start:
// its bodies grow from this fraction of the largest scale at which they fit.
constexpr double random_start_phi = 0.1;
constexpr double lattice_start_fraction = 0.9;
// The deforming cell's strain trials per window of N collisions (sim/event_md.hpp).
constexpr int cell_moves_per_window = 10;

std::string shortest(double x) {
    std::ostringstream text;
    text << x;
    return text.str();
}

// FCC with the bodies' axes along the cube's: basis (1, 1, 0), (1, 0, 1), (0, 1, 1), the paper's
// unsaturated FCC start for the C0 and C1 crystals.
sim::PeriodicConfiguration fcc_start(int particles) {
    const sim::Matrix3 basis{sim::Vector3{1, 1, 0}, sim::Vector3{1, 0, 1}, sim::Vector3{0, 1, 1}};
    return sim::lattice_configuration(basis, particles, 1);
}

Json run_summary(const sim::EventMdResult& run, double seconds) {
    const char* why = run.jammed_pressure ? "jammed: the reduced pressure passed its limit"
                      : run.jammed_rate   ? "jammed: the collision rate passed its limit"
                      : run.collision_limit ? "the collision limit"
                      : run.time_limit      ? "the time limit"
                      : run.stalled         ? "stalled: N collisions in no time (contacts that do not resolve, as on the octahedron's faces)"
                                            : "a body could meet its own image (the cell is too small for it)";
    return Json{{"phi_estimate", run.phi},
                {"initial_scale", run.initial_scale},
                {"scale", run.scale},
                {"collisions", run.collisions},
                {"time", run.time},
                {"reduced_pressure", run.pressure},
                {"jammed", run.jammed_pressure || run.jammed_rate},
                {"stopped_by", why},
                {"initial_energy", run.initial_energy},
                {"final_energy", run.final_energy},
                {"rescalings", run.rescalings},
                {"cell_moves_kept", run.cell_moves_kept},
                {"capped_predictions", run.capped_predictions},
                {"seconds", seconds},
                {"note", "floating-point estimates of the dynamics; the certified phi is below"}};
}

// The options' checks, each with its usage error; returns p (a step of its own: run reads as
// check, start, run, prove, report).
Rational checked_p(const MdOptions& options) {
    const Rational p = parse_p(options.p);
    if (p < Rational(1, 2)) throw Failure(exit_usage, "md: p = " + options.p + " is below 1/2: the dynamics and its proof are for convex superballs");
    require_best_domain(p);
    if (options.particles < min_particles || options.particles > max_particles)
        throw Failure(exit_usage, "--n: " + std::to_string(min_particles) + " to " + std::to_string(max_particles) + " particles, got " +
                                      std::to_string(options.particles));
    if (!(options.growth >= min_growth && options.growth <= max_growth))
        throw Failure(exit_usage, "--growth: 1e-7 to 1, got " + shortest(options.growth));
    if (options.max_collisions < 1 || options.max_collisions > max_collisions_limit)
        throw Failure(exit_usage, "--max-collisions: 1 to 10^9, got " + std::to_string(options.max_collisions));
    if (!(options.pressure_limit >= min_pressure_limit && options.pressure_limit <= max_pressure_limit))
        throw Failure(exit_usage, "--pressure-limit: 10 to 10^9, got " + shortest(options.pressure_limit));
    if (options.cell != "fixed" && options.cell != "deforming")
        throw Failure(exit_usage, "--cell: fixed or deforming, got '" + options.cell + "'");
    return p;
}

// The dynamics' options from the command's (a step of its own, like checked_p).
sim::EventMdOptions md_run_options(const MdOptions& options) {
    sim::EventMdOptions run_options;
    run_options.seed = options.seed;
    run_options.growth_rate = options.growth;
    run_options.max_collisions = options.max_collisions;
    run_options.pressure_limit = options.pressure_limit;
    if (options.cell == "deforming") run_options.cell_moves = cell_moves_per_window;
    return run_options;
}

// The start --init asks for: random at random_start_phi, or a lattice (fcc or a family) whose
// bodies grow from lattice_start_fraction of their largest free scale, which is then set in
// run_options (a step of its own, like checked_p).
sim::PeriodicConfiguration md_start(const MdOptions& options, const std::optional<Family>& family, const Rational& p,
                                    const sim::SuperballShape& shape, const DoubleField& field,
                                    sim::EventMdOptions& run_options) {
    sim::PeriodicConfiguration start;
    if (options.init == "random") {
        sim::RandomSource random(options.seed ^ 0x9e3779b97f4a7c15ULL);
        start = sim::random_configuration(shape, options.particles, random_start_phi, random);
    } else {
        if (family) {
            const FamilyLattice<DInterval> lattice = decided_in_binary64([&] { return enclose_family(*family, p, field); });
            if (lattice.status != Outcome::proved || !lattice.basis)
                throw Failure(exit_undecided, "md: the family " + options.init + " is not certified at p = " + options.p);
            start = lattice_start(*lattice.basis, options.particles, 1);
        } else {
            start = fcc_start(options.particles);
        }
        run_options.initial_scale = lattice_start_fraction * sim::largest_free_scale(shape, start);
    }
    return start;
}

// The dynamics, with progress on stderr at most once a second; `seconds` gets its wall time (a
// step of its own: the timing and the progress are the command's, not the simulation's).
sim::EventMdResult run_dynamics(const sim::SuperballShape& shape, const sim::PeriodicConfiguration& start,
                                const sim::EventMdOptions& run_options, double& seconds) {
    const auto begin = std::chrono::steady_clock::now();
    auto last = begin;
    sim::EventMdResult run;
    try {
        run = sim::run_event_md(shape, start, run_options, [&](const sim::EventMdProgress& progress) {
            const auto now = std::chrono::steady_clock::now();
            if (now - last < std::chrono::seconds(1)) return;
            last = now;
            std::cerr << "md: " << progress.collisions << " collisions, t = " << progress.time << ", phi ~ " << progress.phi
                      << ", reduced pressure ~ " << progress.pressure << "\n";
        });
    } catch (const std::invalid_argument& error) {
        throw Failure(exit_usage, std::string("md: ") + error.what());
    }
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    return run;
}

int run(const MdOptions& options) {
    const Rational p = checked_p(options);
    std::optional<Family> family;
    if (options.init != "random" && options.init != "fcc") family = parse_family(options.init);
    require_packing_files(options.files);
    require_rounding_self_test();
    const DoubleField field;
    const sim::SuperballShape shape(p.get_d());

    const BestLattice<DInterval> best = reference_lattice(p, "md");
    sim::EventMdOptions run_options = md_run_options(options);
    const sim::PeriodicConfiguration start = md_start(options, family, p, shape, field, run_options);

    std::cerr << "md: " << options.particles << " particles from " << options.init << ", growth " << shortest(options.growth) << " (seed "
              << options.seed << ")\n";
    double seconds = 0;
    const sim::EventMdResult run = run_dynamics(shape, start, run_options, seconds);

    std::cerr << "md: proving the final packing\n";
    const PeriodicCertificate<DInterval> proof = decided_in_binary64(
        [&] { return prove_end_state(p, simulation_end_state(run.configuration), separation_guess(shape, run.configuration)); });
    const bool certified = proof.status == Outcome::proved;

    Json document = header_json("md", field, 15);
    document["p"] = options.p;
    document["p_exact"] = rational_text(p);
    document["particles"] = options.particles;
    document["growth"] = options.growth;
    document["seed"] = options.seed;
    document["init"] = options.init;
    document["cell"] = options.cell;
    document["dynamics"] = run_summary(run, seconds);
    add_proof_json(document, proof, best);
    write_packing_files(options.files, proof, "md");
    if (options.json) {
        print_json(document);
    } else {
        std::cout << "md p = " << options.p << ", " << options.particles << " particles from " << options.init << ", growth "
                  << shortest(options.growth) << ", seed " << options.seed << "\n"
                  << "  dynamics phi ~ " << run.phi << " (floating point; " << run.collisions << " collisions, reduced pressure ~ "
                  << run.pressure << ", " << seconds << " s; " << document["dynamics"]["stopped_by"].get<std::string>() << ")\n";
        print_proof(std::cout, proof, best);
    }
    if (!certified) throw Failure(exit_undecided, "md: undecided: " + proof.reason);
    return exit_ok;
}

}  // namespace

void add_md(CLI::App& app) {
    auto options = std::make_shared<MdOptions>();
    CLI::App* command = app.add_subcommand("md", "Event-driven molecular dynamics of growing superballs until jammed, and a proof of the final packing");
    command->add_option("--p", options->p, "deformation parameter 1/2 <= p <= 10^6: a decimal or a fraction")->required();
    command->add_option("--n", options->particles, "particles per cell, 2 to 256 (default 100)");
    command->add_option("--growth", options->growth,
                        "growth rate G = da/dt of the bodies' scale a (mass 1, kT = 1; dD/dt = 2G for spheres), 1e-7 to 1 (default 0.01)");
    add_seed_option(*command, options->seed, "random seed (default 1): the same seed gives the same run");
    command->add_option("--init", options->init,
                        "start: random (density 0.1; default), fcc (cube-aligned FCC), or a family C0, C1, O0, O1, D14, S6; a lattice "
                        "start grows from 0.9 of its largest free scale (unsaturated)");
    command->add_option("--cell", options->cell,
                        "fixed (default) or deforming: after every N collisions, 10 trials of a random strain of the cell at "
                        "fixed volume, kept when nothing overlaps (the cell takes the shape of a denser crystal)");
    command->add_option("--max-collisions", options->max_collisions, "stop after this many collisions, 1 to 10^9 (default 2 10^7)");
    command->add_option("--pressure-limit", options->pressure_limit,
                        "jammed when the reduced pressure P V / (N kT) of a window passes this, 10 to 10^9 (default 10^6)");
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    add_packing_file_options(*command, options->files);
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("md", add_md);
}  // namespace

}  // namespace superpack::cli
