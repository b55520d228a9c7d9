#include "mesh_io.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/import.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
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

/// Whether a header line holds a control character (a tab aside), which vcglib's PLY header
/// parser, working on C strings, does not survive.
bool HasControlCharacter(const std::string& line) {
  return std::any_of(line.begin(), line.end(), [](char c) {
    return (static_cast<unsigned char>(c) < 32 && c != '\t') || c == 127;
  });
}

/// Checks a PLY header before vcglib's reader sees it: that reader dereferences missing
/// tokens (an "element" line without a count crashes it) and allocates whatever count a
/// header declares. Returns why the header is refused, or "" when it is sound.
std::string PlyHeaderProblem(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const long long file_size = in.tellg();
  in.seekg(0);
  static const std::map<std::string, int> kSizes{
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  std::string line;
  long long header_bytes = 0, min_body = 0, element_min = 0, element_count = 0;
  bool binary = false, format = false;
  int lines = 0;
  auto close_element = [&] { min_body += element_count * std::max<long long>(element_min, 1); };
  while (std::getline(in, line)) {
    header_bytes += (long long)line.size() + 1;
    if (++lines > 10000 || header_bytes > (1 << 20)) return "a PLY header of over 1 MB";
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // vcglib reads the header as C strings in fixed buffers.
    if (line.size() > 500) return "a PLY header line of over 500 characters";
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
        return "an unknown PLY format \"" + kind + "\"";
      binary = kind != "ascii";
      format = true;
    } else if (word == "element") {
      std::string name, count;
      words >> name >> count;
      if (name.empty() || count.empty() ||
          count.find_first_not_of("0123456789") != std::string::npos || count.size() > 12)
        return "a PLY element without a valid count: \"" + Excerpt(line, 80) + "\"";
      close_element();
      element_count = std::stoll(count);
      element_min = 0;
    } else if (word == "property") {
      std::string type, a, b;
      words >> type >> a >> b;
      if (type == "list") {
        if (!kSizes.count(a) || !kSizes.count(b) || !(words >> word))
          return "a malformed PLY list property: \"" + Excerpt(line, 80) + "\"";
        element_min += binary ? kSizes.at(a) : 2;
      } else {
        if (!kSizes.count(type) || a.empty())
          return "a malformed PLY property: \"" + Excerpt(line, 80) + "\"";
        element_min += binary ? kSizes.at(type) : 2;
      }
    } else if (word == "end_header") {
      close_element();
      if (!format) return "a PLY header without a format line";
      if (min_body > file_size - header_bytes)
        return "a PLY header that declares more data than the file holds";
      return "";
    }
  }
  return "a PLY header without end_header";
}

/// Reads an STL file, binary or ASCII, into `m` (a triangle soup, welded by the caller).
/// vcglib's ASCII reader loops forever on a file without a line break, so the product reads
/// STL itself. Throws MeshIoError.
void ReadStl(const std::string& path, CMeshO& m) {
  std::ifstream in(path, std::ios::binary);
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
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
  m.Clear();
  if (corners.empty()) return;
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, corners.size());
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, corners.size() / 3);
  for (size_t c = 0; c < corners.size(); ++c, ++vi) vi->P() = corners[c];
  for (size_t t = 0; t < corners.size() / 3; ++t, ++fi)
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[3 * t + k];
}

/// Reads an OFF file (OFF, COFF, NOFF, STOFF and their combinations; positions and faces,
/// polygons fanned into triangles) into `m`. vcglib's OFF reader overruns its buffers and
/// reads freed memory on malformed files, so the product reads OFF itself. Throws MeshIoError.
void ReadOff(const std::string& path, CMeshO& m) {
  std::ifstream in(path, std::ios::binary);
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
  m.Clear();
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, points.size());
  for (const auto& p : points) (vi++)->P() = p;
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, triangles.size());
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[t[k]];
    ++fi;
  }
}

