// Errors the vcg_ext stages throw. Every stage validates its mesh and its parameters before it
// writes, so a thrown error leaves the caller's mesh exactly as it was.
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

/// A parameter outside its range; what() names it and the range, for the user.
class InvalidParameterError : public std::invalid_argument {
public:
  explicit InvalidParameterError(const std::string& what) : std::invalid_argument(what) {}
};

/// Throws InvalidParameterError unless `value` is a number in [lo, hi] (NaN is not).
inline void RequireRange(double value, double lo, double hi, const std::string& name) {
  if (!(value >= lo && value <= hi)) {
    auto text = [](double x) {
      std::string s = std::to_string(x);
      s.erase(s.find_last_not_of('0') + 1);
      if (!s.empty() && s.back() == '.') s.pop_back();
      return s;
    };
    throw InvalidParameterError(name + " must be from " + text(lo) + " to " + text(hi));
  }
}

} // namespace vcg_ext
