#include "checker/json_reader.hpp"

#include <set>
#include <vector>

namespace superpack_checker {

namespace {

// One open object or array, and where the parser stands in it.
struct Frame {
    bool object;
    std::set<std::string> keys;  // an object's keys so far
    std::string key;             // an object's current key
    long index = -1;             // an array's current element
};

std::string path_of(const std::vector<Frame>& frames) {
    std::string path;
    for (const Frame& frame : frames) {
        if (frame.object && !frame.key.empty()) path += (path.empty() ? "" : ".") + frame.key;
        if (!frame.object && frame.index >= 0) path += "[" + std::to_string(frame.index) + "]";
    }
    return path;
}

// A new element of the array the parser is in, if it is in one.
void count_element(std::vector<Frame>& frames) {
    if (!frames.empty() && !frames.back().object) ++frames.back().index;
}

}  // namespace

Json read_json(const std::string& text) {
    std::vector<Frame> frames;
    const Json::parser_callback_t track = [&frames](int, Json::parse_event_t event, Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start:
            case Json::parse_event_t::array_start:
                count_element(frames);
                frames.push_back(Frame{event == Json::parse_event_t::object_start, {}, {}});
                break;
            case Json::parse_event_t::key: {
                Frame& frame = frames.back();
                frame.key = parsed.get<std::string>();
                if (!frame.keys.insert(frame.key).second)
                    throw Rejection{Verdict::malformed, path_of(frames),
                                    "duplicate key \"" + frame.key.substr(0, 60) + "\": each key appears once in its object"};
                break;
            }
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end: frames.pop_back(); break;
            case Json::parse_event_t::value: count_element(frames); break;
        }
        return true;
    };
    return Json::parse(text, track);
}

}  // namespace superpack_checker
