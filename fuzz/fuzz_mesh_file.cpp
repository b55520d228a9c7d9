// libFuzzer target: reading a mesh file (the importers the tool and the plugin feed). The
// first byte picks the format; the rest is the file. A clear MeshIoError or a loaded mesh
// are fine; a crash or a hang is not.
#include "io/mesh_io.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {"ply", "off", "obj", "stl"};
  const std::string path =
      "/tmp/curvature-inpaint-fuzz-" + std::to_string(getpid()) + "." + kExtensions[data[0] % 4];
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  CMeshO m;
  try {
    curvature_inpaint::LoadMesh(path, m);
  } catch (const std::exception&) {
  }
  std::remove(path.c_str());
  return 0;
}
