#include "superpack/sim/event_md.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "superpack/sim/neighbour_regions.hpp"
#include "superpack/sim/periodic_images.hpp"

namespace superpack::sim {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

Vector3 to_vector(const std::array<int, 3>& k) { return {double(k[0]), double(k[1]), double(k[2])}; }

// The shortest nonzero vector of the lattice with basis rows `cell`.
double shortest_lattice_vector(const Matrix3& cell) {
    double shortest = std::min({norm(cell[0]), norm(cell[1]), norm(cell[2])});
    for (const auto& k : image_shifts(cell, {0, 0, 0}, shortest * (1 + 1e-9))) {
        if (k == std::array<int, 3>{0, 0, 0}) continue;
        shortest = std::min(shortest, norm(row_combination(cell, to_vector(k))));
    }
    return shortest;
}

// The scale at which c + s R_a K and c + d + s R_b K start to overlap, by bisection between
// bounds from the circumradius and the inradius: the largest s found not to overlap.
double critical_scale(const SuperballShape& shape, const Matrix3& rotation_a, const Matrix3& rotation_b, const Vector3& d) {
    const double length = norm(d);
    if (shape.p() == 1) return length / 2;
    double low = length / (2 * shape.circumradius()), high = length / (2 * shape.inradius());
    const Placement first{{0, 0, 0}, rotation_a};
    for (int step = 0; step < 200 && high - low > 1e-13 * high; ++step) {
        const double middle = 0.5 * (low + high);
        if (overlapping(shape, first, Placement{(1 / middle) * d, rotation_b})) high = middle;
        else low = middle;
    }
    return low;
}

struct Particle {
    Vector3 position{};  // Cartesian, at `time`
    double time = 0;
    Quaternion orientation;
    Vector3 velocity{}, angular_velocity{};
    long counter = 0;  // collisions (and rescalings) so far: an event predicted before is stale
};

// An event's partner when it is no collision: re-predict (the horizon, or a capped prediction),
// or leave the region (neighbour lists).
constexpr int predict_again = -1, leave_region = -2;

struct Event {
    double time = infinity;
    int partner = predict_again;  // or a particle, or leave_region
    Vector3 offset{};   // added to the partner's position: the image it meets
    long partner_counter = 0;
};

// The earliest of N event times: a tournament tree, ties to the lower index (deterministic).
class EventTree {
public:
    explicit EventTree(int n) : times_(n, infinity) {
        while (size_ < n) size_ *= 2;
        tree_.assign(2 * size_, -1);
        for (int i = 0; i < n; ++i) tree_[size_ + i] = i;
        for (int node = size_ - 1; node >= 1; --node) tree_[node] = better(tree_[2 * node], tree_[2 * node + 1]);
    }
    void set(int i, double time) {
        times_[i] = time;
        for (int node = (size_ + i) / 2; node >= 1; node /= 2) tree_[node] = better(tree_[2 * node], tree_[2 * node + 1]);
    }
    int top() const { return tree_[1]; }

private:
    int better(int a, int b) const {
        if (a < 0) return b;
        if (b < 0) return a;
        return times_[b] < times_[a] ? b : a;
    }
    int size_ = 1;
    std::vector<double> times_;
    std::vector<int> tree_;
};

class Simulation {
public:
    Simulation(const SuperballShape& shape, const PeriodicConfiguration& start, const EventMdOptions& options)
        : shape_(shape), options_(options), tree_(static_cast<int>(start.size())) {
        n_ = static_cast<int>(start.size());
        if (n_ < 2) throw std::invalid_argument("run_event_md: needs at least two particles");
        if (!(options.growth_rate >= 0) || !std::isfinite(options.growth_rate))
            throw std::invalid_argument("run_event_md: needs a finite growth rate >= 0");
        if (!(options.skin > 0) || !std::isfinite(options.skin))
            throw std::invalid_argument("run_event_md: needs a finite skin > 0");
        fast_ = options.loop == EventLoop::neighbour_lists;
        ball_ = shape.p() == 1;
        radius_ = shape.circumradius();
        k_ = inertia_factor(shape.p());
        G_ = options.growth_rate;
        cell_ = start.cell;
        inverse_ = inverse(cell_);
        for (int m = 0; m < 3; ++m) column_norm_[m] = std::hypot(inverse_[0][m], inverse_[1][m], inverse_[2][m]);
        image_scale_ = shortest_lattice_vector(cell_) / (2 * radius_);
        const double free_scale = largest_free_scale(shape, start);
        a0_ = options.initial_scale > 0 ? options.initial_scale : 0.99 * free_scale;
        if (!(a0_ < free_scale))
            throw std::invalid_argument("run_event_md: the bodies overlap at the initial scale " + std::to_string(a0_) +
                                        " (largest free scale " + std::to_string(free_scale) + ")");
        if (!(a0_ < image_scale_))
            throw std::invalid_argument("run_event_md: the cell is too small: a body could meet its own image at the initial scale");
        horizon_ = options.horizon > 0 ? options.horizon : a0_ * radius_ / (2 * std::sqrt(3.0));
        window_ = options.window > 0 ? options.window : n_;
        degrees_ = 3.0 * n_ - 3 + (ball_ ? 0.0 : 3.0 * n_);

        cell_random_ = RandomSource(options.seed ^ 0x5bd1e9955bd1e995ULL);
        RandomSource random(options.seed);
        const auto gaussian = [&random] {
            const double u = random.uniform(), v = random.uniform();
            return std::sqrt(-2 * std::log1p(-u)) * std::cos(2 * M_PI * v);
        };
        particles_.resize(n_);
        events_.assign(n_, Event{});
        Vector3 momentum{0, 0, 0};
        for (int i = 0; i < n_; ++i) {
            Particle& particle = particles_[i];
            particle.position = start.center(i);
            particle.orientation = normalized(start.orientations[i]);
            particle.velocity = {gaussian(), gaussian(), gaussian()};
            const double spread = 1 / std::sqrt(k_ * a0_ * a0_);
            if (!ball_) particle.angular_velocity = {spread * gaussian(), spread * gaussian(), spread * gaussian()};
            momentum = momentum + particle.velocity;
        }
        for (Particle& particle : particles_) particle.velocity = particle.velocity - (1.0 / n_) * momentum;
        rescale(std::sqrt(1 / temperature(0)));
    }

