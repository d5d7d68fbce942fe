#include <ptview/io/ImageIO.h>
#include "LimitedChild.h"
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace ptview {
namespace {

namespace fs = std::filesystem;

fs::path tempPath(const std::string& name) {
    return fs::temp_directory_path() / ("ptview_imageio_" + std::to_string(::getpid()) + "_" + name);
}

TEST(Pfm, RoundTripsAndStoresRowsBottomToTop) {
    ImageRgbF image(2, 2);
    image.set(0, 0, {1.0f, 0.0f, 0.0f}); // top row
    image.set(1, 0, {2.0f, 0.0f, 0.0f});
    image.set(0, 1, {0.0f, 0.0f, 3.0f}); // bottom row
    image.set(1, 1, {0.0f, 0.5f, 4.0f});
    fs::path path = tempPath("rows.pfm");
    writePfm(path, image);

    std::string bytes = testing::readFileBytes(path);
    const std::string header = "PF\n2 2\n-1.0\n";
    ASSERT_EQ(bytes.substr(0, header.size()), header);
    float firstStored[3];
    std::memcpy(firstStored, bytes.data() + header.size(), sizeof firstStored);
    EXPECT_EQ(firstStored[2], 3.0f) << "the first stored row must be the image's bottom row";

    ImageRgbF back = readPfm(path);
    EXPECT_EQ(back.width, 2);
    EXPECT_EQ(back.rgb, image.rgb);
    fs::remove(path);
}

TEST(Pfm, ReadsTheReferenceWithTopLeftOrigin) {
    // Block means quoted in shared/refs/README.md, rows and columns from the top-left.
    ImageRgbF reference = readPfm(PTVIEW_TEST_DATA_DIR "/cornell_reference.pfm");
    auto blockMean = [&](int y0, int y1, int x0, int x1) {
        glm::dvec3 sum(0.0);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) sum += glm::dvec3(reference.at(x, y));
        return sum / double((y1 - y0) * (x1 - x0));
    };
    glm::dvec3 backWall = blockMean(120, 136, 132, 148);
    EXPECT_NEAR(backWall.r, 0.2617, 5e-4);
    EXPECT_NEAR(backWall.g, 0.1929, 5e-4);
    glm::dvec3 leftWall = blockMean(120, 136, 30, 46);
    EXPECT_NEAR(leftWall.r, 0.2292, 5e-4);
    EXPECT_NEAR(leftWall.g, 0.0149, 5e-4);
    glm::dvec3 floor = blockMean(218, 234, 107, 123);
    EXPECT_NEAR(floor.r, 0.2421, 5e-4);
}

// readPfm reads the pixels a chunk (2^20 floats) at a time and then puts the rows top first: an
// image of several chunks, whose rows straddle the chunk boundaries, must come back as written.
TEST(Pfm, ImageOfSeveralReadChunksRoundTrips) {
    ImageRgbF image(700, 601); // 1 261 260 floats; an odd height leaves a middle row in place
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) image.set(x, y, {float(y), float(x), float(x + y * image.width)});
    fs::path path = tempPath("chunks.pfm");
    writePfm(path, image);
    ImageRgbF back = readPfm(path);
    EXPECT_EQ(back.width, image.width);
    EXPECT_EQ(back.height, image.height);
    EXPECT_TRUE(back.rgb == image.rgb);

    // One byte short, in the last chunk: refused, naming the file and the size the header claims.
    const std::string bytes = testing::readFileBytes(path);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes.substr(0, bytes.size() - 1);
    try {
        readPfm(path);
        ADD_FAILURE() << "read a truncated file";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()), path.string() + ": truncated PFM data (the header says 700x601 pixels)");
    }
    fs::remove(path);
}

TEST(Pfm, RejectsTruncatedAndForeignFiles) {
    fs::path path = tempPath("bad.pfm");
    std::ofstream(path, std::ios::binary) << "PF\n4 4\n-1.0\n" << std::string(10, '\0');
    EXPECT_THROW(readPfm(path), std::runtime_error);
    std::ofstream(path, std::ios::binary) << "P6\n4 4\n255\n";
    EXPECT_THROW(readPfm(path), std::runtime_error);
    fs::remove(path);
}

