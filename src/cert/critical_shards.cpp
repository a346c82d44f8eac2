#include "superpack/cert/critical_shards.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>

namespace superpack {

namespace {

const char* const not_regular = "is not a regular file";

// Throws InputError (`who` starts the message) unless `path` names a regular file. lstat: a
// symbolic link is refused, never followed, as the writes of atomic_file refuse one.
void require_regular_file(const std::string& path, const std::string& who) {
    struct stat status {};
    if (lstat(path.c_str(), &status) != 0) throw InputError(who + ": cannot open '" + path + "': " + std::strerror(errno));
    if (S_ISLNK(status.st_mode))
        throw InputError(who + ": '" + path + "' is a symbolic link (superpack reads and writes regular files only; name the "
                         "file itself)");
    if (!S_ISREG(status.st_mode)) throw InputError(who + ": '" + path + "' " + not_regular);
}

// The file's text: a regular file (no symlink followed, no device or FIFO read) of at most
// `limit` bytes; `who` starts the error message.
std::string read_regular_file(const std::string& path, long limit, const std::string& who) {
    require_regular_file(path, who);
    // O_NOFOLLOW and fstat again: the name may have been replaced since.
    const int descriptor = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (descriptor < 0) throw InputError(who + ": cannot open '" + path + "': " + std::strerror(errno));
    const std::unique_ptr<int, void (*)(int*)> closer(new int(descriptor), [](int* d) { close(*d); delete d; });
    struct stat status {};
    if (fstat(descriptor, &status) != 0 || !S_ISREG(status.st_mode)) throw InputError(who + ": '" + path + "' " + not_regular);
    if (status.st_size > limit) throw InputError(who + ": '" + path + "' has more than " + std::to_string(limit) + " bytes");
    std::string text(static_cast<std::size_t>(status.st_size), '\0');
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t got = read(descriptor, &text[done], text.size() - done);
        if (got <= 0) throw InputError(who + ": cannot read '" + path + "'");
        done += static_cast<std::size_t>(got);
    }
    return text;
}

}  // namespace

ShardDocument read_shard_document(const std::string& path) {
    const Json document = Json::parse(read_regular_file(path, max_shard_bytes, "critical --merge"), nullptr, false);
    const std::string where = "critical --merge: '" + path + "': ";
    if (document.is_discarded()) throw InputError(where + "not JSON");
    try {
        if (document.at("command").get<std::string>() != "critical") throw InputError(where + "not a document of superpack critical");
        ShardDocument shard;
        shard.p_exact = document.at("p_exact").get<std::string>();
        shard.gap = document.at("gap").get<std::string>();
        shard.threshold = document.at("threshold");
        const Json& place = document.at("shard");
        if (place.at("top_level_boxes").get<long>() != top_level_boxes)
            throw InputError(where + "made with another domain (top_level_boxes is not " + std::to_string(top_level_boxes) + ")");
        ShardSummary& summary = shard.summary;
        summary.split = place.at("split").get<int>();
        if (summary.split < 0 || summary.split > max_split)
            throw InputError(where + "--split " + std::to_string(summary.split) + " is not 0 to " + std::to_string(max_split));
        const long start_boxes = static_cast<long>(top_level_boxes) << summary.split;
        summary.index = place.at("index").get<int>();
        summary.count = place.at("count").get<int>();
        if (summary.count < 1 || summary.count > start_boxes || summary.index < 0 || summary.index >= summary.count)
            throw InputError(where + "shard " + std::to_string(summary.index) + "/" + std::to_string(summary.count) +
                             " is not i/n with 0 <= i < n <= " + std::to_string(start_boxes));
        summary.proved = document.at("status").get<std::string>() == "proved";
        const Json& boxes = document.at("boxes");
        for (int r = 0; r < box_reasons; ++r) {
            summary.counts[r] = boxes.at(box_reason_name(static_cast<BoxReason>(r))).get<long>();
            if (summary.counts[r] < 0) throw InputError(where + "a negative count of boxes");
        }
        summary.processed = document.at("processed").get<long>();
        summary.start_boxes = document.at("start_boxes").get<long>();
        // Shard i/n holds the start boxes k = i mod n.
        const long expected = (start_boxes - summary.index + summary.count - 1) / summary.count;
        if (summary.start_boxes != expected)
            throw InputError(where + "shard " + std::to_string(summary.index) + "/" + std::to_string(summary.count) + " has " +
                             std::to_string(summary.start_boxes) + " start boxes, not " + std::to_string(expected));
        summary.seconds = document.at("seconds").get<double>();
        return shard;
    } catch (const Json::exception& error) {
        throw InputError(where + "not a shard of superpack critical (" + std::string(error.what()).substr(0, 120) + ")");
    }
}

CoverParts read_cover_parts(const std::vector<std::string>& paths, const std::string& cover, int split) {
    const std::string who = "critical --cover";
    const std::filesystem::path directory = std::filesystem::weakly_canonical(std::filesystem::absolute(cover).parent_path());
    // Every part is there before the first is parsed (each up to 256 MiB): a missing one fails at once.
    for (const std::string& path : paths) require_regular_file(path, who);
    CoverParts parts;
    long start_boxes = 0;
    for (const std::string& path : paths) {
        const std::string where = who + ": '" + path + "': ";
        if (std::filesystem::weakly_canonical(std::filesystem::absolute(path).parent_path()) != directory)
            throw InputError(where + "not in the directory of the cover certificate (--certificate), where the checker opens it");
        const Json document = Json::parse(read_regular_file(path, static_cast<long>(critical_certificate_bytes), who), nullptr, false);
        if (document.is_discarded()) throw InputError(where + "not JSON");
        try {
            const Json& claim = document.at("claim");
            if (claim.at("kind") != "critical-lattice" || claim.at("data").at("domain") != "boxes")
                throw InputError(where + "not a critical-lattice certificate of a shard (superpack critical --shard i/n --certificate)");
            const Json& data = claim.at("data");
            const Json& inputs = document.at("inputs");
            if (parts.names.empty()) {
                parts.p = data.at("p");
                parts.p_decimal = inputs.at("p_decimal");
                parts.gap = inputs.at("gap");
                parts.threshold = data.at("threshold");
                parts.volume = data.at("volume");
                parts.upper_phi = data.at("upper_phi");
            } else if (data.at("p") != parts.p || inputs.at("gap") != parts.gap || data.at("threshold") != parts.threshold) {
                throw InputError(where + "has another p, gap or T than '" + paths.front() + "'");
            }
            start_boxes += static_cast<long>(document.at("proof").at("boxes").size());
        } catch (const Json::exception& error) {
            throw InputError(where + "not a critical-lattice certificate (" + std::string(error.what()).substr(0, 120) + ")");
        }
        parts.names.push_back(std::filesystem::path(path).filename().string());
    }
    if (paths.empty()) throw InputError(who + ": no certificates given");
    parts.split = split;
    if (start_boxes < (static_cast<long>(top_level_boxes) << split))
        throw InputError(who + ": the files hold " + std::to_string(start_boxes) + " start boxes, fewer than the " +
                         std::to_string(static_cast<long>(top_level_boxes) << split) + " = " + std::to_string(top_level_boxes) +
                         " * 2^K of the domain at --split " + std::to_string(split) + ": some shard is missing");
    return parts;
}

}  // namespace superpack
