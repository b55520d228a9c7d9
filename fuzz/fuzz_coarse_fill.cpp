// libFuzzer target: the mesh stages on small random meshes with random holes. A grid whose
// heights, removed faces, extra faces and non-finite coordinates come from the input goes
// through the coarse fill and, for some inputs, the whole method with the embedded inpainter.
// Refusals (InvalidMeshError) are fine; a crash, a non-manifold result from a manifold input,
// or a mesh changed by a refused fill are not.
#include "fuzz_input.h"
#include "pipeline/hole_fill.h"
#include "pipeline/pipeline.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vcg/complex/algorithms/update/topology.h>

using namespace curvature_inpaint;

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  fuzz::StartQt(argc, argv);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::Input in{data, size};
  const int n = 3 + in.Next() % 8;
  const uint8_t flags = in.Next();
  CMeshO m;
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, (n + 1) * (n + 1));
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x, ++vi) {
      const float z = (int(in.Next()) - 128) / 256.0f;
      vi->P() = Point3m(float(x) / n, float(y) / n, (flags & 1) ? z : 0.1f * z);
    }
  if (flags & 2) m.vert[in.Next() % m.vert.size()].P()[0] = (flags & 4) ? NAN : INFINITY;
  std::vector<std::array<int, 3>> faces;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      const uint8_t keep = in.Next();
      if (keep % 5 != 0) faces.push_back({a, b, d});
      if (keep % 7 != 0) faces.push_back({a, d, c});
    }
  for (int extra = in.Next() % 4; extra > 0; --extra)
    faces.push_back({int(in.Next() % m.vert.size()), int(in.Next() % m.vert.size()),
                     int(in.Next() % m.vert.size())});
  if (faces.empty()) return 0;
  fuzz::AddTriangles(m, faces);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);

  const HoleCensus before = CountHoles(m);
  const size_t vn = m.vert.size(), fn = m.face.size();
  try {
    if (flags & 8) {
      HoleFillParams p;
      p.images.image_size = 32;
      p.inpaint.variations = 1;
      p.mode = (flags & 16) ? curvature_inpaint::DeformationMode::kPaper
                            : curvature_inpaint::DeformationMode::kDirect;
      p.paper.max_iterations = 20;
      FillHoles(m, p);
    } else {
      vcg_ext::CoarseFillParams p;
      p.keep_longest_open = flags & 32;
      p.dp_max_edges = (flags & 64) ? 3 : 200;
      CoarseFill(m, p);
    }
  } catch (const std::exception&) {
    if (m.vert.size() != vn || m.face.size() != fn) abort(); // a refusal changes nothing
    return 0;
  }
  if (before.non_manifold_edges == 0 && CountHoles(m).non_manifold_edges != 0) abort();
  return 0;
}
