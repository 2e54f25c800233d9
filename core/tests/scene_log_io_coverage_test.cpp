// Scene-log files on disk: what reading a folder or an oversized file says, and how an atomic save fails
// (a directory in the way, the file-size limit hit mid-write, a folder that cannot be created) without
// leaving anything behind.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <variant>

#include "ricochet/scene_log.hpp"

namespace ricochet {
namespace {

namespace fs = std::filesystem;

class SceneLogFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("ricochet-io-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    static std::string slurp(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }
    static void spit(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
    std::size_t entries() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {})); }
    static mode_t mode_of(const fs::path& p) {
        struct stat st {};
        EXPECT_EQ(::stat(p.c_str(), &st), 0);
        return st.st_mode & 07777;
    }
    fs::path dir_;
};

/// Limits the size of any file this process writes to `bytes` while alive: a write past it fails with
/// EFBIG (SIGXFSZ ignored meanwhile) instead of killing the process.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        ::getrlimit(RLIMIT_FSIZE, &saved_);
        old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit lim = saved_;
        lim.rlim_cur = bytes;
        ::setrlimit(RLIMIT_FSIZE, &lim);
    }
    ~FileSizeLimit() {
        ::setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, old_handler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit saved_{};
    void (*old_handler_)(int) = nullptr;
};

TEST_F(SceneLogFiles, ReadingAFolderSaysSo) {
    const auto r = read_scene_log(dir_);
    ASSERT_TRUE(std::holds_alternative<Diagnostic>(r));
    EXPECT_EQ(std::get<Diagnostic>(r).str(), dir_.string() + ":1:1: error: is a directory, not a scene log");
}

TEST_F(SceneLogFiles, AFileOneByteOverTheLimitIsRefusedBeforeParsing) {
    const fs::path p = dir_ / "big.scene";
    spit(p, std::string(k_max_file_size + 1, '#'));
    const auto r = read_scene_log(p);
    ASSERT_TRUE(std::holds_alternative<Diagnostic>(r));
    EXPECT_EQ(std::get<Diagnostic>(r).str(), p.string() + ":1:1: error: the file is over the limit of 16777216 bytes");
}

TEST_F(SceneLogFiles, AFileReadsBackTheSceneItWasWrittenFrom) {
    Scene s;
    s.kernel = KernelId::exact;
    s.frames = 3;
    s.walls = {{{0, 0}, {1, 0.5}}};
    s.balls = {{{0.25, -0.0}, {1e-300, 2}}};
    const fs::path p = dir_ / "a.scene";
    std::string error;
    ASSERT_TRUE(write_file_atomically(p, write_scene_log(s), &error)) << error;
    const auto r = read_scene_log(p);
    ASSERT_TRUE(std::holds_alternative<Scene>(r)) << std::get<Diagnostic>(r).str();
    EXPECT_TRUE(same_bits(std::get<Scene>(r), s));
}

TEST_F(SceneLogFiles, ANewFileIs0644AndAnOldOneKeepsItsBits) {
    const fs::path fresh = dir_ / "new.scene", old = dir_ / "old.scene";
    spit(old, "old\n");
    ASSERT_EQ(::chmod(old.c_str(), 0600), 0);
    std::string error;
    ASSERT_TRUE(write_file_atomically(fresh, "x\n", &error)) << error;
    ASSERT_TRUE(write_file_atomically(old, "y\n", &error)) << error;
    EXPECT_EQ(mode_of(fresh), 0644u);
    EXPECT_EQ(mode_of(old), 0600u);
    EXPECT_EQ(slurp(old), "y\n");
    EXPECT_EQ(entries(), 2u);
}

TEST_F(SceneLogFiles, AFolderInTheWayFailsTheRenameAndLeavesNoTemporaryFile) {
    // rename(2) of a file over a non-empty directory fails (EISDIR); the folder and its file stay.
    const fs::path p = dir_ / "a.scene";
    fs::create_directories(p);
    spit(p / "inside", "kept\n");
    std::string error;
    EXPECT_FALSE(write_file_atomically(p, "text\n", &error));
    EXPECT_EQ(error, p.string() + ": cannot rename the temporary file into place: Is a directory");
    EXPECT_EQ(entries(), 1u);
    EXPECT_EQ(slurp(p / "inside"), "kept\n");
}