    EventMdResult run(const std::function<void(const EventMdProgress&)>& progress) {
        EventMdResult result;
        result.initial_scale = a0_;
        result.initial_energy = kinetic_energy(0);
        if (fast_) build_regions(0);
        for (int i = 0; i < n_; ++i) predict(i, 0);
        set_stop_time();
        double now = 0;
        Window window;
        for (;;) {
            const int i = tree_.top();
            const Event event = events_[i];
            if (event.time > stop_time_) {
                now = stop_time_;
                (options_.max_time <= image_time_ ? result.time_limit : result.image_limit) = true;
                break;
            }
            now = event.time;
            ++result.events;
            if (event.partner == leave_region) {
                move_region(i, now);
                ++result.region_moves;
            }
            if (event.partner < 0 || particles_[event.partner].counter != event.partner_counter) {
                predict(i, now);
                continue;
            }
            window.virial += collide(i, event);
            ++result.collisions;
            if (static_cast<long>(result.collision_log.size()) < options_.collision_log_limit)
                result.collision_log.push_back({std::min(i, event.partner), std::max(i, event.partner), now});
            if (progress && result.collisions % 1000 == 0)
                progress({result.collisions, now, scale(now), phi(now), result.pressure});
            if (result.collisions >= options_.max_collisions) {
                result.collision_limit = true;
                break;
            }
            if (++window.collisions < window_) continue;
            if (!close_window(result, window, now)) break;
        }
        finish(result, now);
        return result;
    }

private:
    // What a window of collisions gathers between two thermostat steps (kept together so that
    // close_window can read and restart it).
    struct Window {
        double start = 0, temperature = 1, virial = 0;
        long collisions = 0;
    };

    // Stop before a body could meet its own image (the loop never pairs a body with it): a step
    // of its own because a kept cell trial changes the image scale, and so the stop.
    void set_stop_time() {
        image_time_ = G_ > 0 ? (image_scale_ * (1 - 1e-9) - a0_) / G_ : infinity;
        stop_time_ = std::min(options_.max_time, image_time_);
    }

