#include "io/mesh_io.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/io_mask.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cctype>
#include <cmath>
#include <cstring>
#include <iterator>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

namespace curvature_inpaint {

namespace {

std::string Extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool Supported(const std::string& ext) {
  return ext == "ply" || ext == "off" || ext == "obj" || ext == "stl";
}

/// At most `max` characters of a file's text for an error message, anything but printable
/// ASCII shown as '?' (a binary file's bytes would garble the terminal or the log).
std::string Excerpt(const std::string& text, size_t max) {
  std::string out = text.substr(0, max);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return out;
}

/// Whether a header line holds a control character (a tab aside): no PLY writer puts one
/// there, and they would garble the messages that quote the header.
bool HasControlCharacter(const std::string& line) {
  return std::any_of(line.begin(), line.end(), [](char c) {
    return (static_cast<unsigned char>(c) < 32 && c != '\t') || c == 127;
  });
}

struct PlyProperty {
  std::string name;
  int size = 0; ///< bytes of a (binary) value
  bool is_float = false, is_signed = false;
  bool list = false; ///< a count (count_* fields) then that many values
  int count_size = 0;
  bool count_signed = false;
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  bool binary = false, big_endian = false;
  size_t body = 0; ///< offset of the first byte after end_header's line
  std::vector<PlyElement> elements;
};

/// Parses and checks a PLY header: every element with a count, every property with a known
/// type, and no more data declared than the file holds. Returns why it is refused, or "".
std::string ParsePlyHeader(const std::string& data, PlyHeader& header) {
  struct Type {
    int size;
    bool is_float, is_signed;
  };
  static const std::map<std::string, Type> kTypes{
      {"char", {1, false, true}},   {"uchar", {1, false, false}},  {"int8", {1, false, true}},
      {"uint8", {1, false, false}}, {"short", {2, false, true}},   {"ushort", {2, false, false}},
      {"int16", {2, false, true}},  {"uint16", {2, false, false}}, {"int", {4, false, true}},
      {"uint", {4, false, false}},  {"int32", {4, false, true}},   {"uint32", {4, false, false}},
      {"float", {4, true, true}},   {"float32", {4, true, true}},  {"double", {8, true, true}},
      {"float64", {8, true, true}}};
  size_t at = 0;
  bool format = false;
  for (int lines = 1;; ++lines) {
    const size_t end = data.find('\n', at);
    if (end == std::string::npos || end > (1u << 20) || lines > 10000)
      return "a PLY header without end_header in its first megabyte";
    std::string line = data.substr(at, end - at);
    at = end + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (HasControlCharacter(line)) return "a control character in the PLY header";
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (lines == 1) {
      if (word != "ply") return "not a PLY file";
      continue;
    }
    if (word == "format") {
      std::string kind;
      words >> kind;
      if (kind != "ascii" && kind != "binary_little_endian" && kind != "binary_big_endian")
        return "an unknown PLY format \"" + Excerpt(kind, 40) + "\"";
      header.binary = kind != "ascii";
      header.big_endian = kind == "binary_big_endian";
      format = true;
    } else if (word == "element") {
      PlyElement e;
      std::string count;
      words >> e.name >> count;
      if (e.name.empty() || count.empty() ||
          count.find_first_not_of("0123456789") != std::string::npos || count.size() > 12)
        return "a PLY element without a valid count: \"" + Excerpt(line, 80) + "\"";
      e.count = std::stoll(count);
      header.elements.push_back(e);
    } else if (word == "property") {
      if (header.elements.empty()) return "a PLY property before any element";
      PlyProperty prop;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string count_type;
        words >> count_type >> type;
        const auto c = kTypes.find(count_type);
        if (c == kTypes.end() || c->second.is_float)
          return "a malformed PLY list property: \"" + Excerpt(line, 80) + "\"";
        prop.list = true;
        prop.count_size = c->second.size;
        prop.count_signed = c->second.is_signed;
      }
      const auto t = kTypes.find(type);
      if (t == kTypes.end() || !(words >> prop.name))
        return "a malformed PLY property: \"" + Excerpt(line, 80) + "\"";
      prop.size = t->second.size;
      prop.is_float = t->second.is_float;
      prop.is_signed = t->second.is_signed;
      header.elements.back().properties.push_back(prop);
    } else if (word == "end_header") {
      if (!format) return "a PLY header without a format line";
      header.body = at;
      // The least each element can take: a list at least its count; ASCII two bytes a value.
      long double least = 0;
      for (const auto& e : header.elements) {
        long double row = 0;
        for (const auto& prop : e.properties)
          row += header.binary ? (prop.list ? prop.count_size : prop.size) : 2;
        least += e.count * std::max<long double>(row, 1);
      }
      if (least > (long double)(data.size() - at))
        return "a PLY header that declares more data than the file holds";
      return "";
    } else if (word != "comment" && word != "obj_info" && !word.empty()) {
      return "an unknown PLY header line \"" + Excerpt(line, 80) + "\"";
    }
  }
}

/// Reads the values of a PLY body, ASCII or binary, in either byte order.
class PlyBody {
public:
  PlyBody(const std::string& data, const PlyHeader& header)
      : data_(data), at_(header.body), binary_(header.binary), swap_(header.big_endian) {}
  /// The next value of a property (or a list count), as a double; false at the file's end or
  /// on a word that is not a number.
  bool Read(int size, bool is_float, bool is_signed, double& value) {
    if (!binary_) {
      while (at_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[at_]))) ++at_;
      const size_t start = at_;
      while (at_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[at_]))) ++at_;
      if (start == at_ || at_ - start > 64) return false;
      const std::string word = data_.substr(start, at_ - start);
      char* end = nullptr;
      value = std::strtod(word.c_str(), &end);
      return *end == '\0';
    }
    if (size > int(data_.size() - at_)) return false;
    unsigned char b[8];
    std::memcpy(b, data_.data() + at_, size_t(size));
    at_ += size_t(size);
    if (swap_) std::reverse(b, b + size);
    if (is_float) {
      if (size == 4) {
        float f;
        std::memcpy(&f, b, 4);
        value = f;
      } else {
        std::memcpy(&value, b, 8);
      }
      return true;
    }
    uint64_t u = 0;
    std::memcpy(&u, b, size_t(size)); // little-endian host
    if (is_signed && size < 8 && (u >> (8 * size - 1)) & 1) u |= ~uint64_t(0) << (8 * size);
    value = is_signed ? double(int64_t(u)) : double(u);
    return true;
  }

