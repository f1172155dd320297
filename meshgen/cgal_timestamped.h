// A CGAL vertex, cell or face base with a creation stamp. CGAL's Compact_container uses the stamp
// when the type declares Has_timestamp, so handles compare by creation order instead of by
// address: a mesher's refinement order, and its mesh, then do not depend on the state of the heap
// (without the stamps, meshing torus-unstructured level 1 first changed level 2 from 5246 to 5307
// vertices). Shared by delaunay_surface_mesh (3-D) and bump_unstructured (2-D).
#pragma once

#include <CGAL/tags.h>

#include <cstddef>

namespace curvbench {

template <class Base>
struct Timestamped : Base {
  using Base::Base;
  template <class TDS2>
  struct Rebind_TDS {
    using Other = Timestamped<typename Base::template Rebind_TDS<TDS2>::Other>;
  };
  using Has_timestamp = CGAL::Tag_true;
  std::size_t time_stamp() const { return stamp_; }
  void set_time_stamp(std::size_t s) { stamp_ = s; }

 private:
  std::size_t stamp_ = static_cast<std::size_t>(-1);
};

}  // namespace curvbench
