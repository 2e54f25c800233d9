// The `--json` summaries (docs/cli-json.md), built in order through nlohmann-json (an ordered_json tree, so
// members keep the order they were written in) and dumped as ASCII: a byte that is not part of valid UTF-8
// becomes U+FFFD (a path may hold any bytes; a JSON text may not), every other character that is not ASCII a
// \u escape.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace ricochet::app {

/// The version of every document's schema: the "schema" field, "ricochet-NAME/1" (docs/cli-json.md).
inline constexpr int k_json_schema_version = 1;

/// s with every ill-formed UTF-8 sequence replaced by U+FFFD: text any UTF-8 document (JSON, XML) may hold.
std::string valid_utf8(std::string_view s);

/// One JSON value written in order: objects, arrays, keys and scalars.
class JsonWriter {
public:
    JsonWriter();
    ~JsonWriter();
    JsonWriter(const JsonWriter&) = delete;
    JsonWriter& operator=(const JsonWriter&) = delete;

    /// `{`, `}`, `[`, `]`.
    JsonWriter& begin_object();
    JsonWriter& end_object();
    JsonWriter& begin_array();
    JsonWriter& end_array();
    /// The next member's name (inside an object).
    JsonWriter& key(std::string_view name);
    /// Scalars. A double that is not finite is written as null (JSON has no NaN or infinity).
    JsonWriter& value(std::string_view s);
    JsonWriter& value(const char* s) { return value(std::string_view(s)); }
    JsonWriter& value(const std::string& s) { return value(std::string_view(s)); }
    JsonWriter& value(bool b);
    JsonWriter& value(std::int64_t n);
    JsonWriter& value(std::uint64_t n);
    JsonWriter& value(int n) { return value(static_cast<std::int64_t>(n)); }
    JsonWriter& value(double x);
    JsonWriter& null();
    /// key(name) then value(v).
    template <class T>
    JsonWriter& member(std::string_view name, const T& v) {
        key(name);
        return value(v);
    }
    /// The document, ended by a newline, once the outermost value is closed; empty before.
    std::string str() const;

private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
};

}  // namespace ricochet::app