    // The end of a window of window_ collisions: the window's pressure and collision rate
    // (which may stop the run as jammed), then the cell's trials and the thermostat. False when
    // the run stops here. Its own step: run's loop then reads as one event after another.
    bool close_window(EventMdResult& result, Window& window, double now) {
        // The window's pressure and collision rate; then the thermostat.
        const double span = now - window.start, end_temperature = temperature(now);
        // N collisions at one instant are no jamming: contacts that do not resolve (flat
        // faces and sharp edges at p = 1/2, where an impulse at one point of a face leaves
        // another closing).
        if (!(span > 0)) {
            result.stalled = true;
            return false;
        }
        result.pressure = span > 0 ? 1 + window.virial / (3 * n_ * 0.5 * (window.temperature + end_temperature) * span) : infinity;
        const double rate = span > 0 ? window.collisions / (n_ * span) : infinity;
        if (options_.pressure_limit > 0 && result.pressure > options_.pressure_limit) result.jammed_pressure = true;
        else if (options_.collision_rate_limit > 0 && rate > options_.collision_rate_limit) result.jammed_rate = true;
        if (result.jammed_pressure || result.jammed_rate) return false;
        bool repredict = false;
        if (options_.cell_moves > 0) {
            for (int j = 0; j < n_; ++j) synchronise(j, now);
            const long kept = deform_cell(now);
            result.cell_moves_kept += kept;
            if (kept > 0) {
                repredict = true;
                set_stop_time();
                if (fast_) build_regions(now);
            }
        }
        if (G_ > 0) {
            for (int j = 0; j < n_; ++j) synchronise(j, now);
            rescale(std::sqrt(1 / end_temperature));
            ++result.rescalings;
            window.temperature = 1;
            repredict = true;
        } else {
            window.temperature = end_temperature;
        }
        if (repredict) {
            for (Particle& particle : particles_) ++particle.counter;
            for (int j = 0; j < n_; ++j) predict(j, now);
        }
        window.virial = 0;
        window.start = now;
        window.collisions = 0;
        return true;
    }

    // The run's end state at time `now`: every particle synchronised, the counters, and the
    // final configuration at unit scale with fractional coordinates in [0, 1) (a step of its
    // own: what the result reports, apart from how the run went).
    void finish(EventMdResult& result, double now) {
        for (int j = 0; j < n_; ++j) synchronise(j, now);
        result.time = now;
        result.scale = scale(now);
        result.phi = phi(now);
        result.temperature = temperature(now);
        result.final_energy = kinetic_energy(now);
        result.predictions = predictions_;
        result.capped_predictions = capped_;
        result.advancement_steps = iterations_;
        PeriodicConfiguration& end = result.configuration;
        for (int m = 0; m < 3; ++m) end.cell[m] = (1 / result.scale) * cell_[m];
        for (const Particle& particle : particles_) {
            Vector3 f = apply_transpose(inverse_, particle.position);
            for (double& x : f) {
                x -= std::floor(x);
                if (!(x < 1)) x = 0;
            }
            end.fractional.push_back(f);
            end.orientations.push_back(particle.orientation);
        }
    }

    double scale(double t) const { return a0_ + G_ * t; }
    double phi(double t) const { return n_ * superball_volume(shape_.p()) * std::pow(scale(t), 3) / std::fabs(determinant(cell_)); }

    double kinetic_energy(double t) const {
        const double inertia = k_ * scale(t) * scale(t);
        double energy = 0;
        for (const Particle& particle : particles_)
            energy += 0.5 * dot(particle.velocity, particle.velocity) + 0.5 * inertia * dot(particle.angular_velocity, particle.angular_velocity);
        return energy;
    }
    double temperature(double t) const { return 2 * kinetic_energy(t) / degrees_; }

    void rescale(double factor) {
        for (Particle& particle : particles_) {
            particle.velocity = factor * particle.velocity;
            particle.angular_velocity = factor * particle.angular_velocity;
        }
    }

    MovingBody body_at(int i, double t) const {
        const Particle& particle = particles_[i];
        return advance(MovingBody{particle.position, particle.orientation, particle.velocity, particle.angular_velocity}, t - particle.time);
    }

    void synchronise(int i, double t) {
        const MovingBody body = body_at(i, t);
        Particle& particle = particles_[i];
        particle.position = body.center;
        particle.orientation = body.orientation;
        particle.time = t;
    }

    void predict(int i, double t) {
        if (fast_) predict_neighbours(i, t);
        else predict_all_images(i, t);
    }

