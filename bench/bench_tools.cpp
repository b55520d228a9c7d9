// Measurement tools for the benchmark (not part of the product):
//   bench_tools metrics GROUND_TRUTH INPUT RESULT   distances, detail and crease sharpness in
//                                                   the filled region
//   bench_tools subdivide IN OUT                    one midpoint (1-to-4) subdivision
//   bench_tools kept INPUT RESULT                   input vertices the result moved
//   bench_tools render MESH PNG CX CY CZ R [VX VY VZ [CURVATURE_SCALE]]
//                                                   a view of the faces within R of C
//   bench_tools side-by-side OUT PNG...             panels left to right
//   bench_tools learned-planes IMAGE MASK CONTINUATION OUT [IMAGE...]
//                                                   the learned inpainter's input planes,
//                                                   then each further image's curvature, as
//                                                   float32 planes of 128² (train/)
#include "inpaint/learned_inpainter.h"
#include "io/mesh_io.h"
#include "pipeline/curvature_images.h"
#include "pipeline/ground_truth_image.h"
#include "pipeline/pipeline.h"

#include <vcg_ext/curvature_colormap.h>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/append.h>
#include <wrap/io_trimesh/io_mask.h>
#include <vcg/space/index/grid_static_ptr.h>

#include <QColor>
#include <QImage>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <map>
#include <set>
#include <array>
#include <random>
#include <vector>

namespace {

using Grid = vcg::GridStaticPtr<CFaceO, Scalarm>;

struct Surface {
  CMeshO m;
  Grid grid;
  explicit Surface(const std::string& path) {
    curvature_inpaint::LoadMesh(path, m);
    m.face.EnableMark();
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
    // A generous margin: with vcglib's own (diagonal / faces) a query point a rounding error
    // inside the box's border maps to a cell past the grid's end.
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    Box3m box = m.bbox;
    box.Offset(0.01f * box.Diag());
    grid.Set(m.face.begin(), m.face.end(), box);
  }
  // Distance from p to the surface; the closest face's normal in `normal`.
  double Distance(const Point3m& p, Point3m* normal = nullptr) {
    Scalarm dist = m.bbox.Diag();
    Point3m closest;
    CFaceO* f = vcg::tri::GetClosestFaceBase(m, grid, p, m.bbox.Diag(), dist, closest);
    if (f && normal) *normal = f->N();
    return f ? double(dist) : double(m.bbox.Diag());
  }
};

struct Samples {
  std::vector<Point3m> points;
  std::vector<Point3m> normals;
};

// Per face of `from`, whether it lies off `reference` (its centre farther than tol): the region
// a fill covers, faces of the ground truth the input lacks, or faces the filler added.
std::vector<char> RegionFaces(CMeshO& from, Surface& reference, double tol) {
  std::vector<char> in_region(from.face.size(), 0);
  for (size_t f = 0; f < from.face.size(); ++f) {
    const auto& face = from.face[f];
    in_region[f] = reference.Distance((face.cP(0) + face.cP(1) + face.cP(2)) / 3) > tol;
  }
  return in_region;
}

// The angle between two unit normals, in degrees.
double AngleDegrees(const Point3m& a, const Point3m& b) {
  return std::acos(std::max(-1.0, std::min(1.0, double(a * b)))) * 180 / M_PI;
}

// Area-weighted random points on the region's faces.
Samples SampleRegion(CMeshO& from, const std::vector<char>& in_region, int count) {
  std::vector<int> region;
  std::vector<double> cumulative;
  double total = 0;
  for (int f = 0; f < int(from.face.size()); ++f) {
    const auto& face = from.face[f];
    if (!in_region[size_t(f)]) continue;
    total += vcg::DoubleArea(face) / 2;
    region.push_back(f);
    cumulative.push_back(total);
  }
  Samples s;
  if (region.empty()) return s;
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < count; ++i) {
    const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), u(rng) * total);
    const auto& f = from.face[region[std::min<size_t>(it - cumulative.begin(), region.size() - 1)]];
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    s.points.push_back(f.cP(0) * Scalarm(1 - a - b) + f.cP(1) * Scalarm(a) + f.cP(2) * Scalarm(b));
    s.normals.push_back(vcg::TriangleNormal(f).Normalize());
  }
  return s;
}

