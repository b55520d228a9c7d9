// What the libFuzzer targets share: the Qt application QImage needs, and the input read as a
// sequence of one-byte choices.
#pragma once

#include <QGuiApplication>

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

} // namespace fuzz