private:
  const std::string& data_;
  size_t at_;
  bool binary_, swap_;
};

/// Reads a PLY file into `m`: vertex positions, normals, colours and quality; faces (lists of
/// any length, fanned into triangles), their colours and MeshLab's selection flag; every other
/// element and property is skipped. vcglib's PLY reader reads a polygon's corners before it
/// checks them (a heap overflow on a malformed file), so the product reads PLY itself.
/// Returns the vcglib mask of what the file holds. Throws MeshIoError.
/// A PLY vertex or triangle as read, before the mesh is built.
struct PlyVertex {
  Point3m p, n;
  vcg::Color4b c = vcg::Color4b(vcg::Color4b::White);
  float q = 0;
};
struct PlyTriangle {
  std::array<int, 3> v;
  vcg::Color4b c = vcg::Color4b(vcg::Color4b::White);
  bool selected = false;
};

/// What a property is for, decided once per element rather than once per value.
enum class PlyKind { kSkip, kPosition, kNormal, kColor, kQuality, kCorners, kFlags };
struct PlyUse {
  PlyKind kind;
  int channel; ///< x/y/z or r/g/b/a
};

PlyUse UseOf(const PlyProperty& prop, bool is_vertex, bool is_face) {
  const std::string& n = prop.name;
  const int rgba = n == "red" ? 0 : n == "green" ? 1 : n == "blue" ? 2 : n == "alpha" ? 3 : -1;
  if (prop.list)
    return {is_face && (n == "vertex_indices" || n == "vertex_index") ? PlyKind::kCorners
                                                                      : PlyKind::kSkip,
            0};
  if (is_vertex && (n == "x" || n == "y" || n == "z")) return {PlyKind::kPosition, n[0] - 'x'};
  if (is_vertex && (n == "nx" || n == "ny" || n == "nz")) return {PlyKind::kNormal, n[1] - 'x'};
  if ((is_vertex || is_face) && rgba >= 0) return {PlyKind::kColor, rgba};
  if (is_vertex && n == "quality") return {PlyKind::kQuality, 0};
  if (is_face && n == "flags") return {PlyKind::kFlags, 0};
  return {PlyKind::kSkip, 0};
}