// The spread (standard deviation) of the APSS mean curvature over the vertices of the
// region's faces: how much detail a region has.
double CurvatureSpread(CMeshO& from, const std::vector<char>& region_faces) {
  std::vector<char> in_region(from.vert.size(), 0);
  Box3m box;
  for (size_t f = 0; f < from.face.size(); ++f) {
    if (!region_faces[f]) continue;
    const auto& face = from.face[f];
    for (int k = 0; k < 3; ++k)
      in_region[vcg::tri::Index(from, face.cV(k))] = 1, box.Add(face.cP(k));
  }
  if (box.IsNull()) return 0;
  box.Offset(box.Diag() * 0.2f);
  std::vector<Eigen::Vector3d> points, normals;
  std::vector<int> query;
  for (size_t i = 0; i < from.vert.size(); ++i) {
    const auto& v = from.vert[i];
    if (!box.IsIn(v.cP())) continue;
    if (in_region[i]) query.push_back(int(points.size()));
    points.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
    normals.emplace_back(v.cN()[0], v.cN()[1], v.cN()[2]);
  }
  return curvature_inpaint::Spread(vcg_ext::ApssMeanCurvature(points, normals, query));
}

// The creases of the ground truth's hole region (`in_region`, per face of `gt`) and how sharp
// the result keeps them. A crease edge is one whose two faces' normals part by more than 30
// degrees, one of them in the region. Its dihedral angle is read on both meshes alike: the normals
// of the closest faces at two probes, `probe` away from the edge's midpoint into each of its faces,
// so a smooth cap that rounds the crease over a band reads a smaller angle, and a crease carried as
// a row of leaning triangles narrower than the probe reads the whole one.
struct CreaseSharpness {
  int edges = 0;        ///< crease edges of the ground truth in the hole region
  double truth_deg = 0; ///< their mean dihedral angle on the ground truth (length-weighted)
  double error_deg = 0; ///< mean |truth - result| of the dihedral angle (length-weighted)
};

CreaseSharpness MeasureCreases(Surface& gt, const std::vector<char>& in_region, Surface& result) {
  CMeshO& m = gt.m;
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  double length_sum = 0;
  int length_count = 0;
  for (int f = 0; f < int(m.face.size()); ++f) {
    const auto& face = m.face[size_t(f)];
    for (int k = 0; k < 3; ++k) {
      const int a = int(vcg::tri::Index(m, face.cV(k))),
                b = int(vcg::tri::Index(m, face.cV((k + 1) % 3)));
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
      if (in_region[size_t(f)])
        length_sum += vcg::Distance(face.cP(k), face.cP((k + 1) % 3)), ++length_count;
    }
  }
  CreaseSharpness out;
  if (length_count == 0) return out;
  const double probe = length_sum / length_count;
  const double cos_crease = std::cos(30 * M_PI / 180);
  double weight = 0;
  for (const auto& edge_and_faces : edge_faces) {
    const auto& edge = edge_and_faces.first;
    const auto& faces = edge_and_faces.second;
    if (faces.size() != 2 || !(in_region[size_t(faces[0])] || in_region[size_t(faces[1])]))
      continue;
    const auto &f0 = m.face[size_t(faces[0])], &f1 = m.face[size_t(faces[1])];
    if (double(f0.cN() * f1.cN()) > cos_crease) continue;
    const Point3m a = m.vert[size_t(edge.first)].cP(), b = m.vert[size_t(edge.second)].cP();
    const Point3m mid = (a + b) / 2, along = (b - a).Normalize();
    double angle[2];
    Surface* surfaces[2] = {&gt, &result};
    for (int s = 0; s < 2; ++s) {
      Point3m normal[2];
      for (int i = 0; i < 2; ++i) {
        const auto& f = i == 0 ? f0 : f1;
        Point3m inward = (f.cP(0) + f.cP(1) + f.cP(2)) / 3 - mid;
        inward -= along * (inward * along);
        surfaces[s]->Distance(mid + inward.Normalize() * Scalarm(probe), &normal[i]);
      }
      angle[s] = AngleDegrees(normal[0], normal[1]);
    }
    const double w = vcg::Distance(a, b);
    out.truth_deg += w * angle[0];
    out.error_deg += w * std::abs(angle[0] - angle[1]);
    weight += w;
    ++out.edges;
  }
  if (weight > 0) out.truth_deg /= weight, out.error_deg /= weight;
  return out;
}