TEST_F(SceneLogFiles, AWriteCutShortLeavesTheOldFileAndNoTemporaryFile) {
    // 11 bytes against a 4-byte limit: the first write(2) stores 4, the next fails with EFBIG.
    const fs::path p = dir_ / "a.scene";
    spit(p, "old\n");
    std::string error;
    bool ok = true;
    {
        FileSizeLimit limit(4);
        ok = write_file_atomically(p, "hello world", &error);
    }
    EXPECT_FALSE(ok);
    EXPECT_EQ(error, p.string() + ": cannot write the temporary file: File too large");
    EXPECT_EQ(slurp(p), "old\n");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(SceneLogFiles, ABareFileNameIsWrittenInTheCurrentFolder) {
    const fs::path cwd = fs::current_path();
    fs::current_path(dir_);
    std::string error;
    const bool ok = write_file_atomically("bare.scene", "bare\n", &error);
    fs::current_path(cwd);
    ASSERT_TRUE(ok) << error;
    EXPECT_EQ(slurp(dir_ / "bare.scene"), "bare\n");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(SceneLogFiles, FailuresWithoutAnErrorStringOnlyReturnFalse) {
    EXPECT_FALSE(write_file_atomically(dir_ / "missing" / "a.scene", "x", nullptr));
    spit(dir_ / "file", "");
    EXPECT_FALSE(save_scene_log_once(dir_ / "file" / "sub", "p", Scene{}, nullptr));
    EXPECT_EQ(entries(), 1u);
}

TEST_F(SceneLogFiles, SavingUnderAFileInsteadOfAFolderSaysWhy) {
    spit(dir_ / "file", "");
    std::string error;
    EXPECT_FALSE(save_scene_log_once(dir_ / "file" / "sub", "p", Scene{}, &error));
    EXPECT_EQ(error, (dir_ / "file" / "sub").string() + ": cannot create the folder: Not a directory");
}

TEST_F(SceneLogFiles, SavingOnceCreatesTheFolderAndAFailedSaveLeavesItEmpty) {
    const fs::path sub = dir_ / "a" / "b";
    Scene s;
    s.frames = 1;
    s.balls = {{{1, 2}, {3, 4}}};
    std::string error;
    {
        // The canonical text is longer than 8 bytes: the save fails and the folder stays empty.
        FileSizeLimit limit(8);
        EXPECT_FALSE(save_scene_log_once(sub, "case", s, &error));
    }
    EXPECT_NE(error.find(": cannot write the temporary file: File too large"), std::string::npos) << error;
    ASSERT_TRUE(fs::is_directory(sub));
    EXPECT_TRUE(fs::is_empty(sub));
    const auto saved = save_scene_log_once(sub, "case", s, &error);
    ASSERT_TRUE(saved) << error;
    EXPECT_TRUE(saved->is_new);
    EXPECT_EQ(saved->path, sub / ("case-" + scene_content_id(s) + ".scene"));
    EXPECT_EQ(slurp(saved->path), write_scene_log(s));
}

TEST_F(SceneLogFiles, AFolderNamedLikeALogIsNoSavedCase) {
    // Looking for a saved case, save_scene_log_once reads the regular *.scene files only: a folder
    // "x.scene" is passed over and the case is new.
    fs::create_directories(dir_ / "x.scene");
    Scene s;
    s.frames = 1;
    std::string error;
    const auto saved = save_scene_log_once(dir_, "case", s, &error);
    ASSERT_TRUE(saved) << error;
    EXPECT_TRUE(saved->is_new);
    EXPECT_EQ(saved->path, dir_ / ("case-" + scene_content_id(s) + ".scene"));
    EXPECT_EQ(entries(), 2u);
}

TEST_F(SceneLogFiles, SavingTextThatIsNoLogWithoutAnErrorStringOnlyReturnsNothing) {
    EXPECT_FALSE(save_scene_log_once(dir_, "p", std::string_view("not a log\n"), nullptr));
    std::string error;
    EXPECT_FALSE(save_scene_log_once(dir_, "p", std::string_view("not a log\n"), &error));
    EXPECT_EQ(error, "not a scene log: p-*.scene:1:1: error: expected the header 'ricochet 1' before 'not'");
    EXPECT_EQ(entries(), 0u);
}

}  // namespace
}  // namespace ricochet
