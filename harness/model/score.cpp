#include "harness/model/score.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>

#include "core/errors.h"
#include "core/text.h"
#include "harness/model/results_table.h"
#include "mesh/io.h"

namespace curvbench {

namespace {

// The vertex element of a binary little-endian PLY as columns of doubles, by property name.
// Only what `curvbench mesh` writes is needed: the vertex element first, scalar properties.
std::map<std::string, std::vector<double>> read_ply_vertex_columns(const std::string& path,
                                                                   int num_vertices) {
  const std::string bytes = read_file(path);
  const auto end = bytes.find("end_header\n");
  if (end == std::string::npos) throw InputError(path + ": not a PLY file (no end_header)");
  std::istringstream header(bytes.substr(0, end));
  struct Prop {
    std::string name, type;
  };
  std::vector<Prop> props;
  std::string line, format;
  bool in_vertex = false, seen_element = false;
  long long count = -1;
  while (std::getline(header, line)) {
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if (key == "format") {
      ls >> format;
    } else if (key == "element") {
      std::string name;
      ls >> name;
      in_vertex = name == "vertex" && !seen_element;
      if (in_vertex) ls >> count;
      seen_element = true;
    } else if (key == "property" && in_vertex) {
      Prop p;
      ls >> p.type >> p.name;
      props.push_back(p);
    }
  }
  if (format != "binary_little_endian" || count < 0)
    throw InputError(path +
                     ": not a mesh written by `curvbench mesh` (expected a binary "
                     "little-endian PLY whose first element is 'vertex')");
  if (count != num_vertices)
    throw InputError(path + ": vertex element has " + std::to_string(count) + " rows, mesh has " +
                     std::to_string(num_vertices) + " vertices");
  size_t record = 0;
  for (const Prop& p : props) {
    if (p.type == "double")
      record += 8;
    else if (p.type == "int" || p.type == "float")
      record += 4;
    else
      throw InputError(path + ": vertex property '" + p.name + "' has type '" + p.type +
                       "' (a mesh written by `curvbench mesh` has double and int only)");
  }
  const size_t start = end + std::strlen("end_header\n");
  if (bytes.size() < start + record * static_cast<size_t>(count))
    throw InputError(path + ": truncated PLY vertex data");
  std::map<std::string, std::vector<double>> cols;
  size_t offset = 0;
  for (const Prop& p : props) {
    auto& col = cols[p.name];
    col.resize(count);
    for (long long v = 0; v < count; ++v) {
      const char* at = bytes.data() + start + record * v + offset;
      if (p.type == "double") {
        std::memcpy(&col[v], at, 8);
      } else if (p.type == "float") {
        float f;
        std::memcpy(&f, at, 4);
        col[v] = f;
      } else {
        std::int32_t i;
        std::memcpy(&i, at, 4);
        col[v] = i;
      }
    }
    offset += p.type == "double" ? 8 : 4;
  }
  return cols;
}

// Estimate columns and the quantity each belongs to (d2 columns: accepted, not scored).
const char* const kTriples[][3] = {
    {"nx", "ny", "nz"}, {"d1x", "d1y", "d1z"}, {"d2x", "d2y", "d2z"}};
const char* const kScalars[] = {"k1", "k2", "H", "K"};

}  // namespace

ExactMesh read_exact_mesh(const std::string& path) {
  if (lower_extension(path) != "ply")
    throw InputError(path +
                     ": the mesh must be a .ply written by `curvbench mesh` (it carries the "
                     "exact quantities)");
  ExactMesh out;
  out.mesh = read_mesh(path);
  const int n = out.mesh.num_vertices();
  auto cols = read_ply_vertex_columns(path, n);
  for (const char* name : {"nx", "ny", "nz", "k1", "k2", "H", "K"})
    if (!cols.count(name))
      throw InputError(path + ": no exact quantities (vertex property '" + name +
                       "' missing); score needs a mesh written by `curvbench mesh --output "
                       "X.ply`");
  out.has_directions = cols.count("d1x") && cols.count("d1y") && cols.count("d1z");
  const bool has_umbilic = cols.count("umbilic") > 0;
  out.exact.resize(n);
  for (int v = 0; v < n; ++v) {
    SurfacePoint& p = out.exact[v];
    p.normal = Vec3(cols["nx"][v], cols["ny"][v], cols["nz"][v]);
    p.k1 = cols["k1"][v];
    p.k2 = cols["k2"][v];
    p.H = cols["H"][v];
    p.K = cols["K"][v];
    if (out.has_directions) p.d1 = Vec3(cols["d1x"][v], cols["d1y"][v], cols["d1z"][v]);
    p.umbilic = has_umbilic && cols["umbilic"][v] != 0.0;
  }
  return out;
}

EstimateTable read_estimate_csv(const std::string& path, int num_vertices) {
  const CsvTable t = read_csv_table(path);
  auto find = [&](const std::string& name) -> int {
    for (size_t c = 0; c < t.header.size(); ++c)
      if (t.header[c] == name) return static_cast<int>(c);
    return -1;
  };
  for (size_t c = 0; c < t.header.size(); ++c)
    for (size_t d = 0; d < c; ++d)
      if (t.header[c] == t.header[d])
        throw InputError(path + ": column '" + t.header[c] + "' appears twice in the header");
  const int vcol = find("vertex");
  if (vcol < 0) throw InputError(path + ": no 'vertex' column in the header");
  // Columns to read: each present triple whole, each scalar.
  std::vector<std::pair<std::string, int>> read;
  int triple_cols[3][3];
  bool have_triple[3] = {false, false, false};
  for (int k = 0; k < 3; ++k) {
    int present = 0;
    for (int j = 0; j < 3; ++j) present += (triple_cols[k][j] = find(kTriples[k][j])) >= 0;
    if (present != 0 && present != 3)
      throw InputError(path + ": columns " + kTriples[k][0] + "," + kTriples[k][1] + "," +
                       kTriples[k][2] + " must be given together");
    have_triple[k] = present == 3;
    if (have_triple[k])
      for (int j = 0; j < 3; ++j) read.push_back({kTriples[k][j], triple_cols[k][j]});
  }
  int scalar_cols[4];
  for (int s = 0; s < 4; ++s)
    if ((scalar_cols[s] = find(kScalars[s])) >= 0) read.push_back({kScalars[s], scalar_cols[s]});
  if (read.empty())
    throw InputError(path +
                     ": no estimate column (expected any of nx,ny,nz,k1,k2,H,K,d1x,d1y,d1z,"
                     "d2x,d2y,d2z)");
  if (static_cast<int>(t.rows.size()) != num_vertices)
    throw InputError(path + ": " + std::to_string(t.rows.size()) + " rows for a mesh of " +
                     std::to_string(num_vertices) + " vertices (one row per vertex expected)");

  EstimateTable out;
  out.estimates.resize(num_vertices);
  std::vector<int> row_of(num_vertices, -1);
  for (size_t r = 0; r < t.rows.size(); ++r) {
    const std::string where =
        path + ":" + std::to_string(t.lines[r]) + ": row " + std::to_string(r + 1);
    const std::string& id_text = t.text(r, vcol);
    long long id;
    try {
      id = parse_integer(id_text, "");
    } catch (const InputError&) {
      throw InputError(where + ", column 'vertex': '" + id_text + "' is not an integer");
    }
    if (id < 0 || id >= num_vertices)
      throw InputError(where + ", column 'vertex': vertex " + id_text + " out of range 0.." +
                       std::to_string(num_vertices - 1));
    if (row_of[id] >= 0)
      throw InputError(where + ", column 'vertex': vertex " + id_text +
                       " appears twice (first on row " + std::to_string(row_of[id] + 1) + ")");
    row_of[id] = static_cast<int>(r);
    std::map<std::string, double> value;
    for (const auto& [name, c] : read) {
      const std::string& cell = t.text(r, c);
      try {
        value[name] = parse_double(cell, "");
      } catch (const InputError&) {
        throw InputError(where + ", column '" + name + "': '" + cell + "' is not a number");
      }
    }
    VertexEstimate& e = out.estimates[id];
    e.status = VertexStatus::ok;
    if (have_triple[0]) e.normal = Vec3(value["nx"], value["ny"], value["nz"]);
    if (have_triple[1]) e.d1 = Vec3(value["d1x"], value["d1y"], value["d1z"]);
    if (have_triple[2]) e.d2 = Vec3(value["d2x"], value["d2y"], value["d2z"]);
    if (scalar_cols[0] >= 0) e.k1 = value["k1"];
    if (scalar_cols[1] >= 0) e.k2 = value["k2"];
    if (scalar_cols[2] >= 0) e.H = value["H"];
    if (scalar_cols[3] >= 0) e.K = value["K"];
  }
  // Metric order of metrics.h: normal, H, K, k1, k2, d1.
  if (have_triple[0]) out.quantities.push_back(Quantity::normal);
  if (scalar_cols[2] >= 0) out.quantities.push_back(Quantity::H);
  if (scalar_cols[3] >= 0) out.quantities.push_back(Quantity::K);
  if (scalar_cols[0] >= 0) out.quantities.push_back(Quantity::k1);
  if (scalar_cols[1] >= 0) out.quantities.push_back(Quantity::k2);
  if (have_triple[1]) out.quantities.push_back(Quantity::d1);
  return out;
}

ScoreResult score_estimates(const Mesh& mesh, std::span<const SurfacePoint> exact,
                            std::span<const VertexEstimate> estimates,
                            std::span<const Quantity> quantities, VertexSet set) {
  ScoreResult r;
  r.vertex_set = set;
  const std::vector<int> vertices = select_vertices(mesh, set);
  r.vertices_in_set = static_cast<int>(vertices.size());
  for (Quantity q : quantities) {
    QuantityScore s;
    s.quantity = q;
    s.l2 = compute_error(q, Norm::L2, estimates, exact, vertices);
    s.linf = compute_error(q, Norm::Linf, estimates, exact, vertices);
    r.scores.push_back(s);
  }
  return r;
}

ScoreResult score_files(const std::string& mesh_path, const std::string& estimates_path,
                        VertexSet set) {
  const ExactMesh m = read_exact_mesh(mesh_path);
  EstimateTable t = read_estimate_csv(estimates_path, m.mesh.num_vertices());
  if (!m.has_directions)
    std::erase(t.quantities, Quantity::d1);  // a mesh file from before d1 was written
  return score_estimates(m.mesh, m.exact, t.estimates, t.quantities, set);
}

std::string score_json(const ScoreResult& r, const std::string& mesh_path,
                       const std::string& estimates_path) {
  auto num = [](double x) { return std::isfinite(x) ? format_double(x) : std::string("null"); };
  const auto str = [](const std::string& s) { return json_string(s); };
  std::string j = "{\"mesh\": " + str(mesh_path) + ", \"estimates\": " + str(estimates_path) +
                  ", \"vertex_set\": " + str(to_string(r.vertex_set)) +
                  ", \"vertices\": " + std::to_string(r.vertices_in_set) + ", \"errors\": [";
  for (size_t i = 0; i < r.scores.size(); ++i) {
    const QuantityScore& s = r.scores[i];
    j += std::string(i ? ", " : "") + "{\"quantity\": " + str(to_string(s.quantity)) +
         ", \"L2\": " + num(s.l2.value) + ", \"Linf\": " + num(s.linf.value) +
         ", \"counted\": " + std::to_string(s.l2.vertices) +
         ", \"failed\": " + std::to_string(s.l2.excluded) +
         (s.l2.zero_exact_norm ? ", \"relative_to\": \"curvature scale\"" : "") + "}";
  }
  return j + "]}\n";
}

std::string score_text(const ScoreResult& r) {
  std::string out = "vertex set " + std::string(to_string(r.vertex_set)) + ": " +
                    std::to_string(r.vertices_in_set) + " vertices\n";
  char buf[160];
  std::snprintf(buf, sizeof buf, "%-8s %-24s %-24s %8s %8s\n", "quantity", "L2", "Linf", "counted",
                "failed");
  out += buf;
  for (const QuantityScore& s : r.scores) {
    std::snprintf(buf, sizeof buf, "%-8s %-24s %-24s %8d %8d\n", to_string(s.quantity),
                  format_double(s.l2.value).c_str(), format_double(s.linf.value).c_str(),
                  s.l2.vertices, s.l2.excluded);
    out += buf;
  }
  for (const QuantityScore& s : r.scores)
    if (s.l2.zero_exact_norm)
      out += std::string("exact ") + to_string(s.quantity) +
             " is 0 on every vertex: its errors are relative to the curvature scale max(|k1|, "
             "|k2|)" +
             (s.quantity == Quantity::K ? "^2" : "") + " (docs/metrics.md)\n";
  return out;
}

}  // namespace curvbench
