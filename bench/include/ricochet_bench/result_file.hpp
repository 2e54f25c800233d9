// The benchmarks' result files (CSV, chart data, gnuplot scripts) are written whole or not at all: built
// in memory, then written aside and renamed by close() (ricochet::write_file_atomically), so that Ctrl-C,
// a full disk or a crash never leaves a torn one. A ResultFile never closed writes nothing.
#pragma once

#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "ricochet/scene_log.hpp"

namespace ricochet::bench {

class ResultFile {
public:
    explicit ResultFile(std::string path) : path_(std::move(path)) {}

    template <typename... T>
    void print(fmt::format_string<T...> format, T&&... args) {
        fmt::format_to(std::back_inserter(text_), format, std::forward<T>(args)...);
    }

    /// Writes the file; throws std::runtime_error naming it if it cannot be written.
    void close() {
        std::string error;
        if (!write_file_atomically(path_, text_, &error)) throw std::runtime_error(error);
    }

private:
    std::string path_;
    std::string text_;
};

}  // namespace ricochet::bench
