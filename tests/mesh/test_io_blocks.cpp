// Binary PLY read from the file in blocks (read_binary_ply_file) against the same bytes read whole
// (read_ply): the same soup or the same error message, on the corpus, on files larger than the
// read buffer with polygons straddling its edge, and on every truncation of such a file.
#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.h"
#include "mesh/io.h"
#include "mesh/read_soup.h"

namespace curvbench {
namespace {

namespace fs = std::filesystem;

/// "soup: V vertices, P polygons, ..." with every coordinate's bits and every polygon, or
/// "error: <message>"; "not taken" when read_binary_ply_file hands the file back.
std::string describe(const io_detail::Soup& s) {
  std::string d =
      "soup " + std::to_string(s.num_vertices()) + " " + std::to_string(s.num_polygons()) + ":";
  for (std::size_t i = 0; i < s.xyz.size(); ++i) {
    d.push_back(' ');
    d.append(std::to_string(std::bit_cast<std::uint64_t>(s.xyz[i])));
  }
  for (std::size_t f = 0; f < s.num_polygons(); ++f) {
    d.append(" |");
    for (std::size_t i = 0; i < s.polygon_size(f); ++i) {
      d.push_back(' ');
      d.append(std::to_string(s.indices[s.polygon_begin(f) + i]));
    }
  }
  return d;
}

std::string whole(const std::string& path) {
  try {
    return describe(io_detail::read_ply(path, read_file(path), false));
  } catch (const InputError& e) {
    return std::string("error: ") + e.what();
  }
}

std::string blocks(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) return "cannot open";
  std::string out;
  try {
    io_detail::Soup soup;
    out = io_detail::read_binary_ply_file(path, fd, fs::file_size(path), false, &soup)
              ? describe(soup)
              : "not taken";
  } catch (const InputError& e) {
    out = std::string("error: ") + e.what();
  }
  ::close(fd);
  return out;
}

void write(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

template <typename T>
void le(std::string& s, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
  s.append(b, sizeof(T));
}

TEST(MeshIoBlocks, CorpusFilesGiveTheSameSoupOrError) {
  const fs::path corpus = fs::path(CURVBENCH_SOURCE_DIR) / "tests" / "corpus";
  int taken = 0;
  for (const char* folder : {"ply", "regressions"})
    for (const auto& entry : fs::directory_iterator(corpus / folder)) {
      const std::string path = entry.path().string();
      if (entry.path().extension() != ".ply" || fs::file_size(path) == 0) continue;
      const std::string b = blocks(path);
      if (b == "not taken") continue;
      ++taken;
      EXPECT_EQ(b, whole(path)) << path;
    }
  EXPECT_GE(taken, 5);
}

// 60000 vertices of 5 doubles (2.4 MB, more than the 1 MiB buffer), polygons of 3 to 300
// vertices (a list crossing the buffer edge, one longer than a block of faces), then every
// truncation point near the ends of the buffer and of the file.
TEST(MeshIoBlocks, LargeFileAndItsTruncationsGiveTheSameSoupOrError) {
  const std::string dir =
      (fs::temp_directory_path() / ("cb_blocks_" + std::to_string(::getpid()))).string();
  fs::create_directories(dir);
  for (const bool packed : {false, true}) {
    const int n = 60000, m = 3000;
    std::string body;
    for (int v = 0; v < n; ++v) {
      le(body, 0.25 * v);
      le(body, -1.0 / (v + 1));
      if (!packed) le(body, 7.0);
      le(body, static_cast<double>(v % 17));
      if (!packed) le(body, 1e300);
    }
    for (int f = 0; f < m; ++f) {
      const int k = f == 1500 ? 300 : 3 + f % 4;
      le(body, static_cast<std::uint8_t>(k % 256));
      for (int i = 0; i < k % 256; ++i) le(body, static_cast<std::int32_t>((f * 7 + i * 13) % n));
    }
    const std::string header =
        std::string("ply\nformat binary_little_endian 1.0\nelement vertex ") + std::to_string(n) +
        "\nproperty double x\nproperty double y\n" + (packed ? "" : "property double w\n") +
        "property double z\n" + (packed ? "" : "property double q\n") + "element face " +
        std::to_string(m) + "\nproperty list uchar int vertex_indices\nend_header\n";
    const std::string file = header + body;
    const std::string path = dir + "/big.ply";
    write(path, file);
    const std::string b = blocks(path);
    ASSERT_EQ(b.rfind("soup ", 0), 0u) << b.substr(0, 200);
    EXPECT_EQ(b, whole(path));
    for (const std::size_t cut :
         {header.size() + 10, (std::size_t{1} << 20) - 3,
          (std::size_t{1} << 20) + header.size() + 5, file.size() - 1, file.size() - 7}) {
      write(path, file.substr(0, cut));
      const std::string c = blocks(path);
      EXPECT_EQ(c.rfind("error: ", 0), 0u) << cut;
      EXPECT_EQ(c, whole(path)) << cut;
    }
    write(path, file + "  \n x");
    EXPECT_EQ(blocks(path), whole(path));
    EXPECT_NE(blocks(path).find("bytes after the last element"), std::string::npos);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace curvbench
