// Errors the vcg_ext stages throw. Every stage validates before it writes, so a thrown error
// leaves the caller's mesh exactly as it was.
#pragma once

#include <stdexcept>
#include <string>

namespace vcg_ext {

/// The input mesh violates a stage's precondition; what() is one sentence for the user.
class InvalidMeshError : public std::runtime_error {
public:
  explicit InvalidMeshError(const std::string& what) : std::runtime_error(what) {}
};

/// The user cancelled through the progress callback; the mesh is unchanged.
class CancelledError : public std::runtime_error {
public:
  CancelledError() : std::runtime_error("cancelled by the user") {}
};

} // namespace vcg_ext