/// The attribute a used property adds to the mesh (MeshLab's mask bits).
int MaskOf(const PlyUse& use, bool is_vertex) {
  using Mask = vcg::tri::io::Mask;
  switch (use.kind) {
  case PlyKind::kNormal:
    return Mask::IOM_VERTNORMAL;
  case PlyKind::kColor:
    return is_vertex ? Mask::IOM_VERTCOLOR : Mask::IOM_FACECOLOR;
  case PlyKind::kQuality:
    return Mask::IOM_VERTQUALITY;
  case PlyKind::kFlags:
    return Mask::IOM_FACEFLAGS;
  default:
    return 0;
  }
}

/// A colour channel of 0-255 from an integer property, or from a float one of 0-1.
unsigned char ColorChannel(const PlyProperty& prop, double v) {
  const double c = prop.is_float ? 255 * v : v;
  return (unsigned char)std::lround(std::max(0.0, std::min(255.0, c == c ? c : 0.0)));
}

/// `m` made of what was read, with the attributes `mask` names.
void BuildMesh(const std::vector<PlyVertex>& vertices, const std::vector<PlyTriangle>& triangles,
               int mask, CMeshO& m) {
  using Mask = vcg::tri::io::Mask;
  m.Clear();
  if (mask & Mask::IOM_FACECOLOR) m.face.EnableColor();
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, vertices.size());
  for (const PlyVertex& v : vertices) {
    vi->P() = v.p;
    vi->N() = v.n;
    vi->C() = v.c;
    vi->Q() = v.q;
    ++vi;
  }
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, triangles.size());
  for (const PlyTriangle& t : triangles) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[t.v[k]];
    if (mask & Mask::IOM_FACECOLOR) fi->C() = t.c;
    if (t.selected) fi->SetS();
    ++fi;
  }
}

