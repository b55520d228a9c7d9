// Reading and writing meshes outside MeshLab (PLY, OFF, OBJ, STL), for the command-line tool.
// The product reads all four itself, since vcglib's readers crash, hang or overrun their
// buffers on malformed files (found by fuzz/fuzz_mesh_file.cpp); vcglib writes them. MeshLab's
// own I/O plugins do this inside the GUI and meshlabserver.
#pragma once

#include "pipeline/meshlab_mesh.h"

#include <stdexcept>
#include <string>

namespace curvature_inpaint {

class MeshIoError : public std::runtime_error {
public:
  explicit MeshIoError(const std::string& what) : std::runtime_error(what) {}
};

/// Checks that `path` names a format the tool reads and writes (.ply, .off, .obj, .stl), by its
/// extension. Throws MeshIoError.
void CheckMeshFormat(const std::string& path);

/// Loads `path` into `m` (cleared first) and returns vcglib's mask of what the file holds,
/// so SaveMesh can write the same attributes back. Throws MeshIoError.
int LoadMesh(const std::string& path, CMeshO& m);

/// The bytes of the mesh file `path`, for a caller that reads them once for more than loading
/// (batch hashes them too). Throws MeshIoError (an unsupported format, an unreadable file).
std::string ReadMeshFile(const std::string& path);

/// LoadMesh from `bytes`, the content of the file `path` (its extension names the format, its
/// name goes into the messages).
int LoadMesh(const std::string& path, const std::string& bytes, CMeshO& m);

/// Writes `m` to `path` with the attributes in `mask`. The file appears complete or not at
/// all: it is written beside the target (or in `partial_dir`, on the same file system) and
/// renamed over it. Throws MeshIoError.
void SaveMesh(const std::string& path, CMeshO& m, int mask, const std::string& partial_dir = "");

} // namespace curvature_inpaint
