// grammar_agreement [--reject-at LINE] PATH...: the parser target's grammar oracle (agreement.hpp) on fixed
// inputs. Every file named, and every file under every folder named (sorted), is read by parse_scene_log
// and by the independent acceptor; each must get the same verdict (with --reject-at: both reject, at
// LINE). Prints one line per input and a summary; exit 0 if all agree, 1 if some do not, 2 on bad usage.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "grammar/agreement.hpp"
#include "ricochet/scene_log.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    int reject_at = 0;
    std::vector<fs::path> inputs;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--reject-at" && i + 1 < argc) {
            reject_at = std::atoi(argv[++i]);
            if (reject_at < 1) {
                fmt::print(stderr, "grammar_agreement: --reject-at needs a line ≥ 1\n");
                return 2;
            }
        } else if (fs::is_directory(arg)) {
            std::vector<fs::path> files;
            for (const auto& e : fs::recursive_directory_iterator(arg))
                if (e.is_regular_file()) files.push_back(e.path());
            std::sort(files.begin(), files.end());
            inputs.insert(inputs.end(), files.begin(), files.end());
        } else if (fs::is_regular_file(arg)) {
            inputs.emplace_back(arg);
        } else {
            fmt::print(stderr, "grammar_agreement: no such file or folder: {}\n", arg);
            return 2;
        }
    }
    if (inputs.empty()) {
        fmt::print(stderr, "usage: grammar_agreement [--reject-at LINE] PATH...\n");
        return 2;
    }
    int accepted = 0, rejected = 0, failed = 0;
    for (const fs::path& path : inputs) {
        std::ifstream in(path, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const auto c = ricochet_grammar::compare(text, ricochet::parse_scene_log(text, path.string()));
        bool bad = ricochet_grammar::fails(c);
        std::string why = bad ? ricochet_grammar::report(c) : std::string();
        if (!bad && reject_at > 0 && (c.reader.accepted || c.acceptor.accepted || c.reader.line != reject_at ||
                                      c.acceptor.line != reject_at)) {
            bad = true;
            why = fmt::format("expected both to reject at line {}\n  reader:   {}\n  acceptor: {}", reject_at,
                              ricochet_grammar::describe(c.reader), ricochet_grammar::describe(c.acceptor));
        }
        if (bad) {
            ++failed;
            fmt::print("FAIL {}: {}\n", path.string(), why);
        } else {
            (c.reader.accepted ? accepted : rejected) += 1;
            fmt::print("ok {}: both {}\n", path.string(),
                       c.reader.accepted ? std::string("accept") : fmt::format("reject at line {}", c.reader.line));
        }
    }
    fmt::print("grammar agreement: {} inputs, {} accepted by both, {} rejected by both at the same line, {} failed\n",
               inputs.size(), accepted, rejected, failed);
    return failed == 0 ? 0 : 1;
}