TEST(AtomicWrite, ReplacesWholeFileAndLeavesNoTemporary) {
    fs::path dir = tempPath("dir");
    fs::create_directories(dir);
    fs::path path = dir / "out.bin";
    std::ofstream(path) << "old contents that are longer";
    writeFileAtomically(path, "new");
    EXPECT_EQ(testing::readFileBytes(path), "new");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    fs::remove_all(dir);
}

TEST(AtomicWrite, FailureNamesTheFileAndCreatesNothing) {
    fs::path path = tempPath("missing_dir") / "out.png";
    try {
        writeFileAtomically(path, "x");
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos);
    }
    EXPECT_FALSE(fs::exists(path.parent_path()));
}

// A write cut short halfway (here by a file-size limit, as a full disk would) leaves the file that
// was there untouched and no temporary behind. The write runs in a child process so that the
// limit binds only there; the child handles SIGXFSZ as ptview's main does (that the real binary,
// signal disposition and all, survives the limit is CommandLineTest.FileSizeLimitIsAWriteErrorThatKeepsTheOldFile).
TEST(AtomicWrite, WriteCutShortLeavesTheOldFileWhole) {
    fs::path dir = tempPath("cut_short");
    fs::create_directories(dir);
    fs::path path = dir / "image.pfm";
    const std::string old = "the good file from before";
    std::ofstream(path, std::ios::binary) << old;
    const testing::ChildExit child = testing::runInLimitedChild(RLIMIT_FSIZE, 4096, [&] {
        reportFileSizeLimitAsWriteError(); // the write then fails with EFBIG instead of killing the child
        try {
            writeFileAtomically(path, std::string(1 << 20, 'x'));
        } catch (const std::runtime_error& error) {
            // The message names the file and says why.
            const std::string what = error.what();
            return what.find(path.string()) == 0 && what.find("write failed") != std::string::npos ? 0 : 2;
        }
        return 1; // no error: the limit did not bite
    });
    ASSERT_EQ(child.signal, 0);
    EXPECT_EQ(child.code, 0) << "1: the write did not fail, 2: the message did not name the file, 3: no limit";
    EXPECT_EQ(testing::readFileBytes(path), old);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "a temporary was left";
    fs::remove_all(dir);
}

// A symbolic link is written through: the file it names is replaced, beside itself, and the link
// stays; a chain of links and a link to a file not there yet are followed the same way.
TEST(AtomicWrite, SymbolicLinkIsWrittenThroughToTheFileItNames) {
    fs::path dir = tempPath("links");
    fs::remove_all(dir);
    fs::create_directories(dir / "real");
    std::ofstream(dir / "real" / "target.bin") << "old";
    fs::create_symlink("real/target.bin", dir / "link.bin");
    fs::create_symlink("link.bin", dir / "link_to_link.bin");
    fs::create_symlink(dir / "real" / "new.bin", dir / "dangling.bin");
    writeFileAtomically(dir / "link_to_link.bin", "new");
    writeFileAtomically(dir / "dangling.bin", "created");
    EXPECT_TRUE(fs::is_symlink(dir / "link.bin"));
    EXPECT_TRUE(fs::is_symlink(dir / "link_to_link.bin"));
    EXPECT_TRUE(fs::is_symlink(dir / "dangling.bin"));
    EXPECT_EQ(testing::readFileBytes(dir / "real" / "target.bin"), "new");
    EXPECT_EQ(testing::readFileBytes(dir / "real" / "new.bin"), "created");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir / "real"), fs::directory_iterator()), 2) << "a temporary was left";
    // A loop is an error naming the path, not a hang.
    fs::create_symlink("loop_b", dir / "loop_a");
    fs::create_symlink("loop_a", dir / "loop_b");
    try {
        writeFileAtomically(dir / "loop_a", "x");
        ADD_FAILURE() << "a loop of links was written";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir / "loop_a").string() + ": ", 0), 0u) << e.what();
    }
    fs::remove_all(dir);
}

} // namespace
} // namespace ptview
