// A stand-in for libFuzzer's main, for compilers without -fsanitize=fuzzer: runs
// LLVMFuzzerTestOneInput once on every file named on the command line, and on every file under
// every folder named (sorted, so runs are reproducible). Flags (arguments starting with '-') are
// ignored, so a libFuzzer command line still works. Exit 0 if every input ran; an oracle failure
// aborts, as under libFuzzer.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

int run_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "%s: error: cannot read\n", path.c_str());
        return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Copy into an exactly sized heap buffer, as libFuzzer does, so that ASan sees overreads.
    std::vector<std::uint8_t> data(bytes.begin(), bytes.end());
    LLVMFuzzerTestOneInput(data.data(), data.size());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    namespace fs = std::filesystem;
    int errors = 0;
    std::size_t ran = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.starts_with("-")) continue;
        std::error_code ec;
        if (fs::is_directory(arg, ec)) {
            std::vector<fs::path> files;
            for (const auto& entry : fs::recursive_directory_iterator(arg))
                if (entry.is_regular_file()) files.push_back(entry.path());
            std::sort(files.begin(), files.end());
            for (const auto& f : files) {
                errors += run_file(f);
                ++ran;
            }
        } else {
            errors += run_file(arg);
            ++ran;
        }
    }
    std::fprintf(stderr, "standalone fuzz driver (not libFuzzer): ran %zu inputs, %d unreadable\n", ran, errors);
    return errors == 0 ? 0 : 1;
}
