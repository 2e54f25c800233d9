// `ricochet record LOG`: runs a log and writes its expect lines back, atomically. The log's other
// lines (comments included) are kept as they are; old expect lines are replaced.
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "commands.hpp"
#include "ricochet/format.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/record.hpp"
#include "ricochet/scene_log.hpp"

namespace ricochet::cli {

namespace {

/// The log's text without its `expect` lines (and without trailing blank lines).
std::string without_expect_lines(const std::string& text) {
    std::string out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const auto start = line.find_first_not_of(" \t");
        if (start != std::string::npos && line.compare(start, 6, "expect") == 0 &&
            (line.size() == start + 6 || line[start + 6] == ' ' || line[start + 6] == '\t'))
            continue;
        out += line;
        out += '\n';
    }
    while (out.size() >= 2 && out[out.size() - 1] == '\n' && out[out.size() - 2] == '\n') out.pop_back();
    return out;
}

}  // namespace

void register_record(CLI::App& app) {
    auto log = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand("record", "run a log and write its expect lines back (atomically)");
    sub->add_option("LOG", *log, "scene log")->required();
    sub->callback([log] {
        Scene scene = load_scene_or_exit(*log);
        const CheckedRun run = record_expectations(scene);
        if (run.error) {
            fmt::print(stderr, "{}: error: {}; the log is unchanged\n", *log, run.error->message());
            throw Exit{1};
        }
        std::ifstream in(*log, std::ios::binary);
        std::stringstream buffer;
        buffer << in.rdbuf();
        std::string text = without_expect_lines(buffer.str());
        // The expect lines exactly as the canonical writer prints them.
        Scene expects_only;
        expects_only.expect_hash = scene.expect_hash;
        expects_only.expect_failure = scene.expect_failure;
        expects_only.expect_states = scene.expect_states;
        const std::string canonical = write_scene_log(expects_only);
        const auto first_expect = canonical.find("expect ");
        if (first_expect != std::string::npos) text += canonical.substr(first_expect);
        std::string error;
        if (!write_file_atomically(*log, text, &error)) {
            fmt::print(stderr, "ricochet: error: {}\n", error);
            throw Exit{1};
        }
        write_stdout(fmt::format("recorded {}: hash {}, {} expect state line(s){}\n", *log, format_hash(run.hash),
                                 scene.expect_states.size(),
                                 run.failure ? fmt::format(", expect failure {} {} ({})", run.failure->check,
                                                           run.failure->frame, run.failure->message)
                                             : std::string()));
    });
}

}  // namespace ricochet::cli
