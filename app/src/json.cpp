// The `--json` writer (ricochet_app/json.hpp) over nlohmann-json.
#include "ricochet_app/json.hpp"

#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

namespace ricochet::app {

namespace {

using Json = nlohmann::ordered_json;

/// ASCII out (non-ASCII as \u escapes, DEL escaped too), ill-formed UTF-8 as U+FFFD, never an exception.
std::string dump(const Json& j) { return j.dump(-1, ' ', true, Json::error_handler_t::replace); }

}  // namespace

std::string valid_utf8(std::string_view s) {
    // Through a JSON string and back: the dump replaces each ill-formed sequence with U+FFFD.
    return Json::parse(Json(std::string(s)).dump(-1, ' ', false, Json::error_handler_t::replace)).get<std::string>();
}

/// The document so far, and the containers open in it (each inside the one before; the outermost first).
struct JsonWriter::Tree {
    Json root;
    std::vector<Json*> open;
    std::string key;
    bool closed = false;

    /// Puts v where the next value goes (the root, the open array's end, or the open object's key) and returns it.
    Json& put(Json v) {
        if (open.empty()) {
            root = std::move(v);
            closed = !root.is_structured();
            return root;
        }
        Json& top = *open.back();
        if (top.is_array()) {
            top.push_back(std::move(v));
            return top.back();
        }
        return top[key] = std::move(v);
    }
    void close() {
        open.pop_back();
        closed = open.empty();
    }
};

JsonWriter::JsonWriter() : tree_(std::make_unique<Tree>()) {}
JsonWriter::~JsonWriter() = default;

JsonWriter& JsonWriter::begin_object() {
    tree_->open.push_back(&tree_->put(Json::object()));
    return *this;
}

JsonWriter& JsonWriter::end_object() {
    tree_->close();
    return *this;
}

JsonWriter& JsonWriter::begin_array() {
    tree_->open.push_back(&tree_->put(Json::array()));
    return *this;
}

JsonWriter& JsonWriter::end_array() {
    tree_->close();
    return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
    tree_->key = std::string(name);
    return *this;
}

JsonWriter& JsonWriter::value(std::string_view s) {
    tree_->put(std::string(s));
    return *this;
}

JsonWriter& JsonWriter::value(bool b) {
    tree_->put(b);
    return *this;
}

JsonWriter& JsonWriter::value(std::int64_t n) {
    tree_->put(n);
    return *this;
}

JsonWriter& JsonWriter::value(std::uint64_t n) {
    tree_->put(n);
    return *this;
}

JsonWriter& JsonWriter::value(double x) {
    if (!std::isfinite(x)) return null();
    tree_->put(x);
    return *this;
}

JsonWriter& JsonWriter::null() {
    tree_->put(nullptr);
    return *this;
}

std::string JsonWriter::str() const { return tree_->closed ? dump(tree_->root) + "\n" : std::string(); }

}  // namespace ricochet::app
