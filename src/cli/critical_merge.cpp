#include "critical_merge.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>

namespace superpack::cli {

namespace {

// The file's text: a regular file (no symlink followed, no device or FIFO read) of at most
// max_shard_bytes.
std::string read_regular_file(const std::string& path) {
    const int descriptor = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (descriptor < 0) throw InputError("critical --merge: cannot open '" + path + "': " + std::strerror(errno));
    const std::unique_ptr<int, void (*)(int*)> closer(new int(descriptor), [](int* d) { close(*d); delete d; });
    struct stat status {};
    if (fstat(descriptor, &status) != 0 || !S_ISREG(status.st_mode))
        throw InputError("critical --merge: '" + path + "' is not a regular file");
    if (status.st_size > max_shard_bytes)
        throw InputError("critical --merge: '" + path + "' has more than " + std::to_string(max_shard_bytes) + " bytes");
    std::string text(static_cast<std::size_t>(status.st_size), '\0');
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t got = read(descriptor, &text[done], text.size() - done);
        if (got <= 0) throw InputError("critical --merge: cannot read '" + path + "'");
        done += static_cast<std::size_t>(got);
    }
    return text;
}

}  // namespace

ShardDocument read_shard_document(const std::string& path) {
    const Json document = Json::parse(read_regular_file(path), nullptr, false);
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
        summary.index = place.at("index").get<int>();
        summary.count = place.at("count").get<int>();
        if (summary.count < 1 || summary.count > top_level_boxes || summary.index < 0 || summary.index >= summary.count)
            throw InputError(where + "shard " + std::to_string(summary.index) + "/" + std::to_string(summary.count) +
                             " is not i/n with 0 <= i < n <= " + std::to_string(top_level_boxes));
        summary.proved = document.at("status").get<std::string>() == "proved";
        const Json& boxes = document.at("boxes");
        for (int r = 0; r < box_reasons; ++r) {
            summary.counts[r] = boxes.at(box_reason_name(static_cast<BoxReason>(r))).get<long>();
            if (summary.counts[r] < 0) throw InputError(where + "a negative count of boxes");
        }
        summary.processed = document.at("processed").get<long>();
        summary.start_boxes = document.at("start_boxes").get<long>();
        // Shard i/n holds the top-level boxes k = i mod n.
        const long expected = (top_level_boxes - summary.index + summary.count - 1) / summary.count;
        if (summary.start_boxes != expected)
            throw InputError(where + "shard " + std::to_string(summary.index) + "/" + std::to_string(summary.count) + " has " +
                             std::to_string(summary.start_boxes) + " top-level boxes, not " + std::to_string(expected));
        summary.seconds = document.at("seconds").get<double>();
        return shard;
    } catch (const Json::exception& error) {
        throw InputError(where + "not a shard of superpack critical (" + std::string(error.what()).substr(0, 120) + ")");
    }
}

}  // namespace superpack::cli
