// Checked standard output (output.hpp).
#include "output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

namespace ricochet::cli {

void write_stdout(std::string_view text) {
    errno = 0;
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size()) throw OutputError{errno};
}

void check_stdout() {
    if (std::ferror(stdout)) throw OutputError{errno};
}

int report_output_error(int err) {
    fmt::print(stderr, "ricochet: error: writing standard output: {}\n", err != 0 ? std::strerror(err) : "a write failed");
    return 1;
}

int finish_stdout(int exit_code) {
    errno = 0;
    // A buffered write fails only here, at the flush; the error flag keeps an earlier failure.
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) return report_output_error(errno);
    return exit_code;
}

}  // namespace ricochet::cli
