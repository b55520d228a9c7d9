#include "pipeline/curvature_images.h"

#include "io/output_files.h"
#include "pipeline/fill_settings.h"
#include "pipeline/pipeline.h"
#include "report/json_text.h"
#include "report/montage.h"

#include <vcg_ext/curvature_colormap.h>
#include <vcg_ext/parallel_for.h>

#include <QColor>
#include <QDir>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace curvature_inpaint {

namespace {

using Clock = std::chrono::steady_clock;

double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const size_t k = std::min(v.size() - 1, size_t(std::lround(q * double(v.size() - 1))));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

void BuildHoleImage(const CMeshO& m, const vcg_ext::VertexFaces& vf, const vcg_ext::UnitBox& box,
                    const vcg_ext::HoleRegion& region, const std::vector<int>& new_vertices,
                    const CurvatureImagesParams& params, HoleImage& out) {
  out.rings = region.rings;
  out.target_rings = region.target_rings;
  out.patch = vcg_ext::ExtractPatch(m, region, box);
  const std::unordered_set<int> added(new_vertices.begin(), new_vertices.end());
  out.is_new.resize(out.patch.vertices.size());
  for (size_t v = 0; v < out.is_new.size(); ++v) out.is_new[v] = added.count(out.patch.vertices[v]);
  const auto context_faces = std::count(out.patch.is_fill.begin(), out.patch.is_fill.end(), 0);
  if (context_faces == 0 || out.patch.boundary.size() < 4) {
    out.problem = "there is no room for context around it (it touches another hole or the "
                  "mesh's end); it keeps its coarse fill";
    return;
  }
  if (!out.patch.IsDisk()) {
    out.problem = "its patch is not a disk (Euler characteristic " +
                  std::to_string(out.patch.euler) + ", " +
                  std::to_string(out.patch.boundary_loops) + " boundary loops)";
    return;
  }
  const ApssSupport support = ApssNeighbourhood(m, vf, box, out.patch.vertices, params.apss_rings);
  std::vector<int> query(out.patch.vertices.size());
  for (size_t i = 0; i < query.size(); ++i) query[i] = int(i);
  out.curvature = vcg_ext::ApssMeanCurvature(support.points, support.normals, query, params.apss);

  // Normalize by the known ring: the vertices of the scan's faces in the patch. A loop vertex
  // with none (where two holes meet at one vertex) is the scan's too, but no scan surface
  // around it in this patch backs its curvature.
  std::vector<char> on_scan(out.patch.points.size(), 0);
  for (size_t f = 0; f < out.patch.triangles.size(); ++f)
    if (!out.patch.is_fill[f])
      for (int v : out.patch.triangles[f]) on_scan[v] = 1;
  std::vector<double> known;
  for (size_t v = 0; v < out.curvature.size(); ++v)
    if (on_scan[v] && std::isfinite(out.curvature[v])) known.push_back(out.curvature[v]);
  out.low = Percentile(known, params.low_percentile);
  out.high = Percentile(known, params.high_percentile);
  out.scale = params.headroom * std::max({std::abs(out.low), std::abs(out.high), 1e-9});
  out.value.resize(out.curvature.size());
  for (size_t v = 0; v < out.curvature.size(); ++v)
    out.value[v] = std::isfinite(out.curvature[v])
                       ? vcg_ext::CurvatureColormap::Value(out.curvature[v], out.scale)
                       : 0.5;

  out.uv = vcg_ext::ParameterizeMvc(out.patch.points, out.patch.triangles, out.patch.boundary);
  if (!out.uv.solved || out.uv.flipped > 0) {
    out.problem =
        "its parameterization failed (" + std::to_string(out.uv.flipped) + " flipped triangles)";
    return;
  }
  out.image = vcg_ext::RasterizeCurvature(out.uv.uv, out.value, out.patch.triangles,
                                          out.patch.is_fill, params.image_size);
}

} // namespace

ApssSupport ApssNeighbourhood(const CMeshO& m, const vcg_ext::VertexFaces& vf,
                              const vcg_ext::UnitBox& box, const std::vector<int>& patch_vertices,
                              int rings) {
  ApssSupport out;
  std::vector<Eigen::Vector3d>& points = out.points;
  std::vector<Eigen::Vector3d>& normals = out.normals;
  std::vector<int> order(patch_vertices);
  std::unordered_set<int> in(order.begin(), order.end());
  size_t ring_start = 0;
  for (int r = 0; r < rings; ++r) {
    const size_t ring_end = order.size();
    for (size_t i = ring_start; i < ring_end; ++i)
      vf.ForEach(order[i], [&](int f) {
        for (int k = 0; k < 3; ++k) {
          const int v = int(vcg::tri::Index(m, m.face[f].cV(k)));
          if (in.insert(v).second) order.push_back(v);
        }
      });
    ring_start = ring_end;
  }
  for (int v : order) {
    points.push_back(box.ToUnit(m.vert[v].cP()));
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    vf.ForEach(v, [&](int f) {
      const auto& face = m.face[f];
      n += vcg_ext::TriangleNormal(box.ToUnit(face.cV(0)->cP()), box.ToUnit(face.cV(1)->cP()),
                                   box.ToUnit(face.cV(2)->cP()));
    });
    normals.push_back(n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d(0, 0, 1));
  }
  return out;
}