int ReadPly(const std::string& path, const std::string& data, CMeshO& m) {
  using Mask = vcg::tri::io::Mask;
  auto fail = [&](const std::string& why) {
    throw MeshIoError(path + ": not a readable mesh (" + why + ")");
  };
  PlyHeader header;
  const std::string problem = ParsePlyHeader(data, header);
  if (!problem.empty()) fail(problem);
  PlyBody body(data, header);
  auto read = [&](const PlyProperty& prop, const std::string& element, long long row) {
    double v = 0;
    if (!body.Read(prop.size, prop.is_float, prop.is_signed, v))
      fail("the " + element + " " + std::to_string(row) + " is cut short or not a number");
    return v;
  };
  auto read_count = [&](const PlyProperty& prop, const std::string& element, long long row) {
    double n = 0;
    if (!body.Read(prop.count_size, false, prop.count_signed, n) || !(n >= 0 && n <= 1e6) ||
        n != std::floor(n))
      fail("the " + element + " " + std::to_string(row) + " has no valid list length");
    return int(n);
  };

  int mask = Mask::IOM_VERTCOORD | Mask::IOM_FACEINDEX;
  std::vector<PlyVertex> vertices;
  std::vector<PlyTriangle> triangles;
  bool have_vertices = false;
  std::vector<int> corners;
  for (const PlyElement& e : header.elements) {
    const bool is_vertex = e.name == "vertex" && !have_vertices;
    const bool is_face = e.name == "face";
    if (is_vertex) {
      have_vertices = true;
      vertices.resize(size_t(e.count));
    }
    std::vector<PlyUse> uses;
    for (const PlyProperty& prop : e.properties) {
      uses.push_back(UseOf(prop, is_vertex, is_face));
      if (e.count > 0) mask |= MaskOf(uses.back(), is_vertex);
    }
    for (long long row = 0; row < e.count; ++row) {
      PlyTriangle face;
      corners.clear();
      for (size_t i = 0; i < e.properties.size(); ++i) {
        const PlyProperty& prop = e.properties[i];
        const PlyUse use = uses[i];
        if (prop.list) {
          const int count = read_count(prop, e.name, row);
          for (int k = 0; k < count; ++k) {
            const double v = read(prop, e.name, row);
            if (use.kind != PlyKind::kCorners) continue;
            if (!(v >= 0 && v < double(vertices.size())) || v != std::floor(v))
              fail("face " + std::to_string(row) + " names a vertex that does not exist");
            corners.push_back(int(v));
          }
          if (use.kind == PlyKind::kCorners && count < 3)
            fail("face " + std::to_string(row) + " has fewer than three corners");
          continue;
        }
        const double v = read(prop, e.name, row);
        PlyVertex* vx = is_vertex ? &vertices[size_t(row)] : nullptr;
        switch (use.kind) {
        case PlyKind::kPosition:
          vx->p[use.channel] = Scalarm(v);
          break;
        case PlyKind::kNormal:
          vx->n[use.channel] = Scalarm(v);
          break;
        case PlyKind::kColor:
          (vx ? vx->c : face.c)[use.channel] = ColorChannel(prop, v);
          break;
        case PlyKind::kQuality:
          vx->q = float(v);
          break;
        case PlyKind::kFlags:
          face.selected = (int64_t(v) & CFaceO::SELECTED) != 0;
          break;
        default:
          break;
        }
      }
      if (!is_face) continue;
      if (corners.empty()) fail("the faces have no vertex_indices");
      for (size_t k = 1; k + 1 < corners.size(); ++k) {
        face.v = {corners[0], corners[k], corners[k + 1]};
        triangles.push_back(face);
      }
    }
  }
  BuildMesh(vertices, triangles, mask, m);
  return mask;
}

/// Replaces `m` by these vertices and triangles (indices into `points`, checked by the reader).
void SetMesh(CMeshO& m, const std::vector<Point3m>& points,
             const std::vector<std::array<int, 3>>& triangles) {
  m.Clear();
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, points.size());
  for (const auto& p : points) (vi++)->P() = p;
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, triangles.size());
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[t[k]];
    ++fi;
  }
}

/// Reads an STL file, binary or ASCII, into `m` (a triangle soup, welded by the caller).
/// vcglib's ASCII reader loops forever on a file without a line break, so the product reads
/// STL itself. Throws MeshIoError.
void ReadStl(const std::string& path, const std::string& data, CMeshO& m) {
  std::vector<Point3m> corners;
  uint32_t count = 0;
  if (data.size() >= 84) std::memcpy(&count, data.data() + 80, 4);
  if (data.size() >= 84 && data.size() == 84 + 50ull * count) {
    for (uint32_t t = 0; t < count; ++t)
      for (int k = 0; k < 3; ++k) {
        float v[3];
        std::memcpy(v, data.data() + 84 + 50ull * t + 12 + 12 * k, 12);
        corners.emplace_back(v[0], v[1], v[2]);
      }
  } else {
    if (data.compare(0, 5, "solid") != 0)
      throw MeshIoError(path + ": not a readable mesh (neither binary nor ASCII STL)");
    std::istringstream words(data);
    std::string word;
    while (words >> word) {
      if (word != "vertex") continue;
      float v[3];
      if (!(words >> v[0] >> v[1] >> v[2]))
        throw MeshIoError(path + ": not a readable mesh (a vertex without three coordinates)");
      corners.emplace_back(v[0], v[1], v[2]);
    }
    if (corners.size() % 3 != 0)
      throw MeshIoError(path + ": not a readable mesh (vertices not in threes)");
  }
  std::vector<std::array<int, 3>> triangles(corners.size() / 3);
  for (size_t t = 0; t < triangles.size(); ++t)
    triangles[t] = {int(3 * t), int(3 * t + 1), int(3 * t + 2)};
  SetMesh(m, corners, triangles);
}

