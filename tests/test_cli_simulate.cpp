// `superpack simulate` as a user runs it: its limits, its one JSON document, and the files it
// writes of the certified packing (extended XYZ, OBJ mesh, PNG picture, certificate). Short
// runs (200 cycles of 2 particles, well under a second each before the picture).
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gmpxx.h>
#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "scratch.hpp"

namespace {

using superpack::test::Run;
using superpack::test::run;
using superpack::test::Scratch;
using Vector = std::array<double, 3>;

const std::string quick = "simulate --n 2 --steps 200 --p ";
// The OBJ's grid, include/superpack/render/packing_mesh.hpp's default_mesh_resolution (stated in --help).
constexpr long grid = 24;

std::string contents(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(file), {});
}

std::vector<std::string> entries(const std::string& directory) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(directory)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The one JSON document on stdout (parse refuses anything after it), of a certified run.
nlohmann::json certified_document(const Run& result) {
    INFO(result.err);
    REQUIRE(result.status == 0);
    const nlohmann::json document = nlohmann::json::parse(result.out, nullptr, false);
    REQUIRE(document.is_object());
    REQUIRE(document.value("certified", false));
    return document;
}

double exact_value(const nlohmann::json& text) { return mpq_class(text.get<std::string>()).get_d(); }

// A decimal enclosure {"lo", "hi"}: both ends parse, lo <= hi.
std::pair<double, double> ends(const nlohmann::json& enclosure) {
    const double lo = std::stod(enclosure.at("lo").get<std::string>()), hi = std::stod(enclosure.at("hi").get<std::string>());
    CHECK(lo <= hi);
    return {lo, hi};
}

// Particle i of the JSON configuration: its centre and R(q) (rows), as the producer defines it.
struct Particle {
    Vector center;
    std::array<Vector, 3> rotation;
};

Particle particle_of(const nlohmann::json& particle) {
    Particle result;
    for (int c = 0; c < 3; ++c) result.center[c] = exact_value(particle["center"][c]);
    const double w = exact_value(particle["quaternion"][0]), x = exact_value(particle["quaternion"][1]),
                 y = exact_value(particle["quaternion"][2]), z = exact_value(particle["quaternion"][3]);
    const double s = w * w + x * x + y * y + z * z;
    result.rotation = {{{(w * w + x * x - y * y - z * z) / s, 2 * (x * y - w * z) / s, 2 * (x * z + w * y) / s},
                        {2 * (x * y + w * z) / s, (w * w - x * x + y * y - z * z) / s, 2 * (y * z - w * x) / s},
                        {2 * (x * z - w * y) / s, 2 * (y * z + w * x) / s, (w * w - x * x - y * y + z * z) / s}}};
    return result;
}

struct Obj {
    std::vector<Vector> vertices;
    std::vector<std::array<long, 3>> faces;  // from 1, as written
    std::size_t objects = 0;
};

Obj read_obj(const std::string& text) {
    Obj obj;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream fields(line);
        std::string kind;
        fields >> kind;
        if (kind == "v") {
            Vector x;
            fields >> x[0] >> x[1] >> x[2];
            obj.vertices.push_back(x);
        } else if (kind == "f") {
            std::array<long, 3> face;
            fields >> face[0] >> face[1] >> face[2];
            obj.faces.push_back(face);
        } else if (kind == "o") {
            ++obj.objects;
        } else {
            CHECK((kind.empty() || kind[0] == '#'));
        }
        CHECK(!fields.fail());
    }
    return obj;
}

