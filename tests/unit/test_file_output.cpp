// ocean::write_file: a file is written whole or not at all. The failures are real ones through the
// kernel: /dev/full (ENOSPC), a folder that is not there, a file where a folder should be, and a
// file size limit (setrlimit, EFBIG) standing in for a full disk.
#include "common/file_output.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <iterator>
#include <set>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

// A fresh empty folder of this test's own, removed afterwards.
class WriteFile : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("write_file_" + std::to_string(::getpid()) + "_" + test->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    static std::string read(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    // What the folder holds: a temporary file left behind shows up here.
    std::set<std::string> entries() const {
        std::set<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) names.insert(entry.path().filename().string());
        return names;
    }

    fs::path dir_;
};

// Writes past `kilobytes` fail with EFBIG (SIGXFSZ ignored) while it lives, as on a full disk.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t kilobytes) {
        getrlimit(RLIMIT_FSIZE, &saved_);
        old_handler_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = saved_;
        limit.rlim_cur = kilobytes * 1024;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, old_handler_);
    }

private:
    rlimit saved_{};
    void (*old_handler_)(int) = nullptr;
};

TEST_F(WriteFile, WritesTheBytesAndNothingElse) {
    const std::string bytes("a\0b\n", 4);
    EXPECT_EQ(ocean::write_file(dir_ / "out.bin", bytes), std::nullopt);
    EXPECT_EQ(read(dir_ / "out.bin"), bytes);
    EXPECT_EQ(entries(), std::set<std::string>{"out.bin"});
}

TEST_F(WriteFile, ReplacesAnOlderFileAndKeepsItsMode) {
    std::ofstream(dir_ / "preset") << "old";
    fs::permissions(dir_ / "preset", fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(ocean::write_file(dir_ / "preset", "new"), std::nullopt);
    EXPECT_EQ(read(dir_ / "preset"), "new");
    EXPECT_EQ(fs::status(dir_ / "preset").permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(entries(), std::set<std::string>{"preset"});
}

TEST_F(WriteFile, ANewFileGetsTheUmasksPermissions) {
    const mode_t mask = ::umask(027);
    const auto error = ocean::write_file(dir_ / "shot.png", "png");
    ::umask(mask);
    EXPECT_EQ(error, std::nullopt);
    EXPECT_EQ(fs::status(dir_ / "shot.png").permissions() & fs::perms::all, fs::perms(0640));
}

TEST_F(WriteFile, WritesThroughASymbolicLinkAndKeepsTheLink) {
    std::ofstream(dir_ / "real.preset") << "old";
    fs::create_symlink("real.preset", dir_ / "link.preset");
    EXPECT_EQ(ocean::write_file(dir_ / "link.preset", "new"), std::nullopt);
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.preset"));
    EXPECT_EQ(read(dir_ / "real.preset"), "new");
}

// /dev/full through a link in our own folder: a writer that renamed over its target would replace
// the link (and fail this test) rather than the device.
TEST_F(WriteFile, AFullDeviceIsAnErrorAndStaysADevice) {
    fs::create_symlink("/dev/full", dir_ / "full");
    const auto error = ocean::write_file(dir_ / "full", "some bytes");
    ASSERT_TRUE(error);
    EXPECT_EQ(*error, "cannot write '" + (dir_ / "full").string() + "': No space left on device");
    EXPECT_TRUE(fs::is_symlink(dir_ / "full"));
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
    EXPECT_EQ(entries(), std::set<std::string>{"full"});
}

TEST_F(WriteFile, AMissingFolderIsAnErrorNamingTheFile) {
    const fs::path path = dir_ / "no_such_folder" / "x.txt";
    const auto error = ocean::write_file(path, "x");
    ASSERT_TRUE(error);
    EXPECT_EQ(*error, "cannot write '" + path.string() + "': No such file or directory");
    EXPECT_TRUE(entries().empty());
}

TEST_F(WriteFile, AFileWhereAFolderShouldBeIsAnError) {
    std::ofstream(dir_ / "some_file") << "x";
    const auto error = ocean::write_file(dir_ / "some_file" / "sub", "x", "preset");
    ASSERT_TRUE(error);
    EXPECT_EQ(*error, "cannot write preset '" + (dir_ / "some_file" / "sub").string() + "': Not a directory");
}

TEST_F(WriteFile, AFailedWriteLeavesTheOlderFileAsItWasAndNoTemporaryFile) {
    std::ofstream(dir_ / "export.txt") << "the good export";
    std::optional<std::string> error;
    {
        const FileSizeLimit full_disk(1);
        error = ocean::write_file(dir_ / "export.txt", std::string(4096, 'x'));
    }
    ASSERT_TRUE(error);
    EXPECT_EQ(*error, "cannot write '" + (dir_ / "export.txt").string() + "': File too large");
    EXPECT_EQ(read(dir_ / "export.txt"), "the good export");
    EXPECT_EQ(entries(), std::set<std::string>{"export.txt"});
}

TEST_F(WriteFile, AFailedWriteOfANewFileLeavesNothing) {
    std::optional<std::string> error;
    {
        const FileSizeLimit full_disk(1);
        error = ocean::write_file(dir_ / "height.pfm", std::string(4096, 'x'));
    }
    ASSERT_TRUE(error);
    EXPECT_TRUE(entries().empty());
}

}  // namespace