/// Reads an OBJ file's geometry into `m`: vertices ("v x y z", optionally with "r g b" in
/// [0, 1]) and faces ("f" with 1-based or negative indices, "v/vt/vn" corners, polygons fanned
/// into triangles); texture coordinates, normals, groups and materials are skipped. vcglib's
/// OBJ reader keeps a counter in a static variable across files and reads vertex colours past
/// the end of its array, so the product reads OBJ itself. Sets `has_color` when every vertex
/// carries a colour. Throws MeshIoError.
void ReadObj(const std::string& path, CMeshO& m, bool& has_color) {
  std::ifstream in(path, std::ios::binary);
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
  m.Clear();
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, points.size());
  for (size_t v = 0; v < points.size(); ++v, ++vi) {
    vi->P() = points[v];
    if (has_color) vi->C() = colors[v];
  }
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, triangles.size());
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[t[k]];
    ++fi;
  }
}

} // namespace

int LoadMesh(const std::string& path, CMeshO& m) {
  using Importer = vcg::tri::io::Importer<CMeshO>;
  using Mask = vcg::tri::io::Mask;
  const std::string ext = Extension(path);
  if (!Supported(ext))
    throw MeshIoError(path + ": unsupported format \"" + ext + "\" (use .ply, .off, .obj or .stl)");
  if (!std::ifstream(path).good()) throw MeshIoError(path + ": cannot open the file");
  const std::string problem = ext == "ply" ? PlyHeaderProblem(path) : "";
  if (!problem.empty()) throw MeshIoError(path + ": not a readable mesh (" + problem + ")");
  if (ext == "obj") {
    bool has_color = false;
    ReadObj(path, m, has_color);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    return vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX |
           (has_color ? int(vcg::tri::io::Mask::IOM_VERTCOLOR) : 0);
  }
  if (ext == "off") {
    ReadOff(path, m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    return vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX;
  }
  if (ext == "stl") {
    ReadStl(path, m);
    // STL stores each triangle with its own corners: weld them, as MeshLab does on import,
    // or every triangle would be a hole of its own.
    vcg::tri::Clean<CMeshO>::RemoveDuplicateVertex(m);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    return vcg::tri::io::Mask::IOM_VERTCOORD | vcg::tri::io::Mask::IOM_FACEINDEX;
  }
  int mask = 0;
  Importer::LoadMask(path.c_str(), mask);
  m.Clear();
  // MeshLab's mesh keeps some attributes optional: enable those the file carries.
  if (mask & Mask::IOM_FACECOLOR) m.face.EnableColor();
  if (mask & Mask::IOM_FACEQUALITY) m.face.EnableQuality();
  if (mask & Mask::IOM_WEDGTEXCOORD) m.face.EnableWedgeTexCoord();
  if (mask & Mask::IOM_VERTTEXCOORD) m.vert.EnableTexCoord();
  if (mask & Mask::IOM_VERTRADIUS) m.vert.EnableRadius();
  int loaded = mask;
  const int err = Importer::Open(m, path.c_str(), loaded);
  if (err != 0 && Importer::ErrorCritical(err)) {
    const std::string why = Importer::ErrorMsg(err);
    m.Clear();
    throw MeshIoError(path + ": not a readable mesh (" + why + ")");
  }
  // Whatever vcglib's PLY reader missed, a face must name vertices that exist.
  const CVertexO* first = m.vert.empty() ? nullptr : &m.vert.front();
  for (const auto& f : m.face)
    for (int k = 0; k < 3; ++k)
      if (!first || f.cV(k) < first || f.cV(k) >= first + m.vert.size()) {
        m.Clear();
        throw MeshIoError(path +
                          ": not a readable mesh (a face names a vertex that does not exist)");
      }
  if (!(loaded & Mask::IOM_VERTNORMAL))
    vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFace(m);
  else
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  return loaded;
}

void SaveMesh(const std::string& path, CMeshO& m, int mask) {
  using Exporter = vcg::tri::io::Exporter<CMeshO>;
  const std::string ext = Extension(path);
  if (!Supported(ext))
    throw MeshIoError(path + ": unsupported format \"" + ext + "\" (use .ply, .off, .obj or .stl)");
  // Same extension, so vcglib picks the same writer.
  const std::string tmp = path + ".part" + std::to_string(::getpid()) + "." + ext;
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