Vector minus(const Vector& a, const Vector& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vector& a, const Vector& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vector cross(const Vector& a, const Vector& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace

TEST_CASE("simulate: bad usage is one line on stderr and exit 2, before any computation") {
    Scratch empty;
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--p 0.4", "below 1/2"},
        {"--p 2 --n 0", "--n: 1 to 16"},
        {"--p 2 --n 17", "--n: 1 to 16"},
        {"--p 2 --steps 0", "--steps: 1 to 10000000"},
        {"--p 2 --pressure 0", "--pressure: 0.001 to 10^6"},
        {"--p 2 --init C9", "unknown family 'C9'"},
        {"--p 2 --mesh " + empty.path + "/missing/packing.obj", "does not exist"},
        {"--p 2 --png " + empty.path + "/missing/packing.png", "does not exist"},
    };
    superpack::test::check_refused_before_work("simulate", cases);
    CHECK(entries(empty.path).empty());
    // --png runs gnuplot first: without it, the long run does not start.
    const Run missing = run("simulate --p 2 --png packing.png", empty.path, "PATH=" + empty.path);
    CHECK(missing.status == 2);
    CHECK(missing.err.find("gnuplot not found") != std::string::npos);
    CHECK(missing.err.find("certifying") == std::string::npos);
    CHECK(entries(empty.path).empty());
}

TEST_CASE("simulate --json: one document with the certified phi and its ratio to the best lattice") {
    const nlohmann::json document = certified_document(run(quick + "2 --json"));
    const auto [lo, hi] = ends(document.at("phi"));
    CHECK(lo > 0.8);  // the best lattice at p = 2 is 0.8699, a start 2% expanded about 0.82
    CHECK(hi < 1);
    const auto [ratio_lo, ratio_hi] = ends(document.at("ratio_to_best_lattice"));
    const auto [lattice_lo, lattice_hi] = ends(document.at("best_lattice").at("phi"));
    CHECK(ratio_lo <= hi / lattice_lo);
    CHECK(ratio_hi >= lo / lattice_hi);
    CHECK(ratio_lo > 0.9);
    CHECK(document.at("configuration").at("particles").size() == 2);
}

TEST_CASE("simulate --xyz: extended XYZ with the particle count, the cell and the columns") {
    Scratch scratch;
    const std::string path = scratch.path + "/packing.xyz";
    certified_document(run(quick + "2 --json --xyz " + path));
    std::istringstream lines(contents(path));
    std::string count, header, particle;
    std::getline(lines, count);
    std::getline(lines, header);
    CHECK(count == "2");
    CHECK(header.find("Lattice=\"") != std::string::npos);
    CHECK(header.find("Properties=species:S:1:pos:R:3") != std::string::npos);
    int particles = 0;
    while (std::getline(lines, particle)) particles += particle.rfind("Sb ", 0) == 0 ? 1 : 100;
    CHECK(particles == 2);
}

TEST_CASE("simulate --mesh: each particle a closed outward surface on the superball's boundary") {
    for (const std::string p : {"2", "0.8", "1000000"}) {
        INFO("p = " + p);
        Scratch scratch;
        const std::string path = scratch.path + "/packing.obj";
        const nlohmann::json document = certified_document(run(quick + p + " --json --mesh " + path));
        const Obj obj = read_obj(contents(path));
        const long n = 2, per_particle = 6 * grid * grid + 2;
        REQUIRE(static_cast<long>(obj.vertices.size()) == n * per_particle);
        REQUIRE(static_cast<long>(obj.faces.size()) == n * 12 * grid * grid);
        CHECK(obj.objects == 2);

        // Every index in range and within its particle's vertices; every edge once each way.
        std::map<std::pair<long, long>, int> edges;
        bool in_range = true, one_particle = true;
        for (const auto& face : obj.faces) {
            for (long index : face) in_range = in_range && index >= 1 && index <= n * per_particle;
            one_particle = one_particle && (face[0] - 1) / per_particle == (face[1] - 1) / per_particle &&
                           (face[0] - 1) / per_particle == (face[2] - 1) / per_particle;
            for (int k = 0; k < 3; ++k) ++edges[{face[k], face[(k + 1) % 3]}];
        }
        REQUIRE(in_range);
        CHECK(one_particle);
        long unpaired = 0;
        for (const auto& [edge, count] : edges) {
            const auto reverse = edges.find({edge.second, edge.first});
            if (count != 1 || reverse == edges.end() || reverse->second != 1) ++unpaired;
        }
        CHECK(unpaired == 0);
        CHECK(edges.size() == static_cast<std::size_t>(n * 36 * grid * grid));  // 3 directed edges a face

        // Every vertex on its particle's boundary: R^T (v - c) has sum |y_i|^2p = 1; every face
        // turns its normal away from the centre.
        const double exponent = 2 * std::stod(p);
        const nlohmann::json& particles = document.at("configuration").at("particles");
        double worst = 0;
        long inward = 0;
        for (long i = 0; i < n; ++i) {
            const Particle placed = particle_of(particles.at(i));
            for (long k = 0; k < per_particle; ++k) {
                const Vector d = minus(obj.vertices[i * per_particle + k], placed.center);
                double sum = 0;
                for (int c = 0; c < 3; ++c) {
                    const double y = placed.rotation[0][c] * d[0] + placed.rotation[1][c] * d[1] + placed.rotation[2][c] * d[2];
                    sum += std::pow(std::fabs(y), exponent);
                }
                worst = std::max(worst, std::fabs(sum - 1));
            }
            for (const auto& face : obj.faces) {
                if ((face[0] - 1) / per_particle != i) continue;
                const Vector& a = obj.vertices[face[0] - 1];
                const Vector& b = obj.vertices[face[1] - 1];
                const Vector& c = obj.vertices[face[2] - 1];
                const Vector middle{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
                if (dot(cross(minus(b, a), minus(c, a)), minus(middle, placed.center)) <= 0) ++inward;
            }
        }
        // Coordinates are printed to 12 digits (relative 5e-13 of up to about 10), raised to 2p.
        CHECK(worst < 1e-8 + exponent * 1e-10);
        CHECK(inward == 0);
    }
}

TEST_CASE("simulate --png: a PNG picture of the packing, written atomically") {
    Scratch scratch;
    const std::string path = scratch.path + "/packing.png";
    std::ofstream(path) << "an older file";
    const Run result = run(quick + "2 --png " + path);
    INFO(result.err);
    CHECK(result.status == 0);
    const std::string png = contents(path);
    CHECK(png.rfind(std::string("\x89PNG\r\n\x1a\n", 8), 0) == 0);
    CHECK(png.size() > 20000);  // a shaded picture, not an empty canvas (about 300 kB)
    CHECK(entries(scratch.path) == std::vector<std::string>{"packing.png"});
}

TEST_CASE("simulate --certificate: `superpack verify` accepts the certificate") {
    Scratch scratch;
    const std::string path = scratch.path + "/packing.json";
    certified_document(run(quick + "2 --json --certificate " + path));
    const Run verified = run("verify " + path);
    INFO(verified.err);
    CHECK(verified.status == 0);
    CHECK(nlohmann::json::parse(contents(path)).value("command", "") == "simulate");
}

TEST_CASE("simulate: the same seed gives the same certified packing") {
    const std::string arguments = "simulate --p 2 --n 2 --steps 300 --init random --seed 7 --json";
    const nlohmann::json first = certified_document(run(arguments));
    const nlohmann::json second = certified_document(run(arguments));
    CHECK(first.at("phi") == second.at("phi"));
    CHECK(first.at("configuration") == second.at("configuration"));
}