    // The reference loop's prediction: particle i's earliest event from time t, the first
    // contact with any image of any other particle within the horizon (searched only up to the
    // best found so far), or a re-prediction at the horizon (or where a capped prediction stopped).
    void predict_all_images(int i, double t) {
        Event best;
        best.time = t + horizon_;
        const double a = scale(t), largest = scale(t + horizon_);
        const MovingBody self = body_at(i, t);
        const MovingBody first{{0, 0, 0}, self.orientation, self.velocity, self.angular_velocity};
        for (int j = 0; j < n_; ++j) {
            if (j == i) continue;
            const Particle& other = particles_[j];
            const Vector3 delta = other.position + (t - other.time) * other.velocity - self.center;
            // Bounding spheres (radius a R_c) that cannot meet within the horizon are skipped:
            // an image x = delta + k B within `cutoff` has fractional coordinates f + k with
            // |f_m + k_m| <= |column m of B^-1| cutoff, a box of k that is usually empty.
            const double cutoff = norm(other.velocity - self.velocity) * horizon_ + 2 * largest * radius_;
            const Vector3 f = apply_transpose(inverse_, delta);
            std::array<int, 3> low{}, high{};
            bool empty = false;
            for (int m = 0; m < 3; ++m) {
                low[m] = static_cast<int>(std::ceil(-f[m] - column_norm_[m] * cutoff));
                high[m] = static_cast<int>(std::floor(-f[m] + column_norm_[m] * cutoff));
                empty = empty || low[m] > high[m];
            }
            if (empty) continue;
            bool moved = false;
            MovingBody second;
            for (int k0 = low[0]; k0 <= high[0]; ++k0)
                for (int k1 = low[1]; k1 <= high[1]; ++k1)
                    for (int k2 = low[2]; k2 <= high[2]; ++k2) {
                        const Vector3 offset = row_combination(cell_, Vector3{double(k0), double(k1), double(k2)});
                        const Vector3 image = delta + offset;
                        if (!(norm(image) < cutoff)) continue;
                        if (!moved) {
                            second = body_at(j, t);
                            moved = true;
                        }
                        second.center = image;
                        ++predictions_;
                        const ContactPrediction prediction =
                            first_contact(shape_, first, second, a, G_, std::min(horizon_, best.time - t), options_.contact);
                        iterations_ += prediction.iterations;
                        if (prediction.outcome == ContactOutcome::none || !(t + prediction.time < best.time)) continue;
                        best.time = t + prediction.time;
                        if (prediction.outcome == ContactOutcome::capped) {
                            ++capped_;
                            best.partner = -1;
                        } else {
                            best.partner = j;
                            best.offset = offset;
                            best.partner_counter = other.counter;
                        }
                    }
        }
        events_[i] = best;
        tree_.set(i, best.time);
    }

    // The fast loop's prediction: as predict_all_images, but against the neighbours only (no
    // other body can reach i before i or it leaves its region, which is an event of its own),
    // with each pair's GJK started from the pair's last normal, and the horizon cut where i
    // leaves its region.
    void predict_neighbours(int i, double t) {
        Event best;
        best.time = t + horizon_;
        const double leave = leave_time(i, t);
        if (leave < best.time) {
            best.time = leave;
            best.partner = leave_region;
        }
        const MovingBody self = body_at(i, t);
        const MovingBody first{{0, 0, 0}, self.orientation, self.velocity, self.angular_velocity};
        // Nearest first: the earliest contact is usually with a near neighbour, and once it is
        // found the others are searched only up to it.
        std::vector<Neighbour>& neighbours = regions_.neighbours(i);
        order_.clear();
        for (std::size_t k = 0; k < neighbours.size(); ++k) {
            const Particle& other = particles_[neighbours[k].partner];
            const Vector3 image = other.position + (t - other.time) * other.velocity + neighbours[k].offset - self.center;
            order_.push_back({norm(image), static_cast<int>(k)});
        }
        std::sort(order_.begin(), order_.end());
        for (const auto& [length, k] : order_) {
            Neighbour& entry = neighbours[k];
            const int j = entry.partner;
            const Particle& other = particles_[j];
            const Vector3 image = other.position + (t - other.time) * other.velocity + entry.offset - self.center;
            // Bounding spheres that cannot meet before the best event so far are skipped.
            const double reach = norm(other.velocity - self.velocity) * (best.time - t) + 2 * scale(best.time) * radius_;
            if (!(norm(image) < reach)) continue;
            MovingBody second = body_at(j, t);
            second.center = image;
            ++predictions_;
            const ContactPrediction prediction =
                first_contact(shape_, first, second, scale(t), G_, best.time - t, options_.contact, SeparationHint{entry.normal, 0});
            iterations_ += prediction.iterations;
            if (dot(prediction.normal, prediction.normal) > 0) entry.normal = prediction.normal;
            if (prediction.outcome == ContactOutcome::none || !(t + prediction.time < best.time)) continue;
            best.time = t + prediction.time;
            if (prediction.outcome == ContactOutcome::capped) {
                ++capped_;
                best.partner = predict_again;
            } else {
                best.partner = j;
                best.offset = entry.offset;
                best.partner_counter = other.counter;
            }
        }
        events_[i] = best;
        tree_.set(i, best.time);
    }

