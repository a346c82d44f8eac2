// Certificates of claim kind "critical-lattice-cover" (superpack critical --cover, NOTES.md 12.9).
// The checker's split chart domain is the producer's, box for box (two implementations), and a
// cover is rejected at the named file when a part is missing, named twice, outside the cover's
// directory, of another kind, invalid, at another T, or when the parts' start boxes leave a box
// of the split domain uncovered, repeat one, or are not boxes of the split domain. A valid cover
// needs the certificates of every shard of a whole run (minutes of CPU), so it is made and
// replayed by `make proofs-critical`, not here.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "checker/claims/critical_claim.hpp"
#include "checker/verifier.hpp"
#include "critical_certificates.hpp"
#include "scratch.hpp"
#include "support.hpp"
#include "tamper.hpp"

namespace {

using superpack::Rational;
using superpack_checker::Verdict;
using superpack_checker::VerifySettings;
using superpack_checker::verify_document;
using Document = nlohmann::json;

// A scratch directory the parts are written to.
struct Scratch : superpack::test::Scratch {
    void write(const std::string& name, const Document& document) const { std::ofstream(path + "/" + name) << document.dump(); }
};

// The certificate of start box `box` alone of the domain split `split` times at p = 2, gap 0.
Document box_certificate(int split, int box) {
    return superpack::test::critical_certificate_at_p2([&](superpack::CriticalOptions& options) {
        options.split = split;
        options.shard = box;
        options.shards = superpack::top_level_boxes << split;
    });
}

// Start box 5 of the domain split 3 times (shard 5/1344): a few hundred boxes in its tree.
const Document& part_certificate() {
    static const Document document = box_certificate(3, 5);
    return document;
}

// A cover of `files` at the part's p, gap and T, split 3, its claim text left empty.
Document cover_of(const std::vector<std::string>& files, int split = 3) {
    Document cover = part_certificate();
    const Document& data = cover["claim"]["data"];
    cover["claim"] = {{"kind", "critical-lattice-cover"},
                      {"text", ""},
                      {"data",
                       {{"p", data["p"]},
                        {"threshold", data["threshold"]},
                        {"volume", data["volume"]},
                        {"upper_phi", data["upper_phi"]},
                        {"split", split}}}};
    cover["proof"] = {{"kind", "critical-lattice-cover"}, {"files", files}};
    return cover;
}

superpack_checker::VerifyReport replay(const Document& cover, const Scratch& scratch) {
    VerifySettings settings;
    settings.directory = scratch.path;
    settings.threads = 2;
    return verify_document(cover, settings);
}

void check_rejected(const Document& cover, const Scratch& scratch, const std::string& path, const std::string& needle,
                    Verdict verdict = Verdict::invalid) {
    const auto report = replay(cover, scratch);
    INFO(report.path << ": " << report.message);
    CHECK(report.verdict == verdict);
    CHECK(report.path == path);
    CHECK(report.message.find(needle) != std::string::npos);
}

}  // namespace

TEST_CASE("the checker's split chart domain is the producer's, box for box, and halves the volume evenly") {
    using namespace superpack;
    for (int split = 0; split <= 4; ++split) {
        INFO("split " << split);
        const std::vector<ChartBox<DInterval>> producer = split_domain(split);
        const std::vector<superpack_checker::DomainBox> checker = superpack_checker::chart_domain(split);
        REQUIRE(producer.size() == static_cast<std::size_t>(top_level_boxes) << split);
        REQUIRE(checker.size() == producer.size());
        double volume = 0;
        for (std::size_t k = 0; k < producer.size(); ++k) {
            CHECK(configuration_name(producer[k].configuration) ==
                  std::string(superpack_checker::configuration_name(checker[k].configuration)));
            CHECK(producer[k].face2 == checker[k].face2);
            CHECK(producer[k].face3 == checker[k].face3);
            double box_volume = 1;
            for (int j = 0; j < chart_dimension; ++j) {
                CHECK(producer[k].x[j].lower() == checker[k].ends[2 * j]);
                CHECK(producer[k].x[j].upper() == checker[k].ends[2 * j + 1]);
                box_volume *= producer[k].x[j].upper() - producer[k].x[j].lower();
            }
            CHECK(box_volume == 4.0 / static_cast<double>(1 << split));  // (1/2)^2 * 2^4 / 2^K
            volume += box_volume;
        }
        CHECK(volume == 4.0 * top_level_boxes);  // no overlap counted twice, nothing left out
    }
    CHECK_THROWS_AS(split_domain(max_split + 1), InputError);
    CHECK_THROWS_AS(split_domain(-1), InputError);
}

