// The atomic file writer (core/atomic_file.h): content lands under the target name only at
// commit(), a failure or an uncommitted writer leaves nothing, concurrent writers of one path
// get distinct temporaries, and errors name the target.
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/errors.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("curvbench_atomic_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  fs::path dir_;
};

TEST_F(AtomicFileTest, ContentAppearsOnlyAtCommitAndReplacesTheOldFile) {
  const std::string path = (dir_ / "out.csv").string();
  std::ofstream(path) << "old";
  {
    AtomicFile file(path);
    EXPECT_EQ(file.temporary(), temp_path(path));
    file.buffer() += "a,b\n";
    file.append(std::string(3u << 20, 'x'));  // beyond the buffer: written straight through
    file.buffer() += "end\n";
    EXPECT_EQ(slurp(path), "old");
    file.commit();
  }
  EXPECT_EQ(slurp(path), "a,b\n" + std::string(3u << 20, 'x') + "end\n");
  EXPECT_EQ(listing(), std::vector<std::string>{"out.csv"});
}

TEST_F(AtomicFileTest, BackgroundBlocksKeepTheirPlaceAndComeBackForReuse) {
  const std::string path = (dir_ / "blocks.csv").string();
  {
    AtomicFile file(path);
    file.buffer() += "header\n";
    std::string block(4u << 20, 'a');
    std::string back = file.append_in_background(std::move(block), 3);  // "aaa"
    EXPECT_TRUE(back.empty());
    file.buffer() += "|";  // waits for the block in flight, then goes after it
    back = file.append_in_background(std::string(2u << 20, 'b'), 2u << 20);
    EXPECT_EQ(back.size(), 4u << 20);  // the first block's buffer, whole, for the next one
    EXPECT_EQ(back.front(), 'a');
    back.assign("cc-not-this");
    file.append_in_background(std::move(back), 2);  // "cc"
    EXPECT_EQ(slurp(path), "");
    file.commit();
  }
  EXPECT_EQ(slurp(path), "header\naaa|" + std::string(2u << 20, 'b') + "cc");
  EXPECT_EQ(listing(), std::vector<std::string>{"blocks.csv"});
}

TEST_F(AtomicFileTest, AWriterDestroyedWithABlockInFlightLeavesNothing) {
  const std::string path = (dir_ / "inflight.csv").string();
  {
    AtomicFile file(path);
    file.append_in_background(std::string(8u << 20, 'x'), 8u << 20);
  }
  EXPECT_TRUE(listing().empty());
}

TEST_F(AtomicFileTest, AnUncommittedWriterLeavesNothing) {
  const std::string path = (dir_ / "out.ply").string();
  try {
    AtomicFile file(path);
    file.buffer() += "partial";
    throw std::runtime_error("failure while writing");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(listing().empty());
}

TEST_F(AtomicFileTest, TwoWritersOfOnePathUseDistinctTemporariesAndTheLastCommitWins) {
  const std::string path = (dir_ / "t.md").string();
  AtomicFile a(path), b(path);
  EXPECT_NE(a.temporary(), b.temporary());
  EXPECT_EQ(b.temporary(), path + ".1.tmp." + std::to_string(::getpid()));
  a.buffer() += "a";
  b.buffer() += "b";
  a.commit();
  b.commit();
  EXPECT_EQ(slurp(path), "b");
  EXPECT_EQ(listing(), std::vector<std::string>{"t.md"});
}

TEST_F(AtomicFileTest, ATemporaryWrittenByOtherCodeIsRenamedIntoPlace) {
  const std::string path = (dir_ / "plot.png").string();
  AtomicFile file(path);
  std::ofstream(file.temporary(), std::ios::binary) << "image";
  file.commit();
  EXPECT_EQ(slurp(path), "image");
}

TEST_F(AtomicFileTest, WriteFileAtomicCreatesTheFolder) {
  const fs::path path = dir_ / "a" / "b" / "c.csv";
  write_file_atomic(path.string(), "x\n");
  EXPECT_EQ(slurp(path), "x\n");
}

TEST_F(AtomicFileTest, ErrorsNameTheTarget) {
  const auto expect_error = [](const std::string& path, const std::string& part) {
    try {
      AtomicFile file(path);
      ADD_FAILURE() << "no InputError for " << path;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
      EXPECT_NE(msg.find(part), std::string::npos) << msg;
    }
  };
  expect_error(dir_.string(), "is a directory");
  expect_error((dir_ / "missing" / "x.csv").string(), "does not exist");
  expect_error((dir_.string() + "/"), "not a file name");
  EXPECT_TRUE(listing().empty());
}

}  // namespace
}  // namespace curvbench
