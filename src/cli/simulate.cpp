// superpack simulate --p P --n N [--steps S] [--seed K] [--init lattice|random|FAMILY] [--json]
//                    [--xyz FILE] [--mesh FILE.obj] [--png FILE.png] [--certificate FILE]
// The paper's stochastic optimizer (sim/shrinking_cell.hpp) for N superballs per cell, and the
// proof of the packing it ends with (problems/periodic/end_state.hpp): floating point guesses,
// intervals prove.
#include <chrono>
#include <memory>
#include <sstream>

#include "common.hpp"
#include "final_packing.hpp"
#include "superpack/sim/shrinking_cell.hpp"

namespace superpack::cli {

namespace {

struct SimulateOptions {
    std::string p, init = "lattice";
    PackingFiles files;
    int particles = 2;
    long steps = 20000;
    std::uint32_t seed = 1;
    std::optional<double> pressure;
    bool json = false;
};

// Limits, stated in --help: a cycle costs about N^2 overlap tests, so N and the cycles are
// bounded to keep a run within hours; the certification handles up to max_periodic_particles.
constexpr int max_particles = 16;
constexpr long max_steps = 10000000;
// The unsaturated lattice start: every length of the best lattice times this.
constexpr double lattice_expansion = 1.02;
// A random start's density.
constexpr double random_start_phi = 0.2;
// The optimizer's start pressure (sim/shrinking_cell.hpp) by start: low enough for a random
// start to order itself, high enough for a lattice start not to melt. Measured: from the best
// lattice at p = 2, N = 2, 1000 ends 0.03% below C1 and 10 ends 2% below.
constexpr double random_start_pressure = 10, lattice_start_pressure = 1000;
constexpr double min_pressure = 1e-3, max_pressure = 1e6;
Json configuration_summary(const sim::ShrinkingCellResult& run, double seconds) {
    return Json{{"start_phi_estimate", run.start_phi},
                {"phi_estimate", run.phi},
                {"cycles", run.cycles},
                {"particle_acceptance", run.particle_acceptance},
                {"cell_acceptance", run.cell_acceptance},
                {"seconds", seconds},
                {"note", "floating-point estimates of the optimizer; the certified phi is below"}};
}

// The options' checks, each with its usage error; returns p (a step of its own: run reads as
// check, start, run, prove, report).
Rational checked_p(const SimulateOptions& options) {
    const Rational p = parse_p(options.p);
    if (p < Rational(1, 2)) throw Failure(exit_usage, "simulate: p = " + options.p + " is below 1/2: the optimizer and its proof are for convex superballs");
    require_best_domain(p);
    if (options.particles < 1 || options.particles > max_particles)
        throw Failure(exit_usage, "--n: 1 to " + std::to_string(max_particles) + " particles, got " + std::to_string(options.particles));
    if (options.steps < 1 || options.steps > max_steps)
        throw Failure(exit_usage, "--steps: 1 to " + std::to_string(max_steps) + " cycles, got " + std::to_string(options.steps));
    if (options.pressure && !(*options.pressure >= min_pressure && *options.pressure <= max_pressure)) {
        std::ostringstream given;  // shortest form ("0", "2e+07"), not to_string's six decimals
        given << *options.pressure;
        throw Failure(exit_usage, "--pressure: 0.001 to 10^6, got " + given.str());
    }
    return p;
}

// The start --init asks for: a family's lattice, the best lattice, or random (a step of its
// own, like checked_p).
sim::PeriodicConfiguration simulate_start(const SimulateOptions& options, const std::optional<Family>& family, const Rational& p,
                                          const sim::SuperballShape& shape, const DoubleField& field,
                                          const BestLattice<DInterval>& best) {
    sim::PeriodicConfiguration start;
    if (family) {
        const FamilyLattice<DInterval> lattice = decided_in_binary64([&] { return enclose_family(*family, p, field); });
        if (lattice.status != Outcome::proved || !lattice.basis)
            throw Failure(exit_undecided, "simulate: the family " + options.init + " is not certified at p = " + options.p);
        start = lattice_start(*lattice.basis, options.particles, lattice_expansion);
    } else if (options.init == "lattice") {
        start = lattice_start(best_basis(best), options.particles, lattice_expansion);
    } else {
        sim::RandomSource random(options.seed ^ 0x9e3779b97f4a7c15ULL);
        start = sim::random_configuration(shape, options.particles, random_start_phi, random);
    }
    return start;
}

// The optimizer, with a progress bar on stderr at most once a second; `seconds` gets its wall
// time (a step of its own: the timing and the progress are the command's, not the optimizer's).
sim::ShrinkingCellResult run_optimizer(const SimulateOptions& options, const sim::SuperballShape& shape,
                                       const sim::PeriodicConfiguration& start, const sim::ShrinkingCellOptions& run_options,
                                       double& seconds) {
    const auto begin = std::chrono::steady_clock::now();
    auto last = begin;
    const sim::ShrinkingCellResult run = sim::shrink_cell(shape, start, run_options, [&](const sim::ShrinkingCellProgress& progress) {
        const auto now = std::chrono::steady_clock::now();
        if (now - last < std::chrono::seconds(1)) return;
        last = now;
        const long percent = 100 * progress.cycle / options.steps;
        std::cerr << "simulate: [" << std::string(static_cast<std::size_t>(percent / 5), '#') << std::string(static_cast<std::size_t>(20 - percent / 5), '.')
                  << "] " << percent << "%, cycle " << progress.cycle << " / " << options.steps << ", phi ~ " << progress.phi << "\n";
    });
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    return run;
}

int run(const SimulateOptions& options) {
    const Rational p = checked_p(options);
    std::optional<Family> family;
    if (options.init != "lattice" && options.init != "random") family = parse_family(options.init);
    require_packing_files(options.files);
    require_rounding_self_test();
    const DoubleField field;
    const sim::SuperballShape shape(p.get_d());

    // The reference: the best lattice superpack certifies at p, which also gives the lattice start.
    const BestLattice<DInterval> best = reference_lattice(p, "simulate");
    const sim::PeriodicConfiguration start = simulate_start(options, family, p, shape, field, best);

    std::cerr << "simulate: " << options.particles << " particles, " << options.steps << " cycles from " << options.init << " (seed "
              << options.seed << ")\n";
    sim::ShrinkingCellOptions run_options;
    run_options.cycles = options.steps;
    run_options.seed = options.seed;
    run_options.start_pressure = options.pressure ? *options.pressure : options.init == "random" ? random_start_pressure : lattice_start_pressure;
    double seconds = 0;
    const sim::ShrinkingCellResult run = run_optimizer(options, shape, start, run_options, seconds);

    // The proof: exact rounding, a separating plane per close pair (sim's guess), scaled if needed.
    std::cerr << "simulate: proving the final packing\n";
    const PeriodicCertificate<DInterval> proof = decided_in_binary64(
        [&] { return prove_end_state(p, simulation_end_state(run.configuration), separation_guess(shape, run.configuration)); });
    const bool certified = proof.status == Outcome::proved;

    Json document = header_json("simulate", field, 15);
    document["p"] = options.p;
    document["p_exact"] = rational_text(p);
    document["particles"] = options.particles;
    document["seed"] = options.seed;
    document["init"] = options.init;
    document["simulation"] = configuration_summary(run, seconds);
    document["simulation"]["start_pressure"] = run_options.start_pressure;
    add_proof_json(document, proof, best);
    write_packing_files(options.files, proof, "simulate");
    if (options.json) {
        print_json(document);
    } else {
        std::cout << "simulate p = " << options.p << ", " << options.particles << " particles per cell, " << options.steps
                  << " cycles from " << options.init << ", seed " << options.seed << "\n"
                  << "  optimizer phi ~ " << run.phi << " (floating point, " << seconds << " s; start ~ " << run.start_phi << ")\n";
        print_proof(std::cout, proof, best);
    }
    if (!certified) throw Failure(exit_undecided, "simulate: undecided: " + proof.reason);
    return exit_ok;
}

}  // namespace

void add_simulate(CLI::App& app) {
    auto options = std::make_shared<SimulateOptions>();
    CLI::App* command = app.add_subcommand("simulate", "Adaptive-shrinking-cell optimizer for N superballs per cell, and a proof of its final packing");
    command->add_option("--p", options->p, "deformation parameter 1/2 <= p <= 10^6: a decimal or a fraction")->required();
    command->add_option("--n", options->particles, "particles per cell, 1 to " + std::to_string(max_particles) + " (default 2)");
    command->add_option("--steps", options->steps, "optimizer cycles, 1 to " + std::to_string(max_steps) + " (default 20000)");
    add_seed_option(*command, options->seed, "random seed (default 1): the same seed gives the same run");
    command->add_option("--init", options->init,
                        "start: lattice (the best certified lattice, 2% expanded; default), random (density 0.2), or a family "
                        "C0, C1, O0, O1, D14, S6 (2% expanded)");
    command->add_option("--pressure", options->pressure,
                        "the optimizer's start pressure P v_K / kT, 0.001 to 10^6 (default 10 from random, 1000 from a lattice); "
                        "it rises to 10^7 over 80% of the cycles, then only compressions are tried");
    command->add_flag("--json", options->json, "print one JSON document on stdout");
    add_packing_file_options(*command, options->files);
    command->callback([options] { run(*options); });
}

namespace {
const SubcommandRegistration registration("simulate", add_simulate);
}  // namespace

}  // namespace superpack::cli
