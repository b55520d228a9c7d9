// What the libFuzzer targets share: the Qt application QImage needs, the input read as a
// sequence of one-byte choices, and meshes built from triangle lists.
#pragma once

#include "pipeline/meshlab_mesh.h"

#include <QGuiApplication>

#include <array>
#include <vector>

#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace fuzz {

/// Qt's offscreen platform and an application: QImage's PNG plugin needs one.
inline void StartQt(int* argc, char*** argv) {
  setenv("QT_QPA_PLATFORM", "offscreen", 1);
  static QGuiApplication app(*argc, *argv);
}

/// The input as choices, one byte each; zeros once it runs out.
struct Input {
  const uint8_t* data;
  size_t size, at = 0;
  uint8_t Next() { return at < size ? data[at++] : 0; }
};

/// Appends these triangles (indices into m.vert) to `m`.
inline void AddTriangles(CMeshO& m, const std::vector<std::array<int, 3>>& faces) {
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, faces.size());
  for (const auto& t : faces) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[t[k]];
    ++fi;
  }
}

} // namespace fuzz