    // A lower bound on when body i (its bounding sphere, growing) leaves its region: its centre
    // moves at |v| and the sphere's radius grows at G R_c.
    double leave_time(int i, double t) const {
        const Particle& particle = particles_[i];
        const Vector3 position = particle.position + (t - particle.time) * particle.velocity;
        const double room = regions_.radius(i) - scale(t) * radius_ - norm(position - regions_.centre(i));
        const double speed = norm(particle.velocity) + G_ * radius_;
        if (!(speed > 0)) return infinity;
        return t + std::max(0.0, room) / speed;
    }

    Vector3 wrapped(const Vector3& position) const {
        Vector3 f = apply_transpose(inverse_, position);
        for (double& x : f) x -= std::floor(x);
        return row_combination(cell_, f);
    }

    double region_radius(double t) const { return scale(t) * radius_ * (1 + options_.skin); }

    // Every particle synchronised at t, wrapped into the cell and given a region about itself.
    void build_regions(double t) {
        std::vector<Vector3> centres;
        for (int j = 0; j < n_; ++j) {
            synchronise(j, t);
            particles_[j].position = wrapped(particles_[j].position);
            centres.push_back(particles_[j].position);
        }
        regions_.build(cell_, centres, region_radius(t));
    }

    // Particle i at the edge of its region at t gets a new region about it. Its position is
    // wrapped back into the cell only once it has strayed a cell away: a wrap changes the image
    // offsets that the others' events with i hold, so its counter must move on, which makes
    // those events stale (a region move alone leaves every event valid).
    void move_region(int i, double t) {
        synchronise(i, t);
        Particle& particle = particles_[i];
        const Vector3 f = apply_transpose(inverse_, particle.position);
        if (!(f[0] >= -1 && f[0] < 2 && f[1] >= -1 && f[1] < 2 && f[2] >= -1 && f[2] < 2)) {
            particle.position = wrapped(particle.position);
            ++particle.counter;
        }
        regions_.move(i, particle.position, region_radius(t));
    }

    // The deforming cell's trials at time t (every particle synchronised there): b -> b (I + e)
    // with e symmetric, entries uniform in [-s, s], scaled to det 1 (a pure change of shape:
    // measured at p = 2, N = 8 from FCC, letting trials also compress quenched the crystal at
    // 0.91 of C1, shape alone reached 0.97), positions carried by their fractional coordinates; a trial is kept
    // when no two bodies (unit scale: cell and centres over a) overlap and no body could meet
    // its own image. s grows by 1.1 after a kept trial and shrinks by 0.9 after a refused one.
    // Returns the trials kept.
    long deform_cell(double t) {
        const double a = scale(t);
        PeriodicConfiguration trial;
        for (const Particle& particle : particles_) {
            trial.fractional.push_back(apply_transpose(inverse_, particle.position));
            trial.orientations.push_back(particle.orientation);
        }
        long kept = 0;
        for (int move = 0; move < options_.cell_moves; ++move) {
            Matrix3 deformation{};
            for (int r = 0; r < 3; ++r)
                for (int c = r; c < 3; ++c) deformation[r][c] = deformation[c][r] = cell_random_.uniform(-strain_, strain_);
            for (int d = 0; d < 3; ++d) deformation[d][d] += 1;
            const double ratio = determinant(deformation);
            if (!(ratio > 0)) continue;
            for (Vector3& row : deformation) row = std::cbrt(1 / ratio) * row;
            const Matrix3 cell = multiply(cell_, deformation);
            for (int m = 0; m < 3; ++m) trial.cell[m] = (1 / a) * cell[m];
            const bool fits = a < shortest_lattice_vector(cell) / (2 * radius_) * (1 - 1e-9) && !any_overlap(shape_, trial);
            strain_ = fits ? std::min(0.05, 1.1 * strain_) : std::max(1e-9, 0.9 * strain_);
            if (!fits) continue;
            ++kept;
            cell_ = cell;
        }
        if (kept == 0) return 0;
        inverse_ = inverse(cell_);
        for (int m = 0; m < 3; ++m) column_norm_[m] = std::hypot(inverse_[0][m], inverse_[1][m], inverse_[2][m]);
        image_scale_ = shortest_lattice_vector(cell_) / (2 * radius_);
        for (int i = 0; i < n_; ++i) particles_[i].position = row_combination(cell_, trial.fractional[i]);
        return kept;
    }

