// See generation_cache.h.
#include "meshgen/generation_cache.h"

#include <map>
#include <mutex>
#include <tuple>

namespace curvbench {

const GeneratedMesh& generate_once(const std::string& family, int level, std::uint64_t seed,
                                   MeshMaker make) {
  // Recursive: a maker may ask for another family's mesh (torus-unstructured-minval5 starts from
  // torus-unstructured) while the lock is held.
  static std::recursive_mutex mutex;
  static std::map<std::tuple<std::string, int, std::uint64_t>, GeneratedMesh> cache;
  const std::lock_guard<std::recursive_mutex> lock(mutex);
  const auto key = std::make_tuple(family, level, seed);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, make(level, seed)).first;
  return it->second;
}

}  // namespace curvbench