void PrintStats(const char* name, const std::vector<double>& d, double diag) {
  double mx = 0, sum = 0, sq = 0;
  for (double x : d) mx = std::max(mx, x), sum += x, sq += x * x;
  const double n = std::max<size_t>(d.size(), 1);
  std::printf("\"%s\": {\"max\": %.5f, \"mean\": %.5f, \"rms\": %.5f}", name, 100 * mx / diag,
              100 * sum / n / diag, 100 * std::sqrt(sq / n) / diag);
}

int Metrics(const std::string& gt_path, const std::string& input_path,
            const std::string& result_path) {
  Surface gt(gt_path), input(input_path), result(result_path);
  const double diag = gt.m.bbox.Diag();
  const double tol = 1e-5 * diag;
  const int count = 20000;
  const std::vector<char> gt_faces = RegionFaces(gt.m, input, tol);
  const std::vector<char> fill_faces = RegionFaces(result.m, input, tol);
  const Samples gt_region = SampleRegion(gt.m, gt_faces, count);
  const Samples fill_region = SampleRegion(result.m, fill_faces, count);
  std::vector<double> gt_to_result, result_to_gt;
  double normal_dev = 0;
  for (const auto& p : gt_region.points) gt_to_result.push_back(result.Distance(p));
  for (size_t i = 0; i < fill_region.points.size(); ++i) {
    Point3m n;
    result_to_gt.push_back(gt.Distance(fill_region.points[i], &n));
    normal_dev += AngleDegrees(n, fill_region.normals[i]);
  }
  const double spread_fill = CurvatureSpread(result.m, fill_faces);
  const double spread_gt = CurvatureSpread(gt.m, gt_faces);
  const auto census = curvature_inpaint::CountHoles(result.m);
  const CreaseSharpness creases = MeasureCreases(gt, gt_faces, result);
  std::printf("{");
  PrintStats("gt_to_result", gt_to_result, diag);
  std::printf(", ");
  PrintStats("result_to_gt", result_to_gt, diag);
  // A hole in a plane has no curvature to compare a fill's with: its detail ratio is null
  // (not 0, which would count against every filler in a mean).
  char detail[32] = "null";
  if (spread_gt * diag > 1e-6)
    std::snprintf(detail, sizeof detail, "%.3f", spread_fill / spread_gt);
  std::printf(", \"normal_deviation_deg\": %.3f, \"holes_left\": %zu, \"non_manifold_edges\": %zu, "
              "\"filled_samples\": %zu, \"detail_ratio\": %s, \"crease_edges\": %d, "
              "\"crease_angle_deg\": %.2f, \"crease_angle_error_deg\": %.2f}\n",
              normal_dev / std::max<size_t>(fill_region.points.size(), 1), census.loop_edges.size(),
              census.non_manifold_edges, fill_region.points.size(), detail, creases.edges,
              creases.truth_deg, creases.error_deg);
  return 0;
}

// How many vertices of INPUT are not in RESULT at exactly their coordinates: a filler must
// leave every vertex outside its fill bit for bit as it was.
int Kept(const std::string& input_path, const std::string& result_path) {
  CMeshO in, out;
  curvature_inpaint::LoadMesh(input_path, in);
  curvature_inpaint::LoadMesh(result_path, out);
  std::set<std::array<float, 3>> positions;
  for (const auto& v : out.vert) positions.insert({v.cP()[0], v.cP()[1], v.cP()[2]});
  size_t moved = 0;
  for (const auto& v : in.vert) moved += !positions.count({v.cP()[0], v.cP()[1], v.cP()[2]});
  std::printf("{\"moved\": %zu, \"vertices\": %zu}\n", moved, in.vert.size());
  return 0;
}

int Subdivide(const std::string& in, const std::string& out) {
  CMeshO m;
  const int mask = curvature_inpaint::LoadMesh(in, m);
  CMeshO r;
  std::map<std::pair<int, int>, int> mid;
  std::vector<Point3m> pts;
  for (const auto& v : m.vert) pts.push_back(v.cP());
  auto midpoint = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto it = mid.find(key);
    if (it != mid.end()) return it->second;
    pts.push_back((pts[a] + pts[b]) / 2);
    return mid[key] = int(pts.size()) - 1;
  };
  std::vector<std::array<int, 3>> tris;
  for (const auto& f : m.face) {
    const int a = vcg::tri::Index(m, f.cV(0)), b = vcg::tri::Index(m, f.cV(1)),
              c = vcg::tri::Index(m, f.cV(2));
    const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    tris.push_back({a, ab, ca});
    tris.push_back({b, bc, ab});
    tris.push_back({c, ca, bc});
    tris.push_back({ab, bc, ca});
  }
  vcg::tri::Allocator<CMeshO>::AddVertices(r, pts.size());
  for (size_t i = 0; i < pts.size(); ++i) r.vert[i].P() = pts[i];
  vcg::tri::Allocator<CMeshO>::AddFaces(r, tris.size());
  for (size_t i = 0; i < tris.size(); ++i)
    for (int k = 0; k < 3; ++k) r.face[i].V(k) = &r.vert[tris[i][k]];
  curvature_inpaint::SaveMesh(out, r, mask & vcg::tri::io::Mask::IOM_VERTCOORD);
  return 0;
}