    // The collision of i with the partner's image of `event`: both bodies advanced, the impulse
    // applied, both wrapped into the cell and re-predicted. Returns the virial term.
    double collide(int i, const Event& event) {
        const int j = event.partner;
        const double t = event.time, a = scale(t);
        synchronise(i, t);
        synchronise(j, t);
        Particle &first = particles_[i], &second = particles_[j];
        MovingBody body_i{{0, 0, 0}, first.orientation, first.velocity, first.angular_velocity};
        MovingBody body_j{second.position + event.offset - first.position, second.orientation, second.velocity, second.angular_velocity};
        const Contact touching = contact(shape_, body_i, body_j, a);
        double virial = 0;
        if (normal_gap_rate(body_i, body_j, a, G_, touching) < 0) {
            const CollisionResponse response = sim::collide(k_, a, G_, touching, body_i, body_j);
            virial = response.impulse * dot(touching.normal, body_j.center);
            first.velocity = body_i.velocity;
            first.angular_velocity = body_i.angular_velocity;
            second.velocity = body_j.velocity;
            second.angular_velocity = body_j.angular_velocity;
        }
        for (Particle* particle : {&first, &second}) {
            ++particle->counter;
            // The fast loop wraps a particle only when it moves its region (its neighbours'
            // image offsets follow the particle as it is).
            if (fast_) continue;
            Vector3 f = apply_transpose(inverse_, particle->position);
            for (double& x : f) x -= std::floor(x);
            particle->position = row_combination(cell_, f);
        }
        predict(i, t);
        predict(j, t);
        return virial;
    }

    const SuperballShape& shape_;
    EventMdOptions options_;
    int n_ = 0;
    bool fast_ = true;  // the neighbour-list loop, else the reference
    bool ball_ = false;
    double radius_ = 1, k_ = 0.4, G_ = 0, a0_ = 1, horizon_ = 1, image_scale_ = infinity, degrees_ = 1;
    double image_time_ = infinity, stop_time_ = infinity;  // set_stop_time
    long window_ = 1;
    Matrix3 cell_{}, inverse_{};
    Vector3 column_norm_{};
    std::vector<Particle> particles_;
    std::vector<Event> events_;
    EventTree tree_;
    NeighbourRegions regions_;
    std::vector<std::pair<double, int>> order_;  // predict_neighbours' order of the neighbours (kept to reuse its memory)
    long predictions_ = 0, capped_ = 0, iterations_ = 0;
    RandomSource cell_random_{0};
    double strain_ = 0.01;
};

}  // namespace

double largest_free_scale(const SuperballShape& shape, const PeriodicConfiguration& configuration) {
    const std::size_t n = configuration.size();
    const double radius = shape.circumradius(), inner = shape.inradius();
    // An upper bound: bodies whose centres are closer than 2 a r_in overlap.
    double upper = shortest_lattice_vector(configuration.cell) / (2 * inner);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) upper = std::min(upper, norm(nearest_difference(configuration, i, j)) / (2 * inner));
    // Only pairs with |d| < 2 R_c upper can have a critical scale below it.
    double best = upper;
    std::vector<Matrix3> rotations;
    for (std::size_t i = 0; i < n; ++i) rotations.push_back(rotation_matrix(configuration.orientations[i]));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i; j < n; ++j) {
            const Vector3 difference = i == j ? Vector3{0, 0, 0} : nearest_difference(configuration, i, j);
            for (const auto& k : image_shifts(configuration.cell, difference, 2 * radius * best)) {
                if (i == j && k == std::array<int, 3>{0, 0, 0}) continue;
                const Vector3 d = difference + row_combination(configuration.cell, to_vector(k));
                if (!(norm(d) / (2 * radius) < best)) continue;
                // A body and its image are translates: they meet iff d in a (K - K) = 2 a R K.
                const double critical = i == j ? shape.gauge(apply_transpose(rotations[i], d)) / 2 : critical_scale(shape, rotations[i], rotations[j], d);
                best = std::min(best, critical);
            }
        }
    return best;
}

EventMdResult run_event_md(const SuperballShape& shape, const PeriodicConfiguration& start, const EventMdOptions& options,
                           const std::function<void(const EventMdProgress&)>& progress) {
    Simulation simulation(shape, start, options);
    return simulation.run(progress);
}

}  // namespace superpack::sim
