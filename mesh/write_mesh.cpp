// The mesh writers (contract in io.h): OFF, PLY (whole or streamed vertex block by block with
// PlyWriter) and the write_mesh dispatcher. Every file goes through the project's atomic file
// writer (core/atomic_file.h): a temporary file in the target directory renamed into place, so a
// failure never leaves a partial file behind.
#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/text.h"
#include "mesh/io.h"

namespace curvbench {

namespace {

/// Appends `v` as "%.17g" would print it in the C locale.
void append_double(std::string& out, double v) {
  char buf[32];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::general, 17);
  out.append(buf, ptr);
}

template <typename T>
void append_le(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

/// One value per vertex in every property (names and values are checked by PlyWriter).
void check_properties(const Mesh& mesh, const std::vector<VertexProperty>& properties) {
  for (const VertexProperty& p : properties)
    if (p.values.size() != static_cast<std::size_t>(mesh.num_vertices()))
      throw UsageError("vertex property '" + p.name + "' has " + std::to_string(p.values.size()) +
                       " values for " + std::to_string(mesh.num_vertices()) + " vertices");
}

void check_comments(const std::vector<std::string>& comments) {
  for (const std::string& c : comments)
    if (c.find_first_of("\r\n") != std::string::npos)
      throw UsageError("file comment '" + c + "' is not a single line");
}

}  // namespace

void write_off(const std::string& path, const Mesh& mesh,
               const std::vector<std::string>& comments) {
  check_comments(comments);
  AtomicFile file(path);
  file.buffer() += "OFF\n";
  for (const std::string& c : comments) file.buffer() += "# " + c + "\n";
  file.buffer() +=
      std::to_string(mesh.num_vertices()) + " " + std::to_string(mesh.num_faces()) + " 0\n";
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    std::string& out = file.buffer();
    for (int c = 0; c < 3; ++c) {
      append_double(out, mesh.vertices()(v, c));
      out += c < 2 ? ' ' : '\n';
    }
  }
  for (int f = 0; f < mesh.num_faces(); ++f)
    file.buffer() += "3 " + std::to_string(mesh.face_vertex(f, 0)) + " " +
                     std::to_string(mesh.face_vertex(f, 1)) + " " +
                     std::to_string(mesh.face_vertex(f, 2)) + "\n";
  file.commit();
}

struct PlyWriter::Impl {
  AtomicFile file;
  const Mesh& mesh;
  std::vector<Property> properties;
  int written = 0;

  Impl(const std::string& path, const Mesh& m, std::vector<Property> p)
      : file(path), mesh(m), properties(std::move(p)) {}
};

PlyWriter::PlyWriter(const std::string& path, const Mesh& mesh, std::vector<Property> properties,
                     const std::vector<std::string>& comments) {
  std::vector<std::string> names = {"x", "y", "z"};
  for (const Property& p : properties) {
    if (p.name.empty() ||
        std::any_of(p.name.begin(), p.name.end(), [](char c) { return c <= ' ' || c >= 0x7f; }))
      throw UsageError("vertex property name '" + p.name + "' is empty or not a printable word");
    if (std::find(names.begin(), names.end(), p.name) != names.end())
      throw UsageError("vertex property '" + p.name + "' given twice (or clashes with x/y/z)");
    names.push_back(p.name);
  }
  check_comments(comments);
  impl_ = std::make_unique<Impl>(path, mesh, std::move(properties));
  std::string& header = impl_->file.buffer();
  header += "ply\nformat binary_little_endian 1.0\ncomment written by curvbench\n";
  for (const std::string& c : comments) header += "comment " + c + "\n";
  header += "element vertex " + std::to_string(mesh.num_vertices()) + "\n";
  header += "property double x\nproperty double y\nproperty double z\n";
  for (const Property& p : impl_->properties)
    header += std::string("property ") + (p.integer ? "int " : "double ") + p.name + "\n";
  header += "element face " + std::to_string(mesh.num_faces()) + "\n";
  header += "property list uchar int vertex_indices\nend_header\n";
}

PlyWriter::~PlyWriter() = default;