// The inpainting benchmark's ground truth: the curvature images of INPUT's holes (as
// `curvature-inpaint images` makes them) and, beside each, the ideal image: the ground truth's
// own curvature painted over the same patch and UV (the oracle of `fill --oracle`).
int Ideal(const std::string& gt_path, const std::string& input_path, const std::string& dir,
          int size) {
  CMeshO gt, in;
  curvature_inpaint::LoadMesh(gt_path, gt);
  curvature_inpaint::LoadMesh(input_path, in);
  curvature_inpaint::CurvatureImagesParams params;
  params.image_size = size;
  const curvature_inpaint::GroundTruthOracle oracle(gt, in, params);
  const auto result = curvature_inpaint::ComputeCurvatureImages(in, params);
  curvature_inpaint::WriteHoleImages(dir, result);
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const auto truth = oracle.Image(result.holes[k]);
    if (!truth.problem.empty()) continue;
    const std::string path = dir + "/hole_" + std::to_string(k + 1) + "_ideal.png";
    if (!truth.image.save(QString::fromStdString(path)))
      throw std::runtime_error("cannot write " + path);
  }
  return 0;
}

// A and B in one file, B moved beside A: a larger mesh around exactly the same holes of A.
// Punches `count` holes into a closed mesh: every face with a vertex within a random radius
// (min_r..max_r times the mean edge length) of a random vertex is removed, the balls kept
// apart by their radii so holes never merge; unreferenced vertices are dropped.
int PunchMany(const std::string& in, const std::string& out, int count, double min_r,
              double max_r) {
  CMeshO m;
  const int mask = curvature_inpaint::LoadMesh(in, m);
  double edge = 0;
  for (const auto& f : m.face) edge += vcg::Distance(f.cP(0), f.cP(1));
  edge /= std::max<size_t>(m.face.size(), 1);
  std::mt19937 rng(7);
  std::uniform_int_distribution<size_t> pick(0, m.vert.size() - 1);
  std::uniform_real_distribution<double> radius(min_r * edge, max_r * edge);
  std::vector<std::pair<Point3m, double>> balls;
  for (int tries = 0; int(balls.size()) < count && tries < 100 * count; ++tries) {
    const Point3m c = m.vert[pick(rng)].cP();
    const double r = radius(rng);
    bool apart = true;
    for (const auto& b : balls) apart = apart && vcg::Distance(c, b.first) > 2.5 * (r + b.second);
    if (apart) balls.emplace_back(c, r);
  }
  for (auto& f : m.face)
    for (const auto& b : balls) {
      bool inside = false;
      for (int k = 0; k < 3 && !inside; ++k) inside = vcg::Distance(f.cP(k), b.first) < b.second;
      if (inside) {
        vcg::tri::Allocator<CMeshO>::DeleteFace(m, f);
        break;
      }
    }
  vcg::tri::Clean<CMeshO>::RemoveUnreferencedVertex(m);
  vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
  curvature_inpaint::SaveMesh(out, m, mask);
  std::printf("{\"holes\": %zu, \"faces\": %d}\n", balls.size(), m.fn);
  return 0;
}

// The images side by side, left to right, with a gap: the panels of one picture.
int SideBySide(const std::string& out, const std::vector<std::string>& panels) {
  std::vector<QImage> images;
  int w = 0, h = 0;
  for (const auto& p : panels) {
    images.emplace_back(QString::fromStdString(p));
    if (images.back().isNull()) throw std::runtime_error("cannot read " + p);
    w += images.back().width() + 8, h = std::max(h, images.back().height());
  }
  QImage all(w - 8, h, QImage::Format_RGB32);
  all.fill(QColor(255, 255, 255));
  int x = 0;
  for (const auto& img : images) {
    for (int y = 0; y < img.height(); ++y)
      for (int i = 0; i < img.width(); ++i) all.setPixel(x + i, y, img.pixel(i, y));
    x += img.width() + 8;
  }
  return all.save(QString::fromStdString(out)) ? 0 : 1;
}