void CheckCurvatureImagesParams(const CurvatureImagesParams& p) {
  using vcg_ext::RequireRange;
  vcg_ext::CheckCoarseFillParams(p.coarse);
  RequireRange(p.segmentation.context, 0.05, 100, "the context around each hole");
  RequireRange(p.segmentation.max_rings, 1, 1000, "the largest patch (rings)");
  RequireRange(p.apss.filter_scale, 1, 100, "the APSS filter scale");
  RequireRange(p.apss.max_projection_iterations, 1, 1000, "the APSS projection iterations");
  RequireRange(p.apss.projection_accuracy, 1e-9, 1, "the APSS projection accuracy");
  RequireSetting(Setting::kImageSize, p.image_size);
  RequireRange(p.apss_rings, 0, 16, "the rings supporting the curvature fits");
  RequireRange(p.low_percentile, 0, 1, "the low curvature percentile");
  RequireRange(p.high_percentile, p.low_percentile, 1, "the high curvature percentile");
  RequireRange(p.headroom, 1, 100, "the colour map's headroom");
}

CurvatureImagesResult ComputeCurvatureImages(CMeshO& m, const CurvatureImagesParams& params,
                                             vcg::CallBackPos* cb, const HoleImageSink& sink) {
  CheckCurvatureImagesParams(params);
  CurvatureImagesResult result;
  MeshCheckpoint checkpoint(m);
  result.coarse = CoarseFill(m, params.coarse, cb);
  try {
    const auto start = Clock::now();
    const vcg_ext::VertexFaces vf(m);
    result.adjacency_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    std::vector<vcg_ext::FilledHole> filled;
    std::vector<int> index;
    for (size_t h = 0; h < result.coarse.holes.size(); ++h)
      if (result.coarse.holes[h].filled) {
        filled.push_back({result.coarse.holes[h].loop, result.coarse.holes[h].new_faces});
        index.push_back(int(h));
      }
    const auto seg_start = Clock::now();
    const auto regions =
        vcg_ext::SegmentHolePatches(m, vf, filled, result.coarse.box, params.segmentation);
    const double seg_each = std::chrono::duration<double>(Clock::now() - seg_start).count() /
                            std::max<size_t>(filled.size(), 1);
    result.holes.resize(filled.size());
    // The patches are disjoint and only read the mesh: one per thread, the largest first, so
    // that a large hole does not start last and keep one thread busy after the rest are done.
    std::vector<int> largest_first(filled.size());
    std::iota(largest_first.begin(), largest_first.end(), 0);
    std::stable_sort(largest_first.begin(), largest_first.end(), [&](int a, int b) {
      return regions[size_t(a)].faces.size() > regions[size_t(b)].faces.size();
    });
    // Progress after each hole this thread builds and, while it waits for the others' last
    // ones, every 50 ms: the count still moves, and a stop is still heard.
    auto report = [&](int done) {
      const std::string msg =
          std::string(sink ? "Curvature Inpaint: hole " : "Curvature images: hole ") +
          std::to_string(done) + " of " + std::to_string(filled.size());
      return !cb || cb(int(100.0 * done / filled.size()), msg.c_str());
    };
    vcg_ext::ParallelFor(
        int(filled.size()), params.coarse.threads,
        [&](int task) {
          const int i = largest_first[size_t(task)];
          const auto t0 = Clock::now();
          HoleImage& hi = result.holes[i];
          hi.hole = index[i];
          BuildHoleImage(m, vf, result.coarse.box, regions[i],
                         result.coarse.holes[index[i]].new_vertices, params, hi);
          hi.seconds = seg_each + std::chrono::duration<double>(Clock::now() - t0).count();
          if (sink) sink(result.coarse, i, hi);
        },
        report);
  } catch (...) {
    checkpoint.Restore();
    throw;
  }
  for (const HoleImage& hi : result.holes) {
    if (!hi.problem.empty() || !params.color_vertices) continue;
    for (size_t v = 0; v < hi.patch.vertices.size(); ++v) {
      const vcg_ext::Rgb8 c = vcg_ext::CurvatureColormap::Color8(hi.value[v]);
      m.vert[hi.patch.vertices[v]].C() = vcg::Color4b(c.r, c.g, c.b, 255);
    }
  }
  return result;
}

