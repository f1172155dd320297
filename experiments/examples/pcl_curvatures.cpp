// PCL as an outside estimator (harness/external_estimator.h): its own NormalEstimation and
// PrincipalCurvaturesEstimation on the mesh's vertices, so that the numbers are PCL's.
//
//   build/pcl_curvatures MESH.ply OUT.csv [K]      (through experiments/examples/pcl_curvatures.sh)
//
// Built only where CMake finds PCL (libpcl-dev: `bash tools/deps.sh pcl`). Per vertex, with the
// K nearest vertices (default 20, PCL's k-d tree; the vertex itself is one of them):
//   nx,ny,nz  pcl::NormalEstimation's normal: the PCA normal of the K points. PCL orients it
//             towards a viewpoint (the origin by default), which points into a closed surface
//             around the origin; here its sign is instead chosen to agree with the area-weighted
//             vertex normal of the mesh's faces (curvbench's approximate normal), and with no
//             faces PCL's own viewpoint rule stays. The direction is PCL's.
//   H         pcl::NormalEstimation's `curvature`: the surface variation lambda0 / (lambda0 +
//             lambda1 + lambda2) (Pauly et al. 2002), unitless, unsigned, NOT a curvature; in
//             the H column, as the surface-variation method reports it, to show what it is.
//   k1, k2    pcl::PrincipalCurvaturesEstimation's pc1 >= pc2: the largest two eigenvalues of
//             the covariance of the K points' normals projected onto the tangent plane, written
//             as PCL gives them (non-negative, no sign, not 1/length): NOT signed curvatures.
// No K, d1, d2. A point PCL leaves NaN stays NaN (curvbench counts it as failed).
#include <pcl/features/normal_3d.h>
#include <pcl/features/principal_curvatures.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <cstdio>
#include <exception>
#include <string>

#include "core/types.h"
#include "mesh/io.h"
#include "mesh/mesh.h"

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: pcl_curvatures MESH OUT.csv [K]\n");
    return 2;
  }
  try {
    const curvbench::Mesh mesh = curvbench::read_mesh(argv[1]);
    const int k = argc == 4 ? std::stoi(argv[3]) : 20;
    if (k < 3) throw std::invalid_argument("K must be at least 3");
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      const curvbench::Vec3 p = mesh.position(v);
      cloud->push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                     static_cast<float>(p.z())));
    }
    pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
    pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
    pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> ne;
    ne.setInputCloud(cloud);
    ne.setSearchMethod(tree);
    ne.setKSearch(k);
    ne.compute(*normals);
    // The sign: the mesh's area-weighted vertex normal where there are faces (see above).
    if (mesh.num_faces() > 0) {
      const curvbench::VertexMatrix side = mesh.area_weighted_normals();
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        pcl::Normal& n = (*normals)[static_cast<size_t>(v)];
        if (n.normal_x * side(v, 0) + n.normal_y * side(v, 1) + n.normal_z * side(v, 2) < 0) {
          n.normal_x = -n.normal_x;
          n.normal_y = -n.normal_y;
          n.normal_z = -n.normal_z;
        }
      }
    }
    pcl::PointCloud<pcl::PrincipalCurvatures> curvatures;
    pcl::PrincipalCurvaturesEstimation<pcl::PointXYZ, pcl::Normal, pcl::PrincipalCurvatures> pc;
    pc.setInputCloud(cloud);
    pc.setInputNormals(normals);
    pc.setSearchMethod(tree);
    pc.setKSearch(k);
    pc.compute(curvatures);
    std::FILE* out = std::fopen(argv[2], "w");
    if (out == nullptr) throw std::runtime_error(std::string("cannot write ") + argv[2]);
    std::fprintf(out, "vertex,nx,ny,nz,k1,k2,H\n");
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      const pcl::Normal& n = (*normals)[static_cast<size_t>(v)];
      const pcl::PrincipalCurvatures& c = curvatures[static_cast<size_t>(v)];
      std::fprintf(out, "%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", v, n.normal_x, n.normal_y, n.normal_z,
                   c.pc1, c.pc2, n.curvature);
    }
    if (std::fclose(out) != 0) throw std::runtime_error(std::string("cannot write ") + argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pcl_curvatures: %s\n", e.what());
    return 1;
  }
  return 0;
}
