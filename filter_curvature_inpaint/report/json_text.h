// JSON text for the files the pipeline writes by hand (the fill report, hole_<k>.json, the
// filter table): numbers a JSON parser accepts and strings escaped as RFC 8259 asks, so every
// file reads back in any parser with the same values it was written with.
#pragma once

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace curvature_inpaint {

/// A number as JSON has it: JSON has no infinity and no NaN, so a value that is not finite is
/// written as null (a reader then sees "no value", never a made-up one).
struct JsonNumber {
  double value;
};

inline std::ostream& operator<<(std::ostream& o, JsonNumber n) {
  return std::isfinite(n.value) ? o << n.value : o << "null";
}

/// `text` as a JSON string literal, quotes included: quotes and backslashes escaped, control
/// characters as \u00XX; other bytes (UTF-8 included) as they are.
inline std::string JsonQuoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

} // namespace curvature_inpaint
