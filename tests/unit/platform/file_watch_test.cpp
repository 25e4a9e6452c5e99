// FileWatch: a write, a replacement by rename and a removal of a watched file are seen; a
// change of another file of the folder is not.
#include "platform/file_watch.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <chrono>

namespace fs = std::filesystem;
using robottestingframework::platform::FileWatch;

namespace {
void write(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
}
}  // namespace

TEST(FileWatch, SeesWritesRenamesAndRemovalsOfItsFilesOnly) {
    const fs::path folder =
        fs::temp_directory_path() / ("rtf-file-watch-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    write(folder / "suite.xml", "a");
    write(folder / "other.txt", "a");
    FileWatch watch;
    std::string error;
    ASSERT_TRUE(watch.watch({(folder / "suite.xml").string()}, error)) << error;
    std::string changed;
    EXPECT_FALSE(watch.waitForChange(100, changed));

    write(folder / "other.txt", "bb");
    EXPECT_FALSE(watch.waitForChange(700, changed));

    write(folder / "suite.xml", "bb");
    ASSERT_TRUE(watch.waitForChange(2000, changed));
    EXPECT_EQ(fs::path(changed).filename(), "suite.xml");
    while (watch.waitForChange(700, changed)) {
    }

    write(folder / "new.xml", "ccc");
    fs::rename(folder / "new.xml", folder / "suite.xml");  // how editors save
    EXPECT_TRUE(watch.waitForChange(2000, changed));
    while (watch.waitForChange(700, changed)) {
    }

    fs::remove(folder / "suite.xml");
    EXPECT_TRUE(watch.waitForChange(2000, changed));
    fs::remove_all(folder);
}
