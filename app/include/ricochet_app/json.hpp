// The `--json` summaries (docs/cli-json.md) written as text: no JSON library is a dependency of the tree
// (Debian 12 here has no -dev package of one installed), and the documents are small and write-only, so a
// writer of a few lines with a correct string escaper does it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ricochet::app {

/// The version of every document's schema: the "schema" field, "ricochet-NAME/1" (docs/cli-json.md).
inline constexpr int k_json_schema_version = 1;

/// s as a JSON string, quotes included (RFC 8259): `"` `\` and control characters escaped, a byte that is
/// not part of valid UTF-8 replaced by U+FFFD (a path may hold any bytes; a JSON text may not).
std::string json_string(std::string_view s);

/// One JSON value written in order: objects, arrays, keys and scalars, commas put in between.
class JsonWriter {
public:
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
    /// The text so far, ended by a newline once the outermost value is closed.
    std::string str() const { return depth_.empty() ? out_ + "\n" : out_; }

private:
    void separate();
    std::string out_;
    std::vector<bool> depth_;  // per open container: whether it holds a value already
    bool after_key_ = false;
};

}  // namespace ricochet::app