void PlyWriter::write_vertices(int first, int count, const double* values) {
  Impl& w = *impl_;
  if (first != w.written || count < 0 || first + count > w.mesh.num_vertices())
    throw std::logic_error("PlyWriter::write_vertices: vertices out of order");
  const std::size_t P = w.properties.size();
  for (int i = 0; i < count; ++i) {
    const double* row = values + static_cast<std::size_t>(i) * P;
    for (std::size_t p = 0; p < P; ++p) {
      const double x = row[p];
      if (w.properties[p].integer &&
          !(x >= std::numeric_limits<std::int32_t>::min() &&
            x <= std::numeric_limits<std::int32_t>::max() && std::trunc(x) == x))
        throw UsageError("integer vertex property '" + w.properties[p].name + "' has value " +
                         std::to_string(x) + " at vertex " + std::to_string(first + i) +
                         ", not a 32-bit integer");
    }
  }
  const std::size_t record = 24 + [&] {
    std::size_t bytes = 0;
    for (const Property& p : w.properties) bytes += p.integer ? 4 : 8;
    return bytes;
  }();
  std::string block;
  block.reserve(record * static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const int v = first + i;
    for (int c = 0; c < 3; ++c) append_le(block, w.mesh.vertices()(v, c));
    const double* row = values + static_cast<std::size_t>(i) * P;
    for (std::size_t p = 0; p < P; ++p) {
      if (w.properties[p].integer)
        append_le(block, static_cast<std::int32_t>(row[p]));
      else
        append_le(block, row[p]);
    }
  }
  w.file.append(block);
  w.written += count;
}

void PlyWriter::commit() {
  Impl& w = *impl_;
  if (w.written != w.mesh.num_vertices())
    throw std::logic_error("PlyWriter::commit: " + std::to_string(w.written) + " of " +
                           std::to_string(w.mesh.num_vertices()) + " vertices written");
  std::string block;
  const int m = w.mesh.num_faces();
  constexpr int kFaces = 1 << 16;
  for (int f0 = 0; f0 < m; f0 += kFaces) {
    block.clear();
    for (int f = f0; f < std::min(m, f0 + kFaces); ++f) {
      append_le(block, static_cast<std::uint8_t>(3));
      for (int k = 0; k < 3; ++k)
        append_le(block, static_cast<std::int32_t>(w.mesh.face_vertex(f, k)));
    }
    w.file.append(block);
  }
  w.file.commit();
}

void write_ply(const std::string& path, const Mesh& mesh,
               const std::vector<VertexProperty>& properties,
               const std::vector<std::string>& comments) {
  check_properties(mesh, properties);
  std::vector<PlyWriter::Property> types;
  for (const VertexProperty& p : properties) types.push_back({p.name, p.integer});
  PlyWriter writer(path, mesh, std::move(types), comments);
  // Rows of property values, a block of vertices at a time.
  const int n = mesh.num_vertices();
  const std::size_t P = properties.size();
  constexpr int kBlock = 1 << 16;
  std::vector<double> rows;
  for (int first = 0; first < n; first += kBlock) {
    const int count = std::min(kBlock, n - first);
    rows.resize(static_cast<std::size_t>(count) * P);
    for (int i = 0; i < count; ++i)
      for (std::size_t p = 0; p < P; ++p)
        rows[static_cast<std::size_t>(i) * P + p] =
            properties[p].values[static_cast<std::size_t>(first + i)];
    writer.write_vertices(first, count, rows.data());
  }
  writer.commit();
}

void write_mesh(const std::string& path, const Mesh& mesh,
                const std::vector<VertexProperty>& properties,
                const std::vector<std::string>& comments) {
  const std::string ext = lower_extension(path);
  if (ext == "ply") {
    write_ply(path, mesh, properties, comments);
  } else if (ext == "off") {
    if (!properties.empty())
      throw UsageError(path + ": OFF cannot store vertex properties; write .ply instead");
    write_off(path, mesh, comments);
  } else {
    throw UsageError(path + ": cannot write extension '." + ext + "' (expected .off or .ply)");
  }
}

}  // namespace curvbench
