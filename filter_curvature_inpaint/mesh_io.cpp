#include "mesh_io.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/import.h>

#include <cstdio>
#include <fstream>
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

} // namespace

int LoadMesh(const std::string& path, CMeshO& m) {
  using Importer = vcg::tri::io::Importer<CMeshO>;
  using Mask = vcg::tri::io::Mask;
  const std::string ext = Extension(path);
  if (!Supported(ext))
    throw MeshIoError(path + ": unsupported format \"" + ext + "\" (use .ply, .off, .obj or .stl)");
  if (!std::ifstream(path).good()) throw MeshIoError(path + ": cannot open the file");
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
  if (ext == "stl") {
    // STL stores each triangle with its own corners: weld them, as MeshLab does on import,
    // or every triangle would be a hole of its own.
    vcg::tri::Clean<CMeshO>::RemoveDuplicateVertex(m);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
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
