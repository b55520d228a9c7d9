// libFuzzer target: the filter parameters. The input picks every parameter of the whole
// method from the values a filter script, the dialog or the command line can hand it (NaN,
// infinities, negatives, zero, the ends of each range, typical values, unknown names) and runs
// it on a small wavy grid with two holes. A parameter out of range must be refused with
// InvalidParameterError before the mesh is touched; any other outcome must leave the mesh as
// it was on failure, or filled and manifold on success. Valid sizes stay small (images of at
// most 64 pixels, a few dozen steps) so that each input runs in well under a second.
#include "fuzz_input.h"
#include "pipeline/hole_fill.h"
#include "pipeline/pipeline.h"

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

using namespace curvature_inpaint;

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  fuzz::StartQt(argc, argv);
  return 0;
}

namespace {

/// Parameter values: each choice picks one of a few that matter.
struct Choices : fuzz::Input {
  Choices(const uint8_t* data, size_t size) : fuzz::Input{data, size} {}
  int Int() {
    static const int kValues[] = {INT_MIN, -1, 0, 1, 2, 3, 7, 16, 64, 1001, 100001, INT_MAX};
    return kValues[Next() % (sizeof kValues / sizeof *kValues)];
  }
  double Real() {
    static const double kValues[] = {std::numeric_limits<double>::quiet_NaN(),
                                     -std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::infinity(),
                                     -1,
                                     0,
                                     1e-12,
                                     1e-4,
                                     0.03,
                                     0.5,
                                     1,
                                     4,
                                     30,
                                     1e6};
    return kValues[Next() % (sizeof kValues / sizeof *kValues)];
  }
  std::string Text(std::initializer_list<const char*> values) {
    return *(values.begin() + Next() % values.size());
  }
};

/// A 12 x 12 grid bent into waves, with two square holes.
void WavyGridWithHoles(CMeshO& m) {
  const int n = 12;
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, (n + 1) * (n + 1));
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x, ++vi)
      vi->P() = Point3m(float(x) / n, float(y) / n,
                        0.1f * std::sin(5.0f * x / n) * std::cos(4.0f * y / n));
  std::vector<std::array<int, 3>> faces;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      if ((x >= 3 && x < 5 && y >= 3 && y < 5) || (x >= 7 && x < 10 && y >= 6 && y < 9)) continue;
      const int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      faces.push_back({a, b, d});
      faces.push_back({a, d, c});
    }
  fuzz::AddTriangles(m, faces);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
}

std::vector<Point3m> Positions(const CMeshO& m) {
  std::vector<Point3m> p;
  for (const auto& v : m.vert) p.push_back(v.cP());
  return p;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Choices in(data, size);
  HoleFillParams p;
  // Beside the two modes, a value no mode has, which the checks must refuse.
  p.mode = static_cast<curvature_inpaint::DeformationMode>(in.Next() % 3);
  p.pick = in.Int();
  p.direct.iterations = in.Int();
  p.paper.similitude = in.Real();
  p.paper.transformation_constant = in.Real();
  p.paper.max_iterations = in.Int();
  auto& c = p.images.coarse;
  c.max_hole_edges = in.Int();
  c.max_hole_diameter = in.Real();
  c.keep_longest_open = in.Next() & 1;
  c.dp_max_edges = in.Int();
  c.refine = in.Next() & 1;
  c.density_alpha = in.Real();
  c.fair = in.Next() & 1;
  c.threads = in.Int();
  p.images.segmentation.context = in.Real();
  p.images.segmentation.max_rings = in.Int();
  p.images.apss.filter_scale = float(in.Real());
  p.images.apss.max_projection_iterations = in.Int();
  p.images.apss.projection_accuracy = float(in.Real());
  p.images.image_size = in.Int();
  p.images.apss_rings = in.Int();
  p.images.low_percentile = in.Real();
  p.images.high_percentile = in.Real();
  // A backend's name is read where a person gives it, and an unknown one refused there.
  try {
    p.inpaint.backend = ParseBackend(in.Text({"embedded", "", "no-such-backend"}));
  } catch (const vcg_ext::InvalidParameterError&) {
    return 0;
  }
  p.inpaint.variations = in.Int();
  p.inpaint.detail = in.Real();
  p.inpaint.size = in.Int();
  p.inpaint.http.total_timeout_s = in.Real();
  p.inpaint.http.max_retries = in.Int();
  p.symmetry.enabled = in.Next() & 1;
  p.exemplar = in.Next() & 1;
  p.creases = in.Next() & 1;
  p.crease_fill.crease_angle = in.Real();
  p.symmetry.detection.tolerance = in.Real();

  bool valid = true;
  try {
    CheckHoleFillParams(p);
  } catch (const vcg_ext::InvalidParameterError&) {
    valid = false;
  }
  // Keep the accepted inputs fast: the large ends of the ranges are the benchmark's business.
  if (valid && (p.images.image_size > 64 || p.paper.max_iterations > 64 ||
                p.images.segmentation.max_rings > 64 || c.dp_max_edges > 64 ||
                p.images.apss.max_projection_iterations > 64 || c.threads > 2))
    return 0;

  CMeshO m;
  WavyGridWithHoles(m);
  const std::vector<Point3m> before = Positions(m);
  const size_t fn = m.face.size();
  try {
    FillHoles(m, p);
  } catch (const vcg_ext::InvalidParameterError&) {
    if (valid) abort(); // refused although the check accepted it
    if (Positions(m) != before || m.face.size() != fn) abort();
    return 0;
  } catch (const std::exception&) {
    if (Positions(m) != before || m.face.size() != fn) abort(); // a failure changes nothing
    return 0;
  }
  if (!valid) abort(); // ran although the check refused it
  const HoleCensus after = CountHoles(m);
  if (after.non_manifold_edges != 0) abort();
  for (const auto& v : m.vert)
    if (!std::isfinite(v.cP()[0]) || !std::isfinite(v.cP()[1]) || !std::isfinite(v.cP()[2]))
      abort();
  return 0;
}