/// Reads an OFF file (OFF, COFF, NOFF, STOFF and their combinations; positions and faces,
/// polygons fanned into triangles) into `m`. vcglib's OFF reader overruns its buffers and
/// reads freed memory on malformed files, so the product reads OFF itself. Throws MeshIoError.
void ReadOff(const std::string& path, const std::string& data, CMeshO& m) {
  std::istringstream in(data);
  auto fail = [&](const std::string& why) {
    throw MeshIoError(path + ": not a readable mesh (" + why + ")");
  };
  // The file's lines without comments and blank lines.
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  }
  size_t at = 0;
  if (at < lines.size()) {
    std::istringstream first(lines[0]);
    std::string keyword;
    first >> keyword;
    if (keyword.size() >= 3 && keyword.compare(keyword.size() - 3, 3, "OFF") == 0) {
      if (keyword.find('4') != std::string::npos || keyword.find('n') != std::string::npos)
        fail("a " + keyword + " file: only three-dimensional OFF is read");
      lines[0] = lines[0].substr(lines[0].find(keyword) + keyword.size());
      if (lines[0].find_first_not_of(" \t\r") == std::string::npos) ++at;
    }
  }
  long long nv = -1, nf = -1, ne = 0;
  if (at >= lines.size() || !(std::istringstream(lines[at++]) >> nv >> nf >> ne) || nv < 0 ||
      nf < 0)
    fail("no vertex and face counts");
  if (nv > (long long)(lines.size() - at) || nf > (long long)(lines.size() - at) - nv)
    fail("the counts ask for more lines than the file holds");
  std::vector<Point3m> points(static_cast<size_t>(nv));
  for (long long v = 0; v < nv; ++v) {
    std::istringstream words(lines[at++]);
    if (!(words >> points[v][0] >> points[v][1] >> points[v][2]))
      fail("vertex " + std::to_string(v) + " has no three coordinates");
  }
  std::vector<std::array<int, 3>> triangles;
  for (long long f = 0; f < nf; ++f) {
    std::istringstream words(lines[at++]);
    long long corners = 0;
    if (!(words >> corners) || corners < 3 || corners > nv)
      fail("face " + std::to_string(f) + " has no valid corner count");
    std::vector<int> index(static_cast<size_t>(corners));
    for (auto& i : index) {
      long long v = -1;
      if (!(words >> v) || v < 0 || v >= nv)
        fail("face " + std::to_string(f) + " names a vertex that does not exist");
      i = int(v);
    }
    for (long long k = 1; k + 1 < corners; ++k)
      triangles.push_back({index[0], index[size_t(k)], index[size_t(k + 1)]});
  }
  SetMesh(m, points, triangles);
}

