// PLY reader (ASCII, binary little- and big-endian): one validating pass over the data that
// builds the polygon soup as it goes; binary vertex blocks in the common layout (x, y, z double,
// native byte order, nothing else) are copied in bulk.
//
// Read: the 'vertex' element's float or double x, y, z and the 'face' element's int or uint list
// 'vertex_indices' (or 'vertex_index'; a file without a face element is a point set), and the
// vertex element's nx, ny, nz when all three are float or double (the soup's normals); every
// other element and property is checked against the
// header and skipped. Refused: a header CGAL's reader would misread (unknown types, integer x/y/z,
// missing properties, halfedge source/target of another type than uint), counts
// the data section cannot hold (before anything is sized by them), a truncated data section, data
// after the declared elements, a value out of its type's range (ASCII), a negative list length,
// a negative or out-of-range index, a non-finite coordinate (recorded instead with skip_invalid;
// binary ones are decoded and then checked by soup_to_mesh).
//
// The soup equals what CGAL 5.5's read_PLY gives on the same accepted file (tests/mesh/
// test_io_oracle.cpp), but CGAL also accepts malformed input silently: it skips header lines it
// does not understand, including properties of an unknown type (the data is then read
// misaligned); fills a missing x, y or z with 0; dereferences a null pointer when x, y or z is an
// integer property; reads ASCII uchar values through unsigned short and truncates (a list length
// 259 becomes 3); reads "-1" into a uint index as 4294967295; and resizes each list to its length
// before reading the entries (a binary int list length of 2^31 asks for 8 GB).
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/read_soup.h"

namespace curvbench::io_detail {

namespace {

/// Whitespace-separated tokens across lines (PLY ASCII data ignores line structure).
class Tokens {
 public:
  Tokens(std::string_view text, std::size_t pos, std::size_t line)
      : text_(text), pos_(pos), line_(line) {}

  bool next(std::string_view* token) {
    const std::size_t n = text_.size();
    while (pos_ < n && (is_blank(text_[pos_]) || text_[pos_] == '\n')) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ == n) return false;
    const std::size_t start = pos_;
    while (pos_ < n && !is_blank(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    *token = text_.substr(start, pos_ - start);
    return true;
  }

  std::size_t line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t pos_;
  std::size_t line_;
};

enum class PlyType { kChar, kUchar, kShort, kUshort, kInt, kUint, kFloat, kDouble };

struct PlyTypeInfo {
  std::string_view name, alias;
  PlyType type;
  int size;
  bool integer;
  long long min, max;  // for integer types
};

constexpr PlyTypeInfo kPlyTypes[] = {
    {"char", "int8", PlyType::kChar, 1, true, -128, 127},
    {"uchar", "uint8", PlyType::kUchar, 1, true, 0, 255},
    {"short", "int16", PlyType::kShort, 2, true, -32768, 32767},
    {"ushort", "uint16", PlyType::kUshort, 2, true, 0, 65535},
    {"int", "int32", PlyType::kInt, 4, true, -2147483648LL, 2147483647LL},
    {"uint", "uint32", PlyType::kUint, 4, true, 0, 4294967295LL},
    {"float", "float32", PlyType::kFloat, 4, false, 0, 0},
    {"double", "float64", PlyType::kDouble, 8, false, 0, 0},
};

const PlyTypeInfo* ply_type(std::string_view name) {
  for (const PlyTypeInfo& t : kPlyTypes)
    if (name == t.name || name == t.alias) return &t;
  return nullptr;
}

struct PlyProperty {
  std::string name;
  const PlyTypeInfo* type = nullptr;  // value type (entry type of a list)
  const PlyTypeInfo* size = nullptr;  // length type; non-null for a list
};

struct PlyElement {
  std::string name;
  unsigned long long count;
  std::vector<PlyProperty> properties;

