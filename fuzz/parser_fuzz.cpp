// Fuzz target `parser`: arbitrary bytes into the scene-log reader.
// Oracles (besides ASan/UBSan/leaks/timeouts):
// - grammar: the reader accepts the text iff the independent acceptor of docs/scene-log.md
//   (grammar/acceptor.hpp) does, and when both reject they name the same line (grammar/agreement.hpp);
//   the same for the writer's text of an accepted log;
// - a rejected log names a place (line and column ≥ 1) and a reason;
// - an accepted log round-trips: write(read(text)) reads back to the same scene bit for bit (same_bits,
//   so −0 and +0 differ), and writing that again gives the same text.
// None is a `check` a log can name, so a failure here saves no log: the input itself is the reproducer.
// Under libFuzzer a mutator of its own (below) also puts the grammar's edge values in place of whole tokens.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include <fmt/core.h>

#include "fuzz_common.hpp"
#include "grammar/agreement.hpp"
#include "ricochet/scene_log.hpp"
#include "token_mutator.hpp"

namespace {

[[noreturn]] void parser_failed(std::string_view check, std::string_view kind, const std::string& what,
                                std::string_view input) {
    fmt::print(stderr, "{} target=parser kernel=none check={} frame=0 kind={}\n  {}\n  input ({} bytes):\n{}\n",
               ricochet::fuzz::k_failure_tag, check, kind, what, input.size(), input.substr(0, 2000));
    std::fflush(stderr);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ricochet;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const SceneOrDiagnostic first = parse_scene_log(text, "input");
    if (const auto c = ricochet_grammar::compare(text, first); ricochet_grammar::fails(c))
        parser_failed("grammar", "grammar", ricochet_grammar::report(c), text);
    if (const auto* d = std::get_if<Diagnostic>(&first)) {
        if (d->line < 1 || d->col < 1 || d->message.empty())
            parser_failed("round-trip", "diagnostic", fmt::format("a rejection without a place or reason: {}", d->str()),
                          text);
        return 0;
    }
    const Scene& scene = std::get<Scene>(first);
    const std::string written = write_scene_log(scene);
    const SceneOrDiagnostic second = parse_scene_log(written, "written");
    if (const auto* d = std::get_if<Diagnostic>(&second))
        parser_failed("round-trip", "reread",
                      fmt::format("the writer's own text is rejected: {}\n--- written ---\n{}", d->str(), written), text);
    // The canonical text is a scene log by the spec too.
    if (const auto c = ricochet_grammar::compare(written, second); ricochet_grammar::fails(c))
        parser_failed("grammar", "grammar-written", fmt::format("{}\n--- written ---\n{}", ricochet_grammar::report(c), written),
                      text);
    const Scene& back = std::get<Scene>(second);
    if (!same_bits(scene, back))
        parser_failed("round-trip", "round-trip", fmt::format("read(write(s)) differs from s\n--- written ---\n{}", written),
                      text);
    if (write_scene_log(back) != written)
        parser_failed("round-trip", "rewrite",
                      fmt::format("writing the re-read scene gives different text\n--- first ---\n{}", written), text);
    return 0;
}

#ifdef RICOCHET_FUZZ_LIBFUZZER
extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

// One mutation in four sets an edge of the grammar as a whole token (token_mutator.hpp); the others are libFuzzer's
// own, the dictionary (parser.dict) included.
extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
    if (const std::size_t n = ricochet::fuzz::replace_token(data, size, max_size, seed)) return n;
    return LLVMFuzzerMutate(data, size, max_size);
}
#endif