int Append(const std::string& a_path, const std::string& b_path, const std::string& out) {
  CMeshO a, b;
  curvature_inpaint::LoadMesh(a_path, a);
  curvature_inpaint::LoadMesh(b_path, b);
  const Point3m shift(2 * a.bbox.Diag() + b.bbox.Diag(), 0, 0);
  for (auto& v : b.vert) v.P() += shift;
  vcg::tri::Append<CMeshO, CMeshO>::Mesh(a, b);
  curvature_inpaint::SaveMesh(out, a, vcg::tri::io::Mask::IOM_VERTCOORD);
  return 0;
}

// Flat-shaded orthographic view of the faces within `radius` of `center`, looking along -view
// (default: the mean normal there): for looking at fills side by side.
int Render(const std::string& in, const std::string& png, const Point3m& center, double radius,
           Point3m view, double curvature_scale) {
  CMeshO m;
  curvature_inpaint::LoadMesh(in, m);
  vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  // With a curvature scale: every face in the mean-curvature colours of the curvature images
  // (value 0.5 + 0.5 H / scale), shaded; a negative scale is taken from the region itself
  // (its 95th percentile of |H|) and printed, so the other panels can share it.
  std::vector<double> value(m.vert.size(), 0.5);
  if (curvature_scale != 0) {
    std::vector<Eigen::Vector3d> points, normals;
    std::vector<int> index(m.vert.size(), -1), query;
    for (size_t v = 0; v < m.vert.size(); ++v) {
      if (vcg::Distance(m.vert[v].cP(), center) > 1.3 * radius) continue;
      index[v] = int(points.size());
      query.push_back(int(points.size()));
      points.emplace_back(m.vert[v].cP()[0], m.vert[v].cP()[1], m.vert[v].cP()[2]);
      normals.emplace_back(m.vert[v].cN()[0], m.vert[v].cN()[1], m.vert[v].cN()[2]);
    }
    const std::vector<double> h = vcg_ext::ApssMeanCurvature(points, normals, query);
    if (curvature_scale < 0) {
      std::vector<double> a;
      for (double x : h)
        if (std::isfinite(x)) a.push_back(std::abs(x));
      std::sort(a.begin(), a.end());
      curvature_scale = a.empty() ? 1.0 : std::max(1e-12, a[a.size() * 95 / 100]);
    }
    for (size_t v = 0; v < m.vert.size(); ++v)
      if (index[v] >= 0 && std::isfinite(h[size_t(index[v])]))
        value[v] = vcg_ext::CurvatureColormap::Value(h[size_t(index[v])], curvature_scale);
  }
  std::vector<const CFaceO*> near;
  const bool view_given = view.Norm() > 0;
  for (const auto& f : m.face) {
    const Point3m c = (f.cP(0) + f.cP(1) + f.cP(2)) / 3;
    if (vcg::Distance(c, center) > radius) continue;
    near.push_back(&f);
    if (!view_given && vcg::Distance(c, center) < radius / 2) view += vcg::TriangleNormal(f);
  }
  view.Normalize();
  std::printf("{\"view\": [%.6f, %.6f, %.6f], \"curvature_scale\": %.6g}\n", view[0], view[1],
              view[2], curvature_scale);
  Point3m up = std::abs(view[1]) < 0.9 ? Point3m(0, 1, 0) : Point3m(1, 0, 0);
  Point3m right = (up ^ view).Normalize();
  up = (view ^ right).Normalize();
  const int size = 512;
  QImage image(size, size, QImage::Format_RGB32);
  image.fill(QColor(30, 30, 40));
  std::vector<double> depth(size * size, -1e30);
  const Point3m light = (view + right * 0.4f + up * 0.6f).Normalize();
  for (const CFaceO* f : near) {
    double sx[3], sy[3], sz[3];
    for (int k = 0; k < 3; ++k) {
      const Point3m d = f->cP(k) - center;
      sx[k] = (d * right / radius * 0.5 + 0.5) * size;
      sy[k] = (0.5 - d * up / radius * 0.5) * size;
      sz[k] = d * view;
    }
    const double shade = std::max(0.0, double(f->cN() * light));
    const int g = int(40 + 200 * shade);
    QRgb colour = 0;
    if (curvature_scale != 0) {
      double t = 0;
      for (int k = 0; k < 3; ++k) t += value[vcg::tri::Index(m, f->cV(k))] / 3;
      const vcg_ext::Rgb8 c = vcg_ext::CurvatureColormap::Color8(t);
      const double light_level = 0.35 + 0.65 * shade;
      colour = qRgb(int(c.r * light_level), int(c.g * light_level), int(c.b * light_level));
    }
    const int x0 = std::max(0, int(std::floor(std::min({sx[0], sx[1], sx[2]}))));
    const int x1 = std::min(size - 1, int(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
    const int y0 = std::max(0, int(std::floor(std::min({sy[0], sy[1], sy[2]}))));
    const int y1 = std::min(size - 1, int(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
    const double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
    if (std::abs(area) < 1e-12) continue;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double w0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
        const double w1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
        const double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const double z = w0 * sz[0] + w1 * sz[1] + w2 * sz[2];
        if (z <= depth[y * size + x]) continue;
        depth[y * size + x] = z;
        const bool edge = std::getenv("RENDER_EDGES") && std::min({w0, w1, w2}) < 0.04;
        const int s = edge ? g / 2 : g;
        image.setPixel(x, y, curvature_scale != 0 ? colour : qRgb(s, s, std::min(255, s + 10)));
      }
  }
  return image.save(QString::fromStdString(png)) ? 0 : 1;
}

QImage LoadImage(const std::string& path) {
  QImage image(QString::fromStdString(path));
  if (image.isNull()) throw std::runtime_error("cannot read " + path);
  return image;
}

int LearnedPlanes(const std::vector<std::string>& args) {
  using namespace curvature_inpaint;
  const QImage mask = LoadImage(args[1]);
  const CurvatureReading image = ReadCurvatureImage(LoadImage(args[0]), mask);
  Planes planes = LearnedInput(image, ReadCurvatureImage(LoadImage(args[2]), mask));
  for (size_t i = 4; i < args.size(); ++i) {
    const CurvatureReading extra = ReadCurvatureImage(LoadImage(args[i]), mask);
    const std::vector<float> cells = ToLearnedSide(extra.t, extra.width, extra.height);
    planes.data.insert(planes.data.end(), cells.begin(), cells.end());
  }
  FILE* f = std::fopen(args[3].c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write " + args[3]);
  const size_t n = std::fwrite(planes.data.data(), sizeof(float), planes.data.size(), f);
  return std::fclose(f) == 0 && n == planes.data.size() ? 0 : 1;
}

} // namespace

int main(int argc, char** argv) {
  try {
    const std::string cmd = argc > 1 ? argv[1] : "";
    if (cmd == "metrics" && argc == 5) return Metrics(argv[2], argv[3], argv[4]);
    if (cmd == "subdivide" && argc == 4) return Subdivide(argv[2], argv[3]);
    if (cmd == "kept" && argc == 4) return Kept(argv[2], argv[3]);
    if (cmd == "side-by-side" && argc >= 4)
      return SideBySide(argv[2], std::vector<std::string>(argv + 3, argv + argc));
    if (cmd == "learned-planes" && argc >= 6)
      return LearnedPlanes(std::vector<std::string>(argv + 2, argv + argc));
    if (cmd == "append" && argc == 5) return Append(argv[2], argv[3], argv[4]);
    if (cmd == "punch-many" && argc == 7)
      return PunchMany(argv[2], argv[3], std::stoi(argv[4]), std::stod(argv[5]),
                       std::stod(argv[6]));
    if (cmd == "ideal" && argc == 6) return Ideal(argv[2], argv[3], argv[4], std::stoi(argv[5]));
    if (cmd == "render" && (argc == 8 || argc == 11 || argc == 12))
      return Render(
          argv[2], argv[3], Point3m(std::stof(argv[4]), std::stof(argv[5]), std::stof(argv[6])),
          std::stod(argv[7]),
          argc >= 11 ? Point3m(std::stof(argv[8]), std::stof(argv[9]), std::stof(argv[10]))
                     : Point3m(0, 0, 0),
          argc == 12 ? std::stod(argv[11]) : 0.0);
    std::fprintf(stderr, "usage: bench_tools metrics GT INPUT RESULT | subdivide IN OUT | "
                         "append A B OUT | punch-many IN OUT COUNT MIN_R MAX_R | ideal GT INPUT "
                         "DIR SIZE | render MESH OUT.png CX CY CZ "
                         "RADIUS [VX VY VZ]\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_tools: %s\n", e.what());
    return 1;
  }
}