/// Reads an OBJ file's geometry into `m`: vertices ("v x y z", optionally with "r g b" in
/// [0, 1]) and faces ("f" with 1-based or negative indices, "v/vt/vn" corners, polygons fanned
/// into triangles); texture coordinates, normals, groups and materials are skipped. vcglib's
/// OBJ reader keeps a counter in a static variable across files and reads vertex colours past
/// the end of its array, so the product reads OBJ itself. Sets `has_color` when every vertex
/// carries a colour. Throws MeshIoError.
void ReadObj(const std::string& path, const std::string& data, CMeshO& m, bool& has_color) {
  std::istringstream in(data);
  auto fail = [&](long long line, const std::string& why) {
    throw MeshIoError(path + ": not a readable mesh (line " + std::to_string(line) + ": " + why +
                      ")");
  };
  std::vector<Point3m> points;
  std::vector<vcg::Color4b> colors;
  std::vector<std::array<int, 3>> triangles;
  long long number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    // A backslash at the end continues the statement on the next line.
    while (!line.empty() && (line.back() == '\r' || line.back() == '\\')) {
      const bool continued = line.back() == '\\';
      line.pop_back();
      std::string next;
      if (continued && std::getline(in, next)) line += " " + next, ++number;
    }
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string head;
    words >> head;
    if (head == "v") {
      double x[6];
      int n = 0;
      for (std::string word; n < 6 && words >> word; ++n) {
        char* end = nullptr;
        x[n] = std::strtod(word.c_str(), &end);
        if (*end != '\0') fail(number, "\"" + Excerpt(word, 20) + "\" is not a number");
      }
      if (n < 3) fail(number, "a vertex without three coordinates");
      points.emplace_back(Scalarm(x[0]), Scalarm(x[1]), Scalarm(x[2]));
      if (n == 6) {
        auto byte = [](double c) {
          return (unsigned char)std::lround(255 * std::max(0.0, std::min(1.0, c == c ? c : 0.0)));
        };
        colors.emplace_back(byte(x[3]), byte(x[4]), byte(x[5]), 255);
      }
    } else if (head == "f") {
      std::vector<int> corners;
      for (std::string token; words >> token;) {
        const std::string index = token.substr(0, token.find('/'));
        char* end = nullptr;
        const long long i = std::strtoll(index.c_str(), &end, 10);
        const long long nv = (long long)points.size();
        if (index.empty() || *end != '\0' || i == 0 || i > nv || i < -nv)
          fail(number,
               "a face names vertex \"" + Excerpt(index, 20) + "\" of " + std::to_string(nv));
        corners.push_back(int(i > 0 ? i - 1 : nv + i));
      }
      if (corners.size() < 3) fail(number, "a face with fewer than three corners");
      for (size_t k = 1; k + 1 < corners.size(); ++k)
        triangles.push_back({corners[0], corners[k], corners[k + 1]});
    }
  }
  has_color = !points.empty() && colors.size() == points.size();
  SetMesh(m, points, triangles);
  if (has_color)
    for (size_t v = 0; v < colors.size(); ++v) m.vert[v].C() = colors[v];
}

} // namespace

void CheckMeshFormat(const std::string& path) {
  const std::string ext = Extension(path);
  if (!Supported(ext))
    throw MeshIoError(path + ": unsupported format \"" + ext + "\" (use .ply, .off, .obj or .stl)");
}

std::string ReadMeshFile(const std::string& path) {
  CheckMeshFormat(path);
  std::ifstream in(path, std::ios::binary);
  if (!in.good()) throw MeshIoError(path + ": cannot open the file");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw MeshIoError(path + ": cannot read the file");
  return bytes;
}

int LoadMesh(const std::string& path, CMeshO& m) {
  return LoadMesh(path, ReadMeshFile(path), m);
}

int LoadMesh(const std::string& path, const std::string& bytes, CMeshO& m) {
  CheckMeshFormat(path);
  const std::string ext = Extension(path);
  int mask = vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX;
  if (ext == "ply") {
    mask = ReadPly(path, bytes, m);
  } else if (ext == "obj") {
    bool has_color = false;
    ReadObj(path, bytes, m, has_color);
    if (has_color) mask |= vcg::tri::io::Mask::IOM_VERTCOLOR;
  } else if (ext == "off") {
    ReadOff(path, bytes, m);
  } else {
    ReadStl(path, bytes, m);
    // STL stores each triangle with its own corners: weld them, as MeshLab does on import,
    // or every triangle would be a hole of its own.
    vcg::tri::Clean<CMeshO>::RemoveDuplicateVertex(m);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
  }
  if (mask & vcg::tri::io::Mask::IOM_VERTNORMAL)
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
  else
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  return mask;
}

void SaveMesh(const std::string& path, CMeshO& m, int mask, const std::string& partial_dir) {
  using Exporter = vcg::tri::io::Exporter<CMeshO>;
  CheckMeshFormat(path);
  const std::string ext = Extension(path);
  // Same extension, so vcglib picks the same writer.
  const std::string beside =
      partial_dir.empty() ? path : partial_dir + "/" + path.substr(path.find_last_of('/') + 1);
  const std::string tmp = beside + ".part" + std::to_string(::getpid()) + "." + ext;
  const int err = Exporter::Save(m, tmp.c_str(), mask);
  if (err != 0) {
    std::remove(tmp.c_str());
    throw MeshIoError(path + ": cannot write (" + Exporter::ErrorMsg(err) + ")");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw MeshIoError(path + ": cannot write (rename failed)");
  }
}

} // namespace curvature_inpaint
