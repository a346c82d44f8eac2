#include "checker/core/json_reader.hpp"

#include <vector>

#include "checker/core/limits.hpp"

namespace superpack_checker {

namespace {

using Json = nlohmann::json;

// A path from its segments: keys joined by dots, array indices in brackets (claim.data.p,
// proof.cases[0]), as the checker names its steps.
std::string joined(const std::vector<std::string>& segments) {
    std::string path;
    for (const std::string& segment : segments) {
        if (!path.empty() && segment.front() != '[') path += '.';
        path += segment;
    }
    return path;
}

std::string values_message() {
    return "more than " + std::to_string(max_json_values) + " values (max_json_values)";
}

std::string depth_message() {
    return "nested deeper than " + std::to_string(max_json_depth) + " levels of arrays and objects (max_json_depth)";
}

// Builds the document as nlohmann's json_sax_dom_parser does, with the two refusals. `open_`
// holds the containers being filled (each the last value of its parent, so the pointers stay
// valid) and `segments_` the path to each.
class Builder final : public nlohmann::json_sax<Json> {
public:
    explicit Builder(JsonReading& reading) : reading_(reading) {}

    bool null() override { return add(Json(nullptr)); }
    bool boolean(bool value) override { return add(Json(value)); }
    bool number_integer(number_integer_t value) override { return add(Json(value)); }
    bool number_unsigned(number_unsigned_t value) override { return add(Json(value)); }
    bool number_float(number_float_t value, const string_t&) override { return add(Json(value)); }
    bool string(string_t& value) override { return add(Json(std::move(value))); }
    bool binary(binary_t& value) override { return add(Json::binary(std::move(value))); }
    bool start_object(std::size_t) override { return open(Json::object()); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& name) override {
        Json& object = *open_.back();
        if (object.contains(name)) {
            segments_.push_back(name);
            return fail("duplicate key \"" + name + "\" (a reader could see either value)");
        }
        key_ = name;
        member_ = &object[name];
        return true;
    }

    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override {
        return fail(std::string("not JSON: ") + error.what());
    }

private:
    bool fail(const std::string& message) {
        reading_.path = joined(segments_);
        reading_.message = message;
        return false;
    }

    // Places a value in the open container and returns it.
    Json* place(Json&& value) {
        if (open_.empty()) {
            reading_.document = std::move(value);
            return &reading_.document;
        }
        Json& parent = *open_.back();
        if (parent.is_array()) {
            parent.push_back(std::move(value));
            return &parent.back();
        }
        *member_ = std::move(value);
        return member_;
    }

    bool add(Json&& value) {
        if (++values_ > max_json_values) return fail(values_message());
        place(std::move(value));
        return true;
    }

    bool open(Json&& container) {
        if (!open_.empty()) {
            const Json& parent = *open_.back();
            segments_.push_back(parent.is_array() ? "[" + std::to_string(parent.size()) + "]" : key_);
        }
        if (open_.size() >= max_json_depth) return fail(depth_message());
        if (++values_ > max_json_values) return fail(values_message());
        open_.push_back(place(std::move(container)));
        return true;
    }

    bool close() {
        open_.pop_back();
        if (!open_.empty()) segments_.pop_back();
        return true;
    }

    JsonReading& reading_;
    std::vector<Json*> open_;
    std::vector<std::string> segments_;
    std::string key_;
    Json* member_ = nullptr;
    std::size_t values_ = 0;
};

template <class Input>
JsonReading read(Input&& input) {
    JsonReading reading;
    Builder builder(reading);
    reading.ok = Json::sax_parse(std::forward<Input>(input), &builder);
    if (!reading.ok) {
        reading.document = Json();
        if (reading.message.empty()) reading.message = "not JSON";
    }
    return reading;
}

}  // namespace

JsonReading read_json(const std::string& text) { return read(text); }
JsonReading read_json(std::istream& stream) { return read(stream); }

DepthExcess find_depth_excess(const Json& document) {
    // A depth-first walk with an explicit stack: one frame per open container, holding the
    // next child to visit, so that the walk itself cannot overflow the stack.
    struct Frame {
        const Json* container;
        Json::const_iterator next;
        std::size_t index;
    };
    std::vector<Frame> frames;
    std::vector<std::string> segments;
    if (!document.is_structured()) return {};
    frames.push_back({&document, document.cbegin(), 0});
    while (!frames.empty()) {
        Frame& frame = frames.back();
        if (frame.next == frame.container->cend()) {
            frames.pop_back();
            if (!frames.empty()) segments.pop_back();
            continue;
        }
        const Json& child = *frame.next;
        const std::string segment =
            frame.container->is_object() ? frame.next.key() : "[" + std::to_string(frame.index) + "]";
        ++frame.next;
        ++frame.index;
        if (!child.is_structured()) continue;
        segments.push_back(segment);
        if (frames.size() >= max_json_depth) return {true, joined(segments), depth_message()};
        frames.push_back({&child, child.cbegin(), 0});
    }
    return {};
}

}  // namespace superpack_checker