  const PlyProperty* find(std::string_view property) const {
    for (const PlyProperty& p : properties)
      if (p.name == property) return &p;
    return nullptr;
  }
};

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  std::size_t body = 0;       // byte offset of the data section
  std::size_t body_line = 0;  // its line number (ASCII)
};

PlyHeader parse_ply_header(const std::string& path, std::string_view text) {
  PlyHeader h;
  Lines lines(text);
  std::vector<std::string_view> tok;
  std::string_view line;
  if (lines.next(&line)) split(line, tok);
  if (lines.number() != 1 || tok.size() != 1 || tok[0] != "ply")
    fail(path, "bad PLY header: the first line is not 'ply'");
  tok.clear();
  if (lines.next(&line)) split(line, tok);
  if (tok.size() != 3 || tok[0] != "format")
    fail_line(path, 2, "bad PLY header: expected 'format <ascii|binary_...> 1.0'");
  if (tok[1] == "ascii")
    h.format = PlyFormat::kAscii;
  else if (tok[1] == "binary_little_endian")
    h.format = PlyFormat::kBinaryLittleEndian;
  else if (tok[1] == "binary_big_endian")
    h.format = PlyFormat::kBinaryBigEndian;
  else
    fail_line(path, 2, "bad PLY header: unknown format " + quote(tok[1]));

  for (;;) {
    if (!lines.next(&line)) fail(path, "bad PLY header: no end_header line");
    const std::size_t n = lines.number();
    split(line, tok);
    if (tok.empty()) fail_line(path, n, "bad PLY header: empty line");
    if (tok[0] == "end_header") break;
    if (tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "element") {
      unsigned long long count;
      if (tok.size() != 3 || !parse_count(tok[2], &count))
        fail_line(path, n, "bad PLY header: expected 'element <name> <count>'");
      for (const PlyElement& e : h.elements)
        if (e.name == tok[1])
          fail_line(path, n, "bad PLY header: element " + quote(tok[1]) + " declared twice");
      h.elements.push_back({std::string(tok[1]), count, {}});
    } else if (tok[0] == "property") {
      if (h.elements.empty())
        fail_line(path, n, "bad PLY header: property before the first element");
      PlyProperty p;
      if (tok.size() == 5 && tok[1] == "list") {
        p.size = ply_type(tok[2]);
        p.type = ply_type(tok[3]);
        p.name = tok[4];
        if (p.size == nullptr || !p.size->integer)
          fail_line(path, n, "bad PLY header: invalid list length type " + quote(tok[2]));
        if (p.type == nullptr)
          fail_line(path, n, "bad PLY header: unknown property type " + quote(tok[3]));
      } else if (tok.size() == 3) {
        p.type = ply_type(tok[1]);
        p.name = tok[2];
        if (p.type == nullptr)
          fail_line(path, n, "bad PLY header: unknown property type " + quote(tok[1]));
      } else {
        fail_line(path, n, "bad PLY header: malformed property line");
      }
      if (h.elements.back().find(p.name) != nullptr)
        fail_line(path, n, "bad PLY header: property " + quote(p.name) + " declared twice");
      h.elements.back().properties.push_back(std::move(p));
    } else {
      fail_line(path, n, "bad PLY header: unexpected line starting with " + quote(tok[0]));
    }
  }
  h.body = lines.offset();
  h.body_line = lines.number() + 1;
  return h;
}

/// The element named `a` or `b` (CGAL accepts either); null if there is none or there are two.
const PlyElement* find_element(const PlyHeader& h, std::string_view a, std::string_view b) {
  const PlyElement* found = nullptr;
  for (const PlyElement& e : h.elements)
    if (e.name == a || e.name == b) found = found ? nullptr : &e;
  return found;
}

/// Reads an integer of PLY type `t` at `p` (binary).
long long read_binary_integer(const char* p, const PlyTypeInfo& t, bool big_endian) {
  unsigned char b[8];
  std::memcpy(b, p, t.size);
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(b, b + t.size);
  switch (t.type) {
    case PlyType::kChar: {
      std::int8_t v;
      std::memcpy(&v, b, 1);
      return v;
    }
    case PlyType::kUchar:
      return b[0];
    case PlyType::kShort: {
      std::int16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case PlyType::kUshort: {
      std::uint16_t v;
      std::memcpy(&v, b, 2);
      return v;
    }
    case PlyType::kInt: {
      std::int32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    case PlyType::kUint: {
      std::uint32_t v;
      std::memcpy(&v, b, 4);
      return v;
    }
    default:
      return 0;  // not an integer type; never called so
  }
}

/// Reads a float or double of PLY type `t` at `p` (binary) as a double.
double read_binary_real(const char* p, const PlyTypeInfo& t, bool big_endian) {
  unsigned char b[8];
  std::memcpy(b, p, t.size);
  if (big_endian != (std::endian::native == std::endian::big)) std::reverse(b, b + t.size);
  if (t.type == PlyType::kFloat) {
    float v;
    std::memcpy(&v, b, 4);
    return v;
  }
  double v;
  std::memcpy(&v, b, 8);
  return v;
}

std::uint32_t byte_swap(std::uint32_t u) {
  return ((u & 0xffu) << 24) | ((u & 0xff00u) << 8) | ((u >> 8) & 0xff00u) | (u >> 24);
}

/// Reads an int or uint list entry (4 bytes) at `p` (binary).
long long read_binary_index(const char* p, bool is_signed, bool swap) {
  std::uint32_t u;
  std::memcpy(&u, p, 4);
  if (swap) u = ((u & 0xffu) << 24) | ((u & 0xff00u) << 8) | ((u >> 8) & 0xff00u) | (u >> 24);
  return is_signed ? static_cast<long long>(static_cast<std::int32_t>(u))
                   : static_cast<long long>(u);
}

/// The elements read_ply uses, after the header checks.
struct PlyLayout {
  const PlyElement* vertex = nullptr;
  const PlyElement* face = nullptr;
  const PlyProperty* xyz[3] = {nullptr, nullptr, nullptr};
  /// The vertex element's float or double nx, ny, nz (all three, else none) of a file without
  /// faces: normals kept.
  const PlyProperty* normal[3] = {nullptr, nullptr, nullptr};
  bool has_normals() const { return normal[0] != nullptr; }
  const PlyProperty* indices = nullptr;  ///< the face element's index list
  /// Faces declared (0 without a face element: a point set).
  unsigned long long face_count() const { return face != nullptr ? face->count : 0; }
  std::string declared;  ///< "N 'vertex', M 'face'" for messages
};

/// Checks the header for what CGAL's reader needs and refuses counts a data section of a
/// `file_size`-byte file cannot hold.
PlyLayout check_ply_layout(const std::string& path, const PlyHeader& h,
                           unsigned long long file_size) {
  // What CGAL's read_PLY needs: a vertex element with float/double x, y, z ...
  PlyLayout l;
  const PlyElement*& vertex = l.vertex;
  vertex = find_element(h, "vertex", "vertices");
  if (vertex == nullptr) fail(path, "PLY file has no (single) 'vertex' element");
  const PlyProperty** xyz = l.xyz;
  for (int c = 0; c < 3; ++c) {
    const char* name = c == 0 ? "x" : (c == 1 ? "y" : "z");
    xyz[c] = vertex->find(name);
    if (xyz[c] == nullptr) fail(path, std::string("PLY vertex element has no '") + name + "'");
    if (xyz[c]->size != nullptr || xyz[c]->type->integer)
      fail(path, std::string("PLY vertex property '") + name +
                     "' must be float or double (CGAL's reader cannot read other types)");
  }
  // The normals, when nx, ny and nz are all float or double values.
  bool normals = true;
  for (int c = 0; c < 3; ++c) {
    const PlyProperty* p = vertex->find(c == 0 ? "nx" : (c == 1 ? "ny" : "nz"));
    normals = normals && p != nullptr && p->size == nullptr && !p->type->integer;
    l.normal[c] = p;
  }
  if (!normals) l.normal[0] = l.normal[1] = l.normal[2] = nullptr;
  // ... a face element with an int or uint list named vertex_indices or vertex_index ...
  const PlyElement*& face = l.face;
  face = find_element(h, "face", "faces");
  // (none: a point set, every element but the vertices read past)
  const PlyProperty*& indices = l.indices;
  for (const char* name : {"vertex_indices", "vertex_index"}) {
    const PlyProperty* p = face != nullptr ? face->find(name) : nullptr;
    if (indices == nullptr && p != nullptr && p->size != nullptr &&
        (p->type->type == PlyType::kInt || p->type->type == PlyType::kUint))
      indices = p;
  }
  if (face != nullptr && indices == nullptr)
    fail(path, "PLY face element has no 'vertex_indices' list of int or uint");
  // A mesh's vertex normals come from its faces (the file's serve point sets only, option
  // point-normals=file), so with faces nx ny nz are read past, not held (24 bytes a vertex).
  if (l.face_count() > 0) l.normal[0] = l.normal[1] = l.normal[2] = nullptr;
  // ... and, for a halfedge element, uint source/target (CGAL crashes on other types).
  for (const PlyElement& e : h.elements)
    if (e.name == "halfedge")
      for (const char* name : {"source", "target"})
        if (const PlyProperty* p = e.find(name);
            p != nullptr && (p->size != nullptr || p->type->type != PlyType::kUint))
          fail(path, std::string("PLY halfedge property '") + name + "' must be uint");

  // Refuse counts the data section cannot hold: a binary item takes at least its fixed-size
  // fields and list lengths, an ASCII item at least 2 bytes per property ("0 ").
  const bool ascii = h.format == PlyFormat::kAscii;
  const unsigned long long body = file_size - h.body + (ascii ? 1 : 0);
  unsigned long long need = 0;
  bool absurd = false;
  std::string& declared = l.declared;
  for (const PlyElement& e : h.elements) {
    unsigned long long item = 0;
    for (const PlyProperty& p : e.properties)
      item += ascii ? 2 : (p.size != nullptr ? p.size->size : p.type->size);
    if (e.count > body) absurd = true;
    if (!absurd) need += e.count * item;  // < 2^40 * 2^20: no overflow
    declared += (declared.empty() ? "" : ", ") + std::to_string(e.count) + " '" + e.name + "'";
  }
  if (absurd || need > body)
    fail(path, "PLY header declares " + declared + " elements, more than the " +
                   std::to_string(file_size - h.body) +
                   "-byte data section can hold (truncated file or corrupt header)");
  if (vertex->count > kMaxCount || l.face_count() > kMaxCount)
    fail(path, "PLY header declares more than " + std::to_string(kMaxCount) + " elements");
  return l;
}

/// Reserves the soup for the header's counts (within a few times the data section's size,
/// checked by check_ply_layout).
Soup make_soup(const PlyHeader& h, const PlyLayout& l, unsigned long long file_size,
               bool skip_invalid) {
  const bool ascii = h.format == PlyFormat::kAscii;
  const unsigned long long body = file_size - h.body + (ascii ? 1 : 0);
  Soup soup;
  soup.skip_invalid = skip_invalid;
  soup.xyz.reserve(3 * l.vertex->count);
  if (l.has_normals()) soup.normals.reserve(3 * l.vertex->count);
  soup.indices.reserve(std::min<unsigned long long>(3 * l.face_count(), body / (ascii ? 2 : 4)));
  return soup;
}

void read_ascii_body(const std::string& path, std::string_view text, const PlyHeader& h,
                     const PlyLayout& l, Soup& soup) {
  const PlyElement* const vertex = l.vertex;
  const PlyElement* const face = l.face;
  const PlyProperty* const* xyz = l.xyz;
  const PlyProperty* const indices = l.indices;
  const std::string& declared = l.declared;
  const unsigned long long num_vertices = vertex->count;
  Tokens tokens(text, h.body, h.body_line);
  std::string_view t;
  for (const PlyElement& e : h.elements) {
    const bool is_vertex = &e == vertex, is_face = &e == face;
    for (unsigned long long j = 0; j < e.count; ++j) {
      const auto what = [&] { return e.name + " " + std::to_string(j); };
      double point[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
      // Reads one value of type `type` into *integer (integer types) or *real.
      auto value = [&](const PlyProperty& p, const PlyTypeInfo& type, const char* role,
                       long long* integer, double* real) {
        if (!tokens.next(&t))
          fail(path, "truncated PLY data: the file ends in " + e.name + " " + std::to_string(j) +
                         " of " + std::to_string(e.count));
        if (type.integer) {
          if (!parse_integer(t, integer) || *integer < type.min || *integer > type.max)
            fail_line(path, tokens.line(),
                      what() + ": " + role + " " + quote(t) + " of property '" + p.name +
                          "' is not a valid " + std::string(type.name));
          return;
        }
        const Number r = parse_double(t, real);
        if (r == Number::kBad)
          fail_line(path, tokens.line(), what() + ": non-numeric token " + quote(t));
        const bool is_coordinate = is_vertex && (&p == xyz[0] || &p == xyz[1] || &p == xyz[2]);
        const double limit = type.type == PlyType::kFloat ? std::numeric_limits<float>::max()
                                                          : std::numeric_limits<double>::max();
        if (r == Number::kOverflow || !(std::fabs(*real) <= limit)) {
          if (is_coordinate && soup.skip(j)) {
            *real = 0;  // the vertex is dropped
            return;
          }
          fail_line(path, tokens.line(),
                    what() +
                        (is_coordinate ? " has a non-finite coordinate "
                                       : ": non-finite or out-of-range value ") +
                        quote(t) +
                        (is_coordinate ? std::string(kSkipHint) : " of property '" + p.name + "'"));
        }
        if (type.type == PlyType::kFloat) {  // rounded once, to float, as CGAL reads it
          float f;
          parse_float(t, &f);
          *real = f;
        }
      };
      long long integer = 0;
      double real = 0;
      for (const PlyProperty& p : e.properties) {
        if (p.size == nullptr) {
          value(p, *p.type, "value", &integer, &real);
          if (is_vertex)
            for (int c = 0; c < 3; ++c) {
              if (&p == xyz[c]) point[c] = real;
              if (&p == l.normal[c]) normal[c] = real;
            }
          continue;
        }
        long long len;
        value(p, *p.size, "list length", &len, &real);
        const bool is_face_list = is_face && &p == indices;
        for (long long k = 0; k < len; ++k) {
          value(p, *p.type, "entry", &integer, &real);
          if (is_face_list) {
            check_face_index(path, tokens.line(), j, integer, num_vertices);
            soup.indices.push_back(static_cast<std::int32_t>(integer));
          }
        }
      }
      if (is_vertex) soup.xyz.append(point, 3);
      if (is_vertex && l.has_normals()) soup.normals.append(normal, 3);
      if (is_face) soup.end_polygon();
    }
  }
  if (tokens.next(&t))
    fail_line(path, tokens.line(),
              "data " + quote(t) + " after the last element the header declares (" + declared +
                  "; wrong counts?)");
}

/// The data section of a binary file in memory (the whole file's bytes).
class MemoryBytes {
 public:
  MemoryBytes(std::string_view text, std::size_t pos)
      : at_(text.data() + pos), end_(text.data() + text.size()) {}
  unsigned long long left() const { return static_cast<unsigned long long>(end_ - at_); }
  /// At least k contiguous bytes at the cursor (k <= left()).
  const char* need(std::size_t) { return at_; }
  void skip(unsigned long long k) { at_ += k; }
  /// Bytes the read buffer can hand out at once (need()).
  static constexpr std::size_t block() { return std::size_t{1} << 20; }

 private:
  const char* at_;
  const char* end_;
};

/// The data section read from an open file through a buffer of about a mebibyte (no copy of the
/// whole file in memory; the pages of a memory map would count in the resident set too).
class FileWindow {
 public:
  FileWindow(const std::string& path, int fd, unsigned long long size, unsigned long long pos)
      : path_(path),
        fd_(fd),
        size_(size),
        pos_(pos),
        buffer_(new char[kBuffer]),
        capacity_(kBuffer) {}
  unsigned long long left() const { return size_ - pos_; }
  const char* need(std::size_t k) {
    if (pos_ >= base_ && pos_ + k <= base_ + filled_) return buffer_.get() + (pos_ - base_);
    refill(k);
    return buffer_.get();
  }
  void skip(unsigned long long k) { pos_ += k; }
  static constexpr std::size_t block() { return kBuffer; }

 private:
  static constexpr std::size_t kBuffer = std::size_t{1} << 20;

  // Makes the buffer start at the cursor and hold at least k bytes (fewer only at the end of
  // the file): keeps what is already there, reads the rest.
  void refill(std::size_t k) {
    std::size_t kept = 0;
    if (pos_ >= base_ && pos_ < base_ + filled_) {
      kept = static_cast<std::size_t>(base_ + filled_ - pos_);
      std::memmove(buffer_.get(), buffer_.get() + (pos_ - base_), kept);
    }
    if (k > capacity_) {  // a long list: k <= left(), checked by the caller
      std::unique_ptr<char[]> bigger(new char[k]);
      std::memcpy(bigger.get(), buffer_.get(), kept);
      buffer_ = std::move(bigger);
      capacity_ = k;
    }
    base_ = pos_;
    filled_ = kept;
    const std::size_t want =
        static_cast<std::size_t>(std::min<unsigned long long>(capacity_, size_ - pos_));
    while (filled_ < want) {
      const ssize_t got = ::pread(fd_, buffer_.get() + filled_, want - filled_,
                                  static_cast<off_t>(base_ + filled_));
      if (got < 0 && errno == EINTR) continue;
      if (got < 0) fail(path_, std::string("cannot read file (") + std::strerror(errno) + ")");
      if (got == 0) fail(path_, "cannot read file (it shrank while being read)");
      filled_ += static_cast<std::size_t>(got);
    }
  }

  const std::string& path_;
  int fd_;
  unsigned long long size_;
  unsigned long long pos_;       // file offset of the cursor
  unsigned long long base_ = 0;  // file offset of buffer_[0]
  std::size_t filled_ = 0;       // valid bytes in buffer_
  std::unique_ptr<char[]> buffer_;
  std::size_t capacity_;
};

template <typename Bytes>
void read_binary_body(const std::string& path, const PlyHeader& h, const PlyLayout& l, Bytes& in,
                      Soup& soup) {
  const bool big = h.format == PlyFormat::kBinaryBigEndian;
  const bool swap = big != (std::endian::native == std::endian::big);
  const unsigned long long num_vertices = l.vertex->count;
  for (const PlyElement& e : h.elements) {
    const bool is_vertex = &e == l.vertex, is_face = &e == l.face;
    // Elements of fixed-size properties only: one size check for the whole block.
    unsigned long long item = 0;
    bool fixed = true;
    for (const PlyProperty& p : e.properties) {
      fixed = fixed && p.size == nullptr;
      item += p.size == nullptr ? p.type->size : 0;
    }
    if (fixed && item > 0) {
      const unsigned long long left = in.left();
      if (left / item < e.count)  // the file ends in item left / item
        fail(path, "truncated PLY data: the file ends in " + e.name + " " +
                       std::to_string(left / item) + " of " + std::to_string(e.count));
      if (!is_vertex) {
        in.skip(item * e.count);  // (the face element has its index list: never here)
        continue;
      }
      // Byte offsets in the record of x, y, z and of nx, ny, nz.
      const auto offset_of = [&](const PlyProperty* property) {
        std::size_t offset = 0;
        for (const PlyProperty& p : e.properties) {
          if (&p == property) break;
          offset += p.type->size;
        }
        return offset;
      };
      std::size_t offset[3], normal_offset[3];
      for (int c = 0; c < 3; ++c) {
        offset[c] = offset_of(l.xyz[c]);
        normal_offset[c] = l.has_normals() ? offset_of(l.normal[c]) : 0;
      }
      const bool doubles = !swap && l.xyz[0]->type->type == PlyType::kDouble &&
                           l.xyz[1]->type->type == PlyType::kDouble &&
                           l.xyz[2]->type->type == PlyType::kDouble;
      const bool packed = doubles && item == 24 && offset[0] == 0 && offset[1] == 8 &&
                          offset[2] == 16;  // the layout curvbench writes for a plain mesh
      // Through a small staging block: no zero-filled vertex array before it is overwritten.
      constexpr std::size_t kStage = 1024;
      double stage[3 * kStage];
      const unsigned long long per_block = std::max<unsigned long long>(
          1, std::min<unsigned long long>(kStage, Bytes::block() / item));
      for (unsigned long long j = 0; j < e.count;) {
        const auto items = static_cast<std::size_t>(std::min(per_block, e.count - j));
        const char* at = in.need(items * item);
        if (packed) {  // copy the block as it is
          std::memcpy(stage, at, 24 * items);
        } else if (doubles) {
          for (std::size_t i = 0; i < items; ++i)
            for (int c = 0; c < 3; ++c)
              std::memcpy(stage + 3 * i + c, at + i * item + offset[c], 8);
        } else {
          for (std::size_t i = 0; i < items; ++i)
            for (int c = 0; c < 3; ++c)
              stage[3 * i + c] = read_binary_real(at + i * item + offset[c], *l.xyz[c]->type, big);
        }
        soup.xyz.append(stage, 3 * items);
        if (l.has_normals()) {
          for (std::size_t i = 0; i < items; ++i)
            for (int c = 0; c < 3; ++c)
              stage[3 * i + c] =
                  read_binary_real(at + i * item + normal_offset[c], *l.normal[c]->type, big);
          soup.normals.append(stage, 3 * items);
        }
        in.skip(items * item);
        j += items;
      }
      continue;
    }
    // The usual face element, a list of uchar length and int or uint entries and nothing else:
    // triangles are checked and copied a window at a time, 13 bytes each, until the first record
    // that is not a triangle of valid indices; that one and the rest go through the loop below,
    // which reports the error or reads the polygon (the same soup and the same messages).
    unsigned long long j0 = 0;
    if (is_face && e.properties.size() == 1 && &e.properties[0] == l.indices &&
        l.indices->size->size == 1 && soup.all_triangles()) {
      const bool is_signed = l.indices->type->type == PlyType::kInt;
      constexpr std::size_t kStage = 4096;
      std::int32_t stage[3 * kStage];
      bool clean = true;
      while (clean && j0 < e.count) {
        const auto items = static_cast<std::size_t>(
            std::min<unsigned long long>({kStage, e.count - j0, in.left() / 13}));
        if (items == 0) break;
        const char* at = in.need(items * 13);
        std::size_t done = 0;
        for (; done < items; ++done) {
          const char* r = at + 13 * done;
          if (r[0] != 3) break;
          std::uint32_t u[3];
          std::memcpy(u, r + 1, 12);
          bool ok = true;
          for (int c = 0; c < 3; ++c) {
            if (swap) u[c] = byte_swap(u[c]);
            // As read_binary_index: a negative int or an index past the vertices is refused.
            const long long v = is_signed ? static_cast<long long>(static_cast<std::int32_t>(u[c]))
                                          : static_cast<long long>(u[c]);
            ok = ok && v >= 0 && static_cast<unsigned long long>(v) < num_vertices;
            stage[3 * done + static_cast<std::size_t>(c)] = static_cast<std::int32_t>(u[c]);
          }
          if (!ok) break;
        }
        soup.add_triangles(stage, done);
        in.skip(done * 13);
        j0 += done;
        clean = done == items;
      }
    }
    for (unsigned long long j = j0; j < e.count; ++j) {
      auto need_bytes = [&](unsigned long long bytes) {
        if (in.left() < bytes)
          fail(path, "truncated PLY data: the file ends in " + e.name + " " + std::to_string(j) +
                         " of " + std::to_string(e.count));
      };
      double point[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
      for (const PlyProperty& p : e.properties) {
        if (p.size == nullptr) {
          need_bytes(p.type->size);
          if (is_vertex)
            for (int c = 0; c < 3; ++c) {
              if (&p == l.xyz[c]) point[c] = read_binary_real(in.need(p.type->size), *p.type, big);
              if (&p == l.normal[c])
                normal[c] = read_binary_real(in.need(p.type->size), *p.type, big);
            }
          in.skip(p.type->size);
          continue;
        }
        need_bytes(p.size->size);
        const long long len = read_binary_integer(in.need(p.size->size), *p.size, big);
        in.skip(p.size->size);
        if (len < 0)
          fail(path, e.name + " " + std::to_string(j) + ": list '" + p.name +
                         "' has negative length " + std::to_string(len));
        // Compare by division: len * size could overflow.
        if (static_cast<unsigned long long>(len) > in.left() / p.type->size)
          need_bytes(std::numeric_limits<unsigned long long>::max());
        if (is_face && &p == l.indices) {
          const bool is_signed = p.type->type == PlyType::kInt;
          const char* at = in.need(static_cast<std::size_t>(len) * 4);
          for (long long k = 0; k < len; ++k) {
            const long long v = read_binary_index(at + k * 4, is_signed, swap);
            if (v < 0)
              fail(path, "face " + std::to_string(j) + " has a negative vertex index " +
                             std::to_string(v));
            if (static_cast<unsigned long long>(v) >= num_vertices)
              fail(path, "face " + std::to_string(j) + " references vertex " + std::to_string(v) +
                             ", out of range [0, " + std::to_string(num_vertices) + ")");
            soup.indices.push_back(static_cast<std::int32_t>(v));
          }
        }
        in.skip(static_cast<unsigned long long>(len) * p.type->size);
      }
      if (is_vertex) soup.xyz.append(point, 3);
      if (is_vertex && l.has_normals()) soup.normals.append(normal, 3);
      if (is_face) soup.end_polygon();
    }
  }
  // Trailing blanks (a final newline) are harmless; anything else means wrong counts.
  const unsigned long long extra = in.left();
  while (in.left() > 0) {
    const auto k =
        static_cast<std::size_t>(std::min<unsigned long long>(in.left(), Bytes::block()));
    const char* at = in.need(k);
    if (std::any_of(at, at + k, [](char c) { return !is_blank(c) && c != '\n'; }))
      fail(path, std::to_string(extra) + " bytes after the last element the header declares (" +
                     l.declared + "; wrong counts?)");
    in.skip(k);
  }
}

}  // namespace

Soup read_ply(const std::string& path, std::string_view text, bool skip_invalid) {
  const PlyHeader h = parse_ply_header(path, text);
  const PlyLayout l = check_ply_layout(path, h, text.size());
  Soup soup = make_soup(h, l, text.size(), skip_invalid);
  if (h.format == PlyFormat::kAscii) {
    read_ascii_body(path, text, h, l, soup);
  } else {
    MemoryBytes in(text, h.body);
    read_binary_body(path, h, l, in, soup);
  }
  check_not_empty(path, l.vertex->count, l.face_count());
  return soup;
}

bool read_binary_ply_file(const std::string& path, int fd, unsigned long long size,
                          bool skip_invalid, Soup* soup) {
  // The header, if it ends (with its newline) within the first 64 KiB.
  std::string prefix(static_cast<std::size_t>(std::min<unsigned long long>(size, 1 << 16)), '\0');
  std::size_t got = 0;
  while (got < prefix.size()) {
    const ssize_t r =
        ::pread(fd, prefix.data() + got, prefix.size() - got, static_cast<off_t>(got));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    got += static_cast<std::size_t>(r);
  }
  if (!prefix.starts_with("ply") || prefix.find("\nformat binary_") == std::string::npos)
    return false;
  const std::size_t end_header = prefix.find("\nend_header");
  if (end_header == std::string::npos || prefix.find('\n', end_header + 1) == std::string::npos)
    return false;
  const PlyHeader h = parse_ply_header(path, prefix);
  if (h.format == PlyFormat::kAscii || h.body > prefix.size() || prefix[h.body - 1] != '\n')
    return false;
  const PlyLayout l = check_ply_layout(path, h, size);
  *soup = make_soup(h, l, size, skip_invalid);
  FileWindow in(path, fd, size, h.body);
  read_binary_body(path, h, l, in, *soup);
  check_not_empty(path, l.vertex->count, l.face_count());
  return true;
}

}  // namespace curvbench::io_detail
