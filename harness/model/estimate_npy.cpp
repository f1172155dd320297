#include "harness/model/estimate_npy.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "harness/model/estimate_columns.h"

namespace curvbench {

namespace {

static_assert(std::endian::native == std::endian::little, "the .npy writer writes '<' fields");

constexpr std::size_t kRecordsPerWrite = 8192;

}  // namespace

std::string EstimateNpyWriter::header(int vertices, std::span<const int> columns) {
  const std::span<const EstimateColumn> table = estimate_columns();
  std::string descr = "[('vertex', '<i4')";
  for (const int k : columns)
    descr += std::string(", ('") + table[static_cast<std::size_t>(k)].name + "', '" +
             (table[static_cast<std::size_t>(k)].integer ? "<i4" : "<f8") + "')";
  descr += "]";
  std::string dict = "{'descr': " + descr + ", 'fortran_order': False, 'shape': (" +
                     std::to_string(vertices) + ",), }";
  // Magic (6), version (2), length (2), then the dictionary padded with spaces and ended by a
  // newline so that the data starts at a multiple of 64 bytes.
  const std::size_t total = (10 + dict.size() + 1 + 63) / 64 * 64;
  dict.append(total - 10 - dict.size() - 1, ' ');
  dict += '\n';
  const auto len = static_cast<std::uint16_t>(dict.size());
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(len & 0xff);
  out += static_cast<char>(len >> 8);
  return out + dict;
}

EstimateNpyWriter::EstimateNpyWriter(const std::string& path, int vertices,
                                     std::span<const int> source, std::vector<int> columns)
    : file_(path),
      vertices_(vertices),
      source_(source),
      columns_(columns.empty() ? estimate_ply_columns() : std::move(columns)) {
  record_ = 4;
  for (const int k : columns_)
    record_ += estimate_columns()[static_cast<std::size_t>(k)].integer ? 4 : 8;
  file_.append(header(vertices_, columns_));
}

void EstimateNpyWriter::write(int first, std::span<const VertexEstimate> estimates) {
  if (first != written_ || estimates.size() > static_cast<std::size_t>(vertices_ - written_))
    throw std::logic_error("EstimateNpyWriter::write: blocks out of order or too many rows");
  const std::span<const EstimateColumn> table = estimate_columns();
  for (std::size_t i0 = 0; i0 < estimates.size(); i0 += kRecordsPerWrite) {
    const std::size_t rows = std::min(kRecordsPerWrite, estimates.size() - i0);
    buffer_.resize(rows * record_);
    char* p = buffer_.data();
    for (std::size_t i = i0; i < i0 + rows; ++i) {
      const VertexEstimate& e = estimates[i];
      const std::size_t v = static_cast<std::size_t>(first) + i;
      const std::int32_t index = source_.empty() ? static_cast<std::int32_t>(v) : source_[v];
      std::memcpy(p, &index, 4);
      p += 4;
      for (const int k : columns_) {
        const EstimateColumn& c = table[static_cast<std::size_t>(k)];
        if (c.integer) {
          const auto x = static_cast<std::int32_t>(c.value(e));
          std::memcpy(p, &x, 4);
          p += 4;
        } else {
          const double x = c.value(e);
          std::memcpy(p, &x, 8);
          p += 8;
        }
      }
    }
    file_.append(std::string_view(buffer_.data(), buffer_.size()));
  }
  written_ += static_cast<int>(estimates.size());
}

void EstimateNpyWriter::commit() {
  if (written_ != vertices_)
    throw std::logic_error("EstimateNpyWriter::commit: " + std::to_string(written_) + " of " +
                           std::to_string(vertices_) + " rows written");
  file_.commit();
}

}  // namespace curvbench
