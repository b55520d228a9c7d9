// CGAL's hole filler as the benchmark's reference peer (Liepa 2003 as CGAL implements it):
//   cgal_fill IN OUT   fills every hole with triangulate_refine_and_fair_hole and prints the
//                      time of the filling calls alone, in milliseconds.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cstdio>
#include <iterator>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: cgal_fill IN OUT\n");
    return 2;
  }
  Mesh mesh;
  if (!PMP::IO::read_polygon_mesh(argv[1], mesh)) {
    std::fprintf(stderr, "cgal_fill: cannot read %s\n", argv[1]);
    return 1;
  }
  std::vector<Mesh::Halfedge_index> holes;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(holes));
  const auto start = std::chrono::steady_clock::now();
  int filled = 0;
  for (auto h : holes) {
    std::vector<Mesh::Face_index> faces;
    std::vector<Mesh::Vertex_index> vertices;
    const bool ok = std::get<0>(PMP::triangulate_refine_and_fair_hole(
        mesh, h, std::back_inserter(faces), std::back_inserter(vertices)));
    filled += ok;
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (!CGAL::IO::write_polygon_mesh(argv[2], mesh, CGAL::parameters::stream_precision(9))) {
    std::fprintf(stderr, "cgal_fill: cannot write %s\n", argv[2]);
    return 1;
  }
  std::printf("{\"holes\": %zu, \"filled\": %d, \"fill_ms\": %.2f}\n", holes.size(), filled, ms);
  return 0;
}