QImage ToQImage(const vcg_ext::CurvatureImage& img, bool with_alpha) {
  QImage q(img.size, img.size, with_alpha ? QImage::Format_ARGB32 : QImage::Format_RGB32);
  for (int y = 0; y < img.size; ++y)
    for (int x = 0; x < img.size; ++x) {
      const size_t i = size_t(y) * img.size + x;
      const uint8_t* c = &img.rgb[i * 3];
      q.setPixel(x, y, qRgba(c[0], c[1], c[2], with_alpha && img.hole[i] ? 0 : 255));
    }
  return q;
}

QImage MaskImage(const vcg_ext::CurvatureImage& img) {
  QImage q(img.size, img.size, QImage::Format_Grayscale8);
  for (int y = 0; y < img.size; ++y)
    for (int x = 0; x < img.size; ++x)
      q.setPixel(x, y, img.hole[size_t(y) * img.size + x] ? qRgb(255, 255, 255) : qRgb(0, 0, 0));
  return q;
}

void WriteHoleImages(const std::string& dir, const CurvatureImagesResult& result) {
  if (!QDir().mkpath(QString::fromStdString(dir))) throw std::runtime_error("cannot create " + dir);
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const HoleImage& hi = result.holes[k];
    if (!hi.problem.empty()) continue;
    const std::string base = dir + "/hole_" + std::to_string(k + 1);
    SavePngAtomically(ToQImage(hi.image, false), base + "_curvature.png");
    SavePngAtomically(ToQImage(hi.image, true), base + "_rgba.png");
    SavePngAtomically(MaskImage(hi.image), base + "_mask.png");
    std::ostringstream json;
    json.precision(9);
    json << "{\n  \"hole\": " << k + 1
         << ",\n  \"boundary_edges\": " << result.coarse.holes[hi.hole].boundary_edges
         << ",\n  \"patch_vertices\": " << hi.patch.vertices.size()
         << ",\n  \"patch_faces\": " << hi.patch.triangles.size() << ",\n  \"rings\": " << hi.rings
         << ",\n  \"image_size\": " << hi.image.size
         << ",\n  \"normalization\": {\"unit_box_scale\": " << result.coarse.box.scale
         << ", \"curvature_low\": " << hi.low << ", \"curvature_high\": " << hi.high
         << ", \"curvature_scale\": " << hi.scale
         << ", \"value\": \"0.5 + 0.5 * curvature / curvature_scale, clamped to [0, 1]\"},\n"
         << "  \"vertices\": [";
    for (size_t v = 0; v < hi.patch.vertices.size(); ++v)
      json << (v ? ",\n    " : "\n    ") << "{\"index\": " << hi.patch.vertices[v]
           << ", \"u\": " << JsonNumber{hi.uv.uv[v].x()}
           << ", \"v\": " << JsonNumber{hi.uv.uv[v].y()}
           << ", \"curvature\": " << JsonNumber{hi.curvature[v]}
           << ", \"value\": " << JsonNumber{hi.value[v]} << "}";
    json << "\n  ]\n}\n";
    WriteFileAtomically(base + ".json", json.str());
  }
}

void WriteMontage(const std::string& path, const CurvatureImagesResult& result) {
  std::vector<MontageRow> rows;
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const HoleImage& hi = result.holes[k];
    if (hi.problem.empty())
      rows.push_back(MakeImagesRow(hi, k, result.coarse.holes[size_t(hi.hole)].boundary_edges));
  }
  SaveMontage(rows, path);
}

std::vector<std::string> DescribeCurvatureImages(const CurvatureImagesResult& result) {
  std::vector<std::string> lines = DescribeCoarseFill(result.coarse);
  char buf[512];
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const HoleImage& hi = result.holes[k];
    if (!hi.problem.empty())
      std::snprintf(buf, sizeof buf, "image %zu: none: %s", k + 1, hi.problem.c_str());
    else
      std::snprintf(buf, sizeof buf,
                    "image %zu: patch of %zu vertices (%d of %d rings), curvature %.3g..%.3g, "
                    "%d hole pixels of %d^2, %.0f ms",
                    k + 1, hi.patch.vertices.size(), hi.rings, hi.target_rings, hi.low, hi.high,
                    hi.image.HolePixels(), hi.image.size, 1000 * hi.seconds);
    lines.emplace_back(buf);
  }
  return lines;
}

} // namespace curvature_inpaint
