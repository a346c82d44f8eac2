// Event-driven molecular dynamics of N growing, rotating superballs (p >= 1/2) in a fixed
// periodic cell, after Donev, Torquato & Stillinger, J. Comput. Phys. 202, 737 and 765 (2005)
// (the Lubachevsky-Stillinger algorithm for hard nonspherical particles): particle i is
// c_i + a(t) R(q_i) K with the common scale a(t) = a0 + G t. Free flight between collisions,
// collisions predicted by conservative advancement and resolved elastically (sim/collision.hpp,
// which also states the units: mass 1, initial kT = 1, G = da/dt, so dD/dt = 2G for spheres).
// Floating point only: the end state is a guess that problems/ proves (or scales until it can).
//
// The loop: each particle holds its earliest predicted event (a collision with a partner and
// the partner's image offset, or a re-prediction when nothing was found within the horizon), in
// a tournament tree. Particles are updated lazily (each has its own time). A collision advances
// the two bodies, applies the impulse, and re-predicts both against every particle whose
// bounding sphere (radius a R_c, growing) can meet theirs within the horizon. Each particle
// has a collision counter; an event whose partner has collided since it was predicted is stale
// and makes its owner re-predict. A collision of i and j at tau is never lost: the later of the
// two last predictions of i and j before tau saw both trajectories as they are up to tau, and
// tau within its horizon (a particle is re-predicted at least every horizon).
//
// Every `window` collisions (one per particle by default), the temperature kT = 2 E_kin / f (f = 3N - 3 translational degrees
// of freedom, plus 3N rotational unless p = 1, where rotation does nothing and omega stays 0) and
// the reduced pressure of the window are measured; with G > 0, DTS's growth correction injects
// energy, and then the velocities and angular velocities are rescaled to kT = 1 (all particles
// synchronised and re-predicted). The pressure is the collisional virial over the window,
//     P V / (N kT) = 1 + (1 / (3 N kT T)) sum over collisions of J <n, c_j - c_i>,
// T the window's duration, kT the mean of its start and end temperatures.
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include "superpack/sim/collision.hpp"
#include "superpack/sim/periodic_configuration.hpp"

namespace superpack::sim {

// How the loop finds a particle's next event. `neighbour_lists` (the default, NOTES 15.6):
// predictions against the particles whose regions meet its own (sim/neighbour_regions.hpp),
// GJK warm-started from each pair's last normal and loose far from contact, and a re-prediction
// after a stale event that starts, for every partner unchanged since, where the last one ended.
// `reference`: the loop as it was before (every particle's images screened by bounding spheres,
// GJK from the centre line to full accuracy), kept so that bench/ and the tests can measure and
// check the fast loop against it in the same run.
enum class EventLoop { neighbour_lists, reference };

struct EventMdOptions {
    std::uint64_t seed = 1;
    EventLoop loop = EventLoop::neighbour_lists;
    // Neighbour lists: a region's radius is the bounding sphere's a R_c plus this many a R_c.
    double skin = 0.4;
    // Record the first this many collisions in the result (for the tests' comparisons of loops).
    long collision_log_limit = 0;
    // G = da/dt in the units of sim/collision.hpp (mass 1, kT = 1); 0: fixed size.
    double growth_rate = 0.01;
    // a0; 0: 0.99 times the largest scale at which nothing overlaps (`largest_free_scale`).
    double initial_scale = 0;
    // Stop rules: whichever comes first.
    long max_collisions = 100000000;
    double max_time = std::numeric_limits<double>::infinity();
    double pressure_limit = 1e6;  // jammed when a window's reduced pressure exceeds it (0: never)
    double collision_rate_limit = 1e10;  // jammed when collisions per particle per unit time exceed it (0: never)
    // Collisions per measurement window (and thermostat step when G > 0); 0: N.
    long window = 0;
    // Prediction horizon (time); 0: a0 R_c / (2 sqrt 3), about a quarter of a radius at thermal speed.
    double horizon = 0;
    // A deforming cell: after every window, this many trials of a random symmetric strain of the
    // cell at fixed volume (fractional coordinates kept, velocities unchanged), each
    // kept when no two bodies overlap at the current scale; 0: the cell stays fixed. A
    // substitute for DTS's deforming boundary (NOTES 15): it lets the cell take the shape of a
    // denser crystal, such as C1 from an FCC start, while growth compresses.
    int cell_moves = 0;
    ContactOptions contact;
};

struct EventMdProgress {
    long collisions = 0;
    double time = 0, scale = 0, phi = 0, pressure = 0;
};

struct CollisionRecord {
    int first = 0, second = 0;  // the particles, first < second
    double time = 0;
};

struct EventMdResult {
    // The end state at unit scale: centres and cell divided by the final scale a, so that the
    // bodies are center(i) + R(q_i) K again (what periodic_packing proves); fractional
    // coordinates in [0, 1).
    PeriodicConfiguration configuration;
    double initial_scale = 0, scale = 0;  // a0 and the final a
    double phi = 0;                       // N vol(K) a^3 / V at the end
    double pressure = 0;                  // the last window's reduced pressure (0 before the first)
    double time = 0;
    double temperature = 0;               // kT at the end (before any rescaling there)
    double initial_energy = 0, final_energy = 0;  // kinetic (translational + rotational, I = k a^2)
    long collisions = 0;
    long events = 0;       // collisions, re-predictions and stale events popped
    long predictions = 0;  // pair predictions (first_contact calls)
    long capped_predictions = 0;  // predictions stopped by the Zeno cap
    long advancement_steps = 0;   // distance evaluations (GJK runs unless p = 1) in all predictions
    long rescalings = 0;
    long region_moves = 0;        // neighbour lists: particles that left their region and got a new one
    long cell_moves_kept = 0;     // deforming cell: strains kept (of cell_moves per window)
    // Why it stopped (exactly one is set): pressure or collision rate over its limit (jammed),
    // max_collisions, max_time, or the scale at which a body could meet its own image (half the
    // shortest lattice vector over R_c), where the event loop, which never pairs a body with its
    // own image, stops; or stalled.
    // `stalled`: a whole window of collisions took no time (contacts that do not resolve).
    bool jammed_pressure = false, jammed_rate = false, collision_limit = false, time_limit = false, image_limit = false,
         stalled = false;
    std::vector<CollisionRecord> collision_log;  // the first collision_log_limit collisions
};

// The largest a at which the bodies c_i + a R(q_i) K of `configuration` do not overlap (any two,
// images included), to about 1e-12 relative: a pair's critical scale is found by bisection with
// `overlapping` (the set of scales at which two convex bodies meet is an interval [s, inf)), a
// body and its own image's in closed form, gauge(R^T k B) / 2.
double largest_free_scale(const SuperballShape& shape, const PeriodicConfiguration& configuration);

// Runs the dynamics from `start` (unit-scale bodies; they must not overlap at a0: throws
// std::invalid_argument otherwise, or when N < 2 or a body could meet its own image at a0).
// Velocities: Gaussian (Box-Muller from RandomSource(seed)) with the total momentum removed,
// angular velocities Gaussian with variance kT / I (0 at p = 1), both scaled to kT = 1 exactly.
// `progress`, if given, is called every 1000 collisions. The same seed gives the same run.
EventMdResult run_event_md(const SuperballShape& shape, const PeriodicConfiguration& start, const EventMdOptions& options,
                           const std::function<void(const EventMdProgress&)>& progress = {});

}  // namespace superpack::sim