TEST_CASE("critical-lattice-cover: each flaw rejected at the file that has it") {
    const Scratch scratch;
    const Document& part = part_certificate();
    REQUIRE(verify_document(part).verdict == Verdict::valid);
    scratch.write("part.json", part);
    scratch.write("copy.json", part);

    SECTION("one part of 1344 start boxes: every check passes up to the tiling, which leaves box 0 uncovered") {
        check_rejected(cover_of({"part.json"}), scratch, "proof.files", "start box 0 of the split domain");
        check_rejected(cover_of({"part.json"}), scratch, "proof.files", "is not covered");
    }
    SECTION("the same start box in two files") {
        check_rejected(cover_of({"part.json", "copy.json"}), scratch, "proof.files[1]", "also a start box of part.json");
    }
    SECTION("a start box larger than the boxes of the cover's split domain") {
        check_rejected(cover_of({"part.json"}, 4), scratch, "proof.files[0]", "is larger than a box of the chart domain split 4 times");
    }
    SECTION("a start box replaced by its two halves (boxes 10 and 11 at split 4): both placed, box 0 still uncovered") {
        scratch.write("lower.json", box_certificate(4, 10));
        scratch.write("upper.json", box_certificate(4, 11));
        check_rejected(cover_of({"lower.json", "upper.json"}), scratch, "proof.files", "start box 0 of the split domain");
    }
    SECTION("a file named twice") {
        check_rejected(cover_of({"part.json", "part.json"}), scratch, "proof.files[1]", "named twice");
    }
    SECTION("a missing file") {
        check_rejected(cover_of({"missing.json"}), scratch, "proof.files[0]", "cannot read");
    }
    SECTION("a missing file after an invalid one: found before any replay, which would stop at the first") {
        Document tampered = part;
        tampered["claim"]["text"] = "every lattice packing is dense";
        scratch.write("tampered.json", tampered);
        check_rejected(cover_of({"tampered.json", "missing.json"}), scratch, "proof.files[1]", "missing.json: no such file");
    }
    SECTION("a part that is a symbolic link, even to a valid part in the same directory") {
        std::filesystem::create_symlink("part.json", scratch.path + "/link.json");
        check_rejected(cover_of({"link.json"}), scratch, "proof.files[0]", "link.json: a symbolic link");
    }
    SECTION("a part that is a directory") {
        std::filesystem::create_directory(scratch.path + "/directory.json");
        check_rejected(cover_of({"directory.json"}), scratch, "proof.files[0]", "not a regular file");
    }
    SECTION("a name outside the cover's directory") {
        check_rejected(cover_of({"../part.json"}), scratch, "proof.files[0]", "no '/'", Verdict::malformed);
    }
    SECTION("a part of another claim kind, refused before its replay") {
        Document other = part;
        other["claim"]["kind"] = "local-optimum";
        scratch.write("other.json", other);
        check_rejected(cover_of({"other.json"}), scratch, "proof.files[0]", "is a \"local-optimum\" certificate");
    }
    SECTION("an invalid part") {
        Document tampered = part;
        tampered["claim"]["text"] = "every lattice packing is dense";
        scratch.write("tampered.json", tampered);
        check_rejected(cover_of({"tampered.json"}), scratch, "proof.files[0]", "tampered.json is invalid at claim.text");
    }
    SECTION("a cover at another T than its part") {
        Document cover = cover_of({"part.json"});
        superpack::test::tamper_bound(cover, "/claim/data/threshold/lo");  // T raised
        cover["claim"]["data"]["threshold"]["hi"] = cover["claim"]["data"]["threshold"]["lo"];
        check_rejected(cover, scratch, "proof.files[0]", "proves another T");
    }
    SECTION("a cover in memory has no directory to open its files in") {
        const auto report = verify_document(cover_of({"part.json"}));
        CHECK(report.verdict == Verdict::malformed);
        CHECK(report.path == "proof.files");
    }
}
